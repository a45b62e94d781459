// Timers against MATIEC's lib/timer.txt, scan by scan on a virtual clock with 10 ms cycles:
// scan k starts at (k-1) x 10 ms and the FB sees that start time (MATIEC's CURRENT_TIME).
import { describe, expect, it } from 'vitest';
import { createFb, TOF, TON, TP, type FbInstance } from '../../../src/engine/library/fbs';

const CYCLE = 10;

/** Runs one scan per IN value; returns [Q, ET] after each scan. */
function timeline(fb: FbInstance, pt: number, ins: readonly (0 | 1)[]): [boolean, number][] {
  fb.set('PT', pt);
  return ins.map((v, k) => {
    fb.set('IN', v === 1);
    fb.execute(k * CYCLE);
    return [fb.get('Q') as boolean, fb.get('ET') as number];
  });
}

describe('TON (on-delay)', () => {
  it('turns Q on exactly when PT has elapsed since the scan that saw IN rise, and ET stops at PT', () => {
    // The scan that sees the edge starts timing and leaves ET at 0; Q comes at the scan starting at t0 + PT.
    expect(timeline(new TON(), 30, [1, 1, 1, 1, 1, 1, 0, 0])).toEqual([
      [false, 0],
      [false, 10],
      [false, 20],
      [true, 30],
      [true, 30],
      [true, 30],
      [false, 0],
      [false, 0],
    ]);
  });

  it('starts on the very first scan when IN is already ON (the edge memory starts OFF)', () => {
    const t = new TON();
    expect(timeline(t, 20, [1, 1, 1])).toEqual([
      [false, 0],
      [false, 10],
      [true, 20],
    ]);
  });

  it('restarts from 0 when IN drops before PT', () => {
    expect(timeline(new TON(), 30, [1, 1, 0, 1, 1, 1, 1])).toEqual([
      [false, 0],
      [false, 10],
      [false, 0],
      [false, 0],
      [false, 10],
      [false, 20],
      [true, 30],
    ]);
  });

  it('with PT = T#0s still needs one more scan after the edge (MATIEC checks elapsed time only in the next scan)', () => {
    expect(timeline(new TON(), 0, [1, 1])).toEqual([
      [false, 0],
      [true, 0],
    ]);
  });

  it('uses the new PT while timing, and keeps ET at the PT it reached once Q is ON', () => {
    const t = new TON();
    timeline(t, 50, [1, 1]); // ET = 10 after two scans
    t.PT = 15; // shortened below the 20 ms elapsed at the next scan start: done at once, ET = the new PT
    t.execute(20);
    expect([t.Q, t.ET]).toEqual([true, 15]);
    t.PT = 100; // once ON, changing PT neither resets Q nor moves ET
    t.execute(30);
    expect([t.Q, t.ET]).toEqual([true, 15]);
  });
});

describe('TOF (off-delay)', () => {
  it('follows IN ON at once, holds Q for PT after IN falls, then holds ET at PT', () => {
    expect(timeline(new TOF(), 30, [1, 1, 0, 0, 0, 0, 0, 1])).toEqual([
      [true, 0],
      [true, 0],
      [true, 0], // falling edge seen: timing starts, ET not updated yet
      [true, 10],
      [true, 20],
      [false, 30],
      [false, 30], // ET stays at PT while IN stays OFF
      [true, 0],
    ]);
  });

  it('does not pulse at the first scan when IN starts OFF', () => {
    expect(timeline(new TOF(), 30, [0, 0])).toEqual([
      [false, 0],
      [false, 0],
    ]);
  });

  it('IN coming back during the delay resets ET and keeps Q ON', () => {
    expect(timeline(new TOF(), 50, [1, 0, 0, 1, 0])).toEqual([
      [true, 0],
      [true, 0],
      [true, 10],
      [true, 0],
      [true, 0],
    ]);
  });
});

describe('TP (pulse)', () => {
  it('gives a pulse of exactly PT from the rising edge; ET holds PT while IN stays ON', () => {
    expect(timeline(new TP(), 30, [1, 1, 1, 1, 1, 0, 0])).toEqual([
      [true, 0],
      [true, 10],
      [true, 20],
      [false, 30],
      [false, 30],
      [false, 0],
      [false, 0],
    ]);
  });

  it('is not retriggerable: edges during the pulse neither extend nor restart it', () => {
    expect(timeline(new TP(), 40, [1, 0, 1, 0, 1, 0])).toEqual([
      [true, 0],
      [true, 10],
      [true, 20],
      [true, 30],
      [false, 40],
      [false, 0],
    ]);
  });

  it('finishes the pulse even when IN falls at once; ET then reads 0 in the scan the pulse ends', () => {
    expect(timeline(new TP(), 20, [1, 0, 0, 0])).toEqual([
      [true, 0],
      [true, 10],
      [false, 0], // reached PT with IN OFF: STATE 2 then straight back to 0 in the same scan
      [false, 0],
    ]);
  });

  it('needs IN to go OFF before a new pulse can start', () => {
    const tp = new TP();
    const out = timeline(tp, 10, [1, 1, 1, 0, 1]);
    expect(out.map(([q]) => q)).toEqual([true, false, false, false, true]);
  });
});

describe('timer instances', () => {
  it('reset() is a cold restart: outputs, ET and the edge memory go back to their initial values', () => {
    const t = createFb('TON', 'iec')!;
    timeline(t, 20, [1, 1, 1]);
    expect(t.get('Q')).toBe(true);
    t.reset();
    expect([t.get('IN'), t.get('PT'), t.get('Q'), t.get('ET')]).toEqual([false, 0, false, 0]);
    // After reset, IN ON counts as a new edge again.
    expect(timeline(t, 20, [1, 1, 1]).map(([q]) => q)).toEqual([false, false, true]);
  });

  it('lists pins in signature order and refuses unknown pins by name', () => {
    const t = createFb('tof', 'openplc')!;
    expect(t.fbType).toBe('TOF');
    expect(t.pins()).toEqual(['IN', 'PT', 'Q', 'ET']);
    expect(() => t.get('XYZ')).toThrow(/TOF has no pin "XYZ"/);
    expect(createFb('NOT_A_BLOCK', 'iec')).toBeUndefined();
  });
});
