// Samples the trend signals after every scan and hands the new samples to the next frame.
import type { Value } from '../model/iecTypes';
import type { TrendSamples } from './protocol';

export const toTrendNumber = (v: Value): number => (typeof v === 'boolean' ? (v ? 1 : 0) : Number(v));

export class TrendRecorder {
  private names: string[] = [];
  private capacity = 0;
  private scans: number[] = [];
  private times: number[] = [];
  private series: number[][] = [];

  get active(): boolean {
    return this.names.length > 0;
  }

  configure(names: readonly string[], capacity: number): void {
    this.names = [...names];
    this.capacity = Math.max(1, Math.floor(capacity));
    this.clear();
  }

  clear(): void {
    this.scans = [];
    this.times = [];
    this.series = this.names.map(() => []);
  }

  record(scan: number, timeMs: number, read: (name: string) => Value): void {
    this.scans.push(scan);
    this.times.push(timeMs);
    for (let i = 0; i < this.names.length; i++) this.series[i]!.push(toTrendNumber(read(this.names[i]!)));
    // Keep at most `capacity` pending samples (the UI keeps the same window); trim in batches.
    if (this.scans.length >= this.capacity * 2) this.trim();
  }

  /** Samples since the last take, or undefined when there are none. */
  take(): TrendSamples | undefined {
    if (!this.active || this.scans.length === 0) return undefined;
    this.trim();
    const out: TrendSamples = { names: this.names, scans: this.scans, timesMs: this.times, series: this.series };
    this.clear();
    return out;
  }

  private trim(): void {
    const excess = this.scans.length - this.capacity;
    if (excess <= 0) return;
    this.scans.splice(0, excess);
    this.times.splice(0, excess);
    for (const s of this.series) s.splice(0, excess);
  }
}
