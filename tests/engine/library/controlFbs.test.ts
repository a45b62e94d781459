// SEMA and the additional function blocks (INTEGRAL, DERIVATIVE, PID, RAMP, HYSTERESIS), scan by
// scan at a fixed CYCLE. Every expected value is worked out by hand from the blocks' ST bodies
// (OpenPLC Editor's Standard_ and Additional_Function_Blocks.xml, the standard's annex F), with
// REAL operations rounded to 32 bits as MATIEC's C computes them, and TIME_TO_REAL(CYCLE) in
// seconds (openplc) or milliseconds (iec).
import { describe, expect, it } from 'vitest';
import { createFb, type FbInstance } from '../../../src/engine/library/fbs';
import { blockSignature, FB_SIGNATURES } from '../../../src/model/blocks';
import type { Value } from '../../../src/model/iecTypes';
import type { Profile } from '../../../src/model/project';

const f = Math.fround;

const make = (type: string, profile: Profile = 'openplc', pins: Record<string, Value> = {}): FbInstance => {
  const fb = createFb(type, profile);
  if (!fb) throw new Error(`no ${type}`);
  for (const [k, v] of Object.entries(pins)) fb.set(k, v);
  return fb;
};

/** One call per step: writes the step's inputs, executes, reads the outputs named. */
function run(fb: FbInstance, steps: readonly Record<string, Value>[], outs: readonly string[]): Value[][] {
  return steps.map((inputs, k) => {
    for (const [pin, v] of Object.entries(inputs)) fb.set(pin, v);
    fb.execute(k * 100);
    return outs.map((o) => fb.get(o));
  });
}

describe('signatures', () => {
  it('are standard FBs with the pins of OpenPLC Editor’s libraries', () => {
    const pins = (name: string) => {
      const s = blockSignature(name)!;
      return [s.kind, s.category, s.inputs.map((p) => `${p.name}:${p.type}`).join(' '), s.outputs.map((p) => `${p.name}:${p.type}`).join(' ')];
    };
    expect(pins('SEMA')).toEqual(['fb', 'bistable', 'CLAIM:BOOL RELEASE:BOOL', 'BUSY:BOOL']);
    expect(pins('INTEGRAL')).toEqual(['fb', 'control', 'RUN:BOOL R1:BOOL XIN:REAL X0:REAL CYCLE:TIME', 'Q:BOOL XOUT:REAL']);
    expect(pins('DERIVATIVE')).toEqual(['fb', 'control', 'RUN:BOOL XIN:REAL CYCLE:TIME', 'XOUT:REAL']);
    expect(pins('PID')).toEqual(['fb', 'control', 'AUTO:BOOL PV:REAL SP:REAL X0:REAL KP:REAL TR:REAL TD:REAL CYCLE:TIME', 'XOUT:REAL']);
    expect(pins('RAMP')).toEqual(['fb', 'control', 'RUN:BOOL X0:REAL X1:REAL TR:TIME CYCLE:TIME', 'BUSY:BOOL XOUT:REAL']);
    expect(pins('HYSTERESIS')).toEqual(['fb', 'control', 'XIN1:REAL XIN2:REAL EPS:REAL', 'Q:BOOL']);
    for (const name of ['SEMA', 'INTEGRAL', 'DERIVATIVE', 'PID', 'RAMP', 'HYSTERESIS']) {
      expect(FB_SIGNATURES).toContain(blockSignature(name));
      expect(make(name).pins()).toEqual([...blockSignature(name)!.inputs, ...blockSignature(name)!.outputs].map((p) => p.name));
    }
    // RTC (DATE_AND_TIME pins): behaviour in tests/engine/dates.test.ts.
    expect(pins('RTC')).toEqual(['fb', 'control', 'IN:BOOL PDT:DT', 'Q:BOOL CDT:DT']);
  });
});

describe('SEMA', () => {
  it('BUSY := CLAIM OR (BUSY AND NOT RELEASE): CLAIM wins over RELEASE', () => {
    const steps = [
      [0, 0],
      [1, 0],
      [0, 0],
      [0, 1],
      [1, 1],
      [0, 1],
      [0, 0],
    ].map(([c, r]) => ({ CLAIM: c === 1, RELEASE: r === 1 }));
    expect(run(make('SEMA'), steps, ['BUSY']).flat()).toEqual([false, true, true, false, true, false, false]);
  });
});

describe('INTEGRAL', () => {
  it('adds XIN * CYCLE (seconds, openplc) per call with RUN, holds without, R1 loads X0 and wins', () => {
    // CYCLE T#500ms = 0.5 s; XIN = 2: +1.0 per call.
    const fb = make('INTEGRAL', 'openplc', { XIN: 2, X0: 5, CYCLE: 500 });
    const steps = [
      { RUN: false, R1: true },
      { RUN: true, R1: false },
      { RUN: true, R1: false },
      { RUN: false, R1: false },
      { RUN: true, R1: false },
      { RUN: true, R1: true },
    ];
    expect(run(fb, steps, ['Q', 'XOUT'])).toEqual([
      [false, 5],
      [true, 6],
      [true, 7],
      [true, 7],
      [true, 8],
      [false, 5],
    ]);
  });

  it('iec: TIME_TO_REAL gives milliseconds, so the same CYCLE integrates 1000 times faster', () => {
    const fb = make('INTEGRAL', 'iec', { XIN: 2, X0: 5, CYCLE: 500, R1: true });
    fb.execute(0);
    fb.set('R1', false);
    fb.set('RUN', true);
    expect(run(fb, [{}, {}], ['XOUT']).flat()).toEqual([1005, 2005]);
  });

  it('accumulates in REAL: ten steps of 0.1 give 1.0000001192..., not 1', () => {
    // 0.1 as a REAL is 0.100000001490116...; the running sum is rounded to 32 bits at every add.
    const fb = make('INTEGRAL', 'openplc', { XIN: 0.1, CYCLE: 1000, RUN: true });
    for (let i = 0; i < 10; i++) fb.execute(0);
    expect(fb.get('XOUT')).toBe(1.0000001192092896);
  });
});

describe('DERIVATIVE', () => {
  it('XOUT = (3 (XIN - X3) + X1 - X2) / (10 CYCLE) over the last samples; RUN OFF gives 0 and reloads them', () => {
    // CYCLE T#100ms: 10 * REAL 0.1 rounds to exactly 1.0, so XOUT is the numerator.
    const fb = make('DERIVATIVE', 'openplc', { CYCLE: 100 });
    const steps = [
      { RUN: false, XIN: 0 }, // X1 = X2 = X3 = 0
      { RUN: true, XIN: 1 }, // 3*(1-0) + 0 - 0 = 3
      { RUN: true, XIN: 2 }, // 3*(2-0) + 1 - 0 = 7
      { RUN: true, XIN: 3 }, // 3*(3-0) + 2 - 1 = 10
      { RUN: true, XIN: 4 }, // 3*(4-1) + 3 - 2 = 10: slope 1 per 0.1 s
      { RUN: true, XIN: 5 }, // 3*(5-2) + 4 - 3 = 10
      { RUN: false, XIN: 5 }, // 0; X1 = X2 = X3 = 5
      { RUN: true, XIN: 5 }, // 3*0 + 5 - 5 = 0
    ];
    expect(run(fb, steps, ['XOUT']).flat()).toEqual([0, 3, 7, 10, 10, 10, 0, 0]);
  });

  it('iec: CYCLE in milliseconds (3 / (10 * 100)); CYCLE T#0s divides by zero: Inf, as C', () => {
    const fb = make('DERIVATIVE', 'iec', { CYCLE: 100, RUN: true, XIN: 1 });
    fb.execute(0);
    expect(fb.get('XOUT')).toBe(f(0.003));
    const zero = make('DERIVATIVE', 'openplc', { RUN: true, XIN: 1 });
    zero.execute(0);
    expect(zero.get('XOUT')).toBe(Infinity);
  });
});

describe('PID', () => {
  it('manual (AUTO OFF) gives KP * X0; automatic integrates and differentiates ERROR = PV - SP', () => {
    // KP 2, TR 4, TD 0.5, SP 10, X0 3, CYCLE T#1s (1.0 s).
    const fb = make('PID', 'openplc', { KP: 2, TR: 4, TD: 0.5, SP: 10, X0: 3, CYCLE: 1000 });
    const steps = [
      // ERROR -2; ITERM reset to TR*(X0-ERROR) = 20; XOUT = 2*(-2 + 20/4) = 6 = KP*X0.
      { AUTO: false, PV: 8 },
      // ERROR -2; ITERM 20 - 2 = 18; DTERM (3*0 + 0)/10 = 0; XOUT = 2*(-2 + 4.5) = 5.
      { AUTO: true, PV: 8 },
      // ERROR -1; ITERM 17; DTERM (3*(-1+2) - 2 + 2)/10 = REAL 0.3;
      // XOUT = 2*(-1 + 4.25 + 0.3*0.5) = 2*3.4 = REAL 6.8.
      { AUTO: true, PV: 9 },
      // ERROR 0; ITERM 17; DTERM (3*(0+2) + (-1) - (-2))/10 = REAL 0.7;
      // XOUT = 2*(0 + 4.25 + 0.35) = 2*4.6 = REAL 9.2.
      { AUTO: true, PV: 10 },
      // Back to manual: ITERM reset to 4*(3 - 0) = 12; XOUT = 2*(0 + 3) = 6.
      { AUTO: false, PV: 10 },
    ];
    expect(run(fb, steps, ['XOUT']).flat()).toEqual([6, 5, f(6.8), f(9.2), 6]);
  });

  it('keeps its inner ITERM and DTERM over saveState/loadState; reset clears them', () => {
    const fb = make('PID', 'openplc', { KP: 1, TR: 1, TD: 0, SP: 0, CYCLE: 1000, AUTO: true, PV: 1 });
    fb.execute(0);
    fb.execute(0); // ITERM.XOUT = 2 (X0 starts at 0)
    const state = JSON.parse(JSON.stringify(fb.saveState(0))) as ReturnType<FbInstance['saveState']>;
    expect(state['ITERM.XOUT']).toBe(2);
    const copy = make('PID', 'openplc');
    copy.loadState(state, 0);
    copy.execute(0); // ITERM 3: XOUT = 1*(1 + 3/1 + 0)
    expect(copy.get('XOUT')).toBe(4);
    copy.reset();
    expect(copy.saveState(0)['ITERM.XOUT']).toBe(0);
    expect(copy.get('KP')).toBe(0);
  });
});

describe('RAMP', () => {
  it('ramps XOUT from X0 to X1 in TR, one CYCLE per call, BUSY meanwhile; RUN OFF tracks X0', () => {
    // TR T#400ms, CYCLE T#100ms, X0 0, X1 8: XOUT = 8 * T / TR at T = 0, 100, 200, 300 ms, then X1.
    for (const profile of ['openplc', 'iec'] as const) {
      const fb = make('RAMP', profile, { TR: 400, CYCLE: 100, X0: 0, X1: 8 });
      const steps: Record<string, Value>[] = [
        { RUN: false },
        { RUN: true },
        { RUN: true },
        { RUN: true },
        { RUN: true },
        { RUN: true }, // T = 400 >= TR: done
        { RUN: true },
        { RUN: false, X0: 1 },
      ];
      expect(run(fb, steps, ['BUSY', 'XOUT']), profile).toEqual([
        [false, 0],
        [true, 0],
        [true, 2],
        [true, 4],
        [true, 6],
        [false, 8],
        [false, 8],
        [false, 1],
      ]);
    }
  });

  it('starts from the X0 seen when RUN came on (XI), even if X0 changes during the ramp', () => {
    const fb = make('RAMP', 'openplc', { TR: 200, CYCLE: 100, X0: 10, X1: 20 });
    fb.execute(0); // XI = 10
    fb.set('RUN', true);
    fb.set('X0', 0);
    expect(run(fb, [{}, {}, {}], ['XOUT']).flat()).toEqual([10, 15, 20]);
  });
});

describe('HYSTERESIS', () => {
  it('Q goes ON above XIN2 + EPS and OFF below XIN2 - EPS (strictly), holding in between', () => {
    const fb = make('HYSTERESIS', 'openplc', { XIN2: 10, EPS: 1 });
    const xs = [10.5, 11, 11.5, 10, 9.5, 9, 8.9, 10.5, 11.01];
    expect(run(fb, xs.map((x) => ({ XIN1: x })), ['Q']).flat()).toEqual([false, false, true, true, true, true, false, false, true]);
  });
});

describe('cold restart', () => {
  it('reset() brings every pin and internal variable back to its initial value', () => {
    for (const name of ['SEMA', 'INTEGRAL', 'DERIVATIVE', 'PID', 'RAMP', 'HYSTERESIS']) {
      const fresh = make(name).saveState(0);
      const fb = make(name);
      for (const pin of fb.pins()) fb.set(pin, blockSignature(name)!.inputs.concat(blockSignature(name)!.outputs).find((p) => p.name === pin)!.type === 'BOOL' ? true : 7);
      fb.execute(0);
      fb.execute(0);
      expect(fb.saveState(0), name).not.toEqual(fresh);
      fb.reset();
      expect(fb.saveState(0), name).toEqual(fresh);
    }
  });
});
