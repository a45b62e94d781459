// Edge detectors (edge_detection.txt) and bistables (bistable.txt): first-evaluation behaviour and dominance.
import { describe, expect, it } from 'vitest';
import { createFb, F_TRIG, R_TRIG, RS, SR } from '../../../src/engine/library/fbs';

const run = (fb: { CLK: boolean; Q: boolean; execute(t: number): void }, clk: readonly (0 | 1)[]): boolean[] =>
  clk.map((v) => {
    fb.CLK = v === 1;
    fb.execute(0);
    return fb.Q;
  });

describe('R_TRIG', () => {
  it('is ON for exactly one evaluation per rising edge', () => {
    expect(run(new R_TRIG(), [0, 1, 1, 0, 1, 0])).toEqual([false, true, false, false, true, false]);
  });

  it('fires at the first evaluation when CLK is already ON (memory M starts OFF)', () => {
    expect(run(new R_TRIG(), [1, 1])).toEqual([true, false]);
  });
});

describe('F_TRIG', () => {
  it('is ON for exactly one evaluation per falling edge', () => {
    expect(run(new F_TRIG(), [1, 0, 0, 1, 0])).toEqual([false, true, false, false, true]);
  });

  it('fires once at the first evaluation when CLK starts OFF (as MATIEC: M starts FALSE, Q := NOT CLK AND NOT M)', () => {
    expect(run(new F_TRIG(), [0, 0, 0])).toEqual([true, false, false]);
  });

  it('fires again at the first evaluation after a cold restart', () => {
    const f = createFb('F_TRIG', 'iec')!;
    f.execute(0);
    f.execute(0);
    expect(f.get('Q')).toBe(false);
    f.reset();
    f.execute(0);
    expect(f.get('Q')).toBe(true);
  });
});

describe('SR and RS', () => {
  const truth = (make: () => SR | RS, s: 'S1' | 'S', r: 'R' | 'R1') => (sv: boolean, rv: boolean, q: boolean) => {
    const fb = make();
    fb.set(s, sv);
    fb.set(r, false);
    fb.Q1 = q;
    fb.set(r, rv);
    fb.execute(0);
    return fb.Q1;
  };

  it.each([
    // S, R, Q1 before, SR Q1 after, RS Q1 after
    [false, false, false, false, false],
    [false, false, true, true, true],
    [true, false, false, true, true],
    [false, true, true, false, false],
    [true, true, false, true, false], // both ON: SR is set-dominant, RS reset-dominant
    [true, true, true, true, false],
  ])('S=%s R=%s Q1=%s -> SR %s, RS %s', (s, r, q, sr, rs) => {
    expect(truth(() => new SR(), 'S1', 'R')(s, r, q)).toBe(sr);
    expect(truth(() => new RS(), 'S', 'R1')(s, r, q)).toBe(rs);
  });

  it('holds its state between scans with both inputs OFF', () => {
    const fb = new SR();
    fb.S1 = true;
    fb.execute(0);
    fb.S1 = false;
    fb.execute(0);
    fb.execute(0);
    expect(fb.Q1).toBe(true);
  });
});
