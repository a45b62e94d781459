// Rebuilds recorded scans (issue 14): a PLC of the same compiled program restores a segment's key
// (the complete state after its first scan) and replays the recorded scans after it at their
// recorded PLC times with their recorded input images. The engine's scan is a pure function of state,
// input image, forces and time, so every replayed scan is the live scan exactly (tested against live
// runs in tests/sim/replay.test.ts).
//
// The PLC that replays is the live one whenever it stands at a scan boundary: its code is already
// optimised by the JIT (a second PLC of a 1,000-network program replays some 40 times slower for its
// first few thousand scans). Its own state is saved before and put back after, so the live run goes
// on exactly as if nothing had happened. In the middle of a scan (stepping, a breakpoint) or after a
// fault, a second PLC of the same program replays instead; it remembers where it stands, so moving
// forward replays only the scans in between.
import type { Plc, PlcImage, PlcProbe, TextTarget } from '../engine/api';
import { createPlc, type CompiledProgram } from '../engine/plc';
import type { Value } from '../model/iecTypes';
import type { ScanHistory, Segment } from './history';

/** The state after one scan, as rebuilt. */
export interface HistoryState {
  readonly scan: number;
  readonly timeMs: number;
  /** Aligned with the names the replayer was made for (SimLayout.variables). */
  readonly values: Value[];
  /** Packed power words, then one executed flag (0/1) per network. */
  readonly power: Int32Array;
}

interface Replaying {
  readonly plc: Plc;
  readonly probe: PlcProbe;
  /** Sampler of every name, made on first use. */
  sampleAll?: (out: Value[]) => void;
}

export class Replayer {
  private readonly live: Replaying;
  private own: Replaying | undefined;
  /** The PLC replaying in the current operation, and the live PLC's own state while it is borrowed. */
  private current: Replaying | undefined;
  private liveState: PlcImage | undefined;
  private depth = 0;
  /** Where the own PLC stands: after scan `at` of `seg` (none: undefined). */
  private seg: Segment<PlcImage> | undefined;
  private at = -1;
  /** Next input change of `seg` to apply (index in seg.inputAt), and the input image it applies to. */
  private inputPos = 0;
  private image: Value[] = [];

  constructor(
    livePlc: Plc,
    private readonly program: CompiledProgram,
    private readonly history: ScanHistory<PlcImage>,
    /** The names a rebuilt state's values are aligned with. */
    private readonly names: readonly string[],
    /** Told how many outside changes the live PLC counted for being borrowed (PlcProbe.meters[1]). */
    private readonly borrowed: (stateChanges: number) => void = () => {},
  ) {
    this.live = { plc: livePlc, probe: livePlc.probe!() };
  }

  /** Forgets where the second PLC stands (the history was cleared). */
  reset(): void {
    this.seg = undefined;
    this.at = -1;
  }

  /** Runs `fn` with a PLC to replay on: the live one when it is at a scan boundary and not faulted. */
  private using<T>(fn: (r: Replaying) => T): T {
    if (this.depth++ === 0) {
      const live = this.live.plc;
      if (live.nextNetwork === -1 && !live.fault) {
        this.current = this.live;
        this.liveState = this.live.probe.save();
        this.reset();
      } else {
        if (!this.own) {
          const plc = createPlc(this.program, { cycleMs: 1 });
          this.own = { plc, probe: plc.probe!() };
        }
        this.current = this.own;
      }
    }
    try {
      return fn(this.current!);
    } finally {
      if (--this.depth === 0) this.giveBack();
    }
  }

  private giveBack(): void {
    const saved = this.liveState;
    this.current = undefined;
    if (!saved) return;
    this.liveState = undefined;
    this.reset();
    const meters = this.live.probe.meters;
    const before = meters[1]!;
    this.live.probe.restore(saved);
    // Restoring counts as a change from outside (and so did each restore of a key): the state is the
    // live one again, so the recorder need not take a key for it.
    this.borrowed(meters[1]! - before + this.restores);
    this.restores = 0;
  }

  /** Keys restored on the live PLC during the current operation. */
  private restores = 0;

  /** Puts the replaying PLC after `scan`; false when the scan is not recorded. */
  private goto(r: Replaying, scan: number): boolean {
    const seg = this.history.segmentOf(scan);
    if (!seg) return false;
    if (this.seg !== seg || this.at > scan) this.restore(r, seg);
    while (this.at < scan) this.step(r, seg);
    return true;
  }

  private restore(r: Replaying, seg: Segment<PlcImage>): void {
    const before = r.probe.meters[1]!;
    r.probe.restore(seg.image);
    if (r === this.live) this.restores += r.probe.meters[1]! - before;
    this.seg = seg;
    this.at = seg.firstScan;
    this.inputPos = seg.inputIndex(seg.firstScan + 1);
    this.image = r.probe.inputImage.slice();
  }

  private step(r: Replaying, seg: Segment<PlcImage>): void {
    const scan = ++this.at;
    const k = scan - seg.firstScan;
    let inputs: readonly Value[] | undefined;
    if (this.inputPos < seg.inputAt.length && seg.inputAt[this.inputPos] === k) {
      const change = seg.inputs[this.inputPos++]!;
      const image = this.image;
      change.index.forEach((i, j) => (image[i] = change.values[j]!));
      inputs = image;
    }
    const fault = r.probe.replay(seg.plcTimeAt(k), inputs);
    if (fault) {
      this.reset();
      throw new Error(`replaying scan ${scan} faulted (${fault.message}); the history cannot show it`);
    }
  }

  /**
   * Visits the recorded scans from..to in order with the values of `names` after each (the array
   * is reused: read it, do not keep it); stops at the first scan for which `visit` returns true and
   * returns it.
   */
  walk(from: number, to: number, names: readonly string[], visit: (values: readonly Value[], scan: number) => boolean): number | undefined {
    return this.using((r) => {
      const values = new Array<Value>(names.length);
      const sample = r.probe.sampler(names);
      let s = from;
      while (s <= to) {
        const seg = this.history.segmentOf(s);
        if (!seg || !this.goto(r, s)) return undefined;
        sample(values);
        if (visit(values, s)) return s;
        const end = Math.min(to, seg.lastScan);
        while (this.at < end) {
          this.step(r, seg);
          sample(values);
          if (visit(values, this.at)) return this.at;
        }
        s = end + 1;
      }
      return undefined;
    });
  }

  /**
   * The state after `scan`: every value and the power of every network; undefined when not recorded.
   * `also` reads more of that state on the PLC that replayed it (before the live state is put back).
   */
  state(scan: number, also?: (probe: PlcProbe, power: Int32Array, plc: Plc) => void, text?: TextTarget): HistoryState | undefined {
    return this.using((r) => {
      // An ST/IL body shown: observed on the replaying PLC too (from the scans it replays now on).
      if (text) r.plc.observeText([text]);
      if (!this.goto(r, scan)) return undefined;
      const probe = r.probe;
      r.sampleAll ??= probe.sampler(this.names);
      const values = new Array<Value>(this.names.length);
      r.sampleAll(values);
      const words = probe.power.length;
      const ranIn = probe.ranIn;
      const power = new Int32Array(words + ranIn.length);
      power.set(probe.power);
      const own = r.plc.scanCount;
      for (let n = 0; n < ranIn.length; n++) power[words + n] = ranIn[n] === own ? 1 : 0;
      const seg = this.seg!;
      also?.(probe, power, r.plc);
      return { scan, timeMs: seg.timeAt(scan - seg.firstScan), values, power };
    });
  }
}
