// The scan cycle itself (LD-SEMANTICS.md section 7), the base of ScanPlc (scanner.ts): linking the
// generated code, input image -> networks (jumps, returns) -> output image on a virtual clock (scan k
// starts at (k-1) x cycleMs) or an injected real clock, the tasks due at each tick (programRates.ts),
// the watchdog and runtime faults, stepping one network at a time (and into calls), and cold/warm
// restart. What the rest of the app calls (variables, forcing, online change, probe, snapshots) is
// in scanner.ts.
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { Fault, PlcOptions, TaskSchedule, StepFrame, StepReport, TextTarget, TextTrace } from '../api';
import type { FnContext } from '../library/fnTypes';
import { slotKey } from '../compile/emitter';
import { isStraight } from '../compile/programConstants';
import { planDispatch, type DispatchFn, type DispatchPlan } from '../compile/dispatch';
import { dispatchFactory } from './codeCache';
import type { SegmentFn } from '../compile/segments';
import { generateSegment, planSegments } from '../compile/segments';
import { DEFAULT_TIERING, Tiering, type TieringOptions } from './tiering';
import type { CompiledProgram } from '../compile/program';
import type { VarSymbol } from '../compile/symbols';
import { stLines } from '../st/lowered';
import { Memory } from './memory';
import { programRates, type ProgramRates } from './programRates';
import { yieldPoint } from '../yieldPoint';

/** Networks run per call of a dispatch function before the scan time is checked (watchdog). */
const CHUNK = 1024;

/** Thrown out of a call's body when the watchdog trips there; caught where the scan runs. */
class WatchdogTrip {
  constructor(readonly network: number) {}
}

// Wall clock for the watchdog and execMs (the engine core has no DOM or Node typings).
const perf = (globalThis as { performance?: { now(): number } }).performance;
const now: () => number = perf ? () => perf.now() : () => Date.now();

/** What an observed ST/IL body did in scan `scan` (api.ts TextTrace), as it is recorded. */
export interface TextRecord {
  readonly scan: number;
  readonly lines: Set<number>;
  readonly values: Map<string, { line: number; type: ElementaryType; value: Value }>;
}

export abstract class ScanCycle {
  readonly pou: string;
  readonly profile: CompiledProgram['profile'];
  protected readonly mem: Memory;
  protected readonly plan: DispatchPlan;
  /**
   * The dispatch functions (compile/dispatch.ts) and the one holding each network's shape; `groups`
   * stop before segments switched to straight-line code, `stepGroups` (stepping) never do.
   */
  private readonly groups: DispatchFn[];
  private readonly stepGroups: DispatchFn[];
  private readonly groupOf: Int32Array;
  protected readonly tiering: Tiering;
  /** Written by the dispatch functions: the last network run by the last call. */
  private readonly stats = new Int32Array(1);
  /** Power-flow nets of every network, packed (see codegen NETS_PER_WORD), and each network's first word. */
  protected readonly power: Int32Array;
  protected readonly words: Int32Array;
  /** Scan number in which each network last ran. */
  protected readonly ranIn: Int32Array;
  private readonly ctx: FnContext = { error: false };
  protected readonly inputs: VarSymbol[];
  protected readonly inputImage: Value[];
  /** How many times the input image was written, whichever way (IoImage.inputWrites). */
  protected readonly inputWrites = new Uint32Array(1);
  protected readonly outputsVars: VarSymbol[];
  protected readonly outputImage: Value[];
  protected readonly forces = new Map<VarSymbol, Value>();
  private readonly maxEvals: number;
  private readonly maxScanMs: number;
  protected count = 0;
  protected time = 0;
  protected cursor = -1;
  private evals = 0;
  /** Network whose jump last went backwards in this scan (named by the watchdog). */
  private backJump = -1;
  /** Where the programs' networks end, and the end of the program holding each of them. */
  private readonly mainEnd: number;
  private readonly programEnd: Int32Array;
  readonly schedule: TaskSchedule | undefined;
  /** Several rates or event tasks: which programs run in this scan (programRates). */
  protected readonly rates: ProgramRates | undefined;
  /** Virtual clock step, ms. */
  protected readonly cycleMs: number;
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
      this.loopLine = line;
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
    /** Instrumented ST/IL (step code only): the statement at `line` of network `network` starts. */
    st: (network: number, line: number): void => {
      const frame = this.frames[this.frames.length - 1];
      if (frame) frame.line = line;
      if (this.observed[network] === 1) this.traceOf(network).lines.add(line);
    },
    /** Instrumented ST/IL: the statement at `line` wrote `value` to `name`. */
    w: (network: number, line: number, name: string, type: ElementaryType, value: Value): void => {
      if (this.observed[network] !== 1) return;
      const t = this.traceOf(network);
      t.values.delete(name);
      t.values.set(name, { line, type, value });
    },
  };
  /** ST/IL networks (the step code stops before their statements, not before the network). */
  private readonly textNet: Uint8Array;
  /** Networks of the observed ST/IL bodies (1), and what each observed body did, by body index. */
  private readonly observed: Uint8Array;
  private observing = false;
  protected readonly traces = new Map<number, TextRecord>();
  /** Wall time at which a step left the scan paused (the watchdog does not count the pause). */
  private pausedAt = -1;
  /** Line of the ST/IL loop that tripped the watchdog (0: none). */
  private loopLine = 0;
  /** Message of a runtime fault (an array index out of bounds) being thrown out of the scan. */
  private runtimeFault: string | undefined;
  /** `store:slot` of every forced variable (writes through variable indexes check it). */
  protected readonly forcedSlots = new Set<string>();
  private scanStart = 0;
  protected lastExecMs = 0;
  protected clockOrigin = 0;
  protected currentFault: Fault | undefined;
  /** PlcProbe.meters: [0] input image written at a boundary, [1] any other change from outside, [2] last scan's execution ms. */
  protected readonly meters = new Float64Array(3);
  /** The time of a scan being replayed (PlcProbe.replay), instead of the clock's. */
  protected replayAt: number | undefined;

  constructor(
    protected readonly program: CompiledProgram,
    protected readonly opts: PlcOptions,
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
    this.textNet = Uint8Array.from(program.networks, (n) => (n.ops.length === 1 && n.ops[0]!.op === 'st' ? 1 : 0));
    this.observed = new Uint8Array(program.networks.length);
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
      dispatchFactory(body)(
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
    yieldPoint();
    this.groups = plan.bodies.map((body) => {
      const fn = link(body, plan.constants, liveShape) as DispatchFn;
      yieldPoint();
      return fn;
    });
    this.stepGroups = plan.bodies.map((body) => {
      const fn = link(body, plan.constants, plan.shape) as DispatchFn;
      yieldPoint();
      return fn;
    });
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
    yieldPoint();
    this.coldRestart();
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
      this.stopWith('runtime', w, `${this.runtimeFault} in ${w.instance ? `${w.instance} (${w.pou})` : w.pou}`, this.loopLine);
      this.runtimeFault = undefined;
      this.loopLine = 0;
      return;
    }
    const network = this.backJump >= 0 ? this.backJump : at;
    const w = this.where(network);
    const inBody = this.program.bodyOf[network]! >= this.program.programs || this.program.programs > 1;
    const place = this.loopLine > 0 ? `the loop at line ${this.loopLine}` : `network ${w.network + 1}${w.label ? ` (label ${w.label})` : ''}`;
    const owner = inBody || this.loopLine > 0 ? ` of ${w.instance ? `${w.instance} (${w.pou})` : w.pou}` : '';
    const where = `${place}${owner}`;
    const line = this.loopLine;
    this.loopLine = 0;
    const limit =
      this.evals >= this.maxEvals
        ? `${this.maxEvals.toLocaleString('en-US')} network evaluations`
        : `${this.maxScanMs} ms`;
    this.stopWith('watchdog', w, `watchdog: scan exceeded ${limit}; ${this.backJump >= 0 ? `looping in ${where}` : `stopped at ${where}`}`, line);
  }

  /** Ends the scan with a fault at `w`. */
  private stopWith(kind: Fault['kind'], w: ReturnType<ScanCycle['where']>, message: string, line = 0): void {
    this.currentFault = {
      kind,
      pou: w.pou,
      ...(w.instance ? { instance: w.instance } : {}),
      network: w.network,
      ...(w.label ? { networkLabel: w.label } : {}),
      ...(line > 0 ? { line } : {}),
      message,
    };
    this.cursor = -1;
    this.lastExecMs = now() - this.scanStart;
  }

  protected runScans(n: number): void {
    this.unpause();
    for (let k = 0; k < n && !this.currentFault; k++) {
      if (this.observing && !this.stepper) {
        // Observed ST/IL bodies: the scan runs on the instrumented step code.
        if (this.cursor === -1) this.startScan();
        if (this.cursor === -2) {
          this.endScan();
          continue;
        }
        this.stepper = this.stepScan(this.cursor, this.time, this.count);
      }
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

  stepNetwork(opts: { readonly into?: boolean } = {}): StepReport {
    const report = this.stepOnce(opts);
    if (!report.scanDone && !report.fault) this.pausedAt = now();
    return report;
  }

  /** A scan left paused by a step goes on: the pause does not count towards the watchdog. */
  private unpause(): void {
    if (this.pausedAt >= 0 && this.cursor !== -1) this.scanStart += now() - this.pausedAt;
    this.pausedAt = -1;
  }

  private stepOnce(opts: { readonly into?: boolean }): StepReport {
    if (this.currentFault) return { executed: -1, next: -1, scanDone: false, fault: this.currentFault };
    this.unpause();
    if (this.cursor === -1) this.startScan();
    // An ST/IL network steps statement by statement: on the step code, even for a step over.
    const text = this.cursor >= 0 && this.textNet[this.cursor] === 1;
    if (!opts.into && !this.stepper && !text) {
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
      // To the stop before the cursor's network (an ST/IL network: before its first statement,
      // where this step ends: the network has not started yet).
      if (this.advance(() => true)) {
        this.endScan();
        return { executed: -1, next: -1, scanDone: true, frames: [] };
      }
      if (this.currentFault) return { executed: -1, next: -1, scanDone: false, fault: this.currentFault };
      if (text) return { executed: -1, next: this.cursor, scanDone: false, frames: this.position() };
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

  protected stepper: Generator<void, void> | undefined;
  /** Body and (global) network of each level the stepper stands in, the program first. */
  protected frames: { body: number; network: number; line: number }[] = [];
  private stepGens: ((i: number, t: number, scan: number) => Generator<void, number>)[] | undefined;
  protected stepPlan: DispatchPlan | undefined;

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
    const frame = { body: this.program.bodyOf[first] ?? -1, network: first, line: 0 };
    this.frames.push(frame);
    for (let i = first; i >= 0 && i < end; ) {
      frame.network = i;
      frame.line = 0;
      // ST/IL: the stops are before its statements (the instrumented code yields there).
      if (this.textNet[i] !== 1) yield;
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
    this.stepGens = dispatchFactory(plan.stepBody)(
      m.b, m.n, m.g, m.fbs, p.functions, m.edges, this.power, plan.constants, this.ctx,
      this.ranIn, this.stats, plan.P, plan.V, plan.base, plan.shape, this.exec,
    ) as typeof this.stepGens;
    return plan;
  }

  position(): readonly StepFrame[] {
    const frames = this.stepper ? this.frames : this.cursor >= 0 ? [{ body: this.program.bodyOf[this.cursor]!, network: this.cursor, line: 0 }] : [];
    return frames.map((f) => {
      const body = this.program.bodies[f.body]!;
      return {
        pou: body.pou,
        ...(body.instance ? { instance: body.instance } : {}),
        network: f.network - body.first,
        ...(f.line > 0 ? { line: f.line } : {}),
      };
    });
  }

  // ---- observing ST/IL bodies (the instrumented tier) ----

  private matches(target: TextTarget, b: number): boolean {
    const body = this.program.bodies[b]!;
    if (body.pou.toUpperCase() !== target.pou.toUpperCase()) return false;
    return target.instance === undefined || (body.instance ?? '').toUpperCase() === target.instance.toUpperCase();
  }

  observeText(targets: readonly TextTarget[]): void {
    this.observed.fill(0);
    const keep = new Set<number>();
    this.program.bodies.forEach((body, b) => {
      if (!targets.some((t) => this.matches(t, b))) return;
      keep.add(b);
      for (let i = body.first; i < body.end; i++) if (this.textNet[i] === 1) this.observed[i] = 1;
    });
    for (const b of [...this.traces.keys()]) if (!keep.has(b)) this.traces.delete(b);
    this.observing = this.observed.includes(1);
  }

  private traceOf(network: number): TextRecord {
    const b = this.program.bodyOf[network]!;
    let t = this.traces.get(b);
    if (!t || t.scan !== this.count) {
      t = { scan: this.count, lines: new Set(), values: new Map() };
      this.traces.set(b, t);
    }
    return t;
  }

  private readonly stopLines = new Map<number, readonly number[]>();

  /** Lines of every statement of a body's ST/IL networks. */
  private stopsOf(b: number): readonly number[] {
    let hit = this.stopLines.get(b);
    if (!hit) {
      const body = this.program.bodies[b]!;
      const lines = new Set<number>();
      for (let i = body.first; i < body.end; i++) {
        const op = this.program.networks[i]!.ops[0];
        if (this.textNet[i] === 1 && op?.op === 'st') stLines(op.body, lines);
      }
      hit = [...lines].sort((x, y) => x - y);
      this.stopLines.set(b, hit);
    }
    return hit;
  }

  textTrace(target: TextTarget): TextTrace | undefined {
    let best: number | undefined;
    for (const [b, t] of this.traces)
      if (this.matches(target, b) && (best === undefined || t.scan > this.traces.get(best)!.scan)) best = b;
    if (best === undefined) return undefined;
    const t = this.traces.get(best)!;
    const body = this.program.bodies[best]!;
    // Instance members are named as the body's text names them (`Out`, not `PID1.Out`).
    const own = body.instance ? `${body.instance.toUpperCase()}.` : '';
    const local = (name: string) => (own && name.toUpperCase().startsWith(own) ? name.slice(own.length) : name);
    return {
      pou: body.pou,
      ...(body.instance ? { instance: body.instance } : {}),
      scan: t.scan,
      lines: [...t.lines].sort((a, b) => a - b),
      stops: this.stopsOf(best),
      values: [...t.values].map(([name, v]) => ({ name: local(name), line: v.line, type: v.type, value: v.value })),
    };
  }

  // ---- restarts ----

  private resetCommon(): void {
    this.meters[1]!++;
    this.traces.clear();
    this.pausedAt = -1;
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
}
