// Messages between the UI (host.ts) and the simulation worker (worker.ts -> SimSession).
// Both sides are in this repository and built together, so messages are typed, not validated;
// the version lets a stale cached worker be detected.
//
// Gateway seam (issue 6): a bridge feeds each scan's input image with `setInputs` (IEC locations,
// applied at the next input read, exactly like a PLC's input card) and receives the output image
// with `outputs` events after every scan that changed it, once it sent `subscribeOutputs`.
import type { Diagnostic, Fault, InstanceInfo, StepFrame, TextTrace } from '../engine/api';
import type { Value } from '../model/iecTypes';
import type { ProjectDelta } from './projectDelta';
import type { Project, Scenario } from '../model/project';
import type { ExplainTarget, Explanation } from '../engine/explain';
import type { ProgramInstance } from './runTarget';
import type { ScenarioResult } from './scenario';
import type { PlantFrame } from './sessionPlant';
import type { PlantSnapshot } from '../plant/loop';

export const SIM_PROTOCOL_VERSION = 1;

export type SimMode = 'stopped' | 'running' | 'paused' | 'faulted';

/** A value typed by the user ("TRUE", "T#2s", "42") or an already typed value. */
export type SimValueInput = { readonly value: Value } | { readonly text: string };

/** Commands that run the program may carry the document to compile first; a compile error refuses the command. */
interface WithProject {
  readonly project?: Project;
  /** The document as a difference from the one sent before it (projectDelta.ts), instead of `project`. */
  readonly delta?: ProjectDelta;
  /** Sequence number of the document carried (project or delta): the base of the next delta. */
  readonly docSeq?: number;
  /**
   * The store's command counter: the worker echoes the last one it handled in its frames, so the
   * store knows which frames already reflect this command (older ones are in flight).
   */
  readonly epoch?: number;
}

export type HostMessage =
  /** Compile the document. When a program is loaded already this is an online change, applied at the next scan boundary. */
  | ({
      readonly type: 'load';
      /** Apply on request: the change waits for confirmOnline (its plan is posted first), hardware attached or not. */
      readonly confirm?: boolean;
    } & WithProject)
  | ({ readonly type: 'run' } & WithProject)
  | { readonly type: 'pause' }
  | ({ readonly type: 'step'; readonly scans: number } & WithProject)
  /**
   * One network (in an ST/IL body: one statement). Step over (default): the next network or
   * statement runs whole, calls included. Step into (`into`): a call's body stops before each of
   * its networks or statements. Step out (`out`): the rest of the body runs, to the caller's next stop.
   */
  | ({ readonly type: 'stepNetwork'; readonly into?: boolean; readonly out?: boolean } & WithProject)
  /** Cold restart: every variable to its initial value, scan count 0, mode stopped. Forces stay. */
  | { readonly type: 'reset' }
  /** Warm restart: RETAIN and M/SM/RM variables keep their values; a running PLC keeps running. */
  | { readonly type: 'warmRestart' }
  /** Cycle time in ms (0 = as fast as possible). Applies from the next scan. */
  | { readonly type: 'setCycle'; readonly cycleMs: number }
  /**
   * Execution pauses before any of these networks: `networks` are 0-based indexes in the program,
   * `ids` document network ids of any POU (in an FB's or function's body: in every call of it).
   */
  | {
      readonly type: 'setBreakpoints';
      readonly networks?: readonly number[];
      readonly ids?: readonly string[];
      /** ST/IL statements: a line of a POU's text, in one instance or (no `instance`) in every call. */
      readonly lines?: readonly LineBreakpoint[];
    }
  /** The body whose power frames carry (layout network fields follow): a program, an FB instance, a function. */
  | { readonly type: 'setView'; readonly view: SimView }
  | { readonly type: 'write'; readonly name: string; readonly input: SimValueInput }
  | { readonly type: 'force'; readonly name: string; readonly input: SimValueInput }
  | { readonly type: 'unforce'; readonly name: string }
  | { readonly type: 'unforceAll' }
  /** Signals sampled after every scan for the trend; `capacity` scans are kept. */
  | { readonly type: 'setTrend'; readonly names: readonly string[]; readonly capacity: number; readonly trigger?: TrendTrigger }
  /** Gateway: input image by IEC location (%IX0.0 -> true), applied at the next input read. */
  | { readonly type: 'setInputs'; readonly values: Readonly<Record<string, Value>> }
  /** Gateway: start or stop `outputs` events. */
  | { readonly type: 'subscribeOutputs'; readonly enabled: boolean }
  /** Online change: with `required` (hardware attached as controller), an edit waits for confirmOnline before it is applied. */
  | { readonly type: 'setOnlineConfirm'; readonly required: boolean }
  /** The answer to an `onlinePlan` that asked: apply the edit at the next scan boundary, or drop it (the running program is unchanged). */
  | { readonly type: 'confirmOnline'; readonly id: number; readonly apply: boolean }
  /**
   * Another project was opened: stop and drop the program (no PLC, no forces, no gateway inputs);
   * the next Run or Step must carry the new document.
   */
  | { readonly type: 'unload'; readonly epoch?: number }
  // ---- scan history (issue 14) ----
  /** Depth of the scan history: most scans and memory budget in bytes (the oldest drop first). */
  | { readonly type: 'setHistory'; readonly maxScans: number; readonly budgetBytes: number }
  /** Answered with `historyView` of that scan (the live program keeps running). */
  | { readonly type: 'historySeek'; readonly scan: number }
  /** The next (1) or previous (-1) change of a variable, or scan where a condition holds, from `from`; answered with `historyView` or `historyNotFound`. */
  | {
      readonly type: 'historyFind';
      readonly from: number;
      readonly direction: 1 | -1;
      readonly change?: string;
      readonly condition?: string;
    }
  /** "Why?" at a recorded scan; answered with `explanation`. */
  | { readonly type: 'explain'; readonly id: number; readonly scan: number; readonly target: ExplainTarget }
  /** The recorded range as a trace CSV (CLI format) or as a test scenario; answered with `historyText`. */
  | {
      readonly type: 'historyExport';
      readonly id: number;
      readonly format: 'trace' | 'scenario';
      readonly names?: readonly string[];
      readonly inputs?: readonly string[];
      readonly outputs?: readonly string[];
      readonly from?: number;
      readonly to?: number;
    }
  /**
   * Runs a test scenario in the simulator from a cold restart (recorded in the history), stopping
   * after the first divergent scan; answered with `scenarioReplayed`.
   */
  | { readonly type: 'replayScenario'; readonly id: number; readonly project: Project; readonly scenario: Scenario; readonly epoch?: number; readonly docSeq?: number }
  // ---- the machine in closed loop (issue 26) ----
  /** Attach a machine (its id and the addresses the user changed), or none. */
  | { readonly type: 'setPlant'; readonly plant: { readonly id: string; readonly map?: Readonly<Record<string, string>> } | null }
  /** An operator control on the machine (a button held, a switch turned): read by the next scan. */
  | { readonly type: 'plantOperator'; readonly name: string; readonly value: boolean }
  /** A fault on the machine, on or off from the next step. */
  | { readonly type: 'plantFault'; readonly id: string; readonly active: boolean }
  | GatewayHostMessage;

/**
 * The gateway link runs in the worker (issue 21 item 5: the lease heartbeat comes from where the
 * program runs). The page's GatewayClient speaks protocol v1 through a socket the worker holds
 * (gwOpen/gwSend/gwClose, answered by gwEvent); while the page drives the hardware (gwDrive) the
 * worker itself applies the gateway's inputs to the program, sends each scan's output image
 * (coalesced, src/bridge/outputPump.ts) and the heartbeat, so a busy page cannot trip the lease and
 * a stopped or crashed worker does. gwPrograms: the programs whose outputs may drive (the one shown).
 */
export type GatewayHostMessage =
  | { readonly type: 'gwOpen'; readonly id: number; readonly url: string }
  | { readonly type: 'gwSend'; readonly id: number; readonly data: string }
  | { readonly type: 'gwClose'; readonly id: number; readonly code?: number; readonly reason?: string }
  | { readonly type: 'gwDrive'; readonly drive: GatewayDrive | null }
  | { readonly type: 'gwPrograms'; readonly ids: readonly string[] };

/** A program variable bound to a gateway point (src/bridge/mapping.ts Binding, as data). */
export interface DriveBinding {
  readonly address: string;
  readonly varType: string;
  readonly dir: 'in' | 'out';
}

export interface GatewayDrive {
  readonly bindings: readonly DriveBinding[];
  /** run: driven while the program runs (a stop, pause or fault ends it); step: confirmed stepping, fed between steps too. */
  readonly kind: 'run' | 'step';
}

export type GatewayWorkerMessage =
  | { readonly type: 'gwEvent'; readonly id: number; readonly event: 'open' | 'message' | 'close'; readonly data?: string; readonly code?: number; readonly reason?: string }
  /** The worker ended a drive by itself (the program stopped, or the link closed), with why. */
  | { readonly type: 'gwDriveEnded'; readonly reason: string };

/**
 * A box input that no name reads: it is fed by a data line from another block's output (a
 * function's result, an FB's output), in the layout's view (src/sim/pinValues.ts). Frames carry the
 * values, aligned with SimLayout.pins.
 */
export interface SimPinLine {
  /** Document id of the box. */
  readonly element: string;
  readonly pin: string;
  /** Elementary type (how the value is written: T#..., 2.5, TRUE). */
  readonly type: string;
}

/** A recorded scan as the UI draws it (same layout as a frame). */
export interface HistoryView {
  readonly scan: number;
  readonly timeMs: number;
  readonly elements: Uint8Array;
  readonly vlinks: Uint8Array;
  readonly executed: Uint8Array;
  readonly values: readonly Value[];
  /** The values on the data lines of the shown body in that scan, aligned with SimLayout.pins. */
  readonly pins: readonly Value[];
  /** The shown body is ST/IL: what it did in that scan. */
  readonly text?: SimTextTrace;
  /** The machine as it was after that scan, when one is attached and the scan is still kept. */
  readonly plant?: PlantSnapshot;
}

/** A breakpoint on a statement of an ST/IL POU. */
export interface LineBreakpoint {
  readonly pou: string;
  readonly line: number;
  readonly instance?: string;
}

/**
 * The monitored ST/IL body in a scan (engine TextTrace): the lines that ran, each variable's value
 * after the statement that last wrote it. `stale`: the body did not run in that scan (every line
 * dim; the values are those of the scan it last ran in).
 */
export interface SimTextTrace extends TextTrace {
  readonly stale: boolean;
}

/** What the scan history holds. */
export interface HistoryRange {
  readonly first: number;
  readonly last: number;
  readonly bytes: number;
}

export type VariableRole = 'input' | 'output' | 'memory' | 'local' | 'pin';

export interface SimVariable {
  /** `Start`, `T1.ET` for an FB pin. */
  readonly name: string;
  /** Elementary type (BOOL, INT, TIME ...). */
  readonly type: string;
  readonly location?: string;
  readonly role: VariableRole;
}

/**
 * A body to monitor: a program (`instance` absent, or a configuration's program instance), an FB
 * instance (`Motor1`, `Line.Motor1`), or a function (no instance: the call that ran last).
 */
export interface SimView {
  readonly pou: string;
  readonly instance?: string;
}

/** What the loaded program looks like; frames are aligned with it. */
export interface SimLayout {
  /** The program run (a configuration: its first program instance's POU). */
  readonly pou: string;
  /** The body the network fields and the frames' power describe; absent: the program's (first) body. */
  readonly view?: SimView;
  /** User FB instances of the program (`Motor1`, `Line.Motor1`; a configuration's prefixed by the program instance). */
  readonly instances?: readonly InstanceInfo[];
  /** A configuration's program instances in task order (absent when one program runs). */
  readonly programs?: readonly ProgramInstance[];
  /** Document network ids (of the viewed body's POU) in order, so the canvas can find a network's power by id. */
  readonly networkIds: readonly string[];
  /** elementOffsets[n] = index of network n's first element byte in a frame's `elements`; length networks + 1. */
  readonly elementOffsets: readonly number[];
  readonly vlinkOffsets: readonly number[];
  /** Element ids of all networks, packed like a frame's `elements` (so the canvas finds a byte by id). */
  readonly elementIds: readonly string[];
  /** Vertical links of all networks as `row|boundary`, packed like a frame's `vlinks`. */
  readonly vlinkKeys: readonly string[];
  /** Every readable name, aligned with a frame's `values`. */
  readonly variables: readonly SimVariable[];
  /** The view's box inputs on data lines (values no name reads), aligned with a frame's `pins`. */
  readonly pins?: readonly SimPinLine[];
  readonly cycleMs: number;
}

export interface ExecStats {
  readonly lastMs: number;
  readonly avgMs: number;
  readonly maxMs: number;
  /** Scans since Run that started a cycle or more after their time (missed cycles, caught up or dropped as overruns). */
  readonly late?: number;
}

export interface TrendSamples {
  readonly names: readonly string[];
  /** Scan number of each sample. */
  readonly scans: readonly number[];
  readonly timesMs: readonly number[];
  /** series[i][k]: value of names[i] after scans[k]; BOOL as 0/1. */
  readonly series: readonly (readonly number[])[];
}

/**
 * The trend's trigger, evaluated on every scan in the worker: `name` crossing `level` upwards
 * ('rising') or downwards ('falling'); a BOOL (0/1) crosses 0.5, so rising is FALSE -> TRUE.
 */
export interface TrendTrigger {
  readonly name: string;
  readonly direction: 'rising' | 'falling';
  readonly level: number;
  /** Share of the window recorded before the trigger, percent (0-100). */
  readonly prePercent: number;
  /** single: one capture, then stop; normal: re-arm after each capture (the display shows the last). */
  readonly mode: 'single' | 'normal';
  /** Counts the UI's arming: frames name the arming their state and capture belong to. */
  readonly arm: number;
}

/** armed: waiting for the condition; capturing: triggered, filling the window after it; done: single capture taken; unknown: no such variable. */
export type TrendTriggerState = 'armed' | 'capturing' | 'done' | 'unknown';

/** A window of samples around a trigger: `triggerIndex` is the sample of the scan where the condition held. */
export interface TrendCapture {
  readonly samples: TrendSamples;
  readonly triggerIndex: number;
  /** Captures since the trigger was armed (1 for the first). */
  readonly count: number;
  /** The trigger's `arm` it was taken under. */
  readonly arm: number;
}

/** State of the simulation, posted at display rate while running and after every command. */
export interface SimFrame {
  readonly mode: SimMode;
  readonly scan: number;
  readonly timeMs: number;
  readonly cycleMs: number;
  readonly exec: ExecStats;
  readonly fault?: Fault;
  /** Network that executes next when stepping (-1 at a scan boundary). */
  readonly nextNetwork: number;
  /** Set when execution stopped at a breakpoint before this network (0-based, in `breakpointAt.pou`). */
  readonly breakpointHit?: number;
  /** The breakpoint execution stopped at: the POU, the instance and the network. */
  readonly breakpointAt?: StepFrame;
  /** Where execution stands while stepping: the caller frames, then the network to run next; empty at a scan boundary. */
  readonly position?: readonly StepFrame[];
  /** Scans dropped because the worker could not keep the cycle. */
  readonly overruns: number;
  /** Power bytes (api.ts NetworkPower), all networks packed, see SimLayout offsets. Transferred. */
  readonly elements: Uint8Array;
  readonly vlinks: Uint8Array;
  /** 1 when the network ran in the last (or current) scan. */
  readonly executed: Uint8Array;
  /** Aligned with SimLayout.variables. */
  readonly values: readonly Value[];
  /** The values on the data lines between the shown body's blocks, aligned with SimLayout.pins. */
  readonly pins: readonly Value[];
  readonly forced: readonly (readonly [string, Value])[];
  /** New trend samples since the previous frame. */
  readonly trend?: TrendSamples;
  /** The trend trigger's state, when one is set. */
  readonly trendTrigger?: { readonly state: TrendTriggerState; readonly arm: number };
  /** A capture completed since the previous frame. */
  readonly trendCapture?: TrendCapture;
  /** Id (programId) of the program the worker has installed, null when none: what runs. */
  readonly program: string | null;
  /** The last command epoch the worker handled (see WithProject.epoch). */
  readonly epoch: number;
  /** Scans the history can show; absent when nothing is recorded. */
  readonly history?: HistoryRange;
  /** The shown body is ST/IL: what it did in the last (or current) scan. */
  readonly text?: SimTextTrace;
  /** The machine in closed loop with the program, when one is attached. */
  readonly plant?: PlantFrame;
}

/** What an online change keeps and resets (FB instances by name, edge elements by element id). */
export interface OnlineChangePlan {
  /** FB instances and edge elements that keep their state. */
  readonly kept: number;
  /** Those that start from their initial state: `T3`, `|P| Start in network 2`, with the reason (`new`, `TON → TOF`). */
  readonly reset: readonly { readonly name: string; readonly reason: string }[];
  /** Instances and edge elements the edit deleted. */
  readonly removed: readonly string[];
}

export type WorkerMessage =
  | {
      readonly type: 'compiled';
      readonly ok: boolean;
      /** True when the program replaced a loaded one (online change). */
      readonly online: boolean;
      readonly diagnostics: readonly Diagnostic[];
      readonly layout?: SimLayout;
      /** With ok: the id (programId) of the program now installed (or waiting for the scan boundary). */
      readonly program?: string;
    }
  | { readonly type: 'frame'; readonly frame: SimFrame }
  /** The view changed (setView): the layout's network fields now describe that body. */
  | { readonly type: 'layout'; readonly layout: SimLayout }
  /** A command failed (unknown variable, bad value ...): shown to the user. */
  | { readonly type: 'error'; readonly message: string }
  /** Gateway: output image by IEC location after a scan that changed it. */
  | {
      readonly type: 'outputs';
      readonly scan: number;
      readonly timeMs: number;
      readonly outputs: Readonly<Record<string, Value>>;
      /** Id of the program that produced them: the store passes on only the shown program's outputs. */
      readonly program: string;
    }
  | { readonly type: 'ready'; readonly version: number }
  /** An online change is compiled: what it will keep and reset; with `confirm` it waits for confirmOnline. */
  | { readonly type: 'onlinePlan'; readonly id: number; readonly plan: OnlineChangePlan; readonly confirm: boolean }
  /** The online change `id` went in at the boundary after scan `scan`. */
  | { readonly type: 'onlineApplied'; readonly id: number; readonly scan: number; readonly plan: OnlineChangePlan }
  /** The online change `id` was not applied (cancelled): the running program is unchanged. */
  | { readonly type: 'onlineCancelled'; readonly id: number }
  | { readonly type: 'historyView'; readonly view: HistoryView }
  /** A historyFind found nothing: said in words. */
  | { readonly type: 'historyNotFound'; readonly message: string }
  | { readonly type: 'explanation'; readonly id: number; readonly explanation: Explanation }
  /** `refused`: why the recorded scans make no scenario (text is empty then). */
  | { readonly type: 'historyText'; readonly id: number; readonly format: 'trace' | 'scenario'; readonly text: string; readonly refused?: string }
  | { readonly type: 'scenarioReplayed'; readonly id: number; readonly result: ScenarioResult }
  /** A request answered by id (explain, historyExport, replayScenario) could not be answered: why, for its caller. */
  | { readonly type: 'requestFailed'; readonly id: number; readonly message: string }
  | GatewayWorkerMessage;
