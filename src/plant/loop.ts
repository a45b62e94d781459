// A machine in closed loop with a program (issue 26): after every scan the machine reads the
// program's output image, advances by the PLC time since its last step, and presents its sensors
// and operator controls as the input image the next scan reads. The loop also keeps each scan's
// machine state (the scan history shows the machine as it was) and the consequences, located.
//
// It knows the PLC only as an I/O image by address (the `PlcIo` below), so the simulator, the
// scenarios, the CLI and the gateway's simulated device drive it alike.
import type { Value } from '../model/iecTypes';
import { parseLocation } from '../model/iecTypes';
import type { PlantConsequence, PlantModel, PlantPoint } from './types';
import { resolvePlantName } from './values';
import { PlantHistory } from './history';
import { copyPlantState, senseRecord } from './points';

/** What the loop needs of a PLC: its output image and its input image, by address. */
export interface PlcIo {
  outputs(): Record<string, Value>;
  setInputs(values: Readonly<Record<string, Value>>): void;
  /** The image itself, by index (the engine's Plc.ioImage): read and written every scan without a lookup or a call per point. */
  ioImage?(): PlcImage;
}

/** A PLC's input and output images by index, as the engine's Plc.ioImage gives them (this layer does not import the engine). */
export interface PlcImage {
  readonly inputs: readonly Value[];
  readonly outputs: readonly Value[];
  /** Index of the input / output declared at a location, -1 when none. */
  input(location: string): number;
  output(location: string): number;
  /** Writes an input as the engine does (converted, counted, applied at the next input read). */
  write(index: number, value: Value): void;
  /** Counted up by every write of the input image, whoever writes (the engine's IoImage.inputWrites); without it the machine presents its inputs every scan. */
  readonly inputWrites?: Uint32Array;
}

/**
 * The PLC's I/O image as the loop reads and writes it every scan: arrays by index (the engine's
 * own), or, for a PLC without them, the loop's copies of its points (`refresh` reads them again
 * before a step, `write` sets the PLC's input by address).
 */
interface LoopImage {
  readonly inputs: readonly Value[];
  readonly outputs: readonly Value[];
  write(index: number, value: Value): void;
  refresh(): void;
  /** PlcImage.inputWrites, when the image has it. */
  readonly writes?: Uint32Array;
}

/**
 * A machine point wired to the PLC, resolved once per program (bind): its index in the image, and
 * what the scan needs of the point without looking it up (its name, BOOL or not, operator control
 * or sensor slot).
 */
interface Wire {
  readonly point: PlantPoint;
  readonly name: string;
  readonly bool: boolean;
  readonly operator: boolean;
  /** A sensor's slot in what `sense` writes (the loop's `sensed`), -1 for another point. */
  readonly slot: number;
  /** The point's index in the image's inputs (sensors, operator controls) or outputs (actuators). */
  readonly index: number;
  /**
   * Where the point's value is in the step's history record (the loop's own copy of the drive): a
   * BOOL actuator's or an operator control's bit, an INT actuator's number.
   */
  readonly bit: number;
  readonly int: number;
}
const NO_REFRESH = (): void => {};
/** A step is compared with the state it started from (at rest?) every this many scans. */
const REST_CHECK = 16;

/** A consequence where it happened: the scan after which the machine was seen to suffer it. */
export interface PlantEvent extends PlantConsequence {
  readonly scan: number;
  readonly timeMs: number;
  /** "the tank overflowed at scan 1,204 (12.04 s)". */
  readonly text: string;
}

/** Point name -> address, for the points whose address the user changed. */
export type PlantMap = Readonly<Record<string, string>>;

/** `%ix0.0` and `%IX0.0` alike. */
export function addressKey(text: string): string {
  const loc = parseLocation(text.trim());
  return loc
    ? `%${loc.area}${loc.size}${loc.index}${loc.bit !== undefined ? `.${loc.bit}` : ''}`
    : text.trim().toUpperCase();
}

/** The machine's points at their addresses (the defaults, with the user's changes). */
export function mappedPoints(model: PlantModel, map: PlantMap = {}): PlantPoint[] {
  return model.points.map((p) => (map[p.name] ? { ...p, address: map[p.name]! } : p));
}

/** Why an address cannot carry a point (its area or size does not fit), or undefined. */
export function addressProblem(point: PlantPoint, address: string): string | undefined {
  const loc = parseLocation(address.trim());
  if (!loc) return `${point.name}: "${address}" is not an IEC address (%IX0.0, %IW2, %QX1.3)`;
  const wantArea = point.kind === 'actuator' ? 'Q' : 'I';
  if (loc.area !== wantArea)
    return `${point.name}: ${point.kind === 'actuator' ? 'an actuator is a %Q output' : 'a sensor or operator control is a %I input'}, not ${address}`;
  const wantSize = point.type === 'BOOL' ? 'X' : 'W';
  if ((loc.size || 'X') !== wantSize)
    return `${point.name}: ${point.type === 'INT' ? 'an' : 'a'} ${point.type} point needs a %${wantArea}${wantSize} address, not ${address}`;
  return undefined;
}

const NONE: PlantEvent[] = [];
const formatTime = (ms: number): string => `${(ms / 1000).toFixed(2)} s`;

export interface PlantSnapshot {
  readonly scan: number;
  readonly timeMs: number;
  readonly state: unknown;
  readonly faults: readonly string[];
  readonly operator: Readonly<Record<string, boolean>>;
  /** Each actuator as the machine was driven in the step that ended here (absent for the initial state). */
  readonly drive?: Readonly<Record<string, Value>>;
}

export class PlantLoop {
  readonly model: PlantModel;
  readonly points: readonly PlantPoint[];
  /**
   * The machine now, and the other of the two state objects the loop steps between (each step
   * writes the next state into the one not current): no state is made per scan. Whatever is
   * handed out (snapshot, currentState) or kept (the history's keyframes) is a copy.
   */
  private state: unknown;
  private spare: unknown;
  /** What `sense` wrote last: the sensors by slot (sensorSlots), reused every scan. */
  private readonly sensed: Value[];
  /** Each point's sensor slot by name (sensors only). */
  private readonly sensorSlot = new Map<string, number>();
  /** PLC time the machine has reached. */
  private timeMs = 0;
  private scan = 0;
  private readonly faults = new Set<string>();
  private readonly operator: Record<string, boolean> = {};
  /** Sorted faults and a copy of the operator controls, made anew only when they change (shared by snapshots). */
  private faultList: readonly string[] = [];
  private operatorShown: Readonly<Record<string, boolean>> = {};
  private readonly events: PlantEvent[] = [];
  /** The machine after each recorded scan (the latest `keep` at least), compact: replayed from keyframes. */
  private readonly history: PlantHistory;
  private readonly actuators: PlantPoint[];
  private readonly inputs: PlantPoint[];
  /** The points the program declares: actuators to read, sensors and operator controls to write. */
  private outputs: Wire[] = [];
  private declared: Wire[] = [];
  /**
   * The same wiring as code (`compileDrive`, `compilePresent`): straight-line reads and writes of
   * the image at the wired points' indices, no loop over points and no object per point.
   */
  private sensing = false;
  private driveCode: DriveCode = () => false;
  private presentCode: PresentCode = () => {};
  private bound: PlcIo | undefined;
  private image: LoopImage = { inputs: [], outputs: [], write: () => {}, refresh: NO_REFRESH };
  /** The image's `refresh`, undefined for the engine's own arrays (nothing to read again). */
  private refresh: (() => void) | undefined;
  /**
   * The machine is at rest: its last step, given `restDtMs` of time and the drive and faults it
   * has now, left every field of its state as it was (`sameState`). The model is deterministic
   * (docs/PLANTS.md), so the next step with the same drive, faults and time would give that state
   * again: the loop does not make it, nor check or sense it (same state, same sensors, nothing
   * started). Any change of drive, operator control, fault, time or wiring ends the rest.
   * Looked for every REST_CHECK scans (afterScan).
   */
  private rest = false;
  private restDtMs = -1;
  /** Every field of two states alike (Object.is; an array or record in a state by identity), compiled at bind. */
  private sameState: (a: unknown, b: unknown) => boolean = () => false;
  /** The image's count of input writes, and the count after the machine last presented its inputs (-1: not yet). */
  private writes: Uint32Array | undefined;
  private presented = -1;
  /** The image's arrays (kept here: read every scan). */
  private inputImage: readonly Value[] = [];
  private outputImage: readonly Value[] = [];
  /** The record's arrays (kept here: read every scan). */
  private readonly bits: Uint32Array;
  private readonly ints: Float64Array;
  /**
   * Scans at rest the history has not been given yet (settle): how many, the first one, the PLC
   * time the machine had before it, and the record they were all given (a copy: the loop's own
   * record changes in place when the drive, an operator control or a fault does).
   */
  private pending = 0;
  private pendingFrom = 0;
  private pendingTime = 0;
  private readonly restRecord: { readonly bits: Uint32Array; readonly ints: Float64Array };
  /** The record changed since the history was last given it (a drive, operator control or fault). */
  private recordChanged = true;
  /** The drive record handed to step(), refilled every scan. */
  private readonly driveRecord: Record<string, Value> = {};
  /** The same as the history records it (src/plant/history.ts), faults included, kept up to date alongside. */
  private readonly record: { readonly bits: Uint32Array; readonly ints: Float64Array };

  constructor(
    model: PlantModel,
    map: PlantMap = {},
    keep = 100_000,
  ) {
    this.model = model;
    this.points = mappedPoints(model, map);
    for (const p of this.points) {
      const problem = addressProblem(p, p.address);
      if (problem) throw new Error(`${model.id}: ${problem}`);
    }
    // Two points on one wire: the machine would write two sensors into one input (or read one
    // output as two actuators), and the program's variable at the other's address is not wired.
    const at = new Map<string, PlantPoint>();
    for (const p of this.points) {
      const key = addressKey(p.address);
      const other = at.get(key);
      if (other) throw new Error(`${model.id}: ${other.name} and ${p.name} are both at ${addressKey(p.address)}; each point of the machine needs an address of its own`);
      at.set(key, p);
    }
    this.actuators = this.points.filter((p) => p.kind === 'actuator');
    this.inputs = this.points.filter((p) => p.kind !== 'actuator');
    for (const p of this.points) if (p.kind === 'operator') this.operator[p.name] = false;
    this.operatorShown = { ...this.operator };
    // Two objects made alike (one shape: the step's reads and writes stay monomorphic).
    this.state = model.initial();
    this.spare = model.initial();
    this.sensed = [];
    for (const p of this.points)
      if (p.kind === 'sensor') {
        this.sensorSlot.set(p.name, this.sensed.length);
        this.sensed.push(p.type === 'BOOL' ? false : 0);
      }
    this.history = new PlantHistory(model, this.points, keep);
    this.record = this.history.newRecord();
    this.restRecord = this.history.newRecord();
    this.bits = this.record.bits;
    this.ints = this.record.ints;
    this.driveConstants();
  }

  private wire(point: PlantPoint, index: number): Wire {
    return {
      point,
      name: point.name,
      bool: point.type === 'BOOL',
      operator: point.kind === 'operator',
      slot: this.sensorSlot.get(point.name) ?? -1,
      index,
      bit: this.history.bitOf(point.name),
      int: this.history.intOf(point.name),
    };
  }

  private setBit(bit: number, on: boolean): void {
    if (bit < 0) return;
    this.recordChanged = true;
    const bits = this.record.bits;
    if (on) bits[bit >>> 5]! |= 1 << (bit & 31);
    else bits[bit >>> 5]! &= ~(1 << (bit & 31));
  }

  /**
   * The drive record afresh: operator controls as held (set again when one changes) and every
   * actuator off; the scan then writes the wired actuators' changes (drive()).
   */
  private driveConstants(): void {
    this.recordChanged = true;
    const d = this.driveRecord;
    for (const p of this.inputs)
      if (p.kind === 'operator') {
        d[p.name] = this.operator[p.name] === true;
        this.setBit(this.history.bitOf(p.name), this.operator[p.name] === true);
      }
    // Every actuator off, until a wired one reads otherwise (the scan writes only changes).
    for (const p of this.actuators) {
      d[p.name] = p.type === 'BOOL' ? false : 0;
      this.setBit(this.history.bitOf(p.name), false);
      const i = this.history.intOf(p.name);
      if (i >= 0) this.record.ints[i] = 0;
    }
  }

  /** Back to the machine's initial state at PLC time 0 (a cold restart); faults and operator controls stay. */
  reset(): void {
    this.rest = false;
    this.pending = 0;
    this.state = this.model.initial();
    this.spare = this.model.initial();
    this.timeMs = 0;
    this.scan = 0;
    this.events.length = 0;
    this.history.clear();
  }

  /**
   * The machine of `before`, the same model wired otherwise (a point rewired while the program
   * runs), goes on in this loop, not yet bound: its state, PLC time and scan, faults, operator
   * controls and consequences. Moving a terminal does not refill the tank or lower the door. The
   * scans recorded before are `before`'s history, not this one's.
   */
  continueFrom(before: PlantLoop): void {
    if (before.model !== this.model) return;
    // Field by field into this loop's own object (one shape); a state's arrays are never changed, so sharing them is safe.
    Object.assign(this.state as object, before.state as object);
    this.timeMs = before.timeMs;
    this.scan = before.scan;
    this.events.push(...before.events);
    for (const f of before.faults) this.setFault(f, true);
    for (const [name, held] of Object.entries(before.operator)) if (held) this.setOperator(name, true);
  }

  /**
   * The machine is taken away (None chosen, or another machine or wiring): the inputs it drove
   * fall to FALSE / 0, as wires that are cut, instead of keeping the machine's last values (a
   * limit switch left ON with nothing behind it). A forced input keeps its force. No-op unbound.
   */
  release(): void {
    const image = this.image;
    image.refresh();
    for (const w of this.declared)
      if (image.inputs[w.index] !== (w.bool ? false : 0)) image.write(w.index, w.bool ? false : 0);
    this.declared = [];
    this.outputs = [];
    this.flatten();
    this.bound = undefined;
  }

  /**
   * Attaches a (new) PLC: which of the machine's points its program declares. Points it does not
   * declare are simply not wired. The PLC gets the machine's inputs now, for its next scan.
   */
  bind(plc: PlcIo): void {
    this.bound = plc;
    const image = plc.ioImage ? engineImage(plc.ioImage()) : recordImage(plc, this.inputs);
    this.image = image.image;
    this.outputs = this.actuators.flatMap((p) => {
      const i = image.output(p.address);
      return i < 0 ? [] : [this.wire(p, i)];
    });
    this.declared = this.inputs.flatMap((p) => {
      const i = image.input(p.address);
      return i < 0 ? [] : [this.wire(p, i)];
    });
    this.flatten();
    this.driveConstants();
    // The wired actuators as the output image has them now (a frame before the next scan shows them).
    this.drive();
    this.present();
  }

  private flatten(): void {
    const sensors = this.declared.filter((w) => !w.operator);
    this.sensing = sensors.length > 0;
    this.rest = false;
    this.refresh = this.image.refresh === NO_REFRESH ? undefined : this.image.refresh;
    this.sameState = compileSameState(this.state);
    this.inputImage = this.image.inputs;
    this.outputImage = this.image.outputs;
    this.writes = this.image.writes;
    this.presented = -1;
    this.driveCode = compileDrive(this.outputs);
    this.presentCode = compilePresent(
      sensors,
      this.declared.filter((w) => w.operator),
    );
  }

  /** The program's scan `scan` ended; `scanTimeMs` is when it started, `cycleMs` the scan cycle. */
  afterScan(scan: number, scanTimeMs: number, cycleMs: number): readonly PlantEvent[] {
    const target = scanTimeMs + cycleMs;
    // A machine that has not stepped yet starts at this scan's PLC time: attached to a program
    // already at scan 24 (2.4 s), its first step is one cycle, not 2.5 s at once.
    if (this.scan === 0) this.timeMs = scanTimeMs;
    const dt = target > this.timeMs ? target - this.timeMs : 0;
    const before = this.state;
    this.refresh?.();
    const changed = this.driveCode(this.outputImage, this.bits, this.ints, this.driveRecord);
    const same = !(changed || this.recordChanged);
    this.recordChanged = false;
    if (this.rest && same && dt === this.restDtMs && scan === this.scan + 1 && target === this.timeMs + dt) {
      // At rest, the next scan, its time the last one's plus the same step: the history is told of
      // such scans in one go when something changes or it is asked (settle): the same state,
      // record and step each time, its times worked out by the very additions made here.
      if (this.pending === 0) {
        this.pendingFrom = scan;
        this.pendingTime = this.timeMs;
        this.restRecord.bits.set(this.record.bits);
        this.restRecord.ints.set(this.record.ints);
      }
      this.pending++;
      return this.restedAt(scan, target);
    }
    if (this.pending > 0) this.settle();
    // What the step is given, for the history to replay it (the model is deterministic); the
    // history copies `before` when it keeps it whole.
    this.history.push(scan, before, this.timeMs, this.record, target, same);
    if (this.rest && !changed && dt === this.restDtMs) {
      // At rest, a scan the history was given at once (another step, or not right after the last scan).
      return this.restedAt(scan, target);
    }
    // Into the spare state object: `before` is the spare one for the next step.
    const after = this.model.step(before, this.driveRecord, dt, this.faults, this.spare);
    // Whether this step found the machine at rest, looked at every REST_CHECK scans only: the
    // comparison costs a moving machine more than the step it would save (a function and two
    // states' every field read); a machine that stops is at rest a few scans later.
    this.rest = scan % REST_CHECK === 0 && this.sameState(before, after);
    this.restDtMs = dt;
    this.state = after;
    this.spare = before;
    this.timeMs = target;
    this.scan = scan;
    const consequences = this.model.check(before, after);
    if (consequences.length === 0) {
      this.present();
      return NONE;
    }
    const found = consequences.map((c) => this.locate(c, scan, scanTimeMs));
    for (const e of found) this.events.push(e);
    this.present();
    return found;
  }

  /**
   * Scan `scan` at rest (see `rest`): the step would give this very state again, the same sensors
   * (the faults are the same too) and no consequence. The machine reaches the scan's time; its
   * inputs are written again where they differ (a wire drives its input whatever was written to it
   * meanwhile), which only someone else's write since it presented them can make so (the image's
   * count of writes is the one its own writes left: nothing to present again).
   */
  private restedAt(scan: number, target: number): readonly PlantEvent[] {
    this.timeMs = target;
    this.scan = scan;
    const writes = this.writes;
    if (writes === undefined || writes[0] !== this.presented) {
      this.presentCode(this.inputImage, this.sensed, this.bits, this.image);
      if (writes) this.presented = writes[0]!;
    }
    return NONE;
  }

  /**
   * The scans at rest not yet recorded go into the history: each given the rest's record and time
   * step, from the state the machine rests in (unchanged all the while), at the times the scans
   * reached (the same additions as in afterScan, so the same numbers).
   */
  private settle(): void {
    const n = this.pending;
    this.pending = 0;
    let t = this.pendingTime;
    for (let j = 0; j < n; j++) {
      const next = t + this.restDtMs;
      this.history.push(this.pendingFrom + j, this.state, t, this.restRecord, next, true);
      t = next;
    }
  }

  private locate(c: PlantConsequence, scan: number, timeMs: number): PlantEvent {
    return {
      ...c,
      scan,
      timeMs,
      text: `${c.message} at scan ${scan.toLocaleString('en-US')} (${formatTime(timeMs)})`,
    };
  }

  /** The drive record for a step: the wired actuators read from the output image (the rest is kept up to date). */
  private drive(): Record<string, Value> {
    this.image.refresh();
    if (this.driveCode(this.outputImage, this.bits, this.ints, this.driveRecord)) {
      this.rest = false;
      this.recordChanged = true;
    }
    return this.driveRecord;
  }

  /**
   * The machine's sensors and operator controls into the PLC's input image (for its next scan),
   * every scan: the machine drives those inputs as wires would (a forced input keeps its force).
   */
  present(): void {
    if (!this.bound) return;
    if (this.sensing) this.model.sense(this.state, this.faults, this.sensed);
    this.presentCode(this.inputImage, this.sensed, this.bits, this.image);
    if (this.writes) this.presented = this.writes[0]!;
  }

  snapshot(): PlantSnapshot {
    const drive: Record<string, Value> = {};
    if (this.scan > 0) for (const p of this.actuators) drive[p.name] = this.driveRecord[p.name]!;
    return {
      scan: this.scan,
      timeMs: this.timeMs,
      state: copyPlantState(this.state),
      faults: this.faultList,
      operator: this.operatorShown,
      ...(this.scan > 0 ? { drive } : {}),
    };
  }

  /** The machine as it was after scan `scan` (the initial state for 0), if still kept. */
  at(scan: number): PlantSnapshot | undefined {
    if (scan === 0) return { scan: 0, timeMs: 0, state: this.model.initial(), faults: [], operator: {} };
    if (this.pending > 0) this.settle();
    return this.history.at(scan);
  }

  /** The machine after each kept scan of [from, to] in turn (PlantHistory.walk: the snapshot is valid only during the call). */
  walk(from: number, to: number, fn: (snapshot: PlantSnapshot) => void): void {
    if (this.pending > 0) this.settle();
    this.history.walk(from, to, fn);
  }

  /** The operator controls held and the faults set in scan `scan`, if it is still kept (PlantHistory.controlsAt). */
  controlsAt(scan: number): { readonly operator: Record<string, boolean>; readonly faults: string[] } | undefined {
    if (this.pending > 0) this.settle();
    return this.history.controlsAt(scan);
  }

  setOperator(name: string, value: boolean): void {
    const p = this.points.find((q) => q.kind === 'operator' && q.name.toUpperCase() === name.toUpperCase());
    if (!p)
      throw new Error(
        `${this.model.id} has no operator control "${name}"; it has ${this.points
          .filter((q) => q.kind === 'operator')
          .map((q) => q.name)
          .join(', ')}`,
      );
    this.operator[p.name] = value;
    this.driveRecord[p.name] = value;
    this.rest = false;
    this.setBit(this.history.bitOf(p.name), value);
    this.operatorShown = { ...this.operator };
    this.present();
  }

  setFault(id: string, active: boolean): void {
    const f = this.model.faults.find((q) => q.id === id.toLowerCase());
    if (!f)
      throw new Error(
        `${this.model.id} has no fault "${id}"; it has ${this.model.faults.map((q) => q.id).join(', ')}`,
      );
    if (active) this.faults.add(f.id);
    else this.faults.delete(f.id);
    this.rest = false;
    this.setBit(this.history.faultBitOf(f.id), active);
    this.faultList = [...this.faults].sort();
    this.present();
  }

  activeFaults(): string[] {
    return [...this.faults].sort();
  }

  consequences(): readonly PlantEvent[] {
    return this.events;
  }

  /** The machine's state now (a copy: the loop's own objects change every step). */
  currentState(): unknown {
    return copyPlantState(this.state);
  }

  /**
   * `level` or `tank.level`: a quantity, or a point (a sensor as sensed, an actuator as driven, an
   * operator control as held); spelt exactly, `tank.Pump` is the contactor, `tank.pump` the speed.
   */
  read(name: string): Value {
    const bare = name.toLowerCase().startsWith(`${this.model.id}.`)
      ? name.slice(this.model.id.length + 1)
      : name;
    const ref = resolvePlantName(this.model, bare);
    if (ref?.quantity) return this.model.quantity(this.state, ref.quantity.name);
    const p = ref?.point;
    if (p?.kind === 'operator') return this.operator[p.name] === true;
    if (p?.kind === 'sensor') return senseRecord(this.model, this.state, this.faults)[p.name]!;
    if (p) return { ...this.drive() }[p.name]!;
    throw new Error(
      `${this.model.id} has no quantity or point "${bare}"; it has ${[...this.model.quantities.map((x) => x.name), ...this.points.map((x) => x.name)].join(', ')}`,
    );
  }
}

/** The type `tank.level` (or `level`) reads as: a quantity's, or a point's; undefined when the machine has no such name. */
export function plantValueType(model: PlantModel, name: string): 'BOOL' | 'INT' | 'REAL' | undefined {
  const bare = name.toLowerCase().startsWith(`${model.id}.`) ? name.slice(model.id.length + 1) : name;
  const ref = resolvePlantName(model, bare);
  return ref?.quantity?.type ?? ref?.point?.type;
}

/** How a PLC's image is reached: by index into its arrays. */
interface BoundImage {
  readonly image: LoopImage;
  input(address: string): number;
  output(address: string): number;
}

/** The engine's own image (Plc.ioImage): its arrays, read in place. */
function engineImage(io: PlcImage): BoundImage {
  return {
    image: { inputs: io.inputs, outputs: io.outputs, write: io.write.bind(io), refresh: NO_REFRESH, ...(io.inputWrites ? { writes: io.inputWrites } : {}) },
    input: (address) => io.input(address),
    output: (address) => io.output(address),
  };
}

/**
 * A PLC known only by its output and input records (the gateway's simulated device): the loop's
 * copies, the outputs read again before every step, an input read back as last written (a sensor
 * turning OFF is written too).
 */
function recordImage(plc: PlcIo, inputPoints: readonly PlantPoint[]): BoundImage {
  const outputs: Value[] = [];
  const outputKeys: string[] = [];
  const inputs: Value[] = [];
  const inputAddresses: string[] = [];
  // Only the loop writes its copies of the inputs.
  const writes = new Uint32Array(1);
  const image: LoopImage = {
    inputs,
    outputs,
    writes,
    write: (i, v) => {
      plc.setInputs({ [inputAddresses[i]!]: v });
      inputs[i] = v;
      writes[0]!++;
    },
    refresh: () => {
      if (outputKeys.length === 0) return;
      const now = plc.outputs();
      for (let i = 0; i < outputKeys.length; i++) outputs[i] = now[outputKeys[i]!]!;
    },
  };
  return {
    image,
    output: (address) => {
      const key = Object.keys(plc.outputs()).find((k) => addressKey(k) === addressKey(address));
      if (key === undefined) return -1;
      outputKeys.push(key);
      outputs.push(plc.outputs()[key]!);
      return outputs.length - 1;
    },
    input: (address) => {
      const p = inputPoints.find((q) => q.address === address);
      const zero: Value = p?.type === 'BOOL' ? false : 0;
      try {
        plc.setInputs({ [address]: zero });
      } catch {
        return -1;
      }
      inputAddresses.push(address);
      inputs.push(zero);
      return inputs.length - 1;
    },
  };
}

/** Returns whether a wired actuator changed. */
type DriveCode = (values: readonly Value[], bits: Uint32Array, ints: Float64Array, drive: Record<string, Value>) => boolean;
type PresentCode = (inputs: readonly Value[], sensed: readonly Value[], bits: Uint32Array, image: LoopImage) => void;

/**
 * The drive for one wiring as straight-line code (as the engine compiles a program, and where it
 * runs: the simulator's and the scenarios' workers, the CLI, the gateway; the page's CSP allows
 * `new Function` in workers only, src/gateway/staticFiles.ts). Each wired
 * actuator read from its place in the output image; a change goes into the history's record and,
 * by name, into the drive record. BOOL points TRUE or FALSE exactly, INT points numbers.
 */
function compileDrive(outs: readonly Wire[]): DriveCode {
  const body = outs.map((w) => {
    const name = JSON.stringify(w.name);
    if (w.bool) {
      const word = w.bit >>> 5;
      const mask = (1 << (w.bit & 31)) >>> 0;
      return `on = O[${w.index}] === true; if (on !== ((B[${word}] & ${mask}) !== 0)) { B[${word}] ^= ${mask}; D[${name}] = on; c = true; }`;
    }
    return `n = Number(O[${w.index}]); if (!Object.is(n, N[${w.int}])) { N[${w.int}] = n; D[${name}] = n; c = true; }`;
  });
  return compiled<DriveCode>(['O', 'B', 'N', 'D'], `"use strict"; let on, n, c = false;\n${body.join('\n')}\nreturn c;`);
}

/**
 * Whether two states of a machine are alike in every field, as straight-line code for the
 * machine's fields (those of `state`, made by `initial()`: every state has them): numbers and
 * booleans by Object.is (NaN alike, 0 and -0 not), strings by value, arrays and records by
 * identity (a state's are never changed once made: the same one is the same content; a step that
 * makes a new one, even alike, is simply never at rest).
 */
function compileSameState(state: unknown): (a: unknown, b: unknown) => boolean {
  const keys = Object.keys(state as object);
  const body = keys.map((k) => `Object.is(a[${JSON.stringify(k)}], b[${JSON.stringify(k)}])`).join(' &&\n');
  return compiled<(a: unknown, b: unknown) => boolean>(['a', 'b'], `"use strict"; return ${body || 'true'};`);
}

/**
 * Presenting for one wiring as straight-line code: each sensor as sensed (its slot), each operator
 * control as held (its bit in the record), written into the input image only where it differs.
 */
function compilePresent(sensors: readonly Wire[], operators: readonly Wire[]): PresentCode {
  const body = [
    ...sensors.map((w) => `v = S[${w.slot}]; if (I[${w.index}] !== v) M.write(${w.index}, v);`),
    ...operators.map(
      (w) =>
        `v = (B[${w.bit >>> 5}] & ${(1 << (w.bit & 31)) >>> 0}) !== 0; if (I[${w.index}] !== v) M.write(${w.index}, v);`,
    ),
  ];
  return compiled<PresentCode>(['I', 'S', 'B', 'M'], `"use strict"; let v;\n${body.join('\n')}`);
}

/**
 * The functions compiled so far, by their text: the same wiring bound again (a program loaded
 * again, an online change that keeps the I/O, a second loop on the same program) gets the same
 * function, so the loop's calls of it stay monomorphic (a new function per bind makes them
 * polymorphic, then megamorphic: not inlined, slower every scan). A few per machine and wiring.
 */
const COMPILED = new Map<string, unknown>();
/** Kept at most (a session that rewires again and again starts over past it). */
const COMPILED_MAX = 256;
function compiled<F>(params: readonly string[], body: string): F {
  const key = `${params.join(',')}\n${body}`;
  let fn = COMPILED.get(key);
  if (!fn) {
    if (COMPILED.size >= COMPILED_MAX) COMPILED.clear();
    fn = new Function(...params, body);
    COMPILED.set(key, fn);
  }
  return fn as F;
}
