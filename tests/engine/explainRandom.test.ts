// "Why?" against the engine on random programs: every element an explanation names as blocking
// really passed no power in that scan, its left side was powered (it is the first block on its
// path), and an energised coil's named path really carried power end to end.
import { describe, expect, it } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { explain, liveScanView } from '../../src/engine/explain';
import type { Network } from '../../src/model/project';
import { ladder, project, vars } from './ladder';

function rng(seed: number) {
  let s = seed >>> 0;
  return () => {
    s = (s * 1664525 + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

const INPUTS = ['A', 'B', 'C', 'D', 'E'];
const COILS = ['X', 'Y', 'Z'];

function randomNetwork(r: () => number): Network {
  const pick = <T,>(xs: readonly T[]) => xs[Math.floor(r() * xs.length)]!;
  const rows = 1 + Math.floor(r() * 3);
  const cols = 1 + Math.floor(r() * 4);
  const lines: string[] = [];
  for (let row = 0; row < rows; row++) {
    const tokens = ['+'];
    for (let col = 0; col < cols; col++) {
      const v = pick([...INPUTS, ...COILS]);
      tokens.push(r() < 0.15 ? '-' : pick([`[${v}]`, `[${v}]`, `[/${v}]`, `[P:${v}]`, `[N:${v}]`, '[NOT]']));
      // Inner vertical links between consecutive rows make bridges and shared nets.
      if (col < cols - 1 && row > 0 && r() < 0.25) tokens.push('+');
    }
    tokens.push('+');
    if (row === 0) tokens.push(pick(['(X)', '(Y)', '(Z)', '(/X)', '(S:Y)', '(R:Y)', '(P:Z)']));
    lines.push(tokens.join(' '));
  }
  return { ...ladder(lines), title: lines.join(' / ') };
}

describe('Why? agrees with the engine on random programs', () => {
  it('names as blocking only elements that passed no power, and energising paths that carried it', () => {
    let checked = 0;
    let blocking = 0;
    let energised = 0;
    for (let seed = 1; seed <= 60; seed++) {
      const r = rng(seed);
      const networks = Array.from({ length: 1 + Math.floor(r() * 4) }, () => randomNetwork(r));
      const p = project(vars(...INPUTS.map((n) => `${n} BOOL`), ...COILS.map((n) => `${n} BOOL`)), networks);
      const { program } = compileProgram(p);
      if (!program) continue; // a random shape the rules refuse
      const plc = createPlc(program, { cycleMs: 10 });
      const pou = p.pous[0]!;
      for (let scan = 0; scan < 12; scan++) {
        for (const n of INPUTS) if (r() < 0.4) plc.write(n, r() < 0.5);
        plc.scan();
        const snap = plc.snapshot();
        const view = liveScanView(plc, program);
        pou.networks.forEach((net, n) =>
          net.elements.forEach((el, k) => {
            if (el.kind !== 'coil') return;
            const e = explain(program, pou, view, { kind: 'element', network: n, element: k });
            checked++;
            const bytes = snap.networks[n]!.elements;
            const coilPowered = (bytes[k]! & 1) === 1;
            for (const m of e.marks.filter((x) => x.network === n && x.role === 'blocking')) {
              blocking++;
              expect(bytes[m.element]! & 2, `seed ${seed} scan ${scan + 1}: ${e.lines.join(' / ')}`).toBe(0);
            }
            const out = (el: { element: number }) => (bytes[el.element]! & 2) === 2;
            for (const path of e.paths ?? []) {
              const last = path.elements[path.elements.length - 1];
              if (path.blockedAt === undefined) {
                // Energised: its last element passed power to the coil.
                if (last) expect(out(last)).toBe(true);
                continue;
              }
              // Blocked: the named element had power on its input along the path and passed none.
              expect(out(path.elements[path.blockedAt]!)).toBe(false);
              if (path.blockedAt > 0) expect(out(path.elements[path.blockedAt - 1]!)).toBe(true);
            }
            if (coilPowered) {
              energised++;
              expect(e.paths!.some((q) => q.blockedAt === undefined), `seed ${seed}: ${net.title}: ${e.lines.join(' / ')} ${JSON.stringify(program.networks[n]!.ops.map((o) => [o.op, (o as { inNet?: number }).inNet, (o as { outNet?: number }).outNet, (o as { ownNet?: number }).ownNet]))} ${JSON.stringify(e.paths)}`).toBe(true);
            } else if (e.paths) {
              expect(e.paths.every((q) => q.blockedAt !== undefined)).toBe(true);
            }
          }),
        );
      }
    }
    expect(checked).toBeGreaterThan(500);
    expect(blocking).toBeGreaterThan(200);
    expect(energised).toBeGreaterThan(100);
  });
});
