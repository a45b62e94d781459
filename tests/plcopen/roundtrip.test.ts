// Project → PLCopen XML → project gives back the same program: variables, element kinds,
// connections and, compiled by the engine, the same values scan after scan.
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { EXAMPLES } from '../../src/model/examples';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { connections, trace } from './behaviour';
import { allElements, blocks, jumps } from './samples';
import { schemaErrors } from './xsd';

const cases: [string, () => Project][] = [
  ...EXAMPLES.map((e) => [`example ${e.id}`, () => e.build()] as [string, () => Project]),
  ['every contact and coil type', allElements],
  ['timers, counters and a data wire between functions', blocks],
  ['jump, label and return', jumps],
];

const kinds = (p: Project) =>
  p.pous
    .flatMap((pou) =>
      pou.networks.flatMap((n) => n.elements.filter((e) => e.kind !== 'link').map((e) => e.kind)),
    )
    .sort();

describe('PLCopen round trip', () => {
  it.each(cases)('%s: export validates, import gives back the same program', async (_name, build) => {
    const original = build();
    const xml = exportPlcopen(original);
    expect(await schemaErrors(xml)).toEqual([]);
    const back = importPlcopen(xml);
    if (!back.ok) throw new Error(JSON.stringify(back.errors));
    const p = back.project;
    expect(back.report.warnings).toEqual([]);
    expect(p.pous.map((x) => x.name)).toEqual(original.pous.map((x) => x.name));
    expect(p.pous.map((x) => x.variables)).toEqual(original.pous.map((x) => x.variables));
    expect(p.tasks).toEqual(original.tasks);
    expect(kinds(p)).toEqual(kinds(original));
    expect(connections(p)).toEqual(connections(original));
    expect(checkProject(p).filter((d) => d.severity === 'error')).toEqual([]);
    for (const pou of original.pous.filter((x) => x.kind === 'PROGRAM'))
      expect(trace(p, pou.name)).toEqual(trace(original, pou.name));
  });

  it('keeps network titles, comments and labels', () => {
    const original = EXAMPLES.find((e) => e.id === 'jump-label')!.build();
    const back = importPlcopen(exportPlcopen(original));
    if (!back.ok) throw new Error('import failed');
    const meta = (p: Project) =>
      p.pous[0]!.networks.map((n) => ({ title: n.title, comment: n.comment, label: n.label }));
    expect(meta(back.project)).toEqual(meta(original));
  });

  it('after one import, export and import are a fixed point (no drift on repeated round trips)', () => {
    const now = { now: new Date('2026-01-01T00:00:00Z') };
    const once = importPlcopen(exportPlcopen(blocks(), now));
    if (!once.ok) throw new Error('import failed');
    const second = exportPlcopen(once.project, now);
    const twice = importPlcopen(second);
    if (!twice.ok) throw new Error('import failed');
    expect(exportPlcopen(twice.project, now)).toBe(second);
  });
});
