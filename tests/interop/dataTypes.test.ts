// npm run test:interop — the user data types of the real corpus files: SVGHMI's HMI_BOOL (a vendor
// type the traffic-light file uses without declaring it) and the Beremiz DS401 test's MYTYPE ...
// MYTYPE5 (subranges, an enum, a 2-D array of a derived subrange with arrayValue repetitions).
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { leafPaths } from '../../src/model/dataTypes';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { schemaErrors } from '../plcopen/xsd';
import { corpusDir } from './corpusDir';

const CORPUS = corpusDir();

function load(file: string): Project {
  const r = importPlcopen(readFileSync(join(CORPUS, file), 'utf8'));
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}

describe('corpus data types', () => {
  it('svghmi_traffic_light: HMI_BOOL variables are BOOLs; the program compiles and runs', () => {
    const p = load('beremiz__svghmi_traffic_light.xml');
    const hmi = p.pous.flatMap((u) => u.variables).filter((v) => v.type === 'HMI_BOOL');
    expect(hmi.length).toBeGreaterThan(0);
    const { program, diagnostics } = compileProgram(p, { configuration: true });
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 10 });
    const name = program!.symbols.vars.find((v) => v.dataType?.name === 'HMI_BOOL')!.name;
    expect(plc.scan().fault).toBeUndefined();
    expect(typeof plc.read(name)).toBe('boolean');
  });

  it('DS401GUI: MYTYPE ... MYTYPE5 import, resolve and export back valid', async () => {
    const p = load('beremiz__legacy_tc6v10_test_master_DS401GUI.xml');
    expect(p.dataTypes!.map((d) => `${d.name}:${d.def.kind}`)).toEqual([
      'MYTYPE:subrange',
      'MYTYPE2:enum',
      'MYTYPE3:array',
      'MYTYPE4:subrange',
      'MYTYPE5:alias',
    ]);
    const grid = leafPaths(p, { name: 'G', type: 'MYTYPE3' });
    expect(grid.ok && grid.leaves.length).toBe(64);
    expect(grid.ok && [grid.leaves[0], grid.leaves[63]].map((l) => `${l.path}:${l.type}:${l.initial}`)).toEqual(['G[1,1]:UINT:0', 'G[8,8]:UINT:10']);
    // No diagnostic of the whole program is about a data type (LD-E14/E15/E61) or a variable of one.
    const { diagnostics } = compileProgram(p, { configuration: true });
    const typeErrors = diagnostics.filter((d) => d.severity === 'error' && /LD-E1[45]|LD-E6|MYTYPE/.test(`${d.rule} ${d.message}`));
    expect(typeErrors).toEqual([]);
    expect(diagnostics.filter((d) => d.rule === 'LD-W61').map((d) => d.message)).toEqual([
      expect.stringMatching(/"TEST_ARRAY": 32 initial values are outside MYTYPE5 \(1\.\.100\), first TEST_ARRAY\[1,1\] := 0/),
    ]);
    const xml = exportPlcopen(p);
    expect(await schemaErrors(xml, 'DS401GUI.xml')).toEqual([]);
    const again = importPlcopen(xml);
    expect(again.ok && again.project.dataTypes).toEqual(p.dataTypes);
  });
});
