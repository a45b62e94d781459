// The trend trigger: evaluated on every scan's values in the recorder, a window of `capacity`
// samples around it with the chosen share before the trigger; single and normal modes.
import { describe, expect, test } from 'vitest';
import type { Value } from '../../src/model/iecTypes';
import type { TrendTrigger } from '../../src/sim/protocol';
import { crosses, preTriggerCount, TrendRecorder } from '../../src/sim/trendRecorder';

const trigger = (t: Partial<TrendTrigger>): TrendTrigger => ({ name: 'X', direction: 'rising', level: 0.5, prePercent: 20, mode: 'single', arm: 1, ...t });

/** Records scans 1..values.length with X and Y = the scan number (times 10 ms apart). */
function run(rec: TrendRecorder, xs: readonly Value[], first = 1) {
  xs.forEach((x, k) => rec.record(first + k, (first + k) * 10, (n) => (n === 'X' ? x : first + k)));
}

describe('trend trigger', () => {
  test('crossing: rising reaches the level from below, falling from above', () => {
    expect(crosses({ direction: 'rising', level: 0.5 }, 0, 1)).toBe(true);
    expect(crosses({ direction: 'rising', level: 0.5 }, 1, 1)).toBe(false);
    expect(crosses({ direction: 'falling', level: 0.5 }, 1, 0)).toBe(true);
    expect(crosses({ direction: 'rising', level: 100 }, 99.5, 100)).toBe(true);
    expect(crosses({ direction: 'rising', level: 100 }, 100, 101)).toBe(false);
    expect(crosses({ direction: 'falling', level: 100 }, 101, 100)).toBe(true);
  });

  test('pre-trigger share of the window', () => {
    expect(preTriggerCount(100, 20)).toBe(20);
    expect(preTriggerCount(10, 0)).toBe(0);
    expect(preTriggerCount(10, 100)).toBe(9);
  });

  test('a BOOL pulse of one scan triggers; the window holds 20 % before it and the rest after', () => {
    const rec = new TrendRecorder();
    rec.configure(['Y'], 10, trigger({}));
    const xs: boolean[] = Array.from({ length: 40 }, (_, k) => k + 1 === 25);
    run(rec, xs);
    const capture = rec.takeCapture();
    expect(capture).toBeDefined();
    expect(capture!.triggerIndex).toBe(2);
    expect(capture!.samples.scans).toEqual([23, 24, 25, 26, 27, 28, 29, 30, 31, 32]);
    expect(capture!.samples.series[0]).toEqual([23, 24, 25, 26, 27, 28, 29, 30, 31, 32]);
    expect(rec.triggerState).toEqual({ state: 'done', arm: 1 });
    // Single: no second capture on the next pulse.
    run(rec, [false, true, false], 41);
    expect(rec.takeCapture()).toBeUndefined();
  });

  test('falling edge and the state while the window after the trigger fills', () => {
    const rec = new TrendRecorder();
    rec.configure(['Y'], 10, trigger({ direction: 'falling', prePercent: 50 }));
    run(rec, [true, true, true, true, true, true, false, false]);
    expect(rec.triggerState?.state).toBe('capturing');
    expect(rec.takeCapture()).toBeUndefined();
    run(rec, [false, false, false], 9);
    const capture = rec.takeCapture()!;
    expect(capture.samples.scans).toEqual([2, 3, 4, 5, 6, 7, 8, 9, 10, 11]);
    expect(capture.samples.scans[capture.triggerIndex]).toBe(7);
  });

  test('a number crossing a level; fewer samples before when the trigger comes early', () => {
    const rec = new TrendRecorder();
    rec.configure(['Y'], 6, trigger({ level: 30, prePercent: 50 }));
    run(rec, [10, 29, 31, 40, 50, 20, 35]);
    const capture = rec.takeCapture()!;
    expect(capture.samples.scans).toEqual([1, 2, 3, 4, 5, 6]);
    expect(capture.samples.scans[capture.triggerIndex]).toBe(3);
  });

  test('normal mode re-arms after each capture', () => {
    const rec = new TrendRecorder();
    rec.configure(['Y'], 4, trigger({ mode: 'normal', prePercent: 25 }));
    run(rec, [false, true, false, false, false, false, true, false, false, false]);
    // Both captures completed before the take: the later one is handed over.
    const capture = rec.takeCapture()!;
    expect(capture.count).toBe(2);
    expect(capture.samples.scans).toEqual([6, 7, 8, 9]);
    expect(rec.triggerState?.state).toBe('armed');
  });

  test('an online change (same trigger configured again) keeps the state; re-arming starts afresh', () => {
    const rec = new TrendRecorder();
    rec.configure(['Y'], 4, trigger({}));
    run(rec, [false, true, false, false, false]);
    expect(rec.triggerState?.state).toBe('done');
    rec.configure(['Y'], 4, trigger({}));
    expect(rec.triggerState?.state).toBe('done');
    rec.configure(['Y'], 4, trigger({ arm: 2 }), { rearm: true });
    expect(rec.triggerState).toEqual({ state: 'armed', arm: 2 });
    rec.configure(['Y'], 4, trigger({ name: 'Nope', arm: 3 }), { known: false, rearm: true });
    expect(rec.triggerState?.state).toBe('unknown');
  });

  test('live samples keep streaming whatever the trigger does', () => {
    const rec = new TrendRecorder();
    rec.configure(['Y'], 5, trigger({}));
    run(rec, [false, false, true]);
    expect(rec.take()?.scans).toEqual([1, 2, 3]);
  });
});
