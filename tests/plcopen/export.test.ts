// What other tools see in an export: declarations, tasks, and drawing data Beremiz/OpenPLC need.
import { describe, expect, it } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { variable } from '../../src/model/factory';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { child, childrenNamed, parseXml, type XmlElement } from '../../src/plcopen/xml/parse';
import { allElements, blocks } from './samples';
import { schemaErrors } from './xsd';

const all = (el: XmlElement, name: string): XmlElement[] => [
  ...(el.name === name ? [el] : []),
  ...el.children.flatMap((c) => all(c, name)),
];
const pt = (el: XmlElement | undefined) => ({ x: Number(el?.attrs.x), y: Number(el?.attrs.y) });

describe('PLCopen export', () => {
  it('writes a TC6 v2.01 document with LD scaling, the task interval and program instances', async () => {
    const xml = exportPlcopen(EXAMPLES[0]!.build());
    expect(await schemaErrors(xml)).toEqual([]);
    const root = parseXml(xml);
    expect(root.attrs.xmlns).toBe('http://www.plcopen.org/xml/tc6_0201');
    expect(
      child(child(child(child(root, 'contentHeader')!, 'coordinateInfo')!, 'ld')!, 'scaling'),
    ).toBeDefined();
    const task = all(root, 'task')[0]!;
    expect(task.attrs).toMatchObject({ name: 'MainTask', interval: 'T#10ms', priority: '1' });
    expect(child(task, 'pouInstance')!.attrs).toEqual({ name: 'MainInstance', typeName: 'Main' });
  });

  it('declares FB instances as derived types, keeps addresses, initial values, comments, RETAIN and CONSTANT', () => {
    const root = parseXml(exportPlcopen(blocks()));
    const vars = all(root, 'variable').filter((v) => v.attrs.name);
    const byName = new Map(vars.map((v) => [v.attrs.name!, v]));
    expect(child(child(byName.get('T1')!, 'type')!, 'derived')!.attrs.name).toBe('TON');
    expect(byName.get('Run')!.attrs.address).toBe('%IX0.0');
    expect(child(child(byName.get('Shown')!, 'initialValue')!, 'simpleValue')!.attrs.value).toBe('5');
    const elements = parseXml(exportPlcopen(allElements()));
    const lists = all(elements, 'localVars');
    const constant = lists.find((l) => l.attrs.constant === 'true')!;
    expect(childrenNamed(constant, 'variable').map((v) => v.attrs.name)).toEqual(['Limit']);
    const retained = lists
      .filter((l) => l.attrs.retain === 'true')
      .flatMap((l) => childrenNamed(l, 'variable').map((v) => v.attrs.name));
    // Q5 is declared RETAIN; Mem, Q6 and Q7 are written by retentive coils (M, SM, RM), which other tools only know as RETAIN.
    expect(retained.sort()).toEqual(['Mem', 'Q5', 'Q6', 'Q7']);
    expect(all(elements, 'documentation').some((d) => d.children[0]?.text === 'first input')).toBe(true);
  });

  it('writes coil and contact kinds as PLCopen attributes', () => {
    const root = parseXml(exportPlcopen(allElements()));
    const attrs = (c: XmlElement): Record<string, string | undefined> => ({
      v: child(c, 'variable')!.text,
      ...c.attrs,
    });
    const coils = all(root, 'coil')
      .filter((c) => child(c, 'variable'))
      .map(attrs);
    expect(coils.find((c) => c.v === 'Q2')).toMatchObject({ negated: 'true' });
    expect(coils.find((c) => c.v === 'Latch' && c.storage === 'set')).toBeDefined();
    expect(coils.find((c) => c.v === 'Latch' && c.storage === 'reset')).toBeDefined();
    expect(coils.find((c) => c.v === 'Q4')).toMatchObject({ edge: 'rising' });
    expect(coils.find((c) => c.v === 'Q5')).toMatchObject({ edge: 'falling' });
    const contacts = all(root, 'contact')
      .filter((c) => child(c, 'variable'))
      .map(attrs);
    expect(contacts.find((c) => c.v === 'B' && c.negated === 'true')).toBeDefined();
    expect(contacts.find((c) => c.v === 'C' && c.edge === 'rising')).toBeDefined();
    expect(contacts.find((c) => c.v === 'B' && c.edge === 'falling')).toBeDefined();
    // The inverting contact has no PLCopen element: it is written as a NOT block.
    expect(all(root, 'block').map((b) => b.attrs.typeName)).toContain('NOT');
  });

  it('gives every wire points from the consumer pin to the producer pin, so Beremiz reconnects rail pins', () => {
    for (const project of [allElements(), blocks(), ...EXAMPLES.map((e) => e.build())]) {
      const root = parseXml(exportPlcopen(project));
      for (const body of all(root, 'LD')) {
        const objects = new Map(body.children.map((o) => [o.attrs.localId!, o]));
        const pinsOut = (o: XmlElement) =>
          all(o, 'connectionPointOut').map((cp) => {
            const p = pt(child(o, 'position'));
            const r = pt(child(cp, 'relPosition'));
            return {
              x: p.x + r.x,
              y: p.y + r.y,
              formal: all(o, 'variable').find((v) => v.children.includes(cp))?.attrs.formalParameter,
            };
          });
        for (const o of body.children) {
          const origin = pt(child(o, 'position'));
          for (const cp of all(o, 'connectionPointIn')) {
            const rel = pt(child(cp, 'relPosition'));
            for (const c of childrenNamed(cp, 'connection')) {
              const points = childrenNamed(c, 'position').map(pt);
              expect(points.length).toBeGreaterThanOrEqual(2);
              expect(points[0]).toEqual({ x: origin.x + rel.x, y: origin.y + rel.y });
              const source = objects.get(c.attrs.refLocalId!)!;
              const end = points[points.length - 1]!;
              const outs = pinsOut(source).filter(
                (p) =>
                  !c.attrs.formalParameter || p.formal === undefined || p.formal === c.attrs.formalParameter,
              );
              expect(outs.some((p) => p.x === end.x && p.y === end.y)).toBe(true);
              // Wires are drawn with horizontal and vertical segments only.
              for (let i = 1; i < points.length; i++)
                expect(points[i]!.x === points[i - 1]!.x || points[i]!.y === points[i - 1]!.y).toBe(true);
            }
          }
        }
      }
    }
  });

  it('writes globals as configuration variables and functions with their return type', async () => {
    const p = blocks();
    const project = {
      ...p,
      globals: [variable('Shift', 'INT', { location: '%MW3', retain: true })],
      pous: [
        ...p.pous,
        {
          ...p.pous[0]!,
          id: 'pf' as never,
          name: 'Helper',
          kind: 'FUNCTION' as const,
          returnType: 'INT',
          variables: [variable('X', 'INT', { varClass: 'input' })],
        },
      ],
    };
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml)).toEqual([]);
    const root = parseXml(xml);
    const conf = all(root, 'configuration')[0]!;
    const globals = childrenNamed(conf, 'globalVars')[0]!;
    expect(globals.attrs.retain).toBe('true');
    expect(child(globals, 'variable')!.attrs).toEqual({ name: 'Shift', address: '%MW3' });
    const helper = all(root, 'pou').find((x) => x.attrs.name === 'Helper')!;
    expect(helper.attrs.pouType).toBe('function');
    expect(child(child(child(helper, 'interface')!, 'returnType')!, 'INT')).toBeDefined();
    expect(child(child(helper, 'interface')!, 'inputVars')).toBeDefined();
  });
});
