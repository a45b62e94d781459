// The scan cycle (LD-SEMANTICS.md section 7): input image -> networks (jumps, returns) -> output
// image, on a virtual clock (scan k starts at (k-1) x cycleMs) or an injected real clock, with a
// watchdog, forcing, cold/warm restart, stepping one network at a time and power snapshots. A
// configuration whose tasks run at different intervals or on events runs, each scan (one common
// tick), only the programs whose task is due (TaskSchedule; an event task's trigger is sampled after
// the input image, before any program).
import type { Value } from '../../model/iecTypes';
import type {
  Fault,
  InstanceInfo,
  NetworkPower,
  Plc,
  PlcOptions,
  PlcProbe,
  PlcState,
  PowerSnapshot,
  ScanReport,
  TaskSchedule,
  SnapshotOptions,
  StateItem,
  StateTransfer,
  StepFrame,
  StepReport,
} from '../api';
import type { BodyInfo } from '../compile/flatten';
import type { FnContext } from '../library/fnTypes';
import { isStraight, slotKey } from '../compile/codegen';
import { DISPATCH_PARAMS, planDispatch, type DispatchFn, type DispatchPlan } from '../compile/dispatch';
import type { SegmentFn } from '../compile/segments';
import { generateSegment, planSegments } from '../compile/segments';
import { networkPower, type PowerTrace } from './snapshot';
import { DEFAULT_TIERING, Tiering, type TieringOptions } from './tiering';
import type { CompiledProgram } from '../compile/program';
import { programOf } from '../compile/taskSchedule';
import type { Access, VarSymbol } from '../compile/symbols';
import { coerce, Memory } from './memory';
import { exportMemory, importMemory, stateItemsOf } from './instanceState';
import { imageBytes, restoreMemory, saveMemory, type MachineImage } from './machineImage';
import { programRates, type ProgramRates } from './programRates';

type Image = MachineImage<Value, readonly [VarSymbol, Value]>;

/** Networks run per call of a dispatch function before the scan time is checked (watchdog). */
const CHUNK = 1024;

/** Thrown out of a call's body when the watchdog trips there; caught where the scan runs. */
class WatchdogTrip {
  constructor(readonly network: number) {}
}

// Wall clock for the watchdog and execMs (the engine core has no DOM or Node typings).
const perf = (globalThis as { performance?: { now(): number } }).performance;
const now: () => number = perf ? () => perf.now() : () => Date.now();

export class ScanPlc implements Plc {
  readonly pou: string;
  readonly profile: CompiledProgram['profile'];
  private readonly mem: Memory;
  private readonly plan: DispatchPlan;
  /**
   * The dispatch functions (compile/dispatch.ts) and the one holding each network's shape; `groups`
   * stop before segments switched to straight-line code, `stepGroups` (stepping) never do.
   */
  private readonly groups: DispatchFn[];
  private readonly stepGroups: DispatchFn[];
  private readonly groupOf: Int32Array;
  private readonly tiering: Tiering;
  /** Written by the dispatch functions: the last network run by the last call. */
  private readonly stats = new Int32Array(1);
  /** Power-flow nets of every network, packed (see codegen NETS_PER_WORD), and each network's first word. */
  private readonly power: Int32Array;
  private readonly words: Int32Array;
  /** Scan number in which each network last ran. */
  private readonly ranIn: Int32Array;
  private readonly ctx: FnContext = { error: false };
  private readonly inputs: VarSymbol[];
  private readonly inputImage: Value[];
  private readonly outputsVars: VarSymbol[];
  private readonly outputImage: Value[];
  private readonly forces = new Map<VarSymbol, Value>();
  private readonly maxEvals: number;
  private readonly maxScanMs: number;
  private count = 0;
  private time = 0;
  private cursor = -1;
  private evals = 0;
  /** Network whose jump last went backwards in this scan (named by the watchdog). */
  private backJump = -1;
  /** Where the programs' networks end, and the end of the program holding each of them. */
  private readonly mainEnd: number;
  private readonly programEnd: Int32Array;
  readonly schedule: TaskSchedule | undefined;
  /** Several rates or event tasks: which programs run in this scan (programRates). */
  private readonly rates: ProgramRates | undefined;
  /** Virtual clock step, ms. */
  private readonly cycleMs: number;
  /** What the generated code calls to run a body of networks (`X.call(first, end, now, scan)`). */
  private readonly exec = {
    call: (first: number, end: number, t: number, scan: number): void => this.callBody(first, end, t, scan),
    stepCall: (first: number, end: number, t: number, scan: number): Generator<void, void> =>
      this.stepRange(first, end, t, scan),
    /** openplc: the units [first, end) a body's first network (early) or last network (late) runs (compile/codegen.ts bodyUnits), on the dispatch loops. */
    late: (first: number, end: number, t: number, scan: number): void => {
      for (let u = first; u < end; ) u = this.groups[this.groupOf[u]!]!(u, end, t, scan);
    },
    stepLate: (first: number, end: number, t: number, scan: number): Generator<void, void> =>
      this.stepLate(first, end, t, scan),
    /**
     * An array index chosen at run time (ST `A[i]`): i - lower, or a fault (LD-E62) when i is
     * outside lower..upper. MATIEC's C does not check: it reads or writes memory outside the array.
     */
    ix: (network: number, line: number, value: number | bigint, lower: number, upper: number, what: string): number => {
      const i = Number(value);
      if (i >= lower && i <= upper) return i - lower;
      this.runtimeFault = `LD-E62 line ${line}: the index ${i} of ${what} is outside ${lower}..${upper}; the scan stops here (MATIEC does not check array bounds: its compiled C would read or write memory outside the array, or crash)`;
      throw new WatchdogTrip(network);
    },
    /** The slot a write through a variable index goes to: the spare slot while that element is forced. */
    ws: (store: 'b' | 'n' | 'g', slot: number): number => (this.forcedSlots.has(`${store}:${slot}`) ? this.mem.sink[store] : slot),
    /** Asked every 65,536 iterations of an ST/IL loop (or backward IL jump) in network `network`, at `line`. */
    loop: (network: number, line: number): void => {
      if (now() - this.scanStart <= this.maxScanMs) return;
      this.backJump = network;
      this.loopLine = line;
      throw new WatchdogTrip(network);
    },
  };
  /** Line of the ST/IL loop that tripped the watchdog (0: none). */
  private loopLine = 0;
  /** Message of a runtime fault (an array index out of bounds) being thrown out of the scan. */
  private runtimeFault: string | undefined;
  /** `store:slot` of every forced variable (writes through variable indexes check it). */
  private readonly forcedSlots = new Set<string>();
  private scanStart = 0;
  private lastExecMs = 0;
  private clockOrigin = 0;
  private currentFault: Fault | undefined;
  /** PlcProbe.meters: [0] input image written at a boundary, [1] any other change from outside, [2] last scan's execution ms. */
  private readonly meters = new Float64Array(3);
  /** The time of a scan being replayed (PlcProbe.replay), instead of the clock's. */
  private replayAt: number | undefined;

  constructor(
    private readonly program: CompiledProgram,
    private readonly opts: PlcOptions,
    tiering: TieringOptions = DEFAULT_TIERING,
  ) {
    this.pou = program.pou;
    this.profile = program.profile;
    this.mem = new Memory(program);
    const plan = planDispatch(
      program.networks,
      program.functions,
      program.symbols.fbs.map((f) => f.type),
    );
    this.plan = plan;
    this.words = plan.words;
    this.power = new Int32Array(Math.max(1, plan.wordCount));
    this.ranIn = new Int32Array(program.networks.length).fill(-1);
    this.groupOf = plan.groupOf;
    const vars = program.symbols.vars;
    this.inputs = vars.filter((v) => v.location?.area === 'I');
    this.inputImage = this.inputs.map((v) => v.initial);
    this.outputsVars = vars.filter((v) => v.location?.area === 'Q');
    this.outputImage = this.outputsVars.map((v) => v.initial);
    this.maxEvals = opts.maxNetworkEvaluations ?? 100 * program.networks.length + 10_000;
    this.mainEnd = program.mainEnd;
    this.programEnd = new Int32Array(program.mainEnd);
    for (let b = 0; b < program.programs; b++) {
      const body = program.bodies[b]!;
      this.programEnd.fill(body.end, body.first, body.end);
    }
    this.maxScanMs = opts.maxScanMs ?? 1000;
    this.schedule = program.schedule;
    this.rates = programRates(program);
    this.cycleMs = program.schedule?.multiRate ? program.schedule.tickMs : opts.cycleMs;
    const m = this.mem;
    const link = (body: string, constants: unknown, shape: Int32Array) =>
      (new Function(...DISPATCH_PARAMS, body) as (...args: unknown[]) => unknown)(
        m.b,
        m.n,
        m.g,
        m.fbs,
        program.functions,
        m.edges,
        this.power,
        constants,
        this.ctx,
        this.ranIn,
        this.stats,
        plan.P,
        plan.V,
        plan.base,
        shape,
        this.exec,
      );
    const liveShape = plan.shape.slice();
    this.groups = plan.bodies.map((body) => link(body, plan.constants, liveShape) as DispatchFn);
    this.stepGroups = plan.bodies.map((body) => link(body, plan.constants, plan.shape) as DispatchFn);
    const fbTypes = program.symbols.fbs.map((f) => f.type);
    const build = (first: number, end: number): SegmentFn => {
      const forced = new Set([...this.forces.keys()].map((v) => slotKey(v.store, v.slot)));
      const mode = { kind: 'inline', forced, sink: m.sink } as const;
      const seg = generateSegment(program.networks, first, end, program.functions, fbTypes, plan.words, mode);
      return link(seg.body, seg.constants, plan.shape) as SegmentFn;
    };
    const starts = planSegments(program.networks, program.bodies.map((b) => b.first));
    // Bodies without jumps or RETURN are written in place of their calls: never dispatched.
    const dispatched = new Uint8Array(program.networks.length);
    program.bodies.forEach((b, k) => {
      if (k < program.programs || !isStraight(program.networks, b.first, b.end)) dispatched.fill(1, b.first, b.end);
    });
    this.tiering = new Tiering(starts, liveShape, plan.shape, plan.shapeCount, build, now, tiering, (first) => dispatched[first] === 1);
    this.coldRestart();
  }

  get scanCount(): number {
    return this.count;
  }
  get timeMs(): number {
    return this.time;
  }
  get fault(): Fault | undefined {
    return this.currentFault;
  }
  get nextNetwork(): number {
    return this.cursor >= 0 ? this.cursor : -1;
  }

  // ---- scan cycle ----

  private startScan(): void {
    this.count++;
    this.time = this.replayAt !== undefined
      ? this.replayAt
      : this.opts.clock
      ? this.opts.clock.now() - this.clockOrigin
      : (this.count - 1) * this.cycleMs;
    this.scanStart = now();
    // 1. Input image: inputs do not change during the scan; forced inputs keep their forced value.
    for (let i = 0; i < this.inputs.length; i++) {
      const v = this.inputs[i]!;
      if (!this.forces.has(v)) this.mem.store(v, this.inputImage[i]!);
    }
    if (this.rates) this.dueTasks(this.rates);
    this.cursor = this.dueFrom(0);
    this.evals = 0;
    this.backJump = -1;
  }

  private endScan(): void {
    // 3. Output image, in one operation.
    for (let i = 0; i < this.outputsVars.length; i++)
      this.outputImage[i] = this.mem.load(this.outputsVars[i]!);
    this.cursor = -1;
    this.lastExecMs = this.meters[2] = now() - this.scanStart;
    this.tiering.afterScan(this.evals);
  }

  /** Runs networks from the cursor; stops after one when `single`. Returns the network run last. */
  private run(single: boolean): number {
    const count = this.mainEnd;
    const groups = single ? this.stepGroups : this.groups;
    const fast = this.tiering.fast;
    const groupOf = this.groupOf;
    const programEnd = this.programEnd;
    const stats = this.stats;
    const scan = this.count;
    const t = this.time;
    const maxEvals = this.maxEvals;
    let checked = this.evals;
    let i = this.cursor;
    let last = -1;
    const rates = this.rates;
    try {
      while (i >= 0 && i < count) {
        // A program whose task is not due at this tick: on to the next program.
        if (rates && rates.startOf[i]! >= 0 && rates.due[rates.startOf[i]!] === 0) {
          i = programEnd[i]!;
          continue;
        }
        const end = programEnd[i]!;
        const segment = single ? undefined : fast[i];
        const next = segment
          ? segment(t, scan)
          : groups[groupOf[i]!]!(i, single ? i + 1 : Math.min(end, i + CHUNK, i + maxEvals - this.evals), t, scan);
        last = stats[0]!;
        this.ranIn.fill(scan, i, last + 1);
        const evals = (this.evals += last - i + 1);
        if (next <= last && next >= 0) this.backJump = last;
        if (evals >= maxEvals || (evals - checked >= CHUNK && now() - this.scanStart > this.maxScanMs)) {
          this.trip(last);
          return last;
        }
        if (evals - checked >= CHUNK) checked = evals;
        // RETURN (-1) ends this program; the next one starts where it ends.
        i = next < 0 ? end : next;
        if (single) break;
      }
    } catch (e) {
      if (!(e instanceof WatchdogTrip)) throw e;
      this.trip(e.network);
      return e.network;
    }
    this.cursor = i >= 0 && i < count ? this.dueFrom(i) : -2;
    return last;
  }

  /**
   * The tasks due at this tick, before any program runs (MATIEC's RES_run__: every task's flag,
   * then the programs): a cyclic task when the tick (0 for the first scan) is a multiple of its
   * `every`; an event task when its trigger rose since the last tick (R_TRIG: Q = CLK AND NOT M;
   * M = CLK, M FALSE after a restart, so a trigger already TRUE runs the task in the first scan).
   */
  private dueTasks(rates: ProgramRates): void {
    const tick = this.count - 1;
    for (let k = 0; k < rates.every.length; k++) {
      const trigger = rates.triggers[k];
      if (!trigger) {
        rates.taskDue[k] = tick % rates.every[k]! === 0 ? 1 : 0;
        continue;
      }
      const clk = this.mem.load(trigger.clk) === true;
      rates.taskDue[k] = clk && this.mem.load(trigger.m) !== true ? 1 : 0;
      this.mem.store(trigger.m, clk);
    }
    for (let p = 0; p < rates.due.length; p++) rates.due[p] = rates.taskDue[rates.taskOf[p]!]!;
  }

  /** The first network from `i` on that runs in this scan (skipping programs not due), -2 for none. */
  private dueFrom(i: number): number {
    const rates = this.rates;
    if (rates) while (i < this.mainEnd && rates.startOf[i]! >= 0 && rates.due[rates.startOf[i]!] === 0) i = this.programEnd[i]!;
    return i < this.mainEnd ? i : -2;
  }

  /** Runs the body [first, end) of a call, from the generated code; RETURN (-1) ends it. */
  private callBody(first: number, end: number, t: number, scan: number): void {
    const fast = this.tiering.fast;
    const groups = this.groups;
    const groupOf = this.groupOf;
    const stats = this.stats;
    const ranIn = this.ranIn;
    let i = first;
    while (i >= 0 && i < end) {
      const segment = fast[i];
      const next = segment !== undefined ? segment(t, scan) : groups[groupOf[i]!]!(i, end, t, scan);
      const last = stats[0]!;
      for (let k = i; k <= last; k++) ranIn[k] = scan;
      this.evals += last - i + 1;
      if (next >= 0 && next <= last) {
        this.backJump = last;
        if (now() - this.scanStart > this.maxScanMs) throw new WatchdogTrip(last);
      }
      if (this.evals >= this.maxEvals) throw new WatchdogTrip(last);
      i = next;
    }
  }

  /** Where a network is, as the user knows it: its POU, instance and 0-based index in the POU. */
  private where(network: number): { pou: string; instance?: string; network: number; label?: string } {
    const body = this.program.bodies[this.program.bodyOf[network]!]!;
    const label = this.program.networks[network]!.label;
    return {
      pou: body.pou,
      ...(body.instance ? { instance: body.instance } : {}),
      network: network - body.first,
      ...(label ? { label } : {}),
    };
  }

  private trip(at: number): void {
    if (this.runtimeFault !== undefined) {
      const w = this.where(at);
      this.stopWith('runtime', w, `${this.runtimeFault} in ${w.instance ? `${w.instance} (${w.pou})` : w.pou}`);
      this.runtimeFault = undefined;
      return;
    }
    const network = this.backJump >= 0 ? this.backJump : at;
    const w = this.where(network);
    const inBody = this.program.bodyOf[network]! >= this.program.programs || this.program.programs > 1;
    const place = this.loopLine > 0 ? `the loop at line ${this.loopLine}` : `network ${w.network + 1}${w.label ? ` (label ${w.label})` : ''}`;
    const owner = inBody || this.loopLine > 0 ? ` of ${w.instance ? `${w.instance} (${w.pou})` : w.pou}` : '';
    const where = `${place}${owner}`;
    this.loopLine = 0;
    const limit =
      this.evals >= this.maxEvals
        ? `${this.maxEvals.toLocaleString('en-US')} network evaluations`
        : `${this.maxScanMs} ms`;
    this.stopWith('watchdog', w, `watchdog: scan exceeded ${limit}; ${this.backJump >= 0 ? `looping in ${where}` : `stopped at ${where}`}`);
  }

  /** Ends the scan with a fault at `w`. */
  private stopWith(kind: Fault['kind'], w: ReturnType<ScanPlc['where']>, message: string): void {
    this.currentFault = {
      kind,
      pou: w.pou,
      ...(w.instance ? { instance: w.instance } : {}),
      network: w.network,
      ...(w.label ? { networkLabel: w.label } : {}),
      message,
    };
    this.cursor = -1;
    this.lastExecMs = now() - this.scanStart;
  }

  private report(): ScanReport {
    return {
      scan: this.count,
      timeMs: this.time,
      execMs: this.lastExecMs,
      ...(this.currentFault ? { fault: this.currentFault } : {}),
    };
  }

  scan(): ScanReport {
    this.runScans(1);
    return this.report();
  }

  scans(n: number): ScanReport {
    this.runScans(n);
    return this.report();
  }

  private runScans(n: number): void {
    for (let k = 0; k < n && !this.currentFault; k++) {
      if (this.stepper) {
        // A step into a call left the scan inside a body: finish it on the stepping path.
        this.advance(() => false);
        if (this.currentFault) return;
      } else {
        if (this.cursor === -1) this.startScan();
        this.run(false);
        if (this.currentFault) return;
      }
      this.endScan();
    }
  }

  runUntil(cond: (plc: Plc) => boolean, maxScans: number): boolean {
    for (let k = 0; k < maxScans && !this.currentFault; k++) {
      this.runScans(1);
      if (!this.currentFault && cond(this)) return true;
    }
    return false;
  }

  stepNetwork(opts: { readonly into?: boolean } = {}): StepReport {
    if (this.currentFault) return { executed: -1, next: -1, scanDone: false, fault: this.currentFault };
    if (this.cursor === -1) this.startScan();
    if (!opts.into && !this.stepper) {
      const executed = this.cursor >= 0 ? this.run(true) : -1;
      if (this.currentFault) return { executed, next: -1, scanDone: false, fault: this.currentFault };
      if (this.cursor === -2) {
        this.endScan();
        return { executed, next: -1, scanDone: true };
      }
      return { executed, next: this.cursor, scanDone: false };
    }
    if (this.cursor === -2) {
      this.endScan();
      return { executed: -1, next: -1, scanDone: true, frames: [] };
    }
    if (!this.stepper) {
      this.stepper = this.stepScan(this.cursor, this.time, this.count);
      this.stepper.next(); // to the stop before the cursor's network
    }
    const executed = this.frames[0]!.network;
    // Into: to the next stop at any depth; over (a step left inside a body): back to the program.
    const done = this.advance(opts.into ? () => true : () => this.frames.length <= 1);
    if (this.currentFault) return { executed, next: -1, scanDone: false, fault: this.currentFault };
    if (done) {
      this.endScan();
      return { executed, next: -1, scanDone: true, frames: [] };
    }
    this.cursor = this.frames[0]!.network;
    return { executed, next: this.cursor, scanDone: false, frames: this.position() };
  }

  // ---- stepping into calls (a slow path: generators, built on the first step into a call) ----

  private stepper: Generator<void, void> | undefined;
  /** Body and (global) network of each level the stepper stands in, the program first. */
  private frames: { body: number; network: number }[] = [];
  private stepGens: ((i: number, t: number, scan: number) => Generator<void, number>)[] | undefined;
  private stepPlan: DispatchPlan | undefined;

  /** Runs the stepper to the next stop where `stop()` holds (or to the end of the scan: true). */
  private advance(stop: () => boolean): boolean {
    try {
      for (;;) {
        if (this.stepper!.next().done) {
          this.stepper = undefined;
          this.frames = [];
          this.cursor = -2;
          return true;
        }
        if (stop()) return false;
      }
    } catch (e) {
      if (!(e instanceof WatchdogTrip)) throw e;
      this.stepper = undefined;
      this.frames = [];
      this.trip(e.network);
      return false;
    }
  }

  private *stepScan(from: number, t: number, scan: number): Generator<void, void> {
    for (let i = this.dueFrom(from); i >= 0; ) {
      const end = this.programEnd[i]!;
      yield* this.stepRange(i, end, t, scan);
      i = end < this.mainEnd ? this.dueFrom(end) : -2;
    }
  }

  /** Networks [first, end) of one body, stopping before each. */
  private *stepRange(first: number, end: number, t: number, scan: number): Generator<void, void> {
    const plan = this.stepPlan ?? this.buildStepPlan();
    const gens = this.stepGens!;
    const frame = { body: this.program.bodyOf[first] ?? -1, network: first };
    this.frames.push(frame);
    for (let i = first; i >= 0 && i < end; ) {
      frame.network = i;
      yield;
      const next: number = yield* gens[plan.shape[i]!]!(i, t, scan);
      this.ranIn[i] = scan;
      this.evals++;
      if (next >= 0 && next <= i) {
        this.backJump = i;
        if (now() - this.scanStart > this.maxScanMs) throw new WatchdogTrip(i);
      }
      if (this.evals >= this.maxEvals) throw new WatchdogTrip(i);
      i = next;
    }
    this.frames.pop();
  }

  /** Units [first, end) in a step: no stop before them (they start or end their runner network), but calls in them can be stepped into. */
  private *stepLate(first: number, end: number, t: number, scan: number): Generator<void, void> {
    const plan = this.stepPlan ?? this.buildStepPlan();
    for (let u = first; u < end; u++) yield* this.stepGens![plan.shape[u]!]!(u, t, scan);
  }

  /** Code where every call runs its body through X.stepCall (bodies are not written in place). */
  private buildStepPlan(): DispatchPlan {
    const p = this.program;
    const plan = planDispatch(p.networks, p.functions, p.symbols.fbs.map((f) => f.type), false);
    this.stepPlan = plan;
    for (const v of this.forces.keys())
      for (const at of plan.writes.get(slotKey(v.store, v.slot)) ?? []) plan.P[at] = this.mem.sink[v.store];
    const m = this.mem;
    this.stepGens = (new Function(...DISPATCH_PARAMS, plan.stepBody) as (...args: unknown[]) => typeof this.stepGens)(
      m.b, m.n, m.g, m.fbs, p.functions, m.edges, this.power, plan.constants, this.ctx,
      this.ranIn, this.stats, plan.P, plan.V, plan.base, plan.shape, this.exec,
    );
    return plan;
  }

  position(): readonly StepFrame[] {
    const frames = this.stepper ? this.frames : this.cursor >= 0 ? [{ body: this.program.bodyOf[this.cursor]!, network: this.cursor }] : [];
    return frames.map((f) => {
      const body = this.program.bodies[f.body]!;
      return { pou: body.pou, ...(body.instance ? { instance: body.instance } : {}), network: f.network - body.first };
    });
  }

  instances(): readonly InstanceInfo[] {
    return this.program.instances;
  }

  clearFault(): void {
    this.meters[1]!++;
    this.currentFault = undefined;
    this.cursor = -1;
    this.stepper = undefined;
    this.frames = [];
  }

  // ---- variables ----

  private access(name: string): Access {
    const res = this.program.symbols.resolve(name, { literals: false, implicitLocations: false });
    if (!res.ok) throw new Error(`${name}: ${res.message}`);
    return res.access;
  }

  read(name: string): Value {
    return this.mem.read(this.access(name));
  }

  write(name: string, value: Value): void {
    const a = this.access(name);
    const v = coerce(a.type, value, `"${name}"`);
    const input = a.kind === 'var' && a.v.location?.area === 'I';
    this.meters[input && this.cursor === -1 ? 0 : 1]!++;
    if (input) {
      this.inputImage[this.inputs.indexOf(a.v)] = v;
      return;
    }
    if ((a.kind === 'var' || a.kind === 'bit') && this.forces.has(a.v)) return; // a forced value wins
    this.mem.write(a, v);
  }

  private forceTarget(name: string): VarSymbol {
    const a = this.access(name);
    if (a.kind !== 'var') throw new Error(`${name}: only variables can be forced (not FB pins or bits)`);
    return a.v;
  }

  force(name: string, value: Value): void {
    const v = this.forceTarget(name);
    const val = coerce(v.type, value, `"${name}"`);
    const fresh = !this.forces.has(v);
    this.meters[1]!++;
    this.forces.set(v, val);
    this.mem.store(v, val);
    if (fresh) this.redirectWriters(v, true);
  }

  unforce(name: string): void {
    const v = this.forceTarget(name);
    this.meters[1]!++;
    if (this.forces.delete(v)) this.redirectWriters(v, false);
  }

  unforceAll(): void {
    this.meters[1]!++;
    const vars = [...this.forces.keys()];
    this.forces.clear();
    for (const v of vars) this.redirectWriters(v, false);
  }

  forced(): ReadonlyMap<string, Value> {
    return new Map([...this.forces].map(([v, val]) => [v.name, val]));
  }

  /**
   * Points the program's writes to a variable at a spare slot (Memory.sink) while it is forced,
   * so they do not stick, and back at the variable when it is unforced; no code is regenerated.
   */
  private redirectWriters(v: VarSymbol, forced: boolean): void {
    const key = slotKey(v.store, v.slot);
    if (forced) this.forcedSlots.add(key);
    else this.forcedSlots.delete(key);
    const target = forced ? this.mem.sink[v.store] : v.slot;
    for (const at of this.plan.writes.get(key) ?? []) this.plan.P[at] = target;
    for (const at of this.stepPlan?.writes.get(key) ?? []) this.stepPlan!.P[at] = target;
    this.tiering.invalidate(this.plan.writers.get(key) ?? []);
  }

  setInputs(values: Readonly<Record<string, Value>>): void {
    this.meters[this.cursor === -1 ? 0 : 1]!++;
    for (const [loc, value] of Object.entries(values)) {
      const v = this.program.symbols.atLocation(loc, false);
      const index = v ? this.inputs.indexOf(v) : -1;
      if (!v || index < 0) throw new Error(`${loc}: no input variable is declared at this location`);
      this.inputImage[index] = coerce(v.type, value, loc);
    }
  }

  outputs(): Record<string, Value> {
    const out: Record<string, Value> = {};
    this.outputsVars.forEach((v, i) => (out[v.locationText!] = this.outputImage[i]!));
    return out;
  }

  variableNames(): string[] {
    const names = this.program.symbols.vars.filter((v) => !v.hidden).map((v) => v.name);
    for (const fb of this.program.symbols.fbs)
      for (const pin of this.mem.fbs[fb.index]!.pins()) names.push(`${fb.name}.${pin}`);
    return names;
  }

  values(): Record<string, Value> {
    const out: Record<string, Value> = {};
    for (const v of this.program.symbols.vars) if (!v.hidden) out[v.name] = this.mem.load(v);
    return out;
  }

  // ---- restarts ----

  private resetCommon(): void {
    this.meters[1]!++;
    this.cursor = -1;
    this.stepper = undefined;
    this.frames = [];
    this.currentFault = undefined;
    this.ranIn.fill(-1);
    this.power.fill(0);
    for (const [v, val] of this.forces) this.mem.store(v, val);
    this.outputsVars.forEach((v, i) => (this.outputImage[i] = this.mem.load(v)));
  }

  coldRestart(): void {
    this.mem.initialise();
    this.count = 0;
    this.time = 0;
    this.clockOrigin = this.opts.clock?.now() ?? 0;
    this.resetCommon();
  }

  warmRestart(): void {
    const fbs = new Set(this.program.symbols.fbs.filter((f) => f.retain).map((f) => f.index));
    this.mem.initialise({ vars: this.program.retentive, fbs });
    this.resetCommon();
  }

  // ---- online change ----

  /** The time the next scan would start at, on this PLC's clock. */
  private nextScanTime(): number {
    return this.opts.clock ? this.opts.clock.now() - this.clockOrigin : this.count * this.cycleMs;
  }

  stateItems(): readonly StateItem[] {
    return stateItemsOf(this.program);
  }

  exportState(): PlcState {
    return exportMemory(this.program, this.mem, this.nextScanTime());
  }

  importState(state: PlcState): StateTransfer {
    this.meters[1]!++;
    return importMemory(this.program, this.mem, state, this.nextScanTime());
  }

  probe(): PlcProbe {
    const { program, mem, words } = this;
    return {
      reader: (name) => {
        const a = this.access(name);
        return () => mem.read(a);
      },
      sampler: (names) => {
        // Straight-line reads (like the generated scan code): a variable from its store, a standard
        // FB pin from its field; anything else through Memory.read.
        const accesses = names.map((name) => this.access(name));
        const body = accesses.map((a, i) => {
          if (a.kind === 'var') return a.v.store === 'b' ? `o[${i}] = b[${a.v.slot}] === 1;` : `o[${i}] = ${a.v.store}[${a.v.slot}];`;
          if (a.kind === 'pin' && /^[A-Z_][A-Z0-9_]*$/i.test(a.pin) && a.pin in mem.fbs[a.fb.index]!) return `o[${i}] = f[${a.fb.index}].${a.pin};`;
          return `o[${i}] = m.read(a[${i}]);`;
        });
        const make = new Function('b', 'n', 'g', 'f', 'm', 'a', `return (o) => {\n${body.join('\n')}\n};`) as (...args: unknown[]) => (out: Value[]) => void;
        return make(mem.b, mem.n, mem.g, mem.fbs, mem, accesses);
      },
      power: this.power,
      ranIn: this.ranIn,
      words,
      decode: (power: Int32Array, executed: Uint8Array): NetworkPower[] => {
        const ranIn = Int32Array.from(executed, (e) => (e ? 1 : -1));
        return networkPower(program, { scan: 1, power, words, ranIn });
      },
      meters: this.meters,
      inputImage: this.inputImage,
      save: () => this.saveImage(),
      restore: (image) => this.restoreImage(image as Image),
      replay: (timeMs, inputs) => {
        if (inputs) for (let i = 0; i < this.inputImage.length; i++) this.inputImage[i] = inputs[i]!;
        this.replayAt = timeMs;
        try {
          this.runScans(1);
        } finally {
          this.replayAt = undefined;
        }
        return this.currentFault;
      },
    };
  }

  /** The complete state at a scan boundary (PlcProbe.save). */
  private saveImage(): Image {
    const mem = saveMemory(this.mem);
    const extra = this.power.length / 2 + this.ranIn.length / 2 + this.inputImage.length + this.outputImage.length + this.forces.size * 2;
    return {
      scan: this.count,
      timeMs: this.time,
      bytes: imageBytes(mem, extra),
      mem,
      power: this.power.slice(),
      ranIn: this.ranIn.slice(),
      inputs: this.inputImage.slice(),
      outputs: this.outputImage.slice(),
      forces: [...this.forces],
    };
  }

  /** Takes back a saved state (PlcProbe.restore): memory, power, input and output images, forces, scan count and time. */
  private restoreImage(image: Image): void {
    this.clearFault();
    restoreMemory(this.mem, image.mem);
    this.power.set(image.power);
    this.ranIn.set(image.ranIn);
    image.inputs.forEach((v, i) => (this.inputImage[i] = v));
    image.outputs.forEach((v, i) => (this.outputImage[i] = v));
    const forced = new Map(image.forces);
    for (const v of [...this.forces.keys()]) if (!forced.has(v)) {
      this.forces.delete(v);
      this.redirectWriters(v, false);
    }
    for (const [v, value] of forced) {
      const fresh = !this.forces.has(v);
      this.forces.set(v, value);
      if (fresh) this.redirectWriters(v, true);
    }
    this.count = image.scan;
    this.time = image.timeMs;
  }

  snapshot(opts: SnapshotOptions = {}): PowerSnapshot {
    const body = opts.instance === undefined ? this.program.bodies[0] : this.bodyOfInstance(opts.instance);
    if (!body) throw new Error(`${opts.instance}: no FB or program instance of this name is called`);
    const trace: PowerTrace = {
      scan: this.shownScan(body),
      power: this.power,
      words: this.words,
      ranIn: this.ranIn,
    };
    return {
      scan: this.count,
      timeMs: this.time,
      pou: body?.pou ?? this.pou,
      ...(opts.instance !== undefined && body.instance ? { instance: body.instance } : {}),
      networks: networkPower(this.program, trace, body?.first ?? 0, body?.end ?? 0),
    };
  }

  /**
   * The scan whose power flow a body shows: this one, or, when its program's task was not due at
   * this tick, the program's last run (its power is unchanged since: the view does not blink).
   */
  private shownScan(body: BodyInfo): number {
    const rates = this.rates;
    if (!rates) return this.count;
    const root = programOf(this.program.bodies, body);
    const p = this.program.bodies.indexOf(root);
    if (p < 0 || p >= rates.due.length || rates.due[p] === 1 || root.end <= root.first) return this.count;
    // Never run yet (an event task not triggered since the restart): scan 0, which no network ran in.
    return Math.max(0, this.ranIn[root.first]!);
  }

  /** The body of an instance's call that ran last in the scan (the first call if none ran). */
  private bodyOfInstance(path: string): BodyInfo | undefined {
    const key = path.trim().toUpperCase();
    let best: BodyInfo | undefined;
    for (const b of this.program.bodies) {
      if (b.instance?.toUpperCase() !== key) continue;
      if (!best || (b.end > b.first && (this.ranIn[b.first] ?? -1) > (this.ranIn[best.first] ?? -1))) best = b;
    }
    return best;
  }
}
