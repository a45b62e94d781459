// Importing PLCopen files: the constructs real tools write and those no real file had yet.
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import type { Project } from '../../src/model/project';
import { fixture, imported, run } from './fixtures';
import { schemaErrors } from './xsd';

const noErrors = (p: Parameters<typeof checkProject>[0]) =>
  checkProject(p).filter((d) => d.severity === 'error');

describe('PLCopen import: hand-written fixtures', () => {
  it('jump, label and return: networks in order, the label on the network after it, behaviour kept', () => {
    const { project, report } = imported('jump-label-return.xml');
    expect(report.warnings).toEqual([]);
    const nets = project.pous[0]!.networks;
    expect(nets.map((n) => n.label ?? '')).toEqual(['', '', 'OVER', '', '']);
    expect(nets[0]!.elements.find((e) => e.kind === 'jump')).toMatchObject({ target: 'OVER' });
    expect(nets[3]!.elements.some((e) => e.kind === 'return')).toBe(true);
    expect(project.tasks).toEqual([
      { name: 'Fast', cycleMs: 5, priority: 0, programs: [{ instance: 'inst0', pou: 'Main' }] },
    ]);
    expect(noErrors(project)).toEqual([]);
    // A TC6 v2.01 file is what Beremiz and OpenPLC write: it runs as they run it, jump and RETURN
    // dropped by their generator (LD-W20/LD-W21 say so on the elements).
    expect(project.profile).toBe('openplc');
    expect(report.profileReason).toMatch(/^semantics profile openplc: PLCopen TC6 v2\.01 is written by Beremiz and OpenPLC/);
    expect(checkProject(project).filter((d) => d.severity === 'warning').map((d) => d.rule)).toEqual(
      expect.arrayContaining(['LD-W20', 'LD-W21']),
    );
    const generated = run(project, 'Main');
    generated.write('Skip', true);
    generated.write('Stop', true);
    generated.scan();
    expect([generated.read('A'), generated.read('B'), generated.read('C')]).toEqual([true, true, true]);
    // Under the iec profile the jump and the RETURN act (IEC 61131-3 4.2.6).
    const plc = run({ ...project, profile: 'iec' }, 'Main');
    plc.write('Skip', true);
    plc.scan();
    expect([plc.read('A'), plc.read('B'), plc.read('C')]).toEqual([false, true, true]);
    plc.write('Skip', false);
    plc.write('Stop', true);
    plc.scan();
    expect([plc.read('A'), plc.read('B'), plc.read('C')]).toEqual([true, true, true]);
    plc.coldRestart();
    plc.write('Stop', true);
    plc.scan();
    expect(plc.read('C')).toBe(false); // RETURN ended the POU before the last network
  });

  it('connector and continuation join into one network; the continuation fans out', () => {
    const { project } = imported('connector-continuation.xml');
    expect(project.pous[0]!.networks).toHaveLength(1);
    const plc = run(project, 'Main');
    for (const [a, b] of [
      [false, false],
      [true, false],
      [true, true],
      [false, true],
    ] as const) {
      plc.write('A', a);
      plc.write('B', b);
      plc.scan();
      expect(plc.read('Y')).toBe(a && !b);
      expect(plc.read('Z')).toBe(!(a && !b));
    }
  });

  it('edge contacts and edge coils; executionOrderId > 0 decides the network order, except under openplc', () => {
    const coilsOf = (project: Project) =>
      project.pous[0]!.networks.map((n) => n.elements.flatMap((e) => (e.kind === 'coil' ? [`${e.coil}:${e.variable}`] : [])));
    // TC6 v2.0 (CODESYS, TwinCAT; profile iec): the network with the smallest id comes first.
    const v20 = importPlcopen(fixture('edges-and-order.xml').replace('tc6_0201', 'tc6_0200'));
    if (!v20.ok) throw new Error(JSON.stringify(v20.errors));
    expect(v20.project.profile).toBe('iec');
    expect(coilsOf(v20.project)).toEqual([['P:Pulse', 'COIL:Copy'], ['COIL:Rise'], ['COIL:Fall']]);
    // TC6 v2.01 (Beremiz, OpenPLC; profile openplc): their generator orders coils by position and
    // never by id (only blocks and outVariables are ordered): the networks follow the drawing.
    const { project } = imported('edges-and-order.xml');
    expect(coilsOf(project)).toEqual([['COIL:Rise'], ['COIL:Fall'], ['P:Pulse', 'COIL:Copy']]);
    const nets = project.pous[0]!.networks;
    expect(nets[0]!.elements.find((e) => e.kind === 'contact')).toMatchObject({ contact: 'P' });
    expect(nets[1]!.elements.find((e) => e.kind === 'contact')).toMatchObject({ contact: 'N' });
    const plc = run(project, 'Main');
    const seen: string[] = [];
    for (const v of [false, true, true, false, false]) {
      plc.write('In', v);
      plc.scan();
      seen.push(['Pulse', 'Rise', 'Fall'].map((n) => (plc.read(n) ? 1 : 0)).join(''));
    }
    // A falling-edge element sees its variable FALSE at its very first evaluation as a fall (IEC F_TRIG).
    expect(seen).toEqual(['001', '110', '000', '001', '000']);
  });

  it('keeps vendor addData and vendor elements, drops handleUnknown="discard" and says so', async () => {
    const { project, report } = imported('adddata.xml');
    expect(report.warnings.map((w) => w.message)).toContain(
      'addData "http://example.com/acme/cache" dropped (handleUnknown="discard")',
    );
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml)).toEqual([]);
    for (const kept of [
      '<acme:tag color="red">keep me</acme:tag>',
      '<acme:lamp/>',
      '<acme:pouInfo version="3"/>',
      '<acme:project id="42"/>',
      'xmlns:acme="http://example.com/acme"',
    ])
      expect(xml).toContain(kept);
    expect(xml).not.toContain('acme:cache');
    const again = importPlcopen(xml);
    expect(again.ok && exportPlcopen(again.project, { now: new Date(0) })).toBe(
      exportPlcopen(project, { now: new Date(0) }),
    );
  });

  it('CODESYS style (tc6_0200, CRLF, no geometry at all) imports into a readable layout from the wiring', () => {
    const { project, report } = imported('codesys-zero-geometry.xml');
    expect(report.namespace).toBe('http://www.plcopen.org/xml/tc6_0200');
    expect(report.warnings.filter((w) => /cannot be drawn/.test(w.message))).toEqual([]);
    const pou = project.pous[0]!;
    expect(pou.networks.map((n) => n.comment)).toEqual([
      'Motor seal-in',
      'Lamp after 2 s of running',
      'Count lamp scans',
    ]);
    // Rows by branch structure: the seal-in branch sits under Start, the box pins on their own rows.
    expect(pou.networks.map((n) => n.rows)).toEqual([2, 2, 3]);
    const seal = pou.networks[0]!;
    expect(seal.elements.filter((e) => e.kind === 'contact').map((e) => [e.row, e.col])).toEqual([
      [0, 0],
      [1, 0],
      [0, 1],
    ]);
    expect(seal.vlinks).toEqual([{ row: 0, boundary: 1 }]);
    expect(noErrors(project)).toEqual([]);
    const plc = run(project, 'PLC_PRG', 500);
    plc.write('Start', true);
    plc.scan();
    plc.write('Start', false);
    plc.scans(3);
    expect(plc.read('Motor')).toBe(true);
    expect(plc.read('Lamp')).toBe(false);
    plc.scans(1);
    expect(plc.read('Lamp')).toBe(true); // 2 s after the motor started: scan 1 at 0 ms, scan 5 at 2000 ms
    expect(plc.read('Count')).toBe(1);
    expect(plc.read('Elapsed')).toBe(2000);
  });

  it('LD inside SFC actions and transitions stays in the chart (no extra programs); POUs in other languages are POUs kept as written', async () => {
    const { project, report } = imported('sfc-ld-actions.xml');
    expect(project.pous.map((p) => [p.name, p.language])).toEqual([
      ['Sequence', 'SFC'],
      ['Nothing', 'LD'],
      ['Main', 'ST'],
    ]);
    const chart = project.pous[0]!.sfc!;
    expect(chart.actions.map((a) => [a.name, a.body.language])).toEqual([['Light', 'LD']]);
    expect(project.pous[1]!.networks).toEqual([]);
    expect(project.pous[0]!.networks).toEqual([]);
    expect(project.pous[0]!.source).toMatch(/^<SFC>/);
    const text = report.warnings.map((w) => w.message).join('\n');
    expect(text).toContain('POU "Main" is written in ST');
    expect(text).not.toContain('was imported as program');
    // The chart runs its LD action and transition: Light sets Lamp in scan 1, Started fires in scan 2.
    const plc = run(project, 'Main');
    const at = () => [plc.read('Seq.Init.X'), plc.read('Seq.Done.X'), plc.read('Seq.Lamp')];
    expect(at()).toEqual([true, false, false]);
    plc.scans(1);
    expect(at()).toEqual([true, false, true]);
    plc.scans(1);
    expect(at()).toEqual([false, true, true]);
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml)).toEqual([]);
    const again = importPlcopen(xml);
    expect(again.ok && again.project.pous.map((p) => p.name)).toEqual(project.pous.map((p) => p.name));
    expect(again.ok && again.project.pous[0]!.sfc!.actions.map((a) => [a.name, a.body.language])).toEqual([['Light', 'LD']]);
    expect(again.ok && again.project.pous[0]!.sfc!.transitions.length).toBe(chart.transitions.length);
  });
});
