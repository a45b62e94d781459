// Scan history (issue 14): what it takes to rebuild any recorded scan exactly, bounded by a number of
// scans and a memory budget (the oldest go first). Pure TS: used by the simulation worker through
// HistoryRecorder (src/sim/historyRecorder.ts), and by tests and benchmarks.
//
// A scan is a pure function of the PLC's state, its input image, forces and its time. So the history
// keeps, per scan, only its times and (when the input image changed) the inputs that changed; and now
// and then a key: the PLC's complete state after a scan (PlcProbe.save). A segment is a key and the
// scans after it up to the next key; a scan is rebuilt by restoring its segment's key on a PLC of the
// same program and replaying the scans after it (src/sim/replay.ts). A key is also taken after any
// other change from outside (a write, a force, a restart, a change in the middle of a scan), so
// replaying never needs more than the recorded times and inputs.
import type { Value } from '../model/iecTypes';

export interface HistoryOptions {
  /** Most scans kept (default 100,000). */
  readonly maxScans?: number;
  /** Memory budget in bytes (default 64 MB); the oldest scans are dropped first to stay under it. */
  readonly budgetBytes?: number;
  /** Most scans between two keys (default 1,024): bounds the scans a seek replays. */
  readonly keyEvery?: number;
  /** A key is also taken once the scans since the last one took this long to run (ms, default 10): bounds a seek's time on slow programs. */
  readonly keyReplayMs?: number;
}

export const DEFAULT_HISTORY_SCANS = 100_000;
export const DEFAULT_HISTORY_BUDGET = 64 * 1024 * 1024;
export const DEFAULT_KEY_EVERY = 1024;
export const DEFAULT_KEY_REPLAY_MS = 10;

/** A key's state, as the history holds it: only its size matters here. */
export interface KeyImage {
  readonly bytes: number;
}

/** Bytes per recorded scan (two times), per recorded input change and per changed input in it. */
const SCAN_BYTES = 16;
const INPUTS_BYTES = 48;
const INPUT_BYTES = 12;

/** The inputs a scan read that differ from what the scan before read: their indexes in the input image, and their values. */
export interface InputChange {
  readonly index: readonly number[];
  readonly values: readonly Value[];
}

/** A key and the scans after it, up to the next key. */
export class Segment<I extends KeyImage> {
  /** Scans firstScan .. firstScan + count - 1. */
  count = 1;
  /**
   * Per scan k (k = scan - firstScan): at 2k the session's time of the scan, at 2k + 1 the PLC's own
   * time (what its timers saw; they differ after an online change).
   */
  private t: Float64Array;
  /** Offsets of the scans that read a changed input image, ascending, and what changed. */
  readonly inputAt: number[] = [];
  readonly inputs: InputChange[] = [];
  /** Bytes of the input changes. */
  private inputBytes = 0;

  constructor(
    readonly firstScan: number,
    timeMs: number,
    plcTimeMs: number,
    /** The complete state after firstScan. */
    readonly image: I,
  ) {
    this.t = new Float64Array(32);
    this.t[0] = timeMs;
    this.t[1] = plcTimeMs;
  }

  get lastScan(): number {
    return this.firstScan + this.count - 1;
  }

  /** Estimated memory held, in bytes. */
  get bytes(): number {
    return this.image.bytes + 128 + this.count * SCAN_BYTES + this.inputBytes;
  }

  /** The session's time of scan firstScan + k, and the PLC's. */
  timeAt(k: number): number {
    return this.t[2 * k]!;
  }
  plcTimeAt(k: number): number {
    return this.t[2 * k + 1]!;
  }

  /** Appends the next scan. */
  push(timeMs: number, plcTimeMs: number): void {
    const at = 2 * this.count++;
    let t = this.t;
    if (at === t.length) {
      t = new Float64Array(at * 2);
      t.set(this.t);
      this.t = t;
    }
    t[at] = timeMs;
    t[at + 1] = plcTimeMs;
  }

  /** Appends the next scan, which read a changed input image. */
  pushInputs(timeMs: number, plcTimeMs: number, inputs: InputChange): void {
    this.inputAt.push(this.count);
    this.inputs.push(inputs);
    this.inputBytes += INPUTS_BYTES + inputs.index.length * INPUT_BYTES;
    this.push(timeMs, plcTimeMs);
  }

  /** Index in inputAt of the first input change recorded at or after `scan`. */
  inputIndex(scan: number): number {
    const k = scan - this.firstScan;
    const at = this.inputAt;
    let lo = 0;
    let hi = at.length;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (at[mid]! < k) lo = mid + 1;
      else hi = mid;
    }
    return lo;
  }
}

export class ScanHistory<I extends KeyImage = KeyImage> {
  readonly maxScans: number;
  readonly budgetBytes: number;
  readonly keyEvery: number;
  readonly keyReplayMs: number;
  private segs: Segment<I>[] = [];
  /** Bytes of the segments before the open one. */
  private closedBytes = 0;
  /** Set when one segment alone is over the budget: only scans from here on can be seeked. */
  private overBudgetFloor = -Infinity;

  constructor(opts: HistoryOptions = {}) {
    this.maxScans = Math.max(1, Math.floor(opts.maxScans ?? DEFAULT_HISTORY_SCANS));
    this.budgetBytes = Math.max(1024, opts.budgetBytes ?? DEFAULT_HISTORY_BUDGET);
    this.keyEvery = Math.max(2, Math.floor(opts.keyEvery ?? DEFAULT_KEY_EVERY));
    this.keyReplayMs = Math.max(0, opts.keyReplayMs ?? DEFAULT_KEY_REPLAY_MS);
  }

  /** The segment being recorded into, undefined when nothing is recorded. */
  get open(): Segment<I> | undefined {
    return this.segs[this.segs.length - 1];
  }

  /** First and last scan that can be seeked, undefined when nothing is recorded. */
  get first(): number | undefined {
    const first = this.segs[0];
    if (!first) return undefined;
    return Math.max(first.firstScan, this.open!.lastScan - this.maxScans + 1, this.overBudgetFloor);
  }
  get last(): number | undefined {
    return this.open?.lastScan;
  }
  /** Scans that can be seeked. */
  get count(): number {
    const f = this.first;
    return f === undefined ? 0 : this.last! - f + 1;
  }
  /** Estimated memory held, in bytes. */
  get bytes(): number {
    const open = this.open;
    return open ? this.closedBytes + open.bytes : 0;
  }
  get segmentCount(): number {
    return this.segs.length;
  }

  clear(): void {
    this.segs = [];
    this.closedBytes = 0;
    this.overBudgetFloor = -Infinity;
  }

  /**
   * Starts a segment with scan `scan` and the complete state after it. A scan that does not follow
   * the last recorded one (a restart) starts the history over.
   */
  key(scan: number, timeMs: number, plcTimeMs: number, image: I): void {
    const open = this.open;
    if (open && scan !== open.lastScan + 1) this.clear();
    else if (open) this.closedBytes += open.bytes;
    this.segs.push(new Segment(scan, timeMs, plcTimeMs, image));
    this.evict();
  }

  /**
   * Records the scan after the last one: its times and, when it read a changed input image, what
   * changed. Call key() instead for the first scan, after a gap, and after any other change.
   */
  scan(timeMs: number, plcTimeMs: number, inputs?: InputChange): void {
    const open = this.open!;
    if (inputs) open.pushInputs(timeMs, plcTimeMs, inputs);
    else open.push(timeMs, plcTimeMs);
    if (this.closedBytes + open.bytes > this.budgetBytes) this.evict();
  }

  /** Drops the oldest segments while over budget or wholly older than maxScans. */
  private evict(): void {
    while (this.segs.length > 1 && this.bytes > this.budgetBytes) this.dropOldest();
    const floor = this.open!.lastScan - this.maxScans + 1;
    while (this.segs.length > 1 && this.segs[0]!.lastScan < floor) this.dropOldest();
    // One segment over budget on its own: keep its last scan only (seeking it replays the segment).
    if (this.bytes > this.budgetBytes) this.overBudgetFloor = this.open!.lastScan;
  }

  private dropOldest(): void {
    // Never the open segment: at least one stays.
    this.closedBytes -= this.segs.shift()!.bytes;
  }

  /** The segment holding `scan`, when it can be seeked. */
  segmentOf(scan: number): Segment<I> | undefined {
    const first = this.first;
    if (first === undefined || scan < first || scan > this.last!) return undefined;
    const segs = this.segs;
    let lo = 0;
    let hi = segs.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (segs[mid]!.firstScan <= scan) lo = mid;
      else hi = mid - 1;
    }
    return segs[lo];
  }

  /** The segment before / after `seg` (undefined at either end). */
  previous(seg: Segment<I>): Segment<I> | undefined {
    const i = this.segs.indexOf(seg);
    return i > 0 ? this.segs[i - 1] : undefined;
  }
  next(seg: Segment<I>): Segment<I> | undefined {
    const i = this.segs.indexOf(seg);
    return i >= 0 ? this.segs[i + 1] : undefined;
  }

  /** True when the scan can be seeked. */
  has(scan: number): boolean {
    return this.segmentOf(scan) !== undefined;
  }

  /** The session's time of a recorded scan. */
  timeOf(scan: number): number | undefined {
    const seg = this.segmentOf(scan);
    return seg ? seg.timeAt(scan - seg.firstScan) : undefined;
  }
}
