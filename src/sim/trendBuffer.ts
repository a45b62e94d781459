// The UI's window of trend samples: the last `capacity` scans of each chosen signal.
import type { TrendSamples } from './protocol';

export interface TrendBuffer {
  readonly names: readonly string[];
  readonly scans: readonly number[];
  readonly timesMs: readonly number[];
  /** series[i] aligned with scans; BOOL as 0/1. */
  readonly series: readonly (readonly number[])[];
}

export const emptyTrend = (names: readonly string[]): TrendBuffer => ({ names, scans: [], timesMs: [], series: names.map(() => []) });

const tail = <T>(a: readonly T[], b: readonly T[], keep: number): T[] => {
  const joined = a.concat(b);
  return joined.length > keep ? joined.slice(joined.length - keep) : joined;
};

/** Adds new samples; samples for a different signal list (a stale frame) start a fresh window. */
export function appendTrend(buffer: TrendBuffer, samples: TrendSamples, capacity: number): TrendBuffer {
  const same = buffer.names.length === samples.names.length && buffer.names.every((n, i) => n === samples.names[i]);
  const base = same ? buffer : emptyTrend(samples.names);
  // A restart makes scan numbers go backwards: start again rather than draw a line back in time.
  const first = samples.scans[0];
  const last = base.scans[base.scans.length - 1];
  const start = first !== undefined && last !== undefined && first <= last ? emptyTrend(samples.names) : base;
  return {
    names: samples.names,
    scans: tail(start.scans, samples.scans, capacity),
    timesMs: tail(start.timesMs, samples.timesMs, capacity),
    series: samples.series.map((s, i) => tail(start.series[i] ?? [], s, capacity)),
  };
}
