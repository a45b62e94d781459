// Half-drawn and random networks: the checker never throws, and whatever compiles also runs.
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { ElementId } from '../../src/model/ids';
import type { LdElement, VLink } from '../../src/model/elements';
import { newNetwork } from '../../src/model/factory';
import { project, vars } from './ladder';

function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    return s / 4294967296;
  };
}

const NAMES = ['A', 'B', 'X', 'Y', 'T1.Q', 'W.2', 'Nope', '', 'TRUE'];
const BLOCKS: [string, Record<string, string>][] = [
  ['TON', { PT: 'T#20ms' }],
  ['ADD', { IN1: 'N', IN2: '1' }],
  ['GT', { IN1: 'N', IN2: '3' }],
  ['CTU', { R: 'B', PV: '2' }],
  ['MOVE', {}],
];

function randomNetwork(rand: () => number, k: number) {
  const rows = 1 + Math.floor(rand() * 4);
  const cols = 2 + Math.floor(rand() * 6);
  const elements: LdElement[] = [];
  const taken = new Set<string>();
  let n = 0;
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols; c++) {
      const x = rand();
      const id = `r${k}_${n++}` as ElementId;
      const name = NAMES[Math.floor(rand() * NAMES.length)]!;
      if (taken.has(`${r}:${c}`)) continue;
      if (x < 0.3) elements.push({ id, kind: 'link', row: r, col: c });
      else if (x < 0.5)
        elements.push({
          id,
          kind: 'contact',
          contact: (['NO', 'NC', 'P', 'N', 'NOT'] as const)[Math.floor(rand() * 5)]!,
          variable: name,
          row: r,
          col: c,
        });
      else if (x < 0.65)
        elements.push({
          id,
          kind: 'coil',
          coil: (['COIL', 'NEG', 'SET', 'RESET', 'P', 'N', 'M'] as const)[Math.floor(rand() * 7)]!,
          variable: name,
          row: r,
          col: c,
        });
      else if (x < 0.68)
        elements.push({ id, kind: 'jump', target: rand() < 0.5 ? 'L0' : 'L9', row: r, col: c });
      else if (x < 0.7) elements.push({ id, kind: 'return', row: r, col: c });
      else if (x < 0.78) {
        const [type, inputs] = BLOCKS[Math.floor(rand() * BLOCKS.length)]!;
        elements.push({
          id,
          kind: 'box',
          blockType: type,
          ...(type === 'TON' || type === 'CTU' ? { instance: type === 'TON' ? 'T1' : 'C1' } : {}),
          inputs,
          outputs: {},
          row: r,
          col: c,
        });
        for (let rr = r; rr < r + 4; rr++) for (let cc = c; cc < c + 2; cc++) taken.add(`${rr}:${cc}`);
      }
    }
  }
  const vlinks: VLink[] = [];
  for (let i = 0; i < rows * 2; i++)
    vlinks.push({ row: Math.floor(rand() * rows), boundary: Math.floor(rand() * (cols + 1)) });
  return newNetwork({ rows, cols, elements, vlinks, ...(k === 0 ? { label: 'L0' } : {}) });
}

describe('robustness', () => {
  test('400 random networks: checking never throws; programs that compile run 20 scans', () => {
    const rand = rng(7);
    let compiled = 0;
    for (let trial = 0; trial < 100; trial++) {
      const p = project(
        vars('A BOOL', 'B BOOL', 'X BOOL', 'Y BOOL', 'W WORD', 'N INT', 'T1 TON', 'C1 CTU'),
        [0, 1, 2, 3].map((k) => randomNetwork(rand, k)),
      );
      expect(() => checkProject(p)).not.toThrow();
      const { program } = compileProgram(p);
      if (!program) continue;
      compiled++;
      const plc = createPlc(program, { cycleMs: 10, maxNetworkEvaluations: 200 });
      expect(() => plc.scans(20)).not.toThrow();
      expect(() => plc.snapshot()).not.toThrow();
    }
    expect(compiled).toBeLessThan(100); // random grids are nearly always half-drawn
  });

  test('100 random well-formed programs compile with no error and run', () => {
    const rand = rng(11);
    const pick = <T>(xs: readonly T[]): T => xs[Math.floor(rand() * xs.length)]!;
    for (let trial = 0; trial < 100; trial++) {
      const networks = [0, 1, 2].map((k) => {
        const cols = 4 + Math.floor(rand() * 4);
        const m = 1 + Math.floor(rand() * (cols - 2));
        const elements: LdElement[] = [];
        let n = 0;
        const id = () => `w${trial}_${k}_${n++}` as ElementId;
        for (let c = 0; c < m; c++)
          elements.push({
            id: id(),
            kind: 'contact',
            contact: pick(['NO', 'NC', 'P', 'N', 'NOT'] as const),
            variable: pick(['A', 'B', 'X', 'W.2', 'T1.Q']),
            row: 0,
            col: c,
          });
        for (let c = m; c < cols - 1; c++) elements.push({ id: id(), kind: 'link', row: 0, col: c });
        elements.push({
          id: id(),
          kind: 'coil',
          coil: pick(['COIL', 'NEG', 'SET', 'RESET', 'P', 'N', 'M'] as const),
          variable: pick(['X', 'Y', 'W.2']),
          row: 0,
          col: cols - 1,
        });
        const vlinks: VLink[] = [];
        if (rand() < 0.6) {
          const b = 1 + Math.floor(rand() * m);
          for (let c = 0; c < b; c++)
            elements.push({
              id: id(),
              kind: 'contact',
              contact: pick(['NO', 'NC'] as const),
              variable: pick(['A', 'B', 'Y']),
              row: 1,
              col: c,
            });
          vlinks.push({ row: 0, boundary: b });
        }
        return newNetwork({ rows: 2, cols, elements, vlinks, ...(k === 2 ? { label: 'L0' } : {}) });
      });
      const p = project(vars('A BOOL', 'B BOOL', 'X BOOL', 'Y BOOL', 'W WORD', 'T1 TON'), networks);
      const { program, diagnostics } = compileProgram(p);
      expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
      const plc = createPlc(program!, { cycleMs: 10 });
      for (let s = 0; s < 10; s++) {
        plc.write('A', rand() < 0.5);
        plc.write('B', rand() < 0.5);
        plc.scan();
      }
      expect(plc.fault).toBeUndefined();
    }
  });
});
