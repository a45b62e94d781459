// The machine's history (issue 26): the machine as it was after every recorded scan, kept compact
// and exact. What a step was given is kept as runs: consecutive steps given the same drive and
// faults (each BOOL actuator and operator control and each fault one bit, each INT actuator a
// number) and the same time step make one run, kept once with the PLC time its first step reached.
// Outputs, operator controls and faults change seldom and the scan cycle is steady, so a run
// usually spans a whole chunk: a scan costs the history a comparison, not a record. Every CHUNK
// scans the state before the chunk's first step is kept whole (a keyframe); the state after any
// scan is worked out again by replaying the model's `step` from that keyframe with the recorded
// drive, time steps and faults. The model is deterministic (docs/PLANTS.md), so the replayed state
// is the state the machine had, to the bit.
import type { Value } from '../model/iecTypes';
import type { PlantSnapshot } from './loop';
import type { PlantModel, PlantPoint } from './types';
import { copyPlantState } from './points';

/** Scans per keyframe: a seek replays at most CHUNK - 1 steps. */
export const PLANT_HISTORY_CHUNK = 256;

/**
 * A run's fields in a chunk's `runs`, then its record: `words` words of bits (BOOL actuators,
 * operator controls, faults), then one number per INT actuator.
 */
const RUN_START = 0; // the run's first step, by index in the chunk
const RUN_DT = 1; // the time step each of its steps was given (ms)
const RUN_TIME = 2; // the PLC time its first step reached; each next step reached the last's plus RUN_DT
const RUN_RECORD = 3;
/** Runs a chunk has room for at first (the room doubles when full). */
const FIRST_RUNS = 4;

interface Chunk {
  readonly firstScan: number;
  /** The state before the chunk's first step. */
  readonly state: unknown;
  count: number;
  /** The runs, `stride` numbers each, `runCount` of them (the array may have room for more). */
  runs: Float64Array;
  runCount: number;
}

/** Where one drive value or fault sits in a scan's record. */
interface Slot {
  readonly name: string;
  readonly bit: number;
}

export class PlantHistory {
  /** The chunks kept are `chunks[head]` on, oldest first (dropped ones are cleared out of the array now and then, not one by one). */
  private chunks: Chunk[] = [];
  private head = 0;
  /** The two state objects a seek steps between (made on the first seek). */
  private replay: [unknown, unknown] | undefined;
  /** The last chunk, the one being filled (push touches only it and the fields below). */
  private open: Chunk | undefined;
  /** Scans in the open chunk: `chunk` when there is none (the next push starts one). */
  private openCount: number;
  /** The open chunk's last run: where it starts in `runs`, its time step, the PLC time its last step reached. */
  private runBase = 0;
  private runDt = 0;
  private lastTime = 0;
  /** The scan the open chunk takes next. */
  private nextScan = -1;
  /** Scans in the oldest chunk (while it is the open one, kept up to date by dropOldest only when it matters). */
  private oldestCount = 0;
  /** The runs array of the last chunk dropped, used again for the next one. */
  private spare: Float64Array | undefined;
  private total = 0;
  /** BOOL actuators and operator controls (bits), then faults (bits); INT actuators (numbers). */
  private readonly boolDrive: Slot[] = [];
  private readonly intDrive: string[] = [];
  private readonly faultBits: Slot[] = [];
  private readonly words: number;
  private readonly intCount: number;
  /** Numbers per run in a chunk's `runs`. */
  private readonly stride: number;
  private readonly actuators: readonly PlantPoint[];
  private readonly operators: readonly PlantPoint[];

  constructor(
    private readonly model: PlantModel,
    points: readonly PlantPoint[],
    /** At least this many of the latest scans are kept (whole chunks are dropped). */
    private readonly keep: number,
    private readonly chunk = PLANT_HISTORY_CHUNK,
  ) {
    let bit = 0;
    this.actuators = points.filter((p) => p.kind === 'actuator');
    this.operators = points.filter((p) => p.kind === 'operator');
    for (const p of [...this.actuators, ...this.operators])
      if (p.type === 'BOOL') this.boolDrive.push({ name: p.name, bit: bit++ });
      else this.intDrive.push(p.name);
    for (const f of model.faults) this.faultBits.push({ name: f.id, bit: bit++ });
    this.words = Math.max(1, Math.ceil(bit / 32));
    this.intCount = this.intDrive.length;
    this.stride = RUN_RECORD + this.words + this.intCount;
    this.openCount = this.chunk;
  }

  clear(): void {
    this.chunks = [];
    this.head = 0;
    this.open = undefined;
    this.openCount = this.chunk;
    this.nextScan = -1;
    this.oldestCount = 0;
    this.total = 0;
  }

  get length(): number {
    return this.total;
  }

  /** A scan's record: `words` words of bits and one number per INT actuator, filled by the loop (`bitOf`, `intOf`, `faultBitOf`). */
  newRecord(): { readonly bits: Uint32Array; readonly ints: Float64Array } {
    return { bits: new Uint32Array(this.words), ints: new Float64Array(this.intDrive.length) };
  }

  /** The bit of a BOOL actuator or operator control in a record, -1 for another point. */
  bitOf(name: string): number {
    return this.boolDrive.find((s) => s.name === name)?.bit ?? -1;
  }

  /** The number of an INT actuator in a record, -1 for another point. */
  intOf(name: string): number {
    return this.intDrive.indexOf(name);
  }

  faultBitOf(id: string): number {
    return this.faultBits.find((s) => s.name === id)?.bit ?? -1;
  }

  /**
   * Records a step: `before` is the state and PLC time it started from, `record` what it was given
   * (drive and faults, filled as `newRecord` says), `timeMs` the time it reached after scan `scan`
   * (the step was given the time between the two, or 0 when `timeMs` is not later). `same`: the
   * caller knows `record` is the one it gave last time (it is compared otherwise).
   */
  push(
    scan: number,
    before: unknown,
    beforeMs: number,
    record: { readonly bits: Uint32Array; readonly ints: Float64Array },
    timeMs: number,
    same = false,
  ): void {
    const dt = timeMs > beforeMs ? timeMs - beforeMs : 0;
    const i = this.openCount;
    if (i === this.chunk || scan !== this.nextScan) {
      if (this.keep <= 0) return;
      this.startChunk(scan, before);
      this.startRun(0, dt, timeMs, record);
    } else if (dt !== this.runDt || timeMs !== this.lastTime + dt || !(same || this.sameRecord(record))) {
      // The usual case is the other one: the same drive and time step as the scan before, which
      // only lengthens the open run.
      this.startRun(i, dt, timeMs, record);
    }
    this.lastTime = timeMs;
    this.openCount = this.openCount + 1;
    this.nextScan = scan + 1;
    // The oldest chunk goes, whole, once the others hold `keep` scans.
    if (++this.total - this.oldestCount >= this.keep) this.dropOldest();
  }

  /** `record` is the open run's. */
  private sameRecord(record: { readonly bits: Uint32Array; readonly ints: Float64Array }): boolean {
    const runs = this.open!.runs;
    const at = this.runBase + RUN_RECORD;
    const words = this.words;
    for (let w = 0; w < words; w++) if (runs[at + w] !== record.bits[w]) return false;
    const n = this.intCount;
    for (let k = 0; k < n; k++) if (!Object.is(runs[at + words + k], record.ints[k])) return false;
    return true;
  }

  /** A run starting at step `i` of the open chunk. */
  private startRun(i: number, dt: number, timeMs: number, record: { readonly bits: Uint32Array; readonly ints: Float64Array }): void {
    const c = this.open!;
    const stride = this.stride;
    if ((c.runCount + 1) * stride > c.runs.length) {
      const more = new Float64Array(c.runs.length * 2);
      more.set(c.runs);
      c.runs = more;
    }
    const at = c.runCount * stride;
    const runs = c.runs;
    runs[at + RUN_START] = i;
    runs[at + RUN_DT] = dt;
    runs[at + RUN_TIME] = timeMs;
    const words = this.words;
    for (let w = 0; w < words; w++) runs[at + RUN_RECORD + w] = record.bits[w]!;
    for (let k = 0; k < this.intCount; k++) runs[at + RUN_RECORD + words + k] = record.ints[k]!;
    c.runCount++;
    this.runBase = at;
    this.runDt = dt;
  }

  private startChunk(scan: number, before: unknown): void {
    // Every number of the runs array is written before it is read: a dropped chunk's serves as it is.
    const runs = this.spare ?? new Float64Array(FIRST_RUNS * this.stride);
    this.spare = undefined;
    // The chunk open until now is complete (its count is kept in `openCount` while open).
    if (this.open) this.open.count = this.openCount;
    // A copy: the loop steps into its state objects again (no later step changes this one).
    const c: Chunk = { firstScan: scan, state: copyPlantState(before), count: 0, runs, runCount: 0 };
    this.chunks.push(c);
    this.open = c;
    this.openCount = 0;
    if (this.chunks.length - this.head === 1) this.oldestCount = 0;
  }

  private dropOldest(): void {
    const chunks = this.chunks;
    while (this.total - this.countOf(chunks[this.head]!) >= this.keep) {
      const dropped = chunks[this.head]!;
      chunks[this.head++] = undefined!;
      this.total -= dropped.count;
      this.spare = dropped.runs;
    }
    // The dropped ones' places go once they are half the array (a shift per chunk moved the rest every time).
    if (this.head >= 64 && this.head * 2 >= chunks.length) {
      chunks.splice(0, this.head);
      this.head = 0;
    }
    this.oldestCount = this.countOf(chunks[this.head]!);
  }

  /** Scans in a chunk (the open one's count is the history's). */
  private countOf(c: Chunk): number {
    return c === this.open ? this.openCount : c.count;
  }

  /** The oldest scan kept, if any. */
  get firstScan(): number | undefined {
    return this.chunks[this.head]?.firstScan;
  }

  /** The machine after scan `scan`, replayed from its chunk's keyframe; undefined when not kept. */
  at(scan: number): PlantSnapshot | undefined {
    const c = this.chunkOf(scan);
    if (!c) return undefined;
    const last = scan - c.firstScan;
    // Stepped between the history's two replay objects (as the loop steps), from the keyframe,
    // which stays untouched; what is handed out is a copy of the last one written. The same two
    // objects every seek: their shape settles once (fresh ones would change shape in every seek).
    this.replay ??= [this.model.initial(), this.model.initial()];
    let state: unknown = Object.assign(this.replay[0] as object, c.state);
    let spare: unknown = this.replay[1];
    // One drive record and one fault set refilled at each run (valid only during the call, as in the loop).
    const drive: Record<string, Value> = {};
    const faults = new Set<string>();
    const runs = c.runs;
    const stride = this.stride;
    let next = 0;
    let dt = 0;
    let time = 0;
    for (let i = 0; i <= last; i++) {
      if (next < c.runCount && runs[next * stride + RUN_START] === i) {
        const at = next * stride;
        this.fill(runs, at + RUN_RECORD, drive, faults);
        dt = runs[at + RUN_DT]!;
        time = runs[at + RUN_TIME]!;
        next++;
      } else time = time + dt;
      const after = this.model.step(state, drive, dt, faults, spare);
      spare = state;
      state = after;
    }
    const operator: Record<string, boolean> = {};
    for (const p of this.operators) operator[p.name] = drive[p.name] === true;
    const shown: Record<string, Value> = {};
    for (const p of this.actuators) shown[p.name] = drive[p.name]!;
    return { scan, timeMs: time, state: copyPlantState(state), faults: [...faults].sort(), operator, drive: shown };
  }

  /**
   * The operator controls held and the faults set in scan `scan` (what its step was given; read
   * from the run that holds it, nothing replayed), or undefined when the scan is not kept.
   */
  controlsAt(scan: number): { readonly operator: Record<string, boolean>; readonly faults: string[] } | undefined {
    const c = this.chunkOf(scan);
    if (!c) return undefined;
    const i = scan - c.firstScan;
    const stride = this.stride;
    let run = 0;
    while (run + 1 < c.runCount && c.runs[(run + 1) * stride + RUN_START]! <= i) run++;
    const drive: Record<string, Value> = {};
    const faults = new Set<string>();
    this.fill(c.runs, run * stride + RUN_RECORD, drive, faults);
    const operator: Record<string, boolean> = {};
    for (const p of this.operators) operator[p.name] = drive[p.name] === true;
    return { operator, faults: [...faults].sort() };
  }

  private chunkOf(scan: number): Chunk | undefined {
    let lo = this.head;
    let hi = this.chunks.length - 1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      const c = this.chunks[mid]!;
      if (scan < c.firstScan) hi = mid - 1;
      else if (scan >= c.firstScan + this.countOf(c)) lo = mid + 1;
      else return c;
    }
    return undefined;
  }

  /** A run's record (at `at` in `runs`): its drive and faults into the records given. */
  private fill(runs: Float64Array, at: number, drive: Record<string, Value>, faults: Set<string>): void {
    for (const s of this.boolDrive) drive[s.name] = (runs[at + (s.bit >>> 5)]! & (1 << (s.bit & 31))) !== 0;
    const n = this.intDrive.length;
    for (let k = 0; k < n; k++) drive[this.intDrive[k]!] = runs[at + this.words + k]!;
    faults.clear();
    for (const s of this.faultBits) if ((runs[at + (s.bit >>> 5)]! & (1 << (s.bit & 31))) !== 0) faults.add(s.name);
  }
}
