// The trend trigger through the worker's session: armed by setTrend, evaluated on every scan, the
// capture and the trigger's state delivered with the frames.
import { describe, expect, test } from 'vitest';
import type { TrendTrigger } from '../../src/sim/protocol';
import { SimHarness } from './harness';
import { motorProgram } from './programs';

const trigger: TrendTrigger = { name: 'start', direction: 'rising', level: 0.5, prePercent: 50, mode: 'single', arm: 7 };

describe('trend trigger in the session', () => {
  test('a one-scan pulse of an input triggers; the frames carry the capture and the state', () => {
    const h = new SimHarness().send({ type: 'step', scans: 1, project: motorProgram() });
    h.send({ type: 'setTrend', names: ['Start', 'Motor'], capacity: 10, trigger }).settle();
    expect(h.frame.trendTrigger).toEqual({ state: 'armed', arm: 7 });
    // Each Step N may finish on the scheduler (its slices follow the wall clock): settle before the next command.
    h.send({ type: 'step', scans: 8 }).settle();
    h.send({ type: 'write', name: 'Start', input: { value: true } }, { type: 'step', scans: 1 }).settle();
    h.send({ type: 'write', name: 'Start', input: { value: false } }, { type: 'step', scans: 3 }).settle();
    expect(h.frame.trendTrigger).toEqual({ state: 'capturing', arm: 7 });
    h.send({ type: 'step', scans: 5 }).settle();
    const captures = h.of('frame').flatMap((m) => (m.frame.trendCapture ? [m.frame.trendCapture] : []));
    expect(captures).toHaveLength(1);
    const c = captures[0]!;
    expect(c.arm).toBe(7);
    expect(c.triggerIndex).toBe(5);
    expect(c.samples.scans).toHaveLength(10);
    const start = c.samples.series[c.samples.names.indexOf('Start')]!;
    expect(start.flatMap((v, i) => (v ? [i] : []))).toEqual([5]);
    // The motor sealed in from the pulse's scan on.
    const motor = c.samples.series[c.samples.names.indexOf('Motor')]!;
    expect(motor.slice(5).every((v) => v === 1)).toBe(true);
    expect(h.frame.trendTrigger).toEqual({ state: 'done', arm: 7 });
  });

  test('a trigger on a name the program lacks is reported', () => {
    const h = new SimHarness().send({ type: 'step', scans: 1, project: motorProgram() });
    h.send({ type: 'setTrend', names: ['Motor'], capacity: 10, trigger: { ...trigger, name: 'Nope' } }).settle();
    expect(h.frame.trendTrigger).toEqual({ state: 'unknown', arm: 7 });
  });
});
