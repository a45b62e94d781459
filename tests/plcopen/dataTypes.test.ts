// User data types through PLCopen: <dataTypes> (enum, struct, array, subranges, derived aliases,
// initial values with arrayValue/repetitionValue and structValue), variables of those types and of
// an anonymous <array> type: imported, run, exported valid against TC6 v2.01 and imported back equal.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { canonical } from './fixtures';
import { schemaErrors } from './xsd';

const fixture = (name: string) => readFileSync(new URL(`../fixtures/plcopen/${name}`, import.meta.url), 'utf8');

function imported(xml: string): Project {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}

describe('PLCopen data types', () => {
  it('imports every kind of data type and the variables that use them', () => {
    const p = imported(fixture('types-all.xml'));
    expect(p.dataTypes!.map((d) => `${d.name}:${d.def.kind}:${d.initial ?? ''}`)).toEqual([
      'Color:enum:GREEN',
      'Point:struct:',
      'Row:array:[2(1), 3(9)]',
      'Level:subrange:',
      'Count:subrange:',
      'Small:alias:10',
      'Board:array:',
    ]);
    expect(p.dataTypes![4]!.def).toEqual({ kind: 'subrange', base: 'UINT', lower: 1, upper: 100 });
    const vars = p.pous[0]!.variables.map((v) => `${v.name}:${v.type}:${v.initial ?? ''}`);
    expect(vars.slice(0, 6)).toEqual(['C:Color:', 'P:Point:(X := 4)', 'R:Row:', 'L:Level:', 'B:Board:', 'Pts:ARRAY[0..1] OF Point:[(X := 7)]']);
  });

  it('runs the imported program: initial values, enum, array loop, struct copy, 2-D array of an alias', () => {
    const { program, diagnostics } = compileProgram(imported(fixture('types-all.xml')), { configuration: true });
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 10 });
    const names = ['MainInst.Total', 'MainInst.C', 'MainInst.P.X', 'MainInst.Pts[0].X', 'MainInst.Pts[1].X', 'MainInst.Pts[1].Y', 'MainInst.B[2,3]', 'MainInst.L'];
    const trace = [1, 2].map(() => (plc.scan(), names.map((n) => plc.read(n))));
    expect(trace).toEqual([
      [29, 2, 5, 7, 5, 2, 11, -10],
      [29, 1, 6, 7, 6, 2, 11, -10],
    ]);
  });

  it('exports schema-valid XML that imports back equal, and runs the same', async () => {
    const p = imported(fixture('types-all.xml'));
    const xml = exportPlcopen(p);
    expect(await schemaErrors(xml, 'types-all.xml')).toEqual([]);
    expect(xml).toContain('<value repetitionValue="3">');
    expect(xml).toContain('<subrangeUnsigned>');
    expect(xml).toContain('<structValue>');
    const again = imported(xml);
    expect(again.dataTypes).toEqual(p.dataTypes);
    expect(again.pous[0]!.variables).toEqual(p.pous[0]!.variables);
    const third = imported(exportPlcopen(again));
    expect(canonical(third)).toBe(canonical(again));
    const { program } = compileProgram(again, { configuration: true });
    const plc = createPlc(program!, { cycleMs: 10 });
    plc.scan();
    expect([plc.read('MainInst.Total'), plc.read('MainInst.Pts[1].X')]).toEqual([29, 5]);
  });
});
