// Scan history: every recorded scan's values and packed power words, kept as a change log with
// periodic key frames, bounded by a number of scans and a memory budget (the oldest go first).
// Pure TS: used by the simulation worker (src/sim/session.ts) and by tests and benchmarks.
//
// A chunk starts with a key frame (the full state after its first scan); each later scan of the
// chunk stores only what changed since the scan before. Seeking = the chunk's key frame plus its
// deltas up to the scan, so it costs at most one chunk of deltas whatever the depth.
import type { Value } from '../model/iecTypes';

export interface HistoryOptions {
  /** Most scans kept (default 100,000). */
  readonly maxScans?: number;
  /** Memory budget in bytes (default 64 MB); the oldest scans are dropped first to stay under it. */
  readonly budgetBytes?: number;
  /** Scans per key frame (default 256). A chunk also ends early when its deltas outgrow its key frame. */
  readonly keyEvery?: number;
}

export const DEFAULT_HISTORY_SCANS = 100_000;
export const DEFAULT_HISTORY_BUDGET = 64 * 1024 * 1024;

/** The state after one scan, as recorded. */
export interface HistoryState {
  readonly scan: number;
  readonly timeMs: number;
  /** Aligned with the recorder's names (SimLayout.variables). */
  readonly values: Value[];
  /** Packed power words, then one executed flag (0/1) per network. */
  readonly power: Int32Array;
}

/** Estimated bytes of one stored value and one delta entry (index + value), for the budget. */
const VALUE_BYTES = 8;
const DELTA_BYTES = 12;

/** A growable Int32 array (deltas are appended scan by scan). */
class IntLog {
  data = new Int32Array(64);
  length = 0;
  push(v: number): void {
    if (this.length === this.data.length) {
      const next = new Int32Array(this.data.length * 2);
      next.set(this.data);
      this.data = next;
    }
    this.data[this.length++] = v;
  }
}

class Chunk {
  /** Scans firstScan .. firstScan + count - 1 (consecutive). */
  count = 1;
  readonly times: number[];
  /** valEnd[k]: end (exclusive) of scan firstScan+k's value deltas in valIdx/valVal; k = 0 is the key frame (none). */
  readonly valEnd = new IntLog();
  readonly valIdx = new IntLog();
  readonly valVal: Value[] = [];
  readonly powEnd = new IntLog();
  readonly powIdx = new IntLog();
  readonly powVal = new IntLog();
  bytes: number;

  constructor(
    readonly firstScan: number,
    timeMs: number,
    readonly keyValues: Value[],
    readonly keyPower: Int32Array,
  ) {
    this.times = [timeMs];
    this.valEnd.push(0);
    this.powEnd.push(0);
    this.bytes = keyValues.length * VALUE_BYTES + keyPower.length * 4 + 64;
  }

  get lastScan(): number {
    return this.firstScan + this.count - 1;
  }

  get deltaEntries(): number {
    return this.valIdx.length + this.powIdx.length;
  }

  /** Writes the state after scan `scan` (within this chunk) into values/power. */
  stateAt(scan: number, values: Value[], power: Int32Array): void {
    for (let i = 0; i < this.keyValues.length; i++) values[i] = this.keyValues[i]!;
    power.set(this.keyPower);
    const k = scan - this.firstScan;
    const vEnd = this.valEnd.data[k]!;
    const vi = this.valIdx.data;
    for (let j = 0; j < vEnd; j++) values[vi[j]!] = this.valVal[j]!;
    const pEnd = this.powEnd.data[k]!;
    const pi = this.powIdx.data;
    const pv = this.powVal.data;
    for (let j = 0; j < pEnd; j++) power[pi[j]!] = pv[j]!;
  }
}

export class ScanHistory {
  readonly maxScans: number;
  readonly budgetBytes: number;
  readonly keyEvery: number;
  private chunks: Chunk[] = [];
  /** The state after the last recorded scan. */
  private readonly cur: Value[];
  private readonly curPower: Int32Array;
  private totalBytes = 0;
  /** First scan that may be seeked (older scans of the first chunk are beyond maxScans). */
  private floor = 0;

  constructor(
    readonly valueCount: number,
    readonly powerCount: number,
    opts: HistoryOptions = {},
  ) {
    this.maxScans = Math.max(1, Math.floor(opts.maxScans ?? DEFAULT_HISTORY_SCANS));
    this.budgetBytes = Math.max(1024, opts.budgetBytes ?? DEFAULT_HISTORY_BUDGET);
    this.keyEvery = Math.max(2, Math.floor(opts.keyEvery ?? 256));
    this.cur = new Array<Value>(valueCount).fill(false);
    this.curPower = new Int32Array(powerCount);
  }

  /** First and last scan that can be seeked, undefined when nothing is recorded. */
  get first(): number | undefined {
    return this.chunks.length ? Math.max(this.floor, this.chunks[0]!.firstScan) : undefined;
  }
  get last(): number | undefined {
    return this.chunks.length ? this.chunks[this.chunks.length - 1]!.lastScan : undefined;
  }
  /** Scans that can be seeked. */
  get count(): number {
    const f = this.first;
    return f === undefined ? 0 : this.last! - f + 1;
  }
  /** Estimated memory held, in bytes. */
  get bytes(): number {
    return this.totalBytes;
  }
  get chunkCount(): number {
    return this.chunks.length;
  }

  clear(): void {
    this.chunks = [];
    this.totalBytes = 0;
    this.floor = 0;
  }

  /**
   * Records the state after scan `scan`: `values` aligned with the names, `power` the packed words and
   * executed flags. A scan that does not follow the last one (a restart) starts the history over.
   */
  record(scan: number, timeMs: number, values: ArrayLike<Value>, power: ArrayLike<number>): void {
    const last = this.chunks[this.chunks.length - 1];
    if (!last || scan !== last.lastScan + 1 || last.count >= this.keyEvery || last.deltaEntries > 4 * (this.valueCount + this.powerCount) + 64) {
      if (last && scan !== last.lastScan + 1) this.clear();
      this.keyFrame(scan, timeMs, values, power);
    } else {
      this.delta(last, timeMs, values, power);
    }
    this.evict();
  }

  private keyFrame(scan: number, timeMs: number, values: ArrayLike<Value>, power: ArrayLike<number>): void {
    const cur = this.cur;
    for (let i = 0; i < cur.length; i++) cur[i] = values[i]!;
    for (let i = 0; i < this.curPower.length; i++) this.curPower[i] = power[i]!;
    const chunk = new Chunk(scan, timeMs, cur.slice(), this.curPower.slice());
    this.chunks.push(chunk);
    this.totalBytes += chunk.bytes;
  }

  private delta(chunk: Chunk, timeMs: number, values: ArrayLike<Value>, power: ArrayLike<number>): void {
    const cur = this.cur;
    let entries = 0;
    for (let i = 0; i < cur.length; i++) {
      const v = values[i]!;
      if (v !== cur[i]) {
        cur[i] = v;
        chunk.valIdx.push(i);
        chunk.valVal.push(v);
        entries++;
      }
    }
    const cp = this.curPower;
    for (let i = 0; i < cp.length; i++) {
      const w = power[i]!;
      if (w !== cp[i]) {
        cp[i] = w;
        chunk.powIdx.push(i);
        chunk.powVal.push(w);
        entries++;
      }
    }
    chunk.valEnd.push(chunk.valIdx.length);
    chunk.powEnd.push(chunk.powIdx.length);
    chunk.times.push(timeMs);
    chunk.count++;
    const added = entries * DELTA_BYTES + 16;
    chunk.bytes += added;
    this.totalBytes += added;
  }

  /** Drops the oldest chunks while over budget, and hides scans beyond maxScans. */
  private evict(): void {
    while (this.chunks.length > 1 && this.totalBytes > this.budgetBytes) this.dropOldest();
    const last = this.last!;
    this.floor = last - this.maxScans + 1;
    while (this.chunks.length > 1 && this.chunks[0]!.lastScan < this.floor) this.dropOldest();
    if (this.totalBytes > this.budgetBytes) this.floor = Math.max(this.floor, last); // one chunk over budget: keep the last scan only
  }

  private dropOldest(): void {
    const c = this.chunks.shift()!;
    this.totalBytes -= c.bytes;
  }

  private chunkOf(scan: number): Chunk | undefined {
    const first = this.first;
    if (first === undefined || scan < first || scan > this.last!) return undefined;
    let lo = 0;
    let hi = this.chunks.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (this.chunks[mid]!.firstScan <= scan) lo = mid;
      else hi = mid - 1;
    }
    return this.chunks[lo];
  }

  /** True when the scan can be seeked. */
  has(scan: number): boolean {
    return this.chunkOf(scan) !== undefined;
  }

  /** The state after `scan`, exactly as recorded; undefined when it is not (or no longer) recorded. */
  seek(scan: number): HistoryState | undefined {
    const chunk = this.chunkOf(scan);
    if (!chunk) return undefined;
    const values = new Array<Value>(this.valueCount);
    const power = new Int32Array(this.powerCount);
    chunk.stateAt(scan, values, power);
    return { scan, timeMs: chunk.times[scan - chunk.firstScan]!, values, power };
  }

  timeOf(scan: number): number | undefined {
    const chunk = this.chunkOf(scan);
    return chunk ? chunk.times[scan - chunk.firstScan] : undefined;
  }

  /** Value `index` after `scan`. */
  valueAt(scan: number, index: number): Value | undefined {
    const chunk = this.chunkOf(scan);
    if (!chunk) return undefined;
    let v = chunk.keyValues[index]!;
    const end = chunk.valEnd.data[scan - chunk.firstScan]!;
    const idx = chunk.valIdx.data;
    for (let j = 0; j < end; j++) if (idx[j] === index) v = chunk.valVal[j]!;
    return v;
  }

  /**
   * The scan at which value `index` last changed at or before `scan` (its value after that scan
   * differs from the scan before); undefined when it did not change in the recorded range.
   */
  lastChange(index: number, scan: number): number | undefined {
    const target = this.valueAt(scan, index);
    if (target === undefined) return undefined;
    const first = this.first!;
    for (let s = scan; s > first; ) {
      const chunk = this.chunkOf(s)!;
      // Deltas of this chunk, newest first, within (chunk.firstScan, s].
      const k = s - chunk.firstScan;
      const idx = chunk.valIdx.data;
      const ends = chunk.valEnd.data;
      for (let step = k; step >= 1; step--) {
        if (chunk.firstScan + step <= first) return undefined;
        for (let j = ends[step - 1]!; j < ends[step]!; j++) if (idx[j] === index) return chunk.firstScan + step;
      }
      // The key frame scan itself: compare with the scan before it.
      const atKey = chunk.firstScan;
      if (atKey <= first) return undefined;
      if (this.valueAt(atKey - 1, index) !== chunk.keyValues[index]) return atKey;
      s = atKey - 1;
    }
    return undefined;
  }

  /** The first scan after `scan` (or before, with direction -1) where value `index` changes. */
  nextChange(index: number, scan: number, direction: 1 | -1): number | undefined {
    if (direction === -1) {
      const at = this.lastChange(index, scan);
      if (at === undefined) return undefined;
      return at < scan ? at : this.lastChange(index, scan - 1);
    }
    let prev = this.valueAt(scan, index);
    if (prev === undefined) return undefined;
    const last = this.last!;
    for (let s = scan + 1; s <= last; ) {
      const chunk = this.chunkOf(s)!;
      const k0 = s - chunk.firstScan;
      if (k0 === 0) {
        const v = chunk.keyValues[index]!;
        if (v !== prev) return s;
        prev = v;
      }
      const idx = chunk.valIdx.data;
      const ends = chunk.valEnd.data;
      for (let step = Math.max(1, k0); step < chunk.count; step++) {
        for (let j = ends[step - 1]!; j < ends[step]!; j++) if (idx[j] === index && chunk.valVal[j] !== prev) return chunk.firstScan + step;
      }
      s = chunk.lastScan + 1;
    }
    return undefined;
  }

  /**
   * Walks scans from `from` (inclusive) forwards (or backwards) and returns the first for which
   * `test(values)` holds; the values array is reused between calls (read it, do not keep it).
   */
  find(from: number, direction: 1 | -1, test: (values: readonly Value[], scan: number) => boolean): number | undefined {
    const first = this.first;
    if (first === undefined) return undefined;
    const last = this.last!;
    const values = new Array<Value>(this.valueCount);
    const power = new Int32Array(this.powerCount);
    if (direction === -1) {
      for (let s = Math.min(from, last); s >= first; s--) {
        this.chunkOf(s)!.stateAt(s, values, power);
        if (test(values, s)) return s;
      }
      return undefined;
    }
    let s = Math.max(from, first);
    while (s <= last) {
      const chunk = this.chunkOf(s)!;
      chunk.stateAt(s, values, power);
      if (test(values, s)) return s;
      const idx = chunk.valIdx.data;
      const ends = chunk.valEnd.data;
      for (let step = s - chunk.firstScan + 1; step < chunk.count; step++) {
        for (let j = ends[step - 1]!; j < ends[step]!; j++) values[idx[j]!] = chunk.valVal[j]!;
        if (test(values, chunk.firstScan + step)) return chunk.firstScan + step;
      }
      s = chunk.lastScan + 1;
    }
    return undefined;
  }
}
