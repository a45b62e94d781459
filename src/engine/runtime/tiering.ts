// Moving a program from the dispatch loops to straight-line segment functions, a few segments at
// a time. Every program starts on the dispatch loops (compile/dispatch.ts): V8 optimises them in
// the first scans. Straight-line segments (compile/segments.ts) run about twice as fast once
// optimised, but V8 optimises a function only after a few hundred calls, compiles a 64-network
// segment in some 100 ms on a background thread, and queues at most 8 functions at a time; offered
// all at once, most of a big program's segments would be turned away and run unoptimised for tens
// of seconds. So segments are switched over in small batches, the next batch once the previous
// one has had the calls and the time to be optimised. Both forms compute the same thing.
import type { SegmentFn } from '../compile/segments';

export interface TieringOptions {
  /** Network evaluations on the dispatch loops before the first batch. */
  readonly startAfterEvals: number;
  /** Segments per batch (V8 queues 8 functions for optimisation). */
  readonly batch: number;
  /** A batch stays at least this many scans (calls of each segment) ... */
  readonly minScans: number;
  /** ... and this many milliseconds per network, before the next batch. */
  readonly msPerNetwork: number;
  /**
   * Largest program switched to straight-line code. Beyond a few thousand networks the machine code
   * of the segments no longer fits the processor's caches and the compact dispatch loops are faster
   * (measured, ns per network: 1,000 networks 5.7 straight-line against 8.7 dispatch; 3,000: 8.2
   * against 8.6; 10,000: 11.4 against 8.8; switching only the first 2,000 of 10,000 was slower too).
   */
  readonly maxNetworks: number;
  /**
   * Bigger programs are switched too when they have more network shapes than this: the dispatch
   * loops' cost grows with the variety of networks (the processor mispredicts which case comes
   * next; measured on 3,000 networks: 6.4 ns per network with 6 shapes, 16 to 60 with 126).
   */
  readonly manyShapes: number;
}

export const DEFAULT_TIERING: TieringOptions = {
  startAfterEvals: 200_000,
  batch: 4,
  minScans: 600,
  msPerNetwork: 2,
  maxNetworks: 2_000,
  manyShapes: 32,
};

export class Tiering {
  /** Straight-line function of each switched segment, by its first network. */
  readonly fast: (SegmentFn | undefined)[];
  /** Segments still on the dispatch loops, by first network, in program order. */
  private pending: number[];
  private batch: number[] = [];
  private batchScans = 0;
  private batchSince = 0;
  private batchMs = 0;
  private evals = 0;

  constructor(
    /** Segment starts, then the network count (compile/segments.ts planSegments). */
    private readonly starts: readonly number[],
    /** Shapes the running dispatch loops read: -1 at a switched segment's start stops them there. */
    private readonly liveShape: Int32Array,
    private readonly shape: Int32Array,
    shapeCount: number,
    private readonly build: (first: number, end: number) => SegmentFn,
    private readonly clock: () => number,
    private readonly opts: TieringOptions = DEFAULT_TIERING,
    /** Segments the dispatch loops run (not the bodies written in place of their calls). */
    runs: (first: number) => boolean = () => true,
  ) {
    this.fast = new Array<SegmentFn | undefined>(shape.length).fill(undefined);
    const pending = starts.slice(0, -1).filter(runs);
    const networks = pending.reduce((n, first) => n + this.endOf(first) - first, 0);
    const switching = networks <= opts.maxNetworks || shapeCount > opts.manyShapes;
    this.pending = switching ? pending : [];
  }

  private endOf(first: number): number {
    return this.starts[this.starts.indexOf(first) + 1]!;
  }

  /** Called after each complete scan with the networks it evaluated. */
  afterScan(evals: number): void {
    if (this.pending.length === 0 && this.batch.length === 0) return;
    this.evals += evals;
    if (this.evals < this.opts.startAfterEvals) return;
    this.batchScans++;
    if (this.batch.length > 0) {
      if (this.batchScans < this.opts.minScans) return;
      if (this.clock() - this.batchSince < this.batchMs) return;
    }
    this.batch = [];
    let networks = 0;
    while (this.batch.length < this.opts.batch && this.pending.length > 0) {
      const first = this.pending.shift()!;
      const end = this.endOf(first);
      this.batch.push(first);
      networks += end - first;
      this.fast[first] = this.build(first, end);
      this.liveShape[first] = -1;
    }
    this.batchScans = 0;
    this.batchSince = this.clock();
    this.batchMs = networks * this.opts.msPerNetwork;
  }

  /** Sends the segments holding these networks back to the dispatch loops, to be rebuilt later (forcing). */
  invalidate(networks: Iterable<number>): void {
    const firsts = new Set<number>();
    for (const i of networks) {
      let k = 0;
      while (this.starts[k + 1]! <= i) k++;
      firsts.add(this.starts[k]!);
    }
    for (const first of firsts) {
      if (this.fast[first] === undefined) continue;
      this.fast[first] = undefined;
      this.liveShape[first] = this.shape[first]!;
      this.batch = this.batch.filter((s) => s !== first);
      this.pending.unshift(first);
    }
  }
}
