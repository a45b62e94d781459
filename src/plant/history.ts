// The machine's history (issue 26): the machine as it was after every recorded scan, kept compact
// and exact. Per scan only what the step was given is kept: when it ended (PLC time), each BOOL
// actuator and operator control and each fault as one bit, each INT actuator as a number. Every
// CHUNK scans the state before the chunk's first step is kept whole (a keyframe); the state after
// any scan is worked out again by replaying the model's `step` from that keyframe with the recorded
// drive, times and faults. The model is deterministic (docs/PLANTS.md), so the replayed state is
// the state the machine had, to the bit.
import type { Value } from '../model/iecTypes';
import type { PlantSnapshot } from './loop';
import type { PlantModel, PlantPoint } from './types';
import { copyPlantState } from './points';

/** Scans per keyframe: a seek replays at most CHUNK - 1 steps. */
export const PLANT_HISTORY_CHUNK = 256;

interface Chunk {
  readonly firstScan: number;
  /** The state before the chunk's first step, and the PLC time it had reached. */
  readonly state: unknown;
  readonly timeMs: number;
  count: number;
  /** PLC time the machine reached after each step. */
  readonly times: Float64Array;
  /** `words` 32-bit words per scan: BOOL actuators, operator controls, faults, one bit each. */
  readonly bits: Uint32Array;
  /** INT actuators, one number each per scan. */
  readonly ints: Float64Array;
}

/** Where one drive value or fault sits in a scan's record. */
interface Slot {
  readonly name: string;
  readonly bit: number;
}

export class PlantHistory {
  private chunks: Chunk[] = [];
  /** The two state objects a seek steps between (made on the first seek). */
  private replay: [unknown, unknown] | undefined;
  /** The last chunk, the one being filled, and its arrays and count (push touches only these). */
  private open: Chunk | undefined;
  private openTimes: Float64Array = new Float64Array(0);
  private openBits: Uint32Array = new Uint32Array(0);
  private openInts: Float64Array = new Float64Array(0);
  /** Scans in the open chunk: `chunk` when there is none (the next push starts one). */
  private openCount: number;
  /** The scan the open chunk takes next. */
  private nextScan = -1;
  /** Scans in the oldest chunk (while it is the open one, kept up to date by dropOldest only when it matters). */
  private oldestCount = 0;
  /** The arrays of the last chunk dropped, used again for the next one (no allocation in the steady state). */
  private spare: Pick<Chunk, 'times' | 'bits' | 'ints'> | undefined;
  private total = 0;
  /** BOOL actuators and operator controls (bits), then faults (bits); INT actuators (numbers). */
  private readonly boolDrive: Slot[] = [];
  private readonly intDrive: string[] = [];
  private readonly faultBits: Slot[] = [];
  private readonly words: number;
  private readonly intCount: number;
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
    this.openCount = this.chunk;
  }

  clear(): void {
    this.chunks = [];
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
   * (drive and faults, filled as `newRecord` says), `timeMs` the time it reached after scan `scan`.
   */
  push(
    scan: number,
    before: unknown,
    beforeMs: number,
    record: { readonly bits: Uint32Array; readonly ints: Float64Array },
    timeMs: number,
  ): void {
    // The usual case: the next scan of the open chunk, written through the history's own fields
    // (its arrays and count: no other object is touched).
    let i = this.openCount;
    if (i === this.chunk || scan !== this.nextScan) {
      if (this.keep <= 0) return;
      this.startChunk(scan, before, beforeMs);
      i = 0;
    }
    this.openTimes[i] = timeMs;
    const words = this.words;
    if (words === 1) this.openBits[i] = record.bits[0]!;
    else for (let w = 0; w < words; w++) this.openBits[i * words + w] = record.bits[w]!;
    const n = this.intCount;
    for (let k = 0; k < n; k++) this.openInts[i * n + k] = record.ints[k]!;
    this.openCount = i + 1;
    this.nextScan = scan + 1;
    // The oldest chunk goes, whole, once the others hold `keep` scans.
    if (++this.total - this.oldestCount >= this.keep) this.dropOldest();
  }

  private startChunk(scan: number, before: unknown, beforeMs: number): Chunk {
    // Every slot of the arrays is written before it is read: a dropped chunk's serve as they are.
    const arrays = this.spare ?? {
      times: new Float64Array(this.chunk),
      bits: new Uint32Array(this.chunk * this.words),
      ints: new Float64Array(this.chunk * this.intCount),
    };
    this.spare = undefined;
    // The chunk open until now is complete (its count is kept in `openCount` while open).
    if (this.open) this.open.count = this.openCount;
    // A copy: the loop steps into its state objects again (no later step changes this one).
    const c: Chunk = { firstScan: scan, state: copyPlantState(before), timeMs: beforeMs, count: 0, times: arrays.times, bits: arrays.bits, ints: arrays.ints };
    this.chunks.push(c);
    this.open = c;
    this.openTimes = c.times;
    this.openBits = c.bits;
    this.openInts = c.ints;
    this.openCount = 0;
    if (this.chunks.length === 1) this.oldestCount = 0;
    return c;
  }

  private dropOldest(): void {
    while (this.total - this.countOf(this.chunks[0]!) >= this.keep) {
      const dropped = this.chunks.shift()!;
      this.total -= dropped.count;
      if (dropped.times.length === this.chunk) this.spare = dropped;
    }
    this.oldestCount = this.countOf(this.chunks[0]!);
  }

  /** Scans in a chunk (the open one's count is the history's). */
  private countOf(c: Chunk): number {
    return c === this.open ? this.openCount : c.count;
  }

  /** The oldest scan kept, if any. */
  get firstScan(): number | undefined {
    return this.chunks[0]?.firstScan;
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
    let time = c.timeMs;
    // One drive record and one fault set refilled for every step (valid only during the call, as in the loop).
    const drive: Record<string, Value> = {};
    const faults = new Set<string>();
    for (let i = 0; i <= last; i++) {
      // Outputs, operator controls and faults change seldom: the records are refilled only when they do.
      if (i === 0 || !this.sameRecord(c, i - 1, i)) this.fill(c, i, drive, faults);
      const t = c.times[i]!;
      const next = this.model.step(state, drive, Math.max(0, t - time), faults, spare);
      spare = state;
      state = next;
      time = t;
    }
    const operator: Record<string, boolean> = {};
    for (const p of this.operators) operator[p.name] = drive[p.name] === true;
    const shown: Record<string, Value> = {};
    for (const p of this.actuators) shown[p.name] = drive[p.name]!;
    return { scan, timeMs: time, state: copyPlantState(state), faults: [...faults].sort(), operator, drive: shown };
  }

  private chunkOf(scan: number): Chunk | undefined {
    let lo = 0;
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

  /** Scans `i` and `j` of chunk `c` were given the same drive and faults. */
  private sameRecord(c: Chunk, i: number, j: number): boolean {
    const words = this.words;
    for (let w = 0; w < words; w++) if (c.bits[i * words + w] !== c.bits[j * words + w]) return false;
    const n = this.intCount;
    for (let k = 0; k < n; k++) if (!Object.is(c.ints[i * n + k], c.ints[j * n + k])) return false;
    return true;
  }

  /** Scan `i` of chunk `c`: its drive and faults into the records given. */
  private fill(c: Chunk, i: number, drive: Record<string, Value>, faults: Set<string>): void {
    const w = i * this.words;
    const bits = c.bits;
    for (const s of this.boolDrive) drive[s.name] = (bits[w + (s.bit >>> 5)]! & (1 << (s.bit & 31))) !== 0;
    const n = this.intDrive.length;
    for (let k = 0; k < n; k++) drive[this.intDrive[k]!] = c.ints[i * n + k]!;
    faults.clear();
    for (const s of this.faultBits) if ((bits[w + (s.bit >>> 5)]! & (1 << (s.bit & 31))) !== 0) faults.add(s.name);
  }
}
