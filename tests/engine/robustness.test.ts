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

  test('random rungs give the same results as a direct evaluation of their logic, scan after scan', () => {
    const rand = rng(23);
    const pick = <T>(xs: readonly T[]): T => xs[Math.floor(rand() * xs.length)]!;
    type C = { type: 'NO' | 'NC' | 'P' | 'N' | 'NOT'; v: string; mem: boolean };
    type Rung = {
      top: C[];
      branch: C[];
      joinAt: number;
      coil: { type: 'COIL' | 'NEG' | 'SET' | 'RESET' | 'P' | 'N'; v: string; mem: boolean };
    };
    for (let trial = 0; trial < 30; trial++) {
      const rungs: Rung[] = [];
      const networks = [0, 1, 2, 3].map((k) => {
        const cols = 4 + Math.floor(rand() * 3);
        const m = 1 + Math.floor(rand() * (cols - 2));
        const top: C[] = Array.from({ length: m }, () => ({
          type: pick(['NO', 'NC', 'P', 'N', 'NOT'] as const),
          v: pick(['A', 'B', 'X', 'Y']),
          mem: false,
        }));
        const joinAt = rand() < 0.6 ? 1 + Math.floor(rand() * m) : 0;
        const branch: C[] = Array.from({ length: joinAt }, () => ({
          type: pick(['NO', 'NC', 'P'] as const),
          v: pick(['A', 'B', 'Y']),
          mem: false,
        }));
        const coil = {
          type: pick(['COIL', 'NEG', 'SET', 'RESET', 'P', 'N'] as const),
          v: pick(['X', 'Y']),
          mem: false,
        };
        rungs.push({ top, branch, joinAt, coil });
        let n = 0;
        const id = () => `d${trial}_${k}_${n++}` as ElementId;
        const elements: LdElement[] = [
          ...top.map((c, col): LdElement => ({
            id: id(),
            kind: 'contact',
            contact: c.type,
            variable: c.type === 'NOT' ? '' : c.v,
            row: 0,
            col,
          })),
          ...Array.from({ length: cols - 1 - m }, (_, i): LdElement => ({
            id: id(),
            kind: 'link',
            row: 0,
            col: m + i,
          })),
          { id: id(), kind: 'coil', coil: coil.type, variable: coil.v, row: 0, col: cols - 1 },
          ...branch.map((c, col): LdElement => ({
            id: id(),
            kind: 'contact',
            contact: c.type,
            variable: c.v,
            row: 1,
            col,
          })),
        ];
        return newNetwork({ rows: 2, cols, elements, vlinks: joinAt ? [{ row: 0, boundary: joinAt }] : [] });
      });
      const plc = createPlc(
        compileProgram(project(vars('A BOOL', 'B BOOL', 'X BOOL', 'Y BOOL'), networks)).program!,
        { cycleMs: 10 },
      );
      const mem: Record<string, boolean> = { A: false, B: false, X: false, Y: false };
      const contact = (c: C, input: boolean): boolean => {
        const v = mem[c.v]!;
        switch (c.type) {
          case 'NO':
            return input && v;
          case 'NC':
            return input && !v;
          case 'NOT':
            return !input;
          case 'P': {
            const q = v && !c.mem;
            c.mem = v;
            return input && q;
          }
          case 'N': {
            const q = !v && !c.mem;
            c.mem = !v;
            return input && q;
          }
        }
      };
      for (let scan = 0; scan < 12; scan++) {
        mem.A = rand() < 0.5;
        mem.B = rand() < 0.5;
        plc.write('A', mem.A);
        plc.write('B', mem.B);
        plc.scan();
        for (const r of rungs) {
          // Upper row first: the top contacts up to the junction, then the branch, then the rest.
          let top = true;
          for (const c of r.top.slice(0, r.joinAt || r.top.length)) top = contact(c, top);
          let power = top;
          if (r.joinAt) {
            let low = true;
            for (const c of r.branch) low = contact(c, low);
            power = top || low;
            for (const c of r.top.slice(r.joinAt)) power = contact(c, power);
          }
          const coil = r.coil;
          if (coil.type === 'COIL') mem[coil.v] = power;
          else if (coil.type === 'NEG') mem[coil.v] = !power;
          else if (coil.type === 'SET') mem[coil.v] = power || mem[coil.v]!;
          else if (coil.type === 'RESET') mem[coil.v] = !power && mem[coil.v]!;
          else if (coil.type === 'P') {
            mem[coil.v] = power && !coil.mem;
            coil.mem = power;
          } else {
            mem[coil.v] = !power && !coil.mem;
            coil.mem = !power;
          }
        }
        expect({ X: plc.read('X'), Y: plc.read('Y') }).toEqual({ X: mem.X, Y: mem.Y });
      }
    }
  });
});
