// The import report's notes (what the import did that loses nothing), connector names unique in a
// POU, and legacy TC6 v1.0 SFC charts read as v2.01 (issue 12).
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { canonical, fixture, imported, run } from './fixtures';
import { graphOf } from './ldXml';
import { trace } from './behaviour';
import { schemaErrors } from './xsd';

const pairNames = (project: Project) =>
  project.pous[0]!.networks.map((n) =>
    n.elements.flatMap((e) => (e.kind === 'connector' ? [e.name] : [])).sort(),
  );

function reimport(project: Project): Project {
  const r = importPlcopen(exportPlcopen(project));
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}

describe('the import report names the connector pairs it drew', () => {
  it('one note per network, with the pairs and the wires; nothing among the warnings', () => {
    const { report } = imported('conn-crossing.xml');
    expect(report.warnings).toEqual([]);
    expect(report.notes.map((n) => [n.pou, n.message])).toEqual([
      ['Main', 'network 1: 2 wires drawn through connector pairs >C1>, >C2> because the grid cannot route them'],
    ]);
  });

  it('two networks that need pairs: names unique in the POU, one note each; export and import again keep graph, names and trace', async () => {
    // The crossing network twice in one body (localIds of the copy shifted).
    const text = fixture('conn-crossing.xml');
    const body = /<LD>([\s\S]*)<\/LD>/.exec(text)![1]!;
    const copy = body.replace(/(localId|refLocalId)="(\d+)"/g, (_m, a: string, id: string) => `${a}="${Number(id) + 500}"`).replace(/y="(\d+)"/g, (_m, y: string) => `y="${Number(y) + 400}"`);
    const r = importPlcopen(text.replace(body, body + copy));
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    expect(r.project.pous[0]!.networks.length).toBe(2);
    const names = pairNames(r.project);
    expect(names[0]!.length).toBeGreaterThan(0);
    expect(names[0]!.filter((n) => names[1]!.includes(n))).toEqual([]);
    expect(names).toEqual([
      ['C1', 'C2'],
      ['C3', 'C4'],
    ]);
    expect(r.report.notes.map((n) => n.message)).toEqual([
      'network 1: 2 wires drawn through connector pairs >C1>, >C2> because the grid cannot route them',
      'network 2: 2 wires drawn through connector pairs >C3>, >C4> because the grid cannot route them',
    ]);
    const xml = exportPlcopen(r.project);
    expect(await schemaErrors(xml)).toEqual([]);
    const again = reimport(r.project);
    expect(again.pous[0]!.networks.length).toBe(2);
    expect(graphOf(again)).toEqual(graphOf(r.project));
    expect(pairNames(again)).toEqual(names);
    expect(trace(again, 'Main', 60)).toEqual(trace(r.project, 'Main', 60));
  });

  it('pairs a user drew with one name in two networks are written with names unique in the body', async () => {
    const { project } = imported('conn-crossing.xml');
    const net = project.pous[0]!.networks[0]!;
    const twice: Project = { ...project, pous: [{ ...project.pous[0]!, networks: [net, { ...net, id: `${net.id}b` as typeof net.id }] }] };
    const xml = exportPlcopen(twice);
    expect(await schemaErrors(xml)).toEqual([]);
    const again = reimport(twice);
    expect(again.pous[0]!.networks.length).toBe(2);
    expect(graphOf(again)).toEqual(graphOf(twice));
    const names = pairNames(again);
    expect(names[0]!.filter((n) => names[1]!.includes(n))).toEqual([]);
  });
});

describe('a legacy TC6 v1.0 SFC chart (DS401GUI Test_SFC style)', () => {
  const { project, report } = imported('legacy-sfc-v10.xml');

  it('is read as v2.01: the chart (a contact wired to a condition, inline ST) is kept, no error', () => {
    const seq = project.pous.find((p) => p.name === 'Seq')!;
    expect(seq.language).toBe('SFC');
    expect(seq.sfc!.steps.map((s) => s.name)).toEqual(['Start', 'Run']);
    expect(report.warnings.map((w) => w.message)).toContain(
      'POU "Seq" is written in SFC in the legacy v1.0 format: read as v2.01 (the same chart), Rungsmith runs it and exports it in v2.01, but shows it read-only (the editor edits LD)',
    );
    expect(checkProject(project)).toEqual([]);
  });

  it('runs: A (the contact on the condition) leaves Start, Run counts N to 3, the jump returns to Start', () => {
    const plc = run(project, 'Main');
    const out: string[] = [];
    for (let k = 0; k < 8; k++) {
      plc.write('Go', k >= 2 && k < 4);
      plc.scan();
      out.push(`${plc.read('S1.Start.X') ? 'Start' : 'Run'}:${String(plc.read('Count'))}`);
    }
    expect(out).toEqual(['Start:0', 'Start:0', 'Run:1', 'Run:2', 'Run:3', 'Start:0', 'Start:0', 'Start:0']);
  });

  it('exports as valid v2.01 and imports again to the same chart and trace', async () => {
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml)).toEqual([]);
    expect(xml).toMatch(/<condition>\s*<connectionPointIn>\s*<connection refLocalId="4"/);
    expect(xml).toMatch(/<action localId="\d+" qualifier="N"><relPosition x="0" y="0"\/>/);
    const again = reimport(project);
    const chart = (p: Project) => canonical({ ...p, pous: p.pous.filter((x) => x.name === 'Seq').map((x) => ({ ...x, sfc: x.sfc })) } as Project);
    expect(JSON.parse(chart(again)).pous[0].sfc).toEqual(JSON.parse(chart(project)).pous[0].sfc);
    expect(trace(again, 'Main', 40)).toEqual(trace(project, 'Main', 40));
  });
});
