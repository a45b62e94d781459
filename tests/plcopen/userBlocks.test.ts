// A program calling the file's own function blocks and functions (declared after it), POUs in ST and
// FBD: import wires every call as in the file, export is schema-valid with callees first, and a
// round trip gives back the same POUs, interfaces and wiring.
import { describe, expect, it } from 'vitest';
import type { BoxElement } from '../../src/model/elements';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { connections } from './behaviour';
import { imported, run } from './fixtures';
import { schemaErrors } from './xsd';

const boxes = (p: Project, pou: string): BoxElement[] =>
  p.pous
    .find((x) => x.name === pou)!
    .networks.flatMap((n) => n.elements.filter((e): e is BoxElement => e.kind === 'box'));

const reimport = (xml: string): Project => {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
};

describe('PLCopen user blocks', () => {
  it('a program calls an FB and a function declared after it: every pin wired as in the file', () => {
    const { project, report } = imported('user-blocks.xml');
    expect(project.pous.map((p) => [p.name, p.kind, p.language])).toEqual([
      ['Main', 'PROGRAM', 'LD'],
      ['Motor', 'FUNCTION_BLOCK', 'LD'],
      ['Twice', 'FUNCTION', 'ST'],
      ['Avg', 'FUNCTION_BLOCK', 'LD'],
      ['Trace', 'PROGRAM', 'ST'],
    ]);
    expect(report.warnings.filter((w) => /cannot be drawn|dropped|not a pin/.test(w.message))).toEqual([]);
    const [motor, twice, avg] = boxes(project, 'Main');
    // EN/ENO from the file's EN pin; the in-out Count takes its variable; pins named as declared.
    expect(motor).toMatchObject({
      blockType: 'Motor',
      instance: 'Motor0',
      executionControl: true,
      inputs: { Stop: 'Halt', Count: 'Cnt' },
    });
    expect(twice).toMatchObject({ blockType: 'Twice', inputs: { X: 'Cnt' }, outputs: { OUT: 'Doubled' } });
    expect(twice!.instance).toBeUndefined();
    expect(avg).toMatchObject({ blockType: 'Avg', instance: 'Avg0', outputs: { M: 'Mean' } });
    const wires = connections(project).join('\n');
    expect(wires).toMatch(/box:Motor:Motor0:.*\.EN <- contact:NO:Go\.out/);
    expect(wires).toMatch(/box:Motor:Motor0:.*\.Start <- contact:NO:Btn\.out/);
    expect(wires).toMatch(/coil:COIL:Lamp\.in <- box:Motor:Motor0:.*\.Run/);
    expect(wires).toMatch(/coil:COIL:Enabled\.in <- box:Motor:Motor0:.*\.ENO/);
  });

  it('the FB instance is a variable of the FB type; a non-LD POU keeps its interface and source', () => {
    const { project, report } = imported('user-blocks.xml');
    const main = project.pous[0]!;
    expect(main.variables.find((v) => v.name === 'Motor0')?.type).toBe('Motor');
    const twice = project.pous.find((p) => p.name === 'Twice')!;
    expect(twice).toMatchObject({ returnType: 'INT', networks: [], source: 'Twice := X * 2;', comment: 'Doubles its input.' });
    expect(twice.variables.map((v) => [v.name, v.varClass])).toEqual([['X', 'input']]);
    const motor = project.pous.find((p) => p.name === 'Motor')!;
    expect(motor.variables.map((v) => [v.name, v.varClass])).toEqual([
      ['Start', 'input'],
      ['Stop', 'input'],
      ['Count', 'inOut'],
      ['Run', 'output'],
    ]);
    const text = report.warnings.map((w) => w.message).join('\n');
    expect(text).toContain('POU "Twice" is written in ST');
    expect(text).toContain('POU "Avg" was converted from FBD to LD');
    expect(project.tasks[0]!.programs.map((p) => p.pou)).toEqual(['Main', 'Trace']);
  });

  it('an FBD body that the grid draws exactly becomes LD with the same data flow', () => {
    const { project } = imported('user-blocks.xml');
    const [add, div] = boxes(project, 'Avg');
    expect(add).toMatchObject({ blockType: 'ADD', inputs: { IN1: 'A', IN2: 'B' } });
    expect(div).toMatchObject({ blockType: 'DIV', inputs: { IN2: '2' }, outputs: { OUT: 'M' } });
    expect(connections(project).join('\n')).toMatch(/box:DIV:.*\.IN1 <- box:ADD:.*\.OUT/);
  });

  it('export: schema-valid, callees first, in-out pins on both sides, EN/ENO as pins, ST POUs verbatim', async () => {
    const { project } = imported('user-blocks.xml');
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml)).toEqual([]);
    const order = [...xml.matchAll(/<pou name="(\w+)"/g)].map((m) => m[1]);
    expect(order).toEqual(['Motor', 'Avg', 'Twice', 'Main', 'Trace']);
    const block = /<block [^>]*typeName="Motor"[\s\S]*?<\/block>/.exec(xml)![0];
    const inputs = /<inputVariables>[\s\S]*?<\/inputVariables>/.exec(block)![0];
    const outputs = /<outputVariables>[\s\S]*?<\/outputVariables>/.exec(block)![0];
    expect([...inputs.matchAll(/formalParameter="(\w+)"/g)].map((m) => m[1])).toEqual(['EN', 'Start', 'Stop', 'Count']);
    expect([...outputs.matchAll(/formalParameter="(\w+)"/g)].map((m) => m[1])).toEqual(['ENO', 'Run', 'Count']);
    expect(xml).toMatch(/<variable name="Motor0">\s*<type>\s*<derived name="Motor"\/>/);
    // The ST program's array (which Rungsmith does not model) survives: its <pou> is the file's.
    expect(xml).toContain('<array><dimension lower="0" upper="9"/><baseType><INT/></baseType></array>');
  });

  it('round trip: same POUs, interfaces, calls and wiring; a second round trip is a fixed point', async () => {
    const { project } = imported('user-blocks.xml');
    const now = { now: new Date('2026-01-01T00:00:00Z') };
    const first = exportPlcopen(project, now);
    const back = reimport(first);
    const byName = (p: Project) => [...p.pous].sort((a, b) => a.name.localeCompare(b.name));
    expect(byName(back).map((p) => [p.name, p.kind, p.language, p.returnType, p.source])).toEqual(
      byName(project).map((p) => [p.name, p.kind, p.language, p.returnType, p.source]),
    );
    expect(byName(back).map((p) => p.variables)).toEqual(byName(project).map((p) => p.variables));
    expect(connections(back)).toEqual(connections(project));
    expect(back.tasks).toEqual(project.tasks);
    const second = exportPlcopen(back, now);
    expect(exportPlcopen(reimport(second), now)).toBe(second);
  });

  it('a non-LD POU whose interface was edited is written anew: new interface, same body', async () => {
    const { project } = imported('user-blocks.xml');
    const edited: Project = {
      ...project,
      pous: project.pous.map((p) =>
        p.name === 'Twice'
          ? { ...p, variables: [...p.variables, { name: 'Y', type: 'INT', varClass: 'input' as const, retain: false, comment: '' }] }
          : p,
      ),
    };
    const xml = exportPlcopen(edited);
    expect(await schemaErrors(xml)).toEqual([]);
    const back = reimport(xml).pous.find((p) => p.name === 'Twice')!;
    expect(back.variables.map((v) => v.name)).toEqual(['X', 'Y']);
    expect(back.source).toBe('Twice := X * 2;');
    expect(back.comment).toBe('Doubles its input.');
  });
  it('runs: the imported FB call switches the lamp and counts through its VAR_IN_OUT; the round trip runs alike', () => {
    const { project } = imported('user-blocks.xml');
    // Main without its call of the ST function Twice (the simulator runs LD only): Motor and Avg are LD.
    const ldOnly: Project = {
      ...project,
      pous: project.pous.map((p) =>
        p.name === 'Main' ? { ...p, networks: p.networks.filter((n) => !n.elements.some((e) => e.kind === 'box' && e.blockType === 'Twice')) } : p,
      ),
    };
    for (const p of [ldOnly, reimport(exportPlcopen(ldOnly))]) {
      const plc = run(p, 'Main');
      plc.write('Go', true);
      plc.write('Btn', true);
      plc.scan();
      expect([plc.read('Lamp'), plc.read('Enabled'), plc.read('Cnt')]).toEqual([true, true, 1]);
      plc.write('Btn', false);
      plc.scans(3);
      expect([plc.read('Lamp'), plc.read('Cnt')]).toEqual([true, 1]); // sealed in; counted once
      plc.write('Halt', true);
      plc.scan();
      expect(plc.read('Lamp')).toBe(false);
      plc.write('Go', false);
      plc.scan();
      expect(plc.read('Enabled')).toBe(false);
      expect(plc.scans(100).fault).toBeUndefined();
    }
  });
});
