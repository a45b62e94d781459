// The project: plain serialisable data (JSON), versioned. See docs/project-files.md.
import type { LdElement, VLink } from './elements';
import type { NetworkId, PouId } from './ids';

export const PROJECT_FORMAT = 'rungsmith-project';
export const PROJECT_VERSION = 1;

export type VarClass = 'local' | 'input' | 'output' | 'inOut' | 'external' | 'temp';

export interface Variable {
  readonly name: string;
  /** An elementary type (BOOL, INT, TIME, ...) or a function block type (TON, CTU, ...) for FB instances. */
  readonly type: string;
  readonly varClass: VarClass;
  /** IEC location such as %IX0.0, %QX0.1, %MW3. */
  readonly location?: string;
  /** Initial value as IEC literal text (TRUE, 10, T#5s, 2.5). */
  readonly initial?: string;
  readonly retain: boolean;
  readonly constant?: boolean;
  readonly comment: string;
  /**
   * Globals only: where the PLCopen file declared it, `<resource><globalVars>` ('resource') or
   * `<configuration><globalVars>` (absent or 'configuration'). Both are visible to every POU.
   */
  readonly scope?: GlobalScope;
}

export type GlobalScope = 'configuration' | 'resource';

export interface Network {
  readonly id: NetworkId;
  /** Jump target: identifier or unsigned integer; unique in the POU. */
  readonly label?: string;
  readonly title: string;
  readonly comment: string;
  readonly rows: number;
  readonly cols: number;
  readonly elements: readonly LdElement[];
  readonly vlinks: readonly VLink[];
  readonly collapsed?: boolean;
  /**
   * Profile `openplc` (LD-SEMANTICS.md section 6): the turn of each of this network's statements in
   * its POU body's generator order, when a PLCopen file drew it so that Beremiz's order is not
   * network by network, row by row (networks side by side, whose coils Beremiz interleaves by their
   * drawn height). Keys: a coil's element id; a variable written beside a block output,
   * `<box id>.<PIN>`. Consecutive networks with turns run their statements together, by turn (an
   * element without one runs after the one before it in its network). Set by the PLCopen import;
   * the iec profile ignores it.
   */
  readonly turns?: Readonly<Record<string, number>>;
  /** Vendor data kept for round trips (e.g. PLCopen addData); never interpreted. */
  readonly extensions?: Readonly<Record<string, unknown>>;
}

export type PouKind = 'PROGRAM' | 'FUNCTION_BLOCK' | 'FUNCTION';

/**
 * The language of a POU's body. Rungsmith edits and runs LD; a POU in another language (from a
 * PLCopen file) keeps its interface, so LD networks can call it, and its body as written
 * (`source`), so export gives it back unchanged.
 */
export const POU_LANGUAGES = ['LD', 'ST', 'IL', 'FBD', 'SFC'] as const;
export type PouLanguage = (typeof POU_LANGUAGES)[number];

export interface Pou {
  readonly id: PouId;
  readonly name: string;
  readonly kind: PouKind;
  /** FUNCTION only. */
  readonly returnType?: string;
  readonly language: PouLanguage;
  /** Body of a non-LD POU as written: ST or IL text, or the PLCopen XML of an FBD or SFC body. */
  readonly source?: string;
  readonly comment: string;
  readonly variables: readonly Variable[];
  readonly networks: readonly Network[];
  /** SFC only: the chart read from `source` (steps, transitions, actions), ready to run. */
  readonly sfc?: SfcChart;
  readonly extensions?: Readonly<Record<string, unknown>>;
}

/**
 * Code inside a chart: ST text (an expression for a condition, statements for an action), LD
 * networks (a condition's networks write the BOOL `result`), or a piece that could not be read
 * (`why`), reported when the chart is compiled.
 */
export type SfcCode =
  | { readonly language: 'ST'; readonly text: string }
  | { readonly language: 'LD'; readonly networks: readonly Network[]; readonly result?: string }
  | { readonly language: 'none'; readonly why: string };

/** An action of a step: the action (or BOOL variable) it names, its qualifier and time. */
export interface SfcAssociation {
  readonly action: string;
  /** N, R, S, L, D, P, P0, P1, SD, DS, SL. */
  readonly qualifier: string;
  /** Time literal of L, D, SD, DS, SL (`T#2s`). */
  readonly duration?: string;
  readonly indicator?: string;
}

export interface SfcStep {
  readonly name: string;
  readonly initial: boolean;
  readonly associations: readonly SfcAssociation[];
  /** localId in the source chart (for messages). */
  readonly localId?: number;
}

export interface SfcTransition {
  /** Steps that must all be active (several: a simultaneous convergence). */
  readonly from: readonly string[];
  /** Steps activated when it fires (several: a simultaneous divergence). */
  readonly to: readonly string[];
  readonly priority?: number;
  readonly condition: SfcCode;
  /**
   * The condition's blocks run in the chart's COMPUTE_FUNCTION_BLOCKS action (as Beremiz generates
   * it): the transition reads what they gave in the previous cycle.
   */
  readonly delayed?: boolean;
  readonly localId?: number;
}

export interface SfcAction {
  readonly name: string;
  readonly body: SfcCode;
}

/**
 * A sequential function chart in the order MATIEC compiles it (the order Beremiz's generator writes
 * steps, actions and transitions): steps, transitions (tested in this order, by priority first),
 * actions with bodies (executed in this order).
 */
export interface SfcChart {
  readonly steps: readonly SfcStep[];
  readonly transitions: readonly SfcTransition[];
  readonly actions: readonly SfcAction[];
  /** BOOL variables the chart's graphical conditions write (declared with the chart, hidden). */
  readonly locals?: readonly string[];
}

export interface Task {
  readonly name: string;
  /**
   * Cyclic interval in milliseconds. An event task's interval (0: none given) only counts in the
   * common tick, as MATIEC counts it; the task runs on its trigger, never by the interval.
   */
  readonly cycleMs: number;
  /**
   * Event task (IEC 61131-3 `SINGLE :=`, PLCopen `single`): the BOOL global whose rising edge,
   * sampled once per tick before the programs run, runs the task's programs. Absent: cyclic.
   */
  readonly single?: string;
  readonly priority: number;
  /** Program instances run by this task. */
  readonly programs: readonly { readonly instance: string; readonly pou: string }[];
}

export type Profile = 'iec' | 'openplc';

/** A pin of an external block: its direction on the box and its declared type. */
export interface ExternalBlockPin {
  readonly name: string;
  /** 'in' = VAR_INPUT, 'out' = VAR_OUTPUT, 'inOut' = VAR_IN_OUT. */
  readonly dir: 'in' | 'out' | 'inOut';
  /** Declared type text (INT, STRING, ...); absent when the file does not tell (the pin is ANY). */
  readonly type?: string;
  /** Initial value as IEC literal text; absent for the type's default. */
  readonly initial?: string;
}

/**
 * A block the simulator cannot run (an OpenPLC library block for MQTT, sockets, board I/O, or a
 * block a file calls without defining it), known only by its interface. It is called like a user
 * FB or function with an empty body: its outputs hold their initial values unless the watch table
 * or a scenario sets them. See src/model/externalBlocks.ts.
 */
export interface ExternalBlock {
  readonly name: string;
  readonly kind: 'FUNCTION_BLOCK' | 'FUNCTION';
  readonly pins: readonly ExternalBlockPin[];
  /** FUNCTION only: the result type (the `OUT` pin); else the type of an out pin named OUT. */
  readonly returnType?: string;
  /** The library it comes from (e.g. 'MQTT'), when known. */
  readonly library?: string;
  readonly vendor?: string;
  /** What it does, for the palette and tooltips. */
  readonly comment?: string;
}

/**
 * A user data type (IEC 61131-3 TYPE ... END_TYPE; PLCopen `types/dataTypes/dataType`).
 * Type names in `base`, `of` and member types are elementary types, STRING[n], function block
 * types or other data types of the project (declared in any order; cycles are an error).
 */
export type DataTypeDef =
  /** `TYPE Color : (RED, GREEN, BLUE); END_TYPE` — values in order (stored as their index). */
  | { readonly kind: 'enum'; readonly values: readonly string[] }
  /** `TYPE Point : STRUCT X : INT; Y : INT := 5; END_STRUCT; END_TYPE`. */
  | {
      readonly kind: 'struct';
      readonly members: readonly { readonly name: string; readonly type: string; readonly initial?: string; readonly comment?: string }[];
    }
  /** `TYPE Grid : ARRAY[1..8, 0..3] OF INT; END_TYPE` — one entry per dimension. */
  | {
      readonly kind: 'array';
      readonly dims: readonly { readonly lower: number; readonly upper: number }[];
      readonly of: string;
    }
  /** `TYPE Percent : INT (0..100); END_TYPE`. */
  | { readonly kind: 'subrange'; readonly base: string; readonly lower: number; readonly upper: number }
  /** `TYPE Speed : REAL; END_TYPE` (a derived/alias type, e.g. SVGHMI's HMI_BOOL : BOOL). */
  | { readonly kind: 'alias'; readonly base: string };

export interface DataType {
  readonly name: string;
  readonly def: DataTypeDef;
  /**
   * Initial value as IEC literal text: `GREEN` (enum), `(X := 1, Y := 2)` (struct),
   * `[32(0), 30(1)]` (array, with repetition), `10` (subrange/alias). Absent: the base's default.
   */
  readonly initial?: string;
  readonly comment?: string;
  /** Vendor data kept for round trips (PLCopen addData); never interpreted. */
  readonly extensions?: Readonly<Record<string, unknown>>;
}

/** A test scenario stored in the project: its name and its CSV text (src/sim/scenario.ts). */
export interface Scenario {
  readonly name: string;
  readonly csv: string;
}

/**
 * A library kept with the project (docs/libraries.md): the FUNCTION_BLOCK and FUNCTION POUs and the
 * data types of a PLCopen XML file or of another Rungsmith project, read once and stored here.
 * Its blocks are called like the project's own POUs and run in the simulator, but they are not
 * POUs of the project: the editor shows them read-only, and an update replaces them as a whole.
 * Versioned by the SHA-256 of the file they were read from. See src/model/libraries.ts.
 */
export interface ProjectLibrary {
  /** The library's name: the palette's heading for its blocks; unique in the project. */
  readonly name: string;
  /** `sha256:` and the hex SHA-256 of the file's text (its version). */
  readonly hash: string;
  /** The file it was read from (name only, as the user picked it). */
  readonly sourceFile: string;
  /** When it was added or last updated (ISO 8601). */
  readonly addedAt: string;
  /** The kind of file: PLCopen XML or a Rungsmith project. */
  readonly origin: 'plcopen' | 'rungsmith';
  /** Its FUNCTION_BLOCK and FUNCTION POUs (no PROGRAM). */
  readonly pous: readonly Pou[];
  readonly dataTypes?: readonly DataType[];
}

export interface Project {
  readonly format: typeof PROJECT_FORMAT;
  readonly version: typeof PROJECT_VERSION;
  readonly name: string;
  readonly description: string;
  /** Semantics profile (LD-SEMANTICS.md section 10). */
  readonly profile: Profile;
  readonly pous: readonly Pou[];
  /** Global variables (configuration/resource level in PLCopen). */
  readonly globals: readonly Variable[];
  readonly tasks: readonly Task[];
  /**
   * Test scenarios (docs/scenarios.md): inputs per scan and expected values as CSV, run by
   * the Tests panel and `rungsmith test`. Not part of the program: editing them is no online change.
   */
  readonly scenarios?: readonly Scenario[];
  /**
   * The simulator's watch list (docs/simulation.md): the names watched, in order, kept with the
   * project and brought back when it is opened again. Not part of the program: no online change.
   */
  readonly watch?: readonly string[];
  /**
   * Blocks the project calls whose interface only the project knows (e.g. an imported file's
   * vendor blocks that are not in the shipped OpenPLC libraries, with the pins the file wires).
   * Not POUs of the project: export writes only their calls.
   */
  readonly externalBlocks?: readonly ExternalBlock[];
  /** User data types (enumerations, structures, arrays, subranges, aliases). */
  readonly dataTypes?: readonly DataType[];
  /** Libraries kept with the project (ProjectLibrary; docs/libraries.md). */
  readonly libraries?: readonly ProjectLibrary[];
  /**
   * How edits reach the running simulation (docs/simulation.md "Editing while running"): 'edit'
   * (default) compiles each edit and swaps it in at a scan boundary; 'request' keeps the running
   * program until Apply, which lists the changes first. Not part of the program.
   */
  readonly onlineChange?: OnlineChangeMode;
  /**
   * The machine the program controls in the simulator (issue 26, docs/PLANTS.md) and the addresses
   * of its points the user changed (point name -> address). Not part of the program.
   */
  readonly plant?: ProjectPlant;
  readonly extensions?: Readonly<Record<string, unknown>>;
}

export type OnlineChangeMode = 'edit' | 'request';

export interface ProjectPlant {
  /** The machine's id (`tank`). */
  readonly id: string;
  readonly map?: Readonly<Record<string, string>>;
}
