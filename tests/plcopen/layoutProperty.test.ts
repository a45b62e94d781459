// Property: for random LD graphs written as PLCopen XML, the import either draws exactly the
// file's graph (as the engine compiles the grid) or says so in a located finding — never silently
// wrong. Where it is exact, a 100-scan trace survives export and import again.
import { describe, expect, it } from 'vitest';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { trace } from './behaviour';
import { graphOf, ldXml, specGraph, type LdNetwork, type LdObj, type LdVar, type Ref } from './ldXml';

function rng(seed: number) {
  let s = seed >>> 0 || 1;
  return () => ((s = (s * 1103515245 + 12345) >>> 0) & 0x7fffffff) / 0x80000000;
}

/** A random network: series/parallel trees of contacts, fan-out, TON/CTU/CTUD blocks, coils in series. */
function randomNetwork(rnd: () => number): { vars: LdVar[]; net: LdNetwork } {
  const objects: LdObj[] = [];
  let id = 1;
  const inputs = ['A', 'B', 'C', 'D', 'E'];
  const pick = () => inputs[Math.floor(rnd() * inputs.length)]!;
  /** A series/parallel expression from `from`; returns the refs that carry its result. */
  const expr = (from: Ref[], depth: number): Ref[] => {
    const r = rnd();
    if (depth > 2 || r < 0.45) {
      const c = id++;
      objects.push({ id: c, kind: 'contact', v: pick(), ...(rnd() < 0.2 ? { neg: true } : {}), in: from });
      return [String(c)];
    }
    if (r < 0.75) return expr(expr(from, depth + 1), depth + 1); // series
    return [...expr(from, depth + 1), ...expr(from, depth + 1)]; // parallel (OR at the consumer)
  };
  const vars: LdVar[] = [...inputs, 'X', 'Y', 'Z'].map((name) => ({ name, type: 'BOOL' }));
  let power = expr(['rail'], 0);
  const toRail: number[] = [];
  const coil = (v: string, from: Ref[]) => {
    const c = id++;
    objects.push({ id: c, kind: 'coil', v, in: from });
    return c;
  };
  const b = rnd();
  if (b < 0.25) {
    const k = id++;
    vars.push({ name: 'T1', type: 'TON' });
    objects.push({
      id: k,
      kind: 'block',
      type: 'TON',
      instance: 'T1',
      inputs: { IN: power, PT: ['=T#30ms'] },
      outputs: ['Q', 'ET'],
    });
    power = [`${k}.Q`];
  } else if (b < 0.45) {
    const k = id++;
    vars.push({ name: 'K1', type: 'CTUD' }, { name: 'N', type: 'INT' });
    const down = expr(['rail'], 1);
    objects.push({
      id: k,
      kind: 'block',
      type: 'CTUD',
      instance: 'K1',
      inputs: { CU: power, CD: down, R: [], LD: [], PV: ['=2'] },
      outputs: ['QU', 'QD', 'CV'],
      assign: { CV: 'N' },
    });
    const blk = objects[objects.length - 1] as Extract<LdObj, { kind: 'block' }>;
    delete blk.inputs.R;
    delete blk.inputs.LD;
    toRail.push(coil('Z', [`${k}.QD`]));
    power = [`${k}.QU`];
  }
  // Coils: one, two in parallel, or two in series.
  const shape = rnd();
  if (shape < 0.4) toRail.push(coil('X', power));
  else if (shape < 0.7) toRail.push(coil('X', power), coil('Y', power));
  else toRail.push(coil('Y', [String(coil('X', power))]));
  return { vars, net: { objects, toRail } };
}

describe('random LD graphs import exactly or say so', () => {
  it('1,000 graphs', () => {
    const rnd = rng(20260112);
    let exact = 0;
    for (let k = 0; k < 1000; k++) {
      const { vars, net } = randomNetwork(rnd);
      const xml = ldXml(vars, [net]);
      const r = importPlcopen(xml);
      if (!r.ok) throw new Error(`case ${k}: ${JSON.stringify(r.errors)}`);
      const reported = r.report.warnings.some((w) => /cannot be drawn exactly/.test(w.message));
      const same = JSON.stringify(graphOf(r.project)) === JSON.stringify(specGraph([net]));
      if (!reported) expect(same, `case ${k} differs silently:\n${xml}`).toBe(true);
      if (!same) continue;
      exact++;
      if (k % 10 === 0) {
        const again = importPlcopen(exportPlcopen(r.project));
        if (!again.ok) throw new Error(`case ${k}: re-import`);
        expect(trace(again.project, 'Main', 100)).toEqual(trace(r.project, 'Main', 100));
      }
    }
    // Most random graphs draw exactly (a floor, to notice a regression of the layout).
    expect(exact).toBeGreaterThan(700);
  });
});
