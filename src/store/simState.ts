// The simulation store's state as the UI reads it: what the worker last showed, and the commands
// the store offers (implemented by createSimStore in ./simStore.ts).
import type { StoreApi } from 'zustand';
import type { Diagnostic, Fault, StepFrame } from '../engine/api';
import type { ExplainTarget, Explanation } from '../engine/explain';
import type { Value } from '../model/iecTypes';
import type { Project, Scenario } from '../model/project';
import type { ExecStats, HistoryRange, LineBreakpoint, OnlineChangePlan, SimLayout, SimMode, SimTextTrace, SimValueInput, TrendCapture, TrendTrigger, TrendTriggerState } from '../sim/protocol';
import type { ScenarioResult } from '../sim/scenario';
import type { ChangeList } from '../sim/changeList';
import type { OnlineChangeMode } from '../model/project';
import type { CanvasScope, ShownPou } from '../sim/scope';
import type { TrendBuffer } from '../sim/trendBuffer';
import type { PlantFrame } from '../sim/sessionPlant';
import type { PlantSnapshot } from '../plant/loop';

/** A write or force of a variable, before it is sent to the simulator. */
export interface SimValueAction {
  readonly kind: 'write' | 'force';
  readonly name: string;
  readonly input: SimValueInput;
}
export type SimValueGuard = (action: SimValueAction, send: () => void) => boolean;

export interface CompileRefusal {
  readonly diagnostics: readonly Diagnostic[];
  /** True when an edit made while running did not compile (the last good program keeps running). */
  readonly online: boolean;
}

/** An edit made while the program runs (online change), as the worker reported it. */
export type OnlineChangeState =
  /** Compiled; goes in at the next scan boundary. */
  | { readonly kind: 'pending'; readonly id: number; readonly plan: OnlineChangePlan }
  /** Hardware attached, or applied on request: waits for the user's Apply or Cancel. `changes`: running document against the one sent. */
  | { readonly kind: 'confirm'; readonly id: number; readonly plan: OnlineChangePlan; readonly changes?: ChangeList }
  | { readonly kind: 'applied'; readonly id: number; readonly scan: number; readonly plan: OnlineChangePlan }
  /** Not applied: the running program is unchanged. */
  | { readonly kind: 'cancelled'; readonly id: number };

export interface SimContextMenu {
  readonly x: number;
  readonly y: number;
  /** The variable the menu acts on ('' for a call box's menu). */
  readonly variable: string;
  /** A call of a user FB: "Open instance" shows its body with this instance picked. */
  readonly call?: { readonly pou: string; readonly instance: string };
}

export interface SimState {
  readonly mode: SimMode;
  readonly scan: number;
  readonly timeMs: number;
  readonly cycleMs: number;
  readonly exec: ExecStats;
  readonly fault: Fault | undefined;
  readonly nextNetwork: number;
  readonly breakpointHit: number | undefined;
  /** The breakpoint execution stopped at: POU, instance, network. */
  readonly breakpointAt: StepFrame | undefined;
  /** Where execution stands while stepping: caller frames, then the network to run next (empty at a scan boundary). */
  readonly position: readonly StepFrame[];
  /**
   * Counts the stops a debugger follows (a step, a breakpoint hit): the editor then shows the body
   * where execution stands (`stop`), with the caller's instance picked.
   */
  readonly stopSeq: number;
  readonly stop: StepFrame | undefined;
  /** The POU on the canvas (the editor says which); undefined: the program's. */
  readonly shownPou: ShownPou | undefined;
  /** The instance picked for each FB (a configuration: each program), by upper-case POU name. */
  readonly picked: ReadonlyMap<string, string>;
  /** The body the canvas monitors and how its operand names are read; undefined when it is not running. */
  readonly canvasScope: CanvasScope | undefined;
  readonly overruns: number;
  readonly layout: SimLayout | undefined;
  /** True when power flow and live values should be drawn (a program is loaded and has run). */
  readonly live: boolean;
  readonly elementIndex: ReadonlyMap<string, number>;
  readonly vlinkIndex: ReadonlyMap<string, number>;
  readonly variableIndex: ReadonlyMap<string, number>;
  readonly elements: Uint8Array;
  readonly vlinks: Uint8Array;
  readonly executed: Uint8Array;
  readonly values: readonly Value[];
  /** Values on the data lines into the shown body's box inputs (pins no name reads), aligned with layout.pins. */
  readonly pins: readonly Value[];
  /** Forced values by upper-case name. */
  readonly forced: ReadonlyMap<string, Value>;
  readonly breakpoints: readonly string[];
  /** Breakpoints on ST/IL statements: a POU's line, in every instance or in one. */
  readonly lineBreakpoints: readonly LineBreakpoint[];
  /** The shown ST/IL body in the scan shown (live or recorded): lines that ran, values after the writing statement. */
  readonly text: SimTextTrace | undefined;
  readonly watch: readonly string[];
  readonly trendNames: readonly string[];
  readonly trendCapacity: number;
  readonly trend: TrendBuffer;
  /** The trend's trigger (evaluated on every scan in the worker), its state, and the last window it captured. */
  readonly trendTrigger: TrendTrigger | undefined;
  readonly trendTriggerState: TrendTriggerState | undefined;
  readonly trendCapture: TrendCapture | undefined;
  readonly refusal: CompileRefusal | undefined;
  readonly notice: string | undefined;
  readonly contextMenu: SimContextMenu | undefined;
  /** The last online change: what it keeps and resets, whether it waits for an answer, applied or not. */
  readonly onlineChange: OnlineChangeState | undefined;
  /** Online changes ask before they are applied (hardware attached as controller). */
  readonly onlineConfirmRequired: boolean;
  /** The project's online change mode: edits applied as made, or kept until Apply (issue 24). */
  readonly onlineMode: OnlineChangeMode;
  /** The document of the program the worker runs (current epoch), when the store sent it; undefined when none or unknown. */
  readonly runningProject: Project | undefined;
  /** The programId of what the worker runs (current epoch); null when nothing runs. */
  readonly runningProgram: string | null;
  /**
   * Apply on request: the shown document differs from the running program. Edits not applied yet,
   * and the networks to mark (worked out by useOnlineChange).
   */
  readonly unapplied: { readonly changes: ChangeList | undefined; readonly count: number; readonly networks: ReadonlySet<string> } | undefined;
  /** Scans the history holds (issue 14). */
  readonly history: HistoryRange | undefined;
  /** The recorded scan shown instead of the live one (canvas, watch, trend cursor); undefined: live. */
  readonly historyScan: number | undefined;
  readonly historyTimeMs: number | undefined;
  /** The last history search that found nothing, or another history message. */
  readonly historyMessage: string | undefined;
  /** "Why?" of the viewed scan, and whether one is being worked out. */
  readonly explanation: Explanation | undefined;
  /** The machine in closed loop with the program (issue 26), as the worker last showed it. */
  readonly plant: PlantFrame | undefined;
  /** The machine at the recorded scan viewed (historyScan), when the history still has it. */
  readonly plantAtScan: PlantSnapshot | undefined;

  run(project: Project): void;
  pause(): void;
  step(project: Project, scans: number): void;
  /**
   * One network or ST/IL statement: over (it runs whole, calls included), into (stops in a call's
   * body) or out (`out`: the rest of the body runs, to the caller's next stop).
   */
  stepNetwork(project: Project, into?: boolean, out?: boolean): void;
  /** The editor shows another POU (tab): the canvas monitors its body (the picked instance of an FB). */
  showPou(pou: ShownPou | undefined): void;
  /** Picks the instance of an FB (or a configuration's program instance) whose body the canvas shows. */
  pickInstance(pou: string, instance: string): void;
  reset(): void;
  /** Another project was opened: stop, forget the program (the next Run compiles the new one). */
  unload(): void;
  warmRestart(): void;
  setCycle(cycleMs: number): void;
  /** The document changed: compiled and applied as an online change when a program is loaded. */
  documentChanged(project: Project): void;
  toggleBreakpoint(networkId: string): void;
  /** Sets or clears a breakpoint on a line of an ST/IL POU (`instance`: only in that instance). */
  toggleLineBreakpoint(pou: string, line: number, instance?: string): void;
  clearBreakpoints(): void;
  /** Writes once; a write the guard holds (setValueGuard) is sent only when the guard says so. */
  write(name: string, input: SimValueInput): void;
  /** Forces; a force the guard holds (setValueGuard) is sent only when the guard says so. */
  force(name: string, input: SimValueInput): void;
  /**
   * Every write and force passes the guard first: it returns true when it holds the action (a field
   * output of attached hardware asks to confirm) and calls `send` itself if and when it goes ahead.
   */
  setValueGuard(guard: SimValueGuard | undefined): void;
  unforce(name: string): void;
  unforceAll(): void;
  /** Flips a BOOL input (a switch). */
  toggleInput(name: string): void;
  /** Push-button: TRUE while held. */
  pressInput(name: string): void;
  releaseInput(name: string): void;
  addWatch(name: string): void;
  removeWatch(name: string): void;
  toggleTrend(name: string): void;
  setTrendCapacity(scans: number): void;
  /** Sets (or removes) the trend trigger and arms it; the last capture is dropped. */
  setTrendTrigger(trigger: Omit<TrendTrigger, 'arm'> | undefined): void;
  /** Arms the trigger again (after a single capture). */
  armTrendTrigger(): void;
  openContextMenu(menu: SimContextMenu): void;
  closeContextMenu(): void;
  dismissNotice(): void;
  /** Hardware attached as controller (or not): online changes ask first. */
  setOnlineConfirmRequired(required: boolean): void;
  /** The answer to an online change that asks: Apply (at the next scan boundary) or Cancel. */
  answerOnlineChange(apply: boolean): void;
  /** The project's online change mode (from the document). */
  setOnlineMode(mode: OnlineChangeMode): void;
  setUnapplied(unapplied: SimState['unapplied']): void;
  /** Apply on request: compile the shown document and ask (the change list first), then apply at a scan boundary. */
  applyChanges(project: Project): void;
  dismissOnlineChange(): void;
  /** Gateway seam (issue 6): input image by IEC location, applied at the next input read. */
  setInputs(values: Readonly<Record<string, Value>>): void;
  /** Gateway seam: output image after every scan that changed it. Returns an unsubscribe function. */
  onOutputs(listener: (outputs: Readonly<Record<string, Value>>, scan: number) => void): () => void;
  // ---- scan history, "Why?", scenarios (issue 14) ----
  /** Shows a recorded scan (the program runs on). */
  seekHistory(scan: number): void;
  /** Back to the live view. */
  goLive(): void;
  /** The next (1) or previous (-1) change of a variable from the viewed scan. */
  findChange(name: string, direction: 1 | -1): void;
  /** The next (1) or previous (-1) scan where a condition holds (`Motor AND NOT Start`). */
  findCondition(expression: string, direction: 1 | -1): void;
  /** "Why?" at the viewed scan (the last recorded one when live). */
  explain(target: ExplainTarget, scan?: number): void;
  closeExplanation(): void;
  setHistoryDepth(maxScans: number, budgetBytes: number): void;
  /** The recorded range as a trace CSV or a scenario. */
  exportHistory(request: { format: 'trace' | 'scenario'; names?: string[]; inputs?: string[]; outputs?: string[] }): Promise<string>;
  /** Runs a scenario in the simulator (recorded, paused at the first divergent scan). */
  replayScenario(project: Project, scenario: Scenario): Promise<ScenarioResult>;
  // ---- the machine in closed loop (issue 26) ----
  /** Attaches a machine with the addresses the user changed, or none. */
  setPlant(plant: { readonly id: string; readonly map?: Readonly<Record<string, string>> } | null): void;
  /** An operator control on the machine: a button held (true) or released, a switch turned. */
  plantOperator(name: string, value: boolean): void;
  plantFault(id: string, active: boolean): void;
}

export type SimStore = StoreApi<SimState>;
