// Programs run the same whether their networks run in the shared dispatch loops or, after the
// runtime switched them, in straight-line functions: values, outputs and power snapshots agree
// scan by scan, also across forcing, stepping and restarts.
import { describe, expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { compileProgram } from '../../src/engine/plc';
import type { CompiledProgram } from '../../src/engine/plc';
import { ScanPlc } from '../../src/engine/runtime/scanner';
import { DEFAULT_TIERING } from '../../src/engine/runtime/tiering';
import { planDispatch } from '../../src/engine/compile/dispatch';
import { ladder, project, vars } from './ladder';

const dispatchOnly = { ...DEFAULT_TIERING, startAfterEvals: Infinity };
const switchAtOnce = { ...DEFAULT_TIERING, startAfterEvals: 0, minScans: 1, msPerNetwork: 0, batch: 1 };

/** Deterministic pseudo-random bits. */
function bits(seed: number): () => boolean {
  let s = seed;
  return () => {
    s = (s * 1103515245 + 12345) % 2147483648;
    return (s & 0x10000) !== 0;
  };
}

function pair(program: CompiledProgram): [ScanPlc, ScanPlc] {
  return [
    new ScanPlc(program, { cycleMs: 10 }, dispatchOnly),
    new ScanPlc(program, { cycleMs: 10 }, switchAtOnce),
  ];
}

const state = (plc: ScanPlc) => ({
  values: plc.values(),
  outputs: plc.outputs(),
  power: plc.snapshot().networks,
});

describe('dispatch loops and straight-line functions agree', () => {
  test.each(EXAMPLES.map((e) => [e.id, e] as const))('%s, scan by scan, with forcing', (_id, example) => {
    const { program } = compileProgram(example.build());
    const inputs = program!.symbols.vars.filter((v) => v.location?.area === 'I' && v.type === 'BOOL');
    const output = program!.symbols.vars.find((v) => v.location?.area === 'Q' && v.type === 'BOOL');
    const plcs = pair(program!);
    const next = bits(7);
    for (let scan = 1; scan <= 300; scan++) {
      const values = Object.fromEntries(inputs.map((v) => [v.locationText!, next()]));
      if (scan === 100 && output) for (const plc of plcs) plc.force(output.name, true);
      if (scan === 200) for (const plc of plcs) plc.unforceAll();
      for (const plc of plcs) {
        plc.setInputs(values);
        plc.scan();
      }
      expect(state(plcs[1])).toEqual(state(plcs[0]));
    }
  });

  test('stepping through a jump shows the same networks, and a warm restart keeps the same values', () => {
    const { program } = compileProgram(EXAMPLES.find((e) => e.id === 'jump-label')!.build());
    const plcs = pair(program!);
    for (const plc of plcs) plc.scans(50);
    const steps = plcs.map((plc) => Array.from({ length: 12 }, () => plc.stepNetwork()));
    expect(steps[1]).toEqual(steps[0]);
    for (const plc of plcs) {
      plc.warmRestart();
      plc.scans(20);
    }
    expect(state(plcs[1])).toEqual(state(plcs[0]));
  });

  test('networks of the same structure each use their own variables', () => {
    const n = 40;
    const names = Array.from({ length: n }, (_, k) => k);
    const p = project(
      vars(...names.flatMap((k) => [`I${k} BOOL`, `O${k} BOOL`])),
      names.map((k) => ladder([`[I${k}] - (O${k})`])),
    );
    const { program } = compileProgram(p);
    for (const plc of pair(program!)) {
      for (let k = 0; k < n; k += 3) plc.write(`I${k}`, true);
      plc.scans(5);
      expect(names.filter((k) => plc.read(`O${k}`) === true)).toEqual(names.filter((k) => k % 3 === 0));
      plc.force('O1', true);
      plc.write('I3', false);
      plc.scans(5);
      expect([plc.read('O1'), plc.read('O3'), plc.read('O6')]).toEqual([true, false, true]);
    }
  });

  test('a program with many different networks (several dispatch loops) computes every rung', () => {
    // Network k: 1 + k % 6 contacts in series, normally closed where bit j of k / 6 is set.
    const count = 400;
    const inputs = ['A0', 'A1', 'A2', 'A3', 'A4', 'A5'];
    const rung = (k: number) =>
      Array.from({ length: 1 + (k % 6) }, (_, j) =>
        (Math.floor(k / 6) >> j) & 1 ? `[/${inputs[j]}]` : `[${inputs[j]}]`,
      );
    const p = project(
      vars(...inputs.map((a) => `${a} BOOL`), ...Array.from({ length: count }, (_, k) => `O${k} BOOL`)),
      Array.from({ length: count }, (_, k) => ladder([[...rung(k), `(O${k})`].join(' ')])),
    );
    const { program } = compileProgram(p);
    const plan = planDispatch(program!.networks, program!.functions, []);
    expect(plan.bodies.length).toBeGreaterThan(1);
    const next = bits(3);
    for (const plc of pair(program!)) {
      for (let scan = 0; scan < 20; scan++) {
        const a = inputs.map(() => next());
        inputs.forEach((name, j) => plc.write(name, a[j]!));
        plc.scan();
        const expected = Array.from({ length: count }, (_, k) =>
          rung(k).every((c, j) => (c.startsWith('[/') ? !a[j] : a[j])),
        );
        expect(Array.from({ length: count }, (_, k) => plc.read(`O${k}`))).toEqual(expected);
      }
    }
  });
});
