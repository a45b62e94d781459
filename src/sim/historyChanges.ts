// Previous/next change of one recorded value (timeline buttons, "When did it change?" in Why?), found
// by replaying: each segment is replayed once per value asked for, and what it showed (the value at
// its first and last scan, the scans where it changed) is kept, so later questions are answered
// without replaying again. Segments that are dropped from the history take their summaries along.
import type { PlcImage } from '../engine/api';
import type { Value } from '../model/iecTypes';
import type { ScanHistory, Segment } from './history';
import type { Replayer } from './replay';

interface Summary {
  readonly first: Value;
  readonly last: Value;
  /** Last scan summarised (the open segment grows). */
  readonly upTo: number;
  /** Scans after the segment's first where the value differs from the scan before, ascending. */
  readonly changes: number[];
}

/** Values asked about before the oldest summaries are forgotten. */
const MAX_VALUES = 32;

/** Same value (a NaN is the same as a NaN). */
export const sameValue = (a: Value, b: Value): boolean => a === b || (a !== a && b !== b);

export class ChangeIndex {
  private readonly summaries = new Map<number, WeakMap<Segment<PlcImage>, Summary>>();

  constructor(
    private readonly history: ScanHistory<PlcImage>,
    private readonly replayer: Replayer,
    /** The recorded name of a value index. */
    private readonly nameOf: (index: number) => string,
  ) {}

  clear(): void {
    this.summaries.clear();
  }

  private summary(index: number, seg: Segment<PlcImage>, upTo: number): Summary {
    let byValue = this.summaries.get(index);
    if (!byValue) {
      if (this.summaries.size >= MAX_VALUES) this.summaries.delete(this.summaries.keys().next().value!);
      byValue = new WeakMap();
      this.summaries.set(index, byValue);
    }
    const known = byValue.get(seg);
    if (known && known.upTo >= upTo) return known;
    const from = Math.max(seg.firstScan, this.history.first!);
    const end = seg.lastScan;
    const changes: number[] = [];
    let first: Value | undefined;
    let prev: Value = false;
    this.replayer.walk(from, end, [this.nameOf(index)], (values, scan) => {
      const v = values[0]!;
      if (first === undefined) first = v;
      else if (!sameValue(v, prev)) changes.push(scan);
      prev = v;
      return false;
    });
    const summary: Summary = { first: first!, last: prev, upTo: end, changes };
    byValue.set(seg, summary);
    return summary;
  }

  /**
   * The scan at which value `index` last changed at or before `scan` (its value after that scan
   * differs from the scan before); undefined when it did not change in the recorded range.
   */
  lastChange(index: number, scan: number): number | undefined {
    const first = this.history.first;
    const at = this.history.segmentOf(scan);
    if (first === undefined || !at) return undefined;
    let seg: Segment<PlcImage> = at;
    let upTo = scan;
    for (;;) {
      const sum = this.summary(index, seg, upTo);
      const c = lastAtOrBefore(sum.changes, upTo);
      if (c !== undefined) return c > first ? c : undefined;
      if (seg.firstScan <= first) return undefined;
      const prev: Segment<PlcImage> = this.history.previous(seg)!;
      const before = this.summary(index, prev, prev.lastScan);
      if (!sameValue(before.last, sum.first)) return seg.firstScan;
      seg = prev;
      upTo = prev.lastScan;
    }
  }

  /** The first scan after `scan` where value `index` changes. */
  nextChange(index: number, scan: number): number | undefined {
    const at = this.history.segmentOf(scan);
    if (!at) return undefined;
    let seg: Segment<PlcImage> = at;
    let sum = this.summary(index, seg, seg.lastScan);
    const c = sum.changes.find((s) => s > scan);
    if (c !== undefined) return c;
    for (;;) {
      const next = this.history.next(seg);
      if (!next) return undefined;
      const nextSum = this.summary(index, next, next.lastScan);
      if (!sameValue(sum.last, nextSum.first)) return next.firstScan;
      if (nextSum.changes.length > 0) return nextSum.changes[0];
      seg = next;
      sum = nextSum;
    }
  }
}

function lastAtOrBefore(sorted: readonly number[], scan: number): number | undefined {
  let lo = 0;
  let hi = sorted.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (sorted[mid]! <= scan) lo = mid + 1;
    else hi = mid;
  }
  return lo > 0 ? sorted[lo - 1] : undefined;
}
