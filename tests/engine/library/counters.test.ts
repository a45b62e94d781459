// Counters against MATIEC's lib/counter.txt (count inputs are edge-triggered through an internal
// R_TRIG), in both profiles: `iec` counts to the INT limits, `openplc` stops at PV / 0.
import { describe, expect, it } from 'vitest';
import { createFb, CTD, CTU, CTUD } from '../../../src/engine/library/fbs';
import { counterLimits } from '../../../src/engine/library/profiles';
import type { Profile } from '../../../src/model/project';

/** Gives `n` rising edges on a BOOL pin (ON scan then OFF scan). */
function pulses(fb: { execute(now: number): void }, set: (v: boolean) => void, n: number): void {
  for (let i = 0; i < n; i++) {
    set(true);
    fb.execute(0);
    set(false);
    fb.execute(0);
  }
}

describe('CTU', () => {
  it.each<[Profile, number]>([
    ['iec', 5], // keeps counting past PV (the standard counts while CV < PVmax)
    ['openplc', 3], // MATIEC: CV < PV
  ])('%s: five edges with PV = 3 give CV = %i and Q ON', (profile, cv) => {
    const c = new CTU(counterLimits(profile));
    c.PV = 3;
    pulses(c, (v) => (c.CU = v), 5);
    expect(c.CV).toBe(cv);
    expect(c.Q).toBe(true);
  });

  it('iec: stops at 32767 instead of wrapping to -32768', () => {
    const c = createFb('CTU', 'iec')!;
    c.set('PV', 32767);
    c.set('CV', 32765);
    pulses({ execute: (t) => c.execute(t) }, (v) => c.set('CU', v), 5);
    expect(c.get('CV')).toBe(32767);
    expect(c.get('Q')).toBe(true);
  });

  it('counts a CU held ON only once, and counts at the first scan when CU starts ON', () => {
    const c = new CTU(counterLimits('iec'));
    c.PV = 10;
    c.CU = true;
    for (let i = 0; i < 4; i++) c.execute(0);
    expect(c.CV).toBe(1);
  });

  it('a count edge while R is held is lost: releasing R with CU still ON does not count', () => {
    const c = new CTU(counterLimits('iec'));
    c.PV = 10;
    pulses(c, (v) => (c.CU = v), 2);
    c.R = true;
    c.CU = true;
    c.execute(0); // edge consumed by the internal R_TRIG while R wins
    expect(c.CV).toBe(0);
    c.R = false;
    c.execute(0);
    expect(c.CV).toBe(0);
    c.CU = false;
    c.execute(0);
    c.CU = true;
    c.execute(0);
    expect(c.CV).toBe(1);
  });

  it('Q is CV >= PV, so PV <= 0 gives Q ON before any count', () => {
    const c = new CTU(counterLimits('openplc'));
    c.PV = 0;
    c.execute(0);
    expect(c.Q).toBe(true);
    pulses(c, (v) => (c.CU = v), 2);
    expect(c.CV).toBe(0); // openplc: CV < PV never holds
  });
});

describe('CTD', () => {
  it.each<[Profile, number, boolean]>([
    ['iec', -2, true],
    ['openplc', 0, true],
  ])('%s: LD loads PV = 3, five edges give CV = %i', (profile, cv, q) => {
    const c = new CTD(counterLimits(profile));
    c.PV = 3;
    c.LD = true;
    c.execute(0);
    expect([c.CV, c.Q]).toEqual([3, false]);
    c.LD = false;
    pulses(c, (v) => (c.CD = v), 5);
    expect([c.CV, c.Q]).toEqual([cv, q]);
  });

  it('iec: stops at -32768', () => {
    const c = new CTD(counterLimits('iec'));
    c.CV = -32767;
    pulses(c, (v) => (c.CD = v), 3);
    expect(c.CV).toBe(-32768);
  });

  it('LD wins over a CD edge in the same scan', () => {
    const c = new CTD(counterLimits('iec'));
    c.PV = 7;
    c.LD = true;
    c.CD = true;
    c.execute(0);
    expect(c.CV).toBe(7);
  });
});

describe('CTUD', () => {
  it('edges on CU and CD in the same scan cancel out', () => {
    const c = new CTUD(counterLimits('iec'));
    c.PV = 5;
    pulses(c, (v) => (c.CU = v), 2);
    c.CU = true;
    c.CD = true;
    c.execute(0);
    expect(c.CV).toBe(2);
  });

  it('R wins over LD, LD over counting; QU = CV >= PV, QD = CV <= 0', () => {
    const c = new CTUD(counterLimits('iec'));
    c.PV = 2;
    c.LD = true;
    c.R = true;
    c.execute(0);
    expect([c.CV, c.QU, c.QD]).toEqual([0, false, true]);
    c.R = false;
    c.execute(0);
    expect([c.CV, c.QU, c.QD]).toEqual([2, true, false]);
  });

  it.each<[Profile, number, number]>([
    ['iec', 4, -1],
    ['openplc', 2, 0],
  ])('%s: counting up passes PV -> %i, counting down passes 0 -> %i', (profile, up, down) => {
    const c = new CTUD(counterLimits(profile));
    c.PV = 2;
    pulses(c, (v) => (c.CU = v), 4);
    expect(c.CV).toBe(up);
    c.R = true;
    c.execute(0);
    c.R = false;
    pulses(c, (v) => (c.CD = v), 1);
    expect(c.CV).toBe(down);
  });

  it('a held CU does not count again after R is released', () => {
    const c = new CTUD(counterLimits('openplc'));
    c.PV = 9;
    c.R = true;
    c.CU = true;
    c.execute(0);
    c.R = false;
    c.execute(0);
    expect(c.CV).toBe(0);
  });

  it('set() brings PV into INT range the way a PLC stores it (wraps)', () => {
    const c = createFb('CTUD', 'iec')!;
    c.set('PV', 40000);
    expect(c.get('PV')).toBe(-25536);
    expect(c.pins()).toEqual(['CU', 'CD', 'R', 'LD', 'PV', 'QU', 'QD', 'CV']);
  });
});
