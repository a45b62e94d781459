// The engine's public contract, used by the simulator worker, the editor (diagnostics), the CLI
// and PLCopen round-trip tests. Implementations live beside this file; these are the types.
import type { Cell } from '../model/grid';
import type { ElementId } from '../model/ids';
import type { Value } from '../model/iecTypes';
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
  /** Plain words for a PLC programmer, naming the element/variable. */
  readonly message: string;
}

export interface CompileOptions {
  /** POU to compile as the program to run; default: the first PROGRAM. */
  readonly pou?: string;
  /** Default: the project's profile. */
  readonly profile?: Profile;
}

export interface Fault {
  readonly kind: 'watchdog' | 'runtime';
  readonly pou: string;
  readonly network: number;
  readonly networkLabel?: string;
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
  readonly networks: readonly NetworkPower[];
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
}

export interface Clock {
  /** Milliseconds; only differences matter. */
  now(): number;
}

export interface PlcOptions {
  /** Virtual clock: time advances by cycleMs per scan, scan k starts at (k-1) x cycleMs. */
  readonly cycleMs: number;
  /** Real-time clock instead of the virtual one (live run). */
  readonly clock?: Clock;
  /** Watchdog: max network evaluations per scan (default 100 x networks + 10_000). */
  readonly maxNetworkEvaluations?: number;
  /** Watchdog: max wall-clock ms per scan (default 1000). */
  readonly maxScanMs?: number;
}

export interface Plc {
  readonly pou: string;
  readonly profile: Profile;
  readonly scanCount: number;
  readonly timeMs: number;
  readonly fault: Fault | undefined;
  /** Runs one full scan: input read, networks in order (jumps/returns), output write. */
  scan(): ScanReport;
  scans(n: number): ScanReport;
  /** Runs scans until cond() is true after a scan, or maxScans; returns whether cond was met. */
  runUntil(cond: (plc: Plc) => boolean, maxScans: number): boolean;
  /** Executes one network (starting a scan with the input read if needed); the debugger's step. */
  stepNetwork(): StepReport;
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
  snapshot(): PowerSnapshot;
  clearFault(): void;
}
