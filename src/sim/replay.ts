// Rebuilds recorded scans (issue 14): a second PLC of the same compiled program restores a
// segment's key (the complete state after its first scan) and replays the recorded scans after it at
// their recorded PLC times with their recorded input images. The engine's scan is a pure function of
// state, input image, forces and time, so every replayed scan is the live scan exactly (tested against
// live runs in tests/sim/replay.test.ts). The replaying PLC remembers where it stands: moving forward
// in the same segment replays only the scans in between.
import type { Plc, PlcImage, PlcProbe } from '../engine/api';
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

export class Replayer {
  private plc: Plc | undefined;
  private probeOf: PlcProbe | undefined;
  private sampleAll: ((out: Value[]) => void) | undefined;
  /** Where the replaying PLC stands: after scan `at` of `seg` (none yet: undefined). */
  private seg: Segment<PlcImage> | undefined;
  private at = -1;
  /** Next input image of `seg` to apply (index in seg.inputAt). */
  private inputPos = 0;

  constructor(
    private readonly program: CompiledProgram,
    private readonly history: ScanHistory<PlcImage>,
    /** The names a rebuilt state's values are aligned with. */
    private readonly names: readonly string[],
  ) {}

  /** The replaying PLC's probe (made on first use: compiling its code takes a moment). */
  get probe(): PlcProbe {
    if (!this.probeOf) {
      this.plc = createPlc(this.program, { cycleMs: 1 });
      this.probeOf = this.plc.probe!();
    }
    return this.probeOf;
  }

  /** Forgets where the replaying PLC stands (the history was cleared). */
  reset(): void {
    this.seg = undefined;
    this.at = -1;
  }

  /** Puts the replaying PLC after `scan`; false when the scan is not recorded. */
  goto(scan: number): boolean {
    const seg = this.history.segmentOf(scan);
    if (!seg) return false;
    if (this.seg !== seg || this.at > scan) this.restore(seg);
    while (this.at < scan) this.step(seg);
    return true;
  }

  private restore(seg: Segment<PlcImage>): void {
    this.probe.restore(seg.image);
    this.seg = seg;
    this.at = seg.firstScan;
    this.inputPos = seg.inputIndex(seg.firstScan + 1);
  }

  private step(seg: Segment<PlcImage>): void {
    const scan = ++this.at;
    const k = scan - seg.firstScan;
    let inputs: readonly Value[] | undefined;
    if (this.inputPos < seg.inputAt.length && seg.inputAt[this.inputPos] === k) inputs = seg.inputs[this.inputPos++];
    const fault = this.probe.replay(seg.plcTimeAt(k), inputs);
    if (fault) {
      this.reset();
      throw new Error(`replaying scan ${scan} faulted (${fault.message}); the history cannot show it`);
    }
  }

  /**
   * Visits the recorded scans from..to in order, the replaying PLC standing after each (read it with
   * `probe` or a sampler); stops at the first scan for which `visit` returns true and returns it.
   */
  walk(from: number, to: number, visit: (scan: number) => boolean): number | undefined {
    let s = from;
    while (s <= to) {
      const seg = this.history.segmentOf(s);
      if (!seg || !this.goto(s)) return undefined;
      if (visit(s)) return s;
      const end = Math.min(to, seg.lastScan);
      while (this.at < end) {
        this.step(seg);
        if (visit(this.at)) return this.at;
      }
      s = end + 1;
    }
    return undefined;
  }

  /** The state after `scan`: every value and the power of every network; undefined when not recorded. */
  state(scan: number): HistoryState | undefined {
    if (!this.goto(scan)) return undefined;
    const probe = this.probe;
    this.sampleAll ??= probe.sampler(this.names);
    const values = new Array<Value>(this.names.length);
    this.sampleAll(values);
    const words = probe.power.length;
    const ranIn = probe.ranIn;
    const power = new Int32Array(words + ranIn.length);
    power.set(probe.power);
    const own = this.plc!.scanCount;
    for (let n = 0; n < ranIn.length; n++) power[words + n] = ranIn[n] === own ? 1 : 0;
    const seg = this.seg!;
    return { scan, timeMs: seg.timeAt(scan - seg.firstScan), values, power };
  }
}
