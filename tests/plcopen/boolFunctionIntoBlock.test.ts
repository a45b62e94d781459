// Issue 23 class 1 (found again by the differential fuzzer, docs/fuzz.md F5): a generic function
// whose output is BOOL, wired straight into another block's input (AND.OUT -> OR.IN1, OR.OUT ->
// SEL.G), under `openplc` read a net nothing wrote (always FALSE). Reference trace:
// tests/fixtures/reference/fz-bool-function-into-block.
import { describe, expect, it } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Profile } from '../../src/model/project';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { ldXml } from './ldXml';

const xml = ldXml(
  [
    { name: 'A', type: 'BOOL' },
    { name: 'B', type: 'BOOL' },
    { name: 'C', type: 'BOOL' },
    { name: 'Q', type: 'BOOL' },
    { name: 'T', type: 'STRING' },
  ],
  [
    {
      objects: [
        { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
        { id: 2, kind: 'contact', v: 'B', in: ['rail'] },
        { id: 3, kind: 'block', type: 'AND', inputs: { IN1: ['1'], IN2: ['2'] }, outputs: ['OUT'] },
        { id: 4, kind: 'contact', v: 'C', in: ['rail'] },
        { id: 5, kind: 'block', type: 'OR', inputs: { IN1: ['3.OUT'], IN2: ['4'] }, outputs: ['OUT'] },
        { id: 6, kind: 'coil', v: 'Q', in: ['5.OUT'] },
      ],
      toRail: [6],
    },
    {
      objects: [
        { id: 11, kind: 'contact', v: 'A', in: ['rail'] },
        { id: 12, kind: 'contact', v: 'C', in: ['rail'] },
        { id: 13, kind: 'block', type: 'OR', inputs: { IN1: ['11'], IN2: ['12'] }, outputs: ['OUT'] },
        {
          id: 14,
          kind: 'block',
          type: 'SEL',
          inputs: { G: ['13.OUT'], IN0: ["='low'"], IN1: ["='high'"] },
          outputs: ['OUT'],
          assign: { OUT: 'T' },
        },
      ],
    },
  ],
);

function plc(profile: Profile) {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  const { program, diagnostics } = compileProgram(r.project, { pou: 'Main', profile });
  if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
  return createPlc(program, { cycleMs: 10 });
}

describe("a function's BOOL output wired into another block's input", () => {
  for (const profile of ['openplc', 'iec'] as const)
    it(`carries the function's result under ${profile}`, () => {
      const p = plc(profile);
      p.scan();
      expect([p.read('Q'), p.read('T')]).toEqual([false, 'low']);
      p.write('A', true);
      p.write('B', true);
      p.scan();
      expect([p.read('Q'), p.read('T')]).toEqual([true, 'high']);
      p.write('B', false);
      p.scan();
      expect([p.read('Q'), p.read('T')]).toEqual([false, 'high']);
      p.write('A', false);
      p.write('C', true);
      p.scan();
      expect([p.read('Q'), p.read('T')]).toEqual([true, 'high']);
    });
});
