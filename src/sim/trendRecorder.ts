// Samples the trend signals after every scan and hands the new samples to the next frame. A
// trigger (a variable crossing a level, a BOOL's edge) is evaluated here on every scan's values,
// not on what the display shows, so a pulse of one scan triggers; the window around it keeps the
// chosen share of samples from before the trigger.
import type { Value } from '../model/iecTypes';
import type { TrendCapture, TrendSamples, TrendTrigger, TrendTriggerState } from './protocol';

export const toTrendNumber = (v: Value): number => (typeof v === 'boolean' ? (v ? 1 : 0) : Number(v));

/** Did the value cross the trigger's level in its direction between two scans? */
export function crosses(trigger: Pick<TrendTrigger, 'direction' | 'level'>, previous: number, current: number): boolean {
  return trigger.direction === 'rising' ? previous < trigger.level && current >= trigger.level : previous > trigger.level && current <= trigger.level;
}

/** Samples kept before the trigger in a window of `capacity` (the trigger's own sample is after them). */
export const preTriggerCount = (capacity: number, prePercent: number): number =>
  Math.max(0, Math.min(capacity - 1, Math.round((capacity * Math.max(0, Math.min(100, prePercent))) / 100)));

class Samples {
  scans: number[] = [];
  times: number[] = [];
  series: number[][];
  constructor(width: number) {
    this.series = Array.from({ length: width }, () => []);
  }
  get length(): number {
    return this.scans.length;
  }
  push(scan: number, time: number, values: readonly number[]): void {
    this.scans.push(scan);
    this.times.push(time);
    for (let i = 0; i < this.series.length; i++) this.series[i]!.push(values[i]!);
  }
  /** Keeps the last `keep` samples. */
  trim(keep: number): void {
    const excess = this.scans.length - keep;
    if (excess <= 0) return;
    this.scans.splice(0, excess);
    this.times.splice(0, excess);
    for (const s of this.series) s.splice(0, excess);
  }
  copy(): Samples {
    const c = new Samples(0);
    c.scans = [...this.scans];
    c.times = [...this.times];
    c.series = this.series.map((s) => [...s]);
    return c;
  }
  samples(names: readonly string[]): TrendSamples {
    return { names, scans: this.scans, timesMs: this.times, series: this.series };
  }
}

export class TrendRecorder {
  private names: string[] = [];
  private capacity = 0;
  private pending = new Samples(0);
  private trigger: TrendTrigger | undefined;
  private triggerKey = '';
  private state: TrendTriggerState = 'armed';
  /** The trigger variable's value after the previous scan. */
  private previous: number | undefined;
  /** The last samples before the current scan (the pre-trigger share of the window). */
  private before = new Samples(0);
  private capturing: { samples: Samples; triggerIndex: number } | undefined;
  private captures = 0;
  private ready: TrendCapture | undefined;

  get active(): boolean {
    return this.names.length > 0 || this.trigger !== undefined;
  }

  /**
   * The signals, the window and the trigger (`known`: the trigger's variable exists in the program).
   * `rearm` starts the trigger afresh; otherwise the same trigger keeps its state (an online change).
   */
  configure(names: readonly string[], capacity: number, trigger?: TrendTrigger, options: { known?: boolean; rearm?: boolean } = {}): void {
    const key = JSON.stringify([names, capacity, trigger ?? null, options.known ?? true]);
    const keep = !options.rearm && key === this.triggerKey;
    this.triggerKey = key;
    this.names = [...names];
    this.capacity = Math.max(1, Math.floor(capacity));
    this.trigger = trigger;
    this.clear();
    if (keep) return;
    this.captures = 0;
    this.ready = undefined;
    this.state = trigger && options.known === false ? 'unknown' : 'armed';
  }

  /** A restart: the samples go; a capture under way starts again from armed (a single capture taken stays taken). */
  clear(): void {
    this.pending = new Samples(this.names.length);
    this.before = new Samples(this.names.length);
    this.previous = undefined;
    this.capturing = undefined;
    if (this.state === 'capturing') this.state = 'armed';
  }

  /** The trigger's state, undefined without a trigger. */
  get triggerState(): { state: TrendTriggerState; arm: number } | undefined {
    return this.trigger ? { state: this.state, arm: this.trigger.arm } : undefined;
  }

  record(scan: number, timeMs: number, read: (name: string) => Value): void {
    const values = this.names.map((n) => toTrendNumber(read(n)));
    this.pending.push(scan, timeMs, values);
    // Keep at most `capacity` pending samples (the UI keeps the same window); trim in batches.
    if (this.pending.length >= this.capacity * 2) this.pending.trim(this.capacity);
    const trigger = this.trigger;
    if (!trigger || this.state === 'unknown' || this.state === 'done') return;
    const value = toTrendNumber(read(trigger.name));
    const keep = preTriggerCount(this.capacity, trigger.prePercent);
    if (this.capturing) this.capturing.samples.push(scan, timeMs, values);
    else if (this.previous !== undefined && crosses(trigger, this.previous, value)) {
      const samples = this.before.copy();
      samples.trim(keep);
      const triggerIndex = samples.length;
      samples.push(scan, timeMs, values);
      this.capturing = { samples, triggerIndex };
      this.state = 'capturing';
    }
    this.previous = value;
    if (this.capturing && this.capturing.samples.length >= this.capacity) {
      this.ready = { samples: this.capturing.samples.samples(this.names), triggerIndex: this.capturing.triggerIndex, count: ++this.captures, arm: trigger.arm };
      this.capturing = undefined;
      this.state = trigger.mode === 'single' ? 'done' : 'armed';
    }
    // The samples before the next scan, trimmed in batches (a trigger copies only the last `keep`).
    this.before.push(scan, timeMs, values);
    if (this.before.length >= Math.max(2 * keep, 64)) this.before.trim(keep);
  }

  /** Samples since the last take, or undefined when there are none. */
  take(): TrendSamples | undefined {
    if (this.names.length === 0 || this.pending.length === 0) return undefined;
    this.pending.trim(this.capacity);
    const out = this.pending.samples(this.names);
    this.pending = new Samples(this.names.length);
    return out;
  }

  /** The capture completed since the last call, if any. */
  takeCapture(): TrendCapture | undefined {
    const out = this.ready;
    this.ready = undefined;
    return out;
  }
}
