// The engine's public contract, used by the simulator worker, the editor (diagnostics), the CLI
// and PLCopen round-trip tests. Implementations live beside this file; these are the types.
import type { Cell } from '../model/grid';
import type { ElementId } from '../model/ids';
import type { ElementaryType, Value } from '../model/iecTypes';
import type { Profile } from '../model/project';

/** LD-R01..LD-R13 from LD-SEMANTICS.md section 9, plus LD-E.. for errors outside those rules
 * (unknown block type, bad literal, unsupported construct) and LD-W.. for other warnings. */
export type RuleId = `LD-R${string}` | `LD-E${string}` | `LD-W${string}`;

export interface Diagnostic {
  readonly severity: 'error' | 'warning';
  readonly rule: RuleId;
  /** POU name. */
  readonly pou: string;
  /** 0-based network index in the POU (displayed 1-based as "network 3"). -1 for POU-level (variables). */
  readonly network: number;
  readonly networkLabel?: string;
  readonly cell?: Cell;
  readonly elementId?: ElementId;
  /** A text body (ST, IL): where in its text, 1-based line and column (network is then its first). */
  readonly line?: number;
  readonly col?: number;
  /** Plain words for a PLC programmer, naming the element/variable. */
  readonly message: string;
}

export interface CompileOptions {
  /** POU to compile as the program to run; default: the first PROGRAM. */
  readonly pou?: string;
  /**
   * Compile the whole configuration instead: every program instance of the project's tasks, each
   * task at its own interval (TaskSchedule); a program's variables are `Instance.Var`, globals keep
   * their names.
   */
  readonly configuration?: boolean;
  /** Default: the project's profile. */
  readonly profile?: Profile;
}

export interface Fault {
  readonly kind: 'watchdog' | 'runtime';
  /** POU whose network faulted (an FB's or a function's when it was inside a call). */
  readonly pou: string;
  /** FB instance path (or program instance) whose body faulted. */
  readonly instance?: string;
  /** 0-based network index in `pou`. */
  readonly network: number;
  readonly networkLabel?: string;
  /** ST/IL: the line of the body's text (the loop that ran too long, the statement that faulted). */
  readonly line?: number;
  readonly message: string;
}

/**
 * Power flow of one scan (or of the scan so far, when stepping networks), for the UI.
 * Arrays are aligned with the document: elements[i] describes network.elements[i],
 * vlinks[j] describes network.vlinks[j]. Element byte: bit 0 = left side (input) energised,
 * bit 1 = right side (output) energised, bit 2 = element executed this scan.
 */
export interface NetworkPower {
  readonly elements: Uint8Array;
  readonly vlinks: Uint8Array;
  /** False when a jump or return skipped the network this scan. */
  readonly executed: boolean;
}

export interface PowerSnapshot {
  readonly scan: number;
  readonly timeMs: number;
  readonly pou: string;
  /** The FB instance (or program instance) whose body this is, when one was asked for. */
  readonly instance?: string;
  /** One per network of `pou`, in order. */
  readonly networks: readonly NetworkPower[];
}

export interface SnapshotOptions {
  /**
   * An FB instance path (`Motor1`, `Line.Motor1`, case-insensitive) or a program instance of a
   * configuration: the power of its body's networks (indexes = the POU's networks). Called from
   * several places, the call that ran last in the scan is shown.
   */
  readonly instance?: string;
}

/** Where execution stands: a POU's network, in an instance when it is a body. */
export interface StepFrame {
  readonly pou: string;
  readonly instance?: string;
  /** 0-based network index in `pou`. */
  readonly network: number;
  /** ST/IL bodies: the line of the statement to run next (1-based, in the POU's text). */
  readonly line?: number;
}

/** An ST/IL body to observe statement by statement: a POU, in one instance or (no `instance`) in all. */
export interface TextTarget {
  readonly pou: string;
  readonly instance?: string;
}

/**
 * What an observed ST/IL body did in the last scan that ran it (the scan so far while paused in it):
 * the lines whose statements ran, and each variable written with the value it had after the
 * statement that last wrote it, and that statement's line. Plain data (posted by the simulator, kept
 * in recorded scans).
 */
export interface TextTrace {
  readonly pou: string;
  readonly instance?: string;
  /** The scan it describes (earlier than the PLC's scan count: the body did not run since). */
  readonly scan: number;
  /** Lines of the statements that ran, ascending. */
  readonly lines: readonly number[];
  /** Lines of every statement of the body (ELSIF conditions included), ascending: the others hold none. */
  readonly stops: readonly number[];
  /** By the names the body's text uses (`Out`, `A[i]`, `T1.Q`), in the order first written. */
  readonly values: readonly { readonly name: string; readonly line: number; readonly type: ElementaryType; readonly value: Value }[];
}
export interface InstanceInfo {
  /** `Motor1`, `Line.Motor1` (a configuration: `Prog1.Motor1`). */
  readonly path: string;
  /** The FB's POU name. */
  readonly type: string;
}

export interface ScanReport {
  /** Scans completed since the last cold restart. */
  readonly scan: number;
  /** Virtual (or real) time at the start of the last scan, ms. */
  readonly timeMs: number;
  /** Wall-clock execution time of the last scan, ms. */
  readonly execMs: number;
  readonly fault?: Fault;
}

export interface StepReport {
  /** Network that was just executed, or -1 when this step finished the scan (outputs written). */
  readonly executed: number;
  /** Network that will execute next, -1 when the next step starts a new scan. */
  readonly next: number;
  readonly scanDone: boolean;
  readonly fault?: Fault;
  /**
   * Where execution stands after the step: the caller frames then the network to run next, e.g.
   * `[{ pou: 'Main', network: 3 }, { pou: 'Motor', instance: 'Motor1', network: 1 }]`; empty at a
   * scan boundary.
   */
  readonly frames?: readonly StepFrame[];
}

export interface Clock {
  /** Milliseconds; only differences matter. */
  now(): number;
}

/**
 * How a configuration's tasks share the scans, as MATIEC's resource runs them: one scan is one tick
 * of the common tick (the greatest common divisor of every task's interval); a cyclic task runs in
 * the scans whose tick number (0 for the first scan after a cold restart) is a multiple of `every`,
 * an event task in the scans where its trigger has risen since the last tick; the program instances
 * of the tasks due run in declaration order (task order, then the order within the task).
 */
export interface TaskSchedule {
  /** The common tick, ms: the virtual clock advances by it per scan. */
  readonly tickMs: number;
  /** The tasks that run program instances, in the project's order. */
  readonly tasks: readonly TaskRate[];
  /**
   * True when some task runs less often than every scan, or on an event (a scan then runs only the
   * tasks due, and the scan is the tick).
   */
  readonly multiRate: boolean;
}

export interface TaskRate {
  readonly name: string;
  /** The interval, ms (an event task's: 0 when none is given; it only counts in the tick). */
  readonly intervalMs: number;
  /** Ticks from one run to the next: intervalMs / tickMs; 0 for an event task. */
  readonly every: number;
  /** An event task's trigger: the BOOL global whose rising edge runs it (MATIEC: `SINGLE :=`). */
  readonly single?: string;
  /** Its program instances, in declaration order. */
  readonly instances: readonly string[];
}

export interface PlcOptions {
  /**
   * Virtual clock: time advances by cycleMs per scan, scan k starts at (k-1) x cycleMs. A
   * configuration whose tasks run at different intervals takes its common tick
   * (TaskSchedule.tickMs) and nothing else.
   */
  readonly cycleMs: number;
  /** Real-time clock instead of the virtual one (live run). */
  readonly clock?: Clock;
  /** Watchdog: max network evaluations per scan (default 100 x networks + 10_000). */
  readonly maxNetworkEvaluations?: number;
  /** Watchdog: max wall-clock ms per scan (default 1000). */
  readonly maxScanMs?: number;
}

/**
 * A piece of a PLC's state that an online change can keep: a function block instance (matched by
 * its declared name) or the edge memory of a |P| |N| contact or (P) (N) coil (matched by the
 * element's id in the document), never by position.
 */
export interface StateItem {
  readonly kind: 'fb' | 'edge';
  /** Identity: the instance name in upper case, or the element id. */
  readonly key: string;
  /** The FB type (TON), or the element's symbol: `|P|`, `|N|`, `(P)`, `(N)`. */
  readonly type: string;
  /** Edge elements: the variable (or `Instance.Pin`, bit) the element reads or writes. */
  readonly operand?: string;
  /** Edge elements: 0-based network index. */
  readonly network?: number;
  /** As the user knows it: `T3`, `|P| Start in network 2`. */
  readonly label: string;
}

/**
 * FB instances and edge memories of a PLC, taken at a scan boundary. Plain numbers and booleans
 * (structured-clone and JSON safe). Time fields of timers (START_TIME) are relative to the time the
 * next scan would start at (negative: in the past), so they carry exactly to another PLC clock.
 */
export interface PlcState {
  readonly fbs: readonly { readonly item: StateItem; readonly fields: Readonly<Record<string, number | boolean | string>> }[];
  readonly edges: readonly { readonly item: StateItem; readonly memory: boolean }[];
}

export type ResetReason = 'new' | 'type-changed' | 'operand-changed';

/** What an online change keeps and what it starts fresh. */
export interface StateTransfer {
  /** Items of the new program that take the old program's state. */
  readonly kept: readonly StateItem[];
  /** Items of the new program that start from their initial state, with the reason in words (`TON → TOF`). */
  readonly reset: readonly { readonly item: StateItem; readonly reason: ResetReason; readonly detail: string }[];
  /** Items of the old program that the new one no longer has. */
  readonly removed: readonly StateItem[];
}

/**
 * Raw access for the scan history (src/sim/history.ts): names resolved once, the packed power words
 * without a copy, and the snapshot's own decoding applied to recorded words.
 */
export interface PlcProbe {
  /** A reader for one name (`Motor`, `T1.ET`), resolved now; throws on unknown names. */
  reader(name: string): () => Value;
  /** One function that copies the values of `names` into `out` (same order), generated once; throws on unknown names. */
  sampler(names: readonly string[]): (out: Value[]) => void;
  /** Packed power-flow words of every network as the last scan left them (a live view: copy what you keep). */
  readonly power: Int32Array;
  /** Scan in which each network last ran (a live view). */
  readonly ranIn: Int32Array;
  /** Index of each network's first word in `power`. */
  readonly words: Int32Array;
  /** The snapshot's decoding of recorded words: `executed[i]` 1 when network i ran in that scan. */
  decode(power: Int32Array, executed: Uint8Array): NetworkPower[];
  /**
   * A live view: [0] and [1] count changes made from outside the scans: [0] the input image written
   * at a scan boundary (write to an input, setInputs), [1] anything else (other writes, forces,
   * restarts, importState, clearFault, restore) and any change made in the middle of a scan;
   * [2] the wall-clock execution time of the last scan, ms.
   */
  readonly meters: Float64Array;
  /** The input image the next input read applies (a live view: copy what you keep). */
  readonly inputImage: readonly Value[];
  /** The complete state at a scan boundary: every variable, FB instance, edge memory, power word, the input image, forces, scan count and time. */
  save(): PlcImage;
  /** Takes back a state save() gave on a PLC of the same compiled program (at a scan boundary, fault cleared). */
  restore(image: PlcImage): void;
  /**
   * Runs one scan at PLC time `timeMs` whatever the clock says, with `inputs` (when given) as the
   * input image: a recorded scan replayed exactly. Returns the fault when the scan faulted.
   */
  replay(timeMs: number, inputs?: readonly Value[]): Fault | undefined;
  /** The data lines on box pins of the networks [first, end) (a body of the program), made once per range. */
  pinLines(first: number, end: number): PinLines;
}

/** A box pin whose value is a data line (a wire between blocks), in a body's networks (compile/pinLines.ts). */
export interface PinLineInfo {
  /** Network index relative to the body's first network. */
  readonly network: number;
  /** The box's index in the network's elements. */
  readonly element: number;
  readonly pin: string;
  readonly side: 'in' | 'out';
  /** Elementary type of the value. */
  readonly type: string;
}

/** The data lines of one body and a reader of their current values (aligned with `lines`). */
export interface PinLines {
  readonly lines: readonly PinLineInfo[];
  read(out: Value[]): void;
}

/** A PLC's complete state (PlcProbe.save): opaque but for what it is of and its estimated size. */
export interface PlcImage {
  /** Scans completed and the time of the last one when it was taken. */
  readonly scan: number;
  readonly timeMs: number;
  /** Estimated memory held, in bytes. */
  readonly bytes: number;
}

export interface Plc {
  readonly pou: string;
  readonly profile: Profile;
  /** What runs in which scan, when the PLC runs a configuration (several program instances). */
  readonly schedule?: TaskSchedule;
  readonly scanCount: number;
  readonly timeMs: number;
  readonly fault: Fault | undefined;
  /** Runs one full scan: input read, networks in order (jumps/returns), output write. */
  scan(): ScanReport;
  scans(n: number): ScanReport;
  /** Runs scans until cond() is true after a scan, or maxScans; returns whether cond was met. */
  runUntil(cond: (plc: Plc) => boolean, maxScans: number): boolean;
  /**
   * Executes one network (starting a scan with the input read if needed); the debugger's step.
   * With `into`, a network that calls a user FB or function stops before each network of the
   * called body (and of bodies it calls); without, a call runs whole (a step left inside a body
   * finishes the program's network).
   */
  stepNetwork(opts?: { readonly into?: boolean }): StepReport;
  /**
   * Observes ST/IL bodies statement by statement (textTrace): while any is observed, scans run on
   * the instrumented step code (a slower tier, runtime/scanCycle.ts); an empty list: the fast path.
   */
  observeText(targets: readonly TextTarget[]): void;
  /** What an observed body did (an instance, or without one the body of the POU that ran last). */
  textTrace(target: TextTarget): TextTrace | undefined;
  /** Where execution stands (as StepReport.frames): empty at a scan boundary. */
  position(): readonly StepFrame[];
  /** User FB instances of the program, nested ones by path. */
  instances(): readonly InstanceInfo[];
  /** Network to run next within the current scan, -1 at a scan boundary. */
  readonly nextNetwork: number;
  /** Reads a variable or FB pin: `Motor`, `T1.ET`, `%QX0.0` (by location). Throws on unknown names. */
  read(name: string): Value;
  /** Sets a variable once (inputs: takes effect at the next input read). Throws on unknown name/bad value. */
  write(name: string, value: Value): void;
  force(name: string, value: Value): void;
  unforce(name: string): void;
  unforceAll(): void;
  forced(): ReadonlyMap<string, Value>;
  /** Input image by IEC location (%IX0.0 -> true), applied at the next input read. */
  setInputs(values: Readonly<Record<string, Value>>): void;
  /** Output image by IEC location, as written at the end of the last scan. */
  outputs(): Record<string, Value>;
  /** Every variable (and FB pin) name the PLC can read, in declaration order. */
  variableNames(): string[];
  /** All variables (not FB internals) with their current values, by name. */
  values(): Record<string, Value>;
  coldRestart(): void;
  warmRestart(): void;
  snapshot(opts?: SnapshotOptions): PowerSnapshot;
  clearFault(): void;
  /** Identities of the state this program holds: its FB instances, then its edge elements. */
  stateItems(): readonly StateItem[];
  /** FB instances and edge memories, for an online change (call at a scan boundary). */
  exportState(): PlcState;
  /**
   * Takes the state of every item of `state` that this program has with the same identity (same
   * instance name and FB type; same element id, symbol and operand); the others keep their initial
   * state. Call at a scan boundary, normally before this PLC's first scan.
   */
  importState(state: PlcState): StateTransfer;
  /** Raw access for recording every scan (scan history); optional for other implementations. */
  probe?(): PlcProbe;
  /**
   * One point of the I/O image by location, resolved once (a machine in closed loop reads and
   * writes its points every scan, issue 26): an input's image (write: applied at the next input
   * read, as setInputs), an output's image (read only). Undefined when no variable is declared there.
   */
  ioPoint?(location: string): IoPoint | undefined;
  /**
   * The I/O image itself, by index, for a caller that reads and writes many points every scan
   * without a call per point (a machine in closed loop, issue 26). The same arrays for the PLC's
   * life; optional for other implementations.
   */
  ioImage?(): IoImage;
}

/** A PLC's input and output images by index (Plc.ioImage). */
export interface IoImage {
  /** The input image: what the next scan reads (a forced input's force still wins). Written only through `write`. */
  readonly inputs: readonly Value[];
  /** The output image as the last scan left it. */
  readonly outputs: readonly Value[];
  /** The index in `inputs` of the input variable declared at a location, -1 when none. */
  input(location: string): number;
  /** The index in `outputs` of the output variable declared at a location, -1 when none. */
  output(location: string): number;
  /** Writes input `index` as IoPoint.write does: converted to the variable's type, applied at the next input read. */
  write(index: number, value: Value): void;
  /**
   * One counter, counted up by every write of the input image, whichever way (`write`, setInputs,
   * a variable written by name, a restore or a replay of the history): a reader that finds the count
   * its own last write left knows nobody else wrote an input since.
   */
  readonly inputWrites: Uint32Array;
}

export interface IoPoint {
  read(): Value;
  /** Inputs only; throws for an output, or a value not of the variable's type. */
  write(value: Value): void;
}
