// Variables of anonymous types in POU interfaces (`<type><struct>`, `<type><array>`,
// `<type><enum>` inside a `<variable>`): imported as type texts the engine resolves like named
// types, run in LD and ST (members, elements, bare enum values), watched and forced by leaf,
// exported back as the same anonymous types (no invented <dataType>), valid against TC6 v2.01, and
// imported again to the same declarations and trace.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Plc } from '../../src/engine/api';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { schemaErrors } from './xsd';

const XML = readFileSync(new URL('../fixtures/plcopen/anonymous-types.xml', import.meta.url), 'utf8');

function imported(xml: string): { project: Project; warnings: string[] } {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return { project: r.project, warnings: r.report.warnings.map((w) => w.message) };
}

function plcOf(p: Project): Plc {
  const { program, diagnostics } = compileProgram(p, { configuration: true });
  expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
  return createPlc(program!, { cycleMs: 10 });
}

const NAMES = ['MainInst.Pump.Run', 'MainInst.Pump.Speed', 'MainInst.Buf[3]', 'MainInst.Done', 'SeqInst.State', 'SeqInst.Count', 'SeqInst.Log[1]', 'SeqInst.Log[3]'];
const STEPS: Record<string, boolean | number>[] = [{}, { 'MainInst.Go': true, 'SeqInst.Start': true }, {}, {}, {}, { 'MainInst.Buf[1]': 10 }];

function run(p: Project): unknown[][] {
  const plc = plcOf(p);
  return STEPS.map((step) => {
    for (const [k, v] of Object.entries(step)) plc.write(k, v);
    plc.scan();
    return NAMES.map((n) => plc.read(n));
  });
}

describe('anonymous types in declarations', () => {
  it('imports anonymous struct, array and enum variables as their type texts, without a warning', () => {
    const { project, warnings } = imported(XML);
    expect(warnings.filter((w) => /type|struct|enum|array/i.test(w))).toEqual([]);
    expect(project.dataTypes ?? []).toEqual([]);
    const types = (pou: string) => Object.fromEntries(project.pous.find((p) => p.name === pou)!.variables.map((v) => [v.name, v.type]));
    expect(types('Main')).toEqual({ Go: 'BOOL', Done: 'BOOL', Pump: 'STRUCT Run : BOOL; Speed : INT := 5; END_STRUCT', Buf: 'ARRAY[0..3] OF INT' });
    expect(types('Seq')).toEqual({ Start: 'BOOL', State: '(Idle, Run, Fault)', Count: 'INT', Log: 'ARRAY[1..3] OF INT' });
  });

  it('runs them in LD and ST: members, elements, bare enum values in CASE; watched and forced by leaf', () => {
    const { project } = imported(XML);
    // State holds the index of its value: Idle 0, Run 1, Fault 2.
    expect(run(project)).toEqual([
      [false, 5, 0, false, 0, 0, 0, 0],
      [true, 5, 7, true, 1, 0, 0, 0],
      [true, 5, 7, true, 1, 1, 10, 0],
      [true, 5, 7, true, 1, 2, 10, 0],
      [true, 5, 7, true, 2, 3, 10, 30],
      [true, 5, 15, true, 2, 3, 10, 30],
    ]);
    const plc = plcOf(project);
    expect(plc.variableNames()).toEqual(expect.arrayContaining(['MainInst.Pump.Run', 'MainInst.Pump.Speed', 'MainInst.Buf[0]', 'SeqInst.State']));
    plc.write('MainInst.Go', true);
    plc.force('MainInst.Pump.Run', false);
    plc.scan();
    expect([plc.read('MainInst.Pump.Run'), plc.read('MainInst.Done'), plc.read('MainInst.Buf[3]')]).toEqual([false, false, 0]);
  });

  it('exports the same anonymous types (schema-valid, no <dataType>), which import back to the same declarations and trace', async () => {
    const { project } = imported(XML);
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml, 'anonymous-types.xml')).toEqual([]);
    expect(xml).not.toContain('<dataType ');
    expect(xml).toMatch(/<variable name="Pump">\s*<type>\s*<struct>/);
    expect(xml).toMatch(/<variable name="State">\s*<type>\s*<enum>\s*<values>\s*<value name="Idle"\/>/);
    expect(xml).toMatch(/<variable name="Buf">\s*<type>\s*<array>\s*<dimension lower="0" upper="3"\/>/);
    const again = imported(xml).project;
    for (const pou of ['Main', 'Seq'])
      expect(again.pous.find((p) => p.name === pou)!.variables).toEqual(project.pous.find((p) => p.name === pou)!.variables);
    expect(run(again)).toEqual(run(project));
  });
});
