// The simulation worker's logic, as a plain class so it runs (and is tested) in Node without a Worker:
// commands in (HostMessage), frames and events out (WorkerMessage) through an injected `post`.
// The session owns the program and the mode; ScanRunner executes the scans.
import type { Diagnostic, Plc, TextTarget } from '../engine/api';
import type { Value } from '../model/iecTypes';
import type { Project } from '../model/project';
import { carryDisplay, carryForces, carryInstances, carryValues, planInstances, valueFor, type ShownScan } from './carryOver';
import { outputsChanged, readValues } from './frames';
import { HistoryRecorder } from './historyRecorder';
import { withPinLines } from './pinValues';
import type { HistoryOptions } from './history';
import { buildLayout, findPou, programFingerprint, withView } from './layout';
import { parseScenario, prepareScenario, runPrepared, scenarioCycle, type ScenarioResult } from './scenario';
import type { CompiledProgram } from '../engine/plc';
import type { Pou, Scenario } from '../model/project';
import { fingerprintId } from './programId';
import type { HostMessage, LineBreakpoint, OnlineChangePlan, SimFrame, SimLayout, SimMode, SimView, TrendTrigger, WorkerMessage } from './protocol';
import { programInstances, runOptions } from './runTarget';
import { packView } from './viewPower';
import type { Breakpoint } from '../engine/runtime/breakpoints';
import { ScanRunner, type ScanOutcome } from './scanRunner';
import type { Scheduler } from './scheduler';
import { TrendRecorder } from './trendRecorder';
import { inputKeysOf, locationKey } from './inputKeys';
import { buildFrame } from './sessionFrame';
import { answerHistory, historyRange } from './sessionHistory';
import { plcScanWithClock, programLayout, type SinceColdStart } from './scenarioRecording';
import type { SimEngine } from './simEngine';
import { withYieldPoints, yieldPoint } from '../engine/yieldPoint';
import { applyDelta } from './projectDelta';
import { SessionPlant } from './sessionPlant';
import { plantNameWhy, withPlantWhy } from './plantWhy';

export interface SessionDeps {
  readonly engine: SimEngine;
  readonly scheduler: Scheduler;
  post(message: WorkerMessage, transfer?: Transferable[]): void;
  /** Wall clock for measuring execution time; default performance.now. */
  readonly wallNow?: () => number;
}

/** Frames are posted at most this often while running (display rate, not scan rate). */
export const FRAME_INTERVAL_MS = 25;

interface LoadedProgram {
  readonly plc: Plc;
  readonly layout: SimLayout;
  readonly fingerprint: string;
  /** fingerprintId(fingerprint), worked out before the swap. */
  readonly id: string;
  /** The compiled program and its document POU, for the scan history and "Why?". */
  readonly program: unknown;
  readonly pou: Pou | undefined;
  /** The document it was compiled from (breakpoints by network id, views of other POUs). */
  readonly project: Project;
}

interface PendingChange {
  readonly program: LoadedProgram;
  readonly diagnostics: readonly Diagnostic[];
  readonly id: number;
  readonly plan: OnlineChangePlan;
  awaiting: boolean;
}

export class SimSession {
  private plc: Plc | undefined;
  private loaded: LoadedProgram | undefined;
  private layout: SimLayout | undefined;
  private fingerprint = '';
  /**
   * An online change waiting for the next scan boundary (or, `awaiting`, for the user's answer),
   * with what it will keep and reset.
   */
  private pending: PendingChange | undefined;
  /** Hardware is attached as controller: online changes wait for confirmOnline. */
  private confirmOnline = false;
  private onlineIds = 0;
  /** The last document the store sent: what its next difference (projectDelta.ts) is made against. */
  private documentBase: { readonly seq: number; readonly project: Project } | undefined;
  private mode: SimMode = 'stopped';
  /** The cycle the UI set; a program whose tasks run at different intervals scans at their common tick instead. */
  private requestedCycle: number | undefined;
  private scanBase = 0;
  private lastFrameAt = -Infinity;
  private readonly trend = new TrendRecorder();
  /** Signals the UI asked for; the trend samples those the loaded program has. */
  private trendRequest: { names: string[]; capacity: number; trigger?: TrendTrigger } = { names: [], capacity: 1 };
  private outputsSubscribed = false;
  private lastOutputs: Record<string, Value> | undefined;
  private gatewayInputs: Record<string, Value> = {};
  /** Locations of the installed program's input variables: the gateway inputs it binds. */
  private inputKeys: ReadonlySet<string> = new Set();
  /** programId of the installed program (what runs), null when none. */
  private programId: string | null = null;
  /** The last command epoch handled, echoed in frames. */
  private epoch = 0;
  private readonly runner: ScanRunner;
  /** Records every scan of the installed program (issue 14); a new program starts a new history. */
  private recorder: HistoryRecorder | undefined;
  private historyOptions: HistoryOptions = {};
  /**
   * What happened since the last cold start (Reset, or a program installed afresh) that a scenario,
   * which replays from a cold start, cannot reproduce: an online change or warm restart (at the
   * scan given), and the variables forced.
   */
  private sinceColdStart: SinceColdStart = { forced: new Set() };
  /** The body the UI monitors (setView); absent: the program's. */
  private view: SimView | undefined;
  /** Breakpoints as the UI sent them: program network indexes and document network ids. */
  private breakpointRequest: { networks: readonly number[]; ids: readonly string[]; lines: readonly LineBreakpoint[] } = { networks: [], ids: [], lines: [] };
  /**
   * After an online change at a scan boundary, what the last scan of the replaced program showed,
   * mapped to the new program (carryDisplay): shown until the new program runs a network.
   */
  private carried: { plc: Plc; shown: ShownScan } | undefined;
  /** The machine in closed loop with the program (issue 26). */
  private readonly plant = new SessionPlant();
  /** The machine's names the trend may sample (`tank.level`), read off the machine rather than the PLC. */
  private trendPlantNames: ReadonlySet<string> = new Set();

  constructor(private readonly deps: SessionDeps) {
    this.runner = new ScanRunner(
      {
        current: () => this.requirePlc(),
        atBoundary: () => this.applyPending(),
        scanCompleted: (plc, startTime) => {
          this.recorder?.record(this.scanBase + plc.scanCount, startTime);
          // The machine after the scan is recorded as it ran (the recorder takes its input image):
          // outputs are written, the next scan's inputs not yet read.
          if (this.plant.active) this.plant.afterScan(this.scanBase + plc.scanCount, startTime, this.runner.cycleMs);
          // Sampled after the machine's step: `tank.level` in a scan's sample is the machine after
          // that scan, as the history shows it (the program's variables are unchanged by the step,
          // which writes only the input image the next scan reads).
          if (this.trend.active) this.trend.record(this.scanBase + plc.scanCount, startTime, this.trendRead(plc));
          if (this.outputsSubscribed) this.postOutputs();
        },
        stopped: (outcome) => this.stoppedAt(outcome),
        crashed: (error) => {
          this.mode = 'paused';
          this.deps.post({ type: 'error', message: `the simulation stopped: ${error instanceof Error ? error.message : String(error)}` });
          this.postFrame();
        },
        progress: () => {
          if (this.deps.scheduler.now() - this.lastFrameAt >= FRAME_INTERVAL_MS) this.postFrame();
        },
      },
      deps.scheduler,
      deps.wallNow ?? (() => performance.now()),
    );
  }

  handle(message: HostMessage): void {
    try {
      this.dispatch(this.withDocument(message));
    } catch (error) {
      const text = error instanceof Error ? error.message : String(error);
      // A request the page waits on by id is answered, with the reason: a notice alone would leave it waiting.
      if (message.type === 'explain' || message.type === 'historyExport' || message.type === 'replayScenario')
        this.deps.post({ type: 'requestFailed', id: message.id, message: text });
      else this.deps.post({ type: 'error', message: text });
      this.postFrame();
    }
  }

  /**
   * A command carrying the document as a difference from the one sent before (projectDelta.ts)
   * gets the whole document back; the document carried becomes the base of the next difference.
   */
  private withDocument(m: HostMessage): HostMessage {
    if (!('docSeq' in m) || m.docSeq === undefined) return m;
    let project = m.project;
    if ('delta' in m && m.delta) {
      if (this.documentBase?.seq !== m.delta.base) {
        this.documentBase = undefined;
        throw new Error("the simulator lost its copy of the project (internal); press Run again");
      }
      project = applyDelta(this.documentBase.project, m.delta);
    }
    if (project) this.documentBase = { seq: m.docSeq, project };
    return project ? ({ ...m, project } as HostMessage) : m;
  }

  private dispatch(m: HostMessage): void {
    if ('epoch' in m && m.epoch !== undefined) this.epoch = m.epoch;
    switch (m.type) {
      case 'load':
        if (!m.project) throw new Error('no document to load');
        this.load(m.project, false, m.confirm === true);
        return;
      case 'run':
        if (!this.loadToStart(m.project) || this.refuseIfFaulted()) return;
        this.requirePlc();
        this.mode = 'running';
        this.runner.startRun();
        this.postFrame();
        return;
      case 'pause':
        if (this.mode !== 'running') return;
        this.runner.stop();
        this.mode = 'paused';
        this.postFrame();
        return;
      case 'step':
        if (!this.loadToStart(m.project) || this.refuseIfFaulted()) return;
        this.requirePlc();
        this.mode = 'running';
        this.runner.startBatch(m.scans);
        return;
      case 'stepNetwork': {
        if (!this.loadToStart(m.project) || this.refuseIfFaulted()) return;
        this.requirePlc();
        this.mode = this.runner.stepNetwork(m.out === true ? 'out' : m.into === true ? 'into' : 'over') ? 'faulted' : 'paused';
        this.postFrame();
        return;
      }
      case 'reset':
        this.coldRestart();
        return;
      case 'warmRestart':
        this.warmRestart();
        return;
      case 'setCycle':
        if (!Number.isFinite(m.cycleMs) || m.cycleMs < 0 || m.cycleMs > 60_000) {
          throw new Error(`cycle time ${m.cycleMs} ms is out of range (0 to 60000 ms)`);
        }
        this.requestedCycle = m.cycleMs;
        this.applyCycle(this.plc);
        this.postFrame();
        return;
      case 'setBreakpoints':
        this.breakpointRequest = { networks: m.networks ?? [], ids: m.ids ?? [], lines: m.lines ?? [] };
        this.resolveBreakpoints();
        this.postFrame();
        return;
      case 'setView':
        this.view = m.view;
        this.observeView();
        if (this.loaded && this.layout) {
          this.layout = withPinLines(withView(this.loaded.project, this.layout, m.view), this.loaded.plc, this.loaded.program as CompiledProgram, this.loaded.project);
          this.deps.post({ type: 'layout', layout: this.layout });
          this.postFrame();
        }
        return;
      case 'write':
        this.requirePlc().write(m.name, valueFor(this.deps.engine, this.layout, m.name, m.input));
        this.postFrame();
        return;
      case 'force':
        this.requirePlc().force(m.name, valueFor(this.deps.engine, this.layout, m.name, m.input));
        this.sinceColdStart.forced.add(m.name);
        this.postFrame();
        return;
      case 'unforce':
        this.requirePlc().unforce(m.name);
        this.postFrame();
        return;
      case 'unforceAll':
        this.plc?.unforceAll();
        this.postFrame();
        return;
      case 'setTrend':
        this.trendRequest = { names: [...m.names], capacity: m.capacity, ...(m.trigger ? { trigger: m.trigger } : {}) };
        this.configureTrend(true);
        this.postFrame();
        return;
      case 'setInputs':
        this.gatewayInputs = { ...this.gatewayInputs, ...m.values };
        if (this.plc) this.bindInputs(this.plc, this.inputKeys, m.values);
        return;
      case 'unload':
        this.dropProgram();
        this.postFrame();
        return;
      case 'setOnlineConfirm':
        this.confirmOnline = m.required;
        return;
      case 'confirmOnline':
        this.answerOnline(m.id, m.apply);
        return;
      case 'setHistory':
        this.historyOptions = { maxScans: m.maxScans, budgetBytes: m.budgetBytes };
        if (this.plc && this.layout && this.recorder && this.loaded)
          this.recorder = HistoryRecorder.for(this.plc, programLayout(this.loaded.project, this.layout), this.loaded.program, this.loaded.pou, this.historyOptions, this.loaded.project);
        this.postFrame();
        return;
      case 'historySeek':
      case 'historyFind':
      case 'explain':
      case 'historyExport': {
        const why = this.plant.whyContext();
        // "Why?" on a machine name (`tank.level`) that is not the program's: the machine explains it.
        if (why && m.type === 'explain' && !this.layout?.variables.some((v) => m.target.kind === 'variable' && v.name.toUpperCase() === m.target.name.toUpperCase())) {
          const explanation = plantNameWhy(m.scan, m.target, why);
          if (explanation) {
            this.deps.post({ type: 'explanation', id: m.id, explanation });
            return;
          }
        }
        answerHistory(m, {
          recorder: this.recorder,
          plc: this.plc,
          layout: this.layout,
          project: this.loaded?.project,
          sinceColdStart: this.sinceColdStart,
          cycleMs: this.runner.cycleMs,
          text: this.textTarget(),
          plant: this.plant.recording(),
          post: (message, transfer) => {
            // A recorded scan shows the machine as it was then.
            const plant = message.type === 'historyView' ? this.plant.at(message.view.scan) : undefined;
            if (plant && message.type === 'historyView') this.deps.post({ ...message, view: { ...message.view, plant } }, transfer);
            // An input the machine writes, an output it reads: the machine says its part.
            else if (why && message.type === 'explanation') this.deps.post({ ...message, explanation: withPlantWhy(message.explanation, why) }, transfer);
            else this.deps.post(message, transfer);
          },
        });
        return;
      }
      case 'replayScenario':
        this.replayScenario(m.id, m.project, m.scenario);
        return;
      case 'setPlant':
        this.plant.configure(m.plant, this.plc);
        // The trend may name the machine (`tank.level`): known now, or no longer.
        this.configureTrend();
        this.postFrame();
        return;
      case 'plantOperator':
        // Running, paused or stopped, a click is held until a scan has read it (Step scan too).
        this.plant.setOperator(m.name, m.value, this.mode !== 'faulted');
        this.postFrame();
        return;
      case 'plantFault':
        this.plant.setFault(m.id, m.active);
        this.postFrame();
        return;
      case 'subscribeOutputs':
        this.outputsSubscribed = m.enabled;
        this.lastOutputs = undefined;
        if (m.enabled && this.plc) this.postOutputs();
        return;
    }
  }

  // ---- loading and online change -------------------------------------------------------

  /**
   * Run/Step with a document: compiles and installs it. When that fails, the previous program is
   * dropped too (what runs is always what is shown): mode stopped, no program, the reason posted.
   */
  private loadToStart(project: Project | undefined): boolean {
    if (!project) return true;
    let ok: boolean;
    try {
      ok = this.load(project, true);
    } catch (error) {
      this.dropProgram();
      this.deps.post({ type: 'error', message: `the program could not be installed, the simulation is stopped: ${error instanceof Error ? error.message : String(error)}` });
      this.postFrame();
      return false;
    }
    if (!ok) {
      // 'compiled' (ok: false) already said why.
      this.dropProgram();
      this.postFrame();
    }
    return ok;
  }

  /** Stop and forget the program: no PLC, no forces, no gateway inputs, mode stopped. */
  private dropProgram(): void {
    this.runner.stop();
    this.carried = undefined;
    this.runner.breakpointHit = undefined;
    this.pending = undefined;
    this.plc = undefined;
    this.layout = undefined;
    this.loaded = undefined;
    this.recorder = undefined;
    this.fingerprint = '';
    this.programId = null;
    this.gatewayInputs = {};
    this.inputKeys = new Set();
    this.lastOutputs = undefined;
    this.runner.clock.set(0);
    this.configureTrend();
    this.resetCounters();
    this.mode = 'stopped';
  }

  /**
   * Gateway inputs the program reads: only addresses of its declared input variables are bound;
   * the gateway's other points are not this program's I/O and are left out (never an error).
   */
  private bindInputs(plc: Plc, declared: ReadonlySet<string>, values: Readonly<Record<string, Value>>): void {
    const bound: Record<string, Value> = {};
    for (const [address, value] of Object.entries(values)) if (declared.has(locationKey(address))) bound[address] = value;
    if (Object.keys(bound).length > 0) plc.setInputs(bound);
  }

  /** Compiles the document. Returns false (and reports why) when it has errors. */
  private load(project: Project, starting = false, confirm = false): boolean {
    // While Run paces scans, the scans that fall due during the compile run at its yield points
    // (between networks): compiling an online change never delays a scan of the running program.
    // So does making the document's fingerprint (a yield point every 64 networks).
    const poll = () => this.runner.poll();
    const fingerprint = withYieldPoints(poll, () => programFingerprint(project));
    poll();
    if (this.plc && fingerprint === (this.pending?.program.fingerprint ?? this.fingerprint)) return true;
    const { program, diagnostics } = withYieldPoints(poll, () => this.deps.engine.compile(project));
    const online = this.plc !== undefined && (this.mode !== 'stopped' || this.plc.scanCount > 0);
    if (!program || diagnostics.some((d) => d.severity === 'error')) {
      this.deps.post({ type: 'compiled', ok: false, online: online && !starting, diagnostics });
      return false;
    }
    const clock = this.runner.clock;
    if (!online) clock.set(0);
    const plc = withYieldPoints(poll, () => this.deps.engine.createPlc(program, { cycleMs: this.runner.cycleMs, clock }));
    poll();
    // The layout and the pins' data lines are built between yield points too (a name, a network at a time).
    const layout = withYieldPoints(poll, () =>
      buildLayout(project, plc.pou, plc.variableNames(), this.cycleFor(plc), {
        instances: plc.instances(),
        ...(runOptions(project).configuration ? { programs: programInstances(project) } : {}),
      }),
    );
    poll();
    const shownId = withYieldPoints(poll, () => fingerprintId(fingerprint));
    poll();
    const shownLayout = this.view && findPou(project, this.view.pou) ? withView(project, layout, this.view) : layout;
    const next: LoadedProgram = {
      plc,
      layout: withYieldPoints(poll, () => withPinLines(shownLayout, plc, program as CompiledProgram, project)),
      fingerprint,
      id: shownId,
      program,
      pou: findPou(project, plc.pou),
      project,
    };
    poll();
    if (!online) {
      this.install(next, false, diagnostics);
      return true;
    }
    // The swap at the scan boundary writes the kept values into the new PLC by name (carryValues):
    // its names are resolved here, between yield points, so the boundary does not (14 ms at 650 networks).
    withYieldPoints(poll, () => resolveNames(plc, next.layout));
    // Swapped in at the next scan boundary: right now when the PLC is between scans. With hardware
    // attached, or applied on request, an edit (not a Run/Step) first waits for the user's answer to its plan.
    const id = ++this.onlineIds;
    const plan = planInstances(this.plc!, plc);
    poll();
    const awaiting = (this.confirmOnline || confirm) && !starting;
    this.pending = { program: next, diagnostics, id, plan, awaiting };
    this.deps.post({ type: 'onlinePlan', id, plan, confirm: awaiting });
    this.applyIfBetweenScans();
    return true;
  }

  private applyIfBetweenScans(): void {
    if (this.plc?.nextNetwork === -1 && !this.runner.runningLive) this.applyPending();
  }

  /** The user's answer to an online change that asked (hardware attached). */
  private answerOnline(id: number, apply: boolean): void {
    const pending = this.pending;
    if (!pending || pending.id !== id || !pending.awaiting) return;
    if (!apply) {
      this.pending = undefined;
      this.deps.post({ type: 'onlineCancelled', id });
      return;
    }
    pending.awaiting = false;
    this.applyIfBetweenScans();
  }

  private applyPending(): void {
    const pending = this.pending;
    if (!pending || pending.awaiting) return;
    this.pending = undefined;
    let plan = pending.plan;
    // The display keeps the last scan until the new program runs (a second change in a row keeps
    // what the first kept).
    // While Run paces scans the new program scans right after the swap: nothing to carry (and no time to spend at the boundary).
    const live = this.runner.runningLive;
    const before = this.plc && this.layout && !live ? (this.carriedShown() ?? (this.plc.scanCount > 0 ? this.shownNow(this.plc, this.layout) : undefined)) : undefined;
    this.carried = undefined;
    if (this.plc && this.layout) {
      const next = pending.program;
      if (before) this.carried = { plc: next.plc, shown: carryDisplay(this.layout, before, next.layout, readValues(next.plc, next.layout)) };
      carryValues(this.plc, this.layout, pending.program.plc, pending.program.layout);
      plan = carryInstances(this.plc, pending.program.plc);
      this.scanBase += this.plc.scanCount;
    }
    this.install(pending.program, true, pending.diagnostics);
    this.sinceColdStart.interruptedAt ??= { scan: this.scanBase, what: 'an online change' };
    this.deps.post({ type: 'onlineApplied', id: pending.id, scan: this.scanBase, plan });
  }

  private install(next: LoadedProgram, online: boolean, diagnostics: readonly Diagnostic[]): void {
    if (this.plc) carryForces(this.plc, next.plc);
    this.inputKeys = inputKeysOf(next.layout);
    this.bindInputs(next.plc, this.inputKeys, this.gatewayInputs);
    this.plant.install(next.plc, !online);
    this.plc = next.plc;
    this.layout = next.layout;
    this.loaded = next;
    this.applyCycle(next.plc);
    this.resolveBreakpoints();
    this.observeView();
    // The history records the program's own networks whatever body is monitored.
    this.recorder = HistoryRecorder.for(next.plc, programLayout(next.project, next.layout), next.program, next.pou, this.historyOptions, next.project);
    this.fingerprint = next.fingerprint;
    this.programId = next.id;
    this.lastOutputs = undefined;
    this.configureTrend();
    if (!online) {
      this.resetCounters();
      this.carried = undefined;
    }
    this.deps.post({ type: 'compiled', ok: true, online, diagnostics, layout: next.layout, program: this.programId });
    // An online change while Run paces scans is installed at a scan boundary, right before the new
    // program's first scan: the frame after that scan (the burst's, posted at once) shows it; none
    // is built here, where every millisecond delays the scan.
    if (online && this.runner.runningLive) this.lastFrameAt = Number.NEGATIVE_INFINITY;
    else this.postFrame();
  }

  /**
   * The scan cycle for a PLC: the common tick when its tasks run at different intervals (a scan is
   * one tick, the Cycle field shows it read-only), else the cycle the UI set (at first the runner's).
   */
  private cycleFor(plc: Plc | undefined): number {
    const s = plc?.schedule;
    return s?.multiRate ? s.tickMs : (this.requestedCycle ?? this.runner.cycleMs);
  }

  private applyCycle(plc: Plc | undefined): void {
    const cycle = this.cycleFor(plc);
    if (this.runner.cycleMs !== cycle) this.runner.setCycle(cycle);
    if (this.layout && this.layout.cycleMs !== cycle) this.layout = { ...this.layout, cycleMs: cycle };
  }

  /** The runner's breakpoints in the installed program: network ids found in every POU of its document. */
  /** The monitored body when it is written in ST or IL (observed statement by statement: the instrumented tier). */
  private textTarget(): TextTarget | undefined {
    const loaded = this.loaded;
    if (!loaded) return undefined;
    const view = this.view ?? { pou: loaded.plc.pou };
    const pou = findPou(loaded.project, view.pou);
    return pou && (pou.language === 'ST' || pou.language === 'IL') ? view : undefined;
  }

  /** Only a shown ST/IL body is observed: the others run on the fast path. */
  private observeView(): void {
    const target = this.textTarget();
    this.loaded?.plc.observeText(target ? [target] : []);
  }

  private resolveBreakpoints(): void {
    const { networks, ids, lines } = this.breakpointRequest;
    const list: Breakpoint[] = lines.map((b) => ({ pou: b.pou, network: -1, line: b.line, ...(b.instance ? { instance: b.instance } : {}) }));
    if (this.plc) for (const network of networks) list.push({ pou: this.plc.pou, network });
    if (this.loaded && ids.length > 0) {
      const wanted = new Set(ids);
      for (const pou of this.loaded.project.pous)
        pou.networks.forEach((n, network) => {
          if (wanted.has(n.id)) list.push({ pou: pou.name, network });
        });
    }
    this.runner.breakpoints = list;
  }

  private configureTrend(rearm = false): void {
    const request = this.trendRequest.trigger;
    // The layout's names looked up only when the trend asks for some (an online change installs a
    // program at a scan boundary: no index of thousands of names made there for nothing).
    const known =
      this.trendRequest.names.length > 0 || request
        ? new Map((this.layout?.variables ?? []).map((v) => [v.name.toUpperCase(), v.name]))
        : new Map<string, string>();
    // The program's names, then the machine's (`tank.level`; `tank.Pump` and `tank.pump` differ by case).
    const machine = new Set<string>();
    const spell = (n: string): string | undefined => {
      const own = known.get(n.toUpperCase());
      if (own !== undefined) return own;
      const m = this.plant.spelling(n);
      if (m !== undefined) machine.add(m);
      return m;
    };
    const names = this.trendRequest.names.flatMap((n) => spell(n) ?? []);
    const triggerName = request && spell(request.name);
    this.trendPlantNames = machine;
    // Before a program is loaded the trigger waits armed; a name the program lacks is reported.
    const trigger = request && { ...request, name: triggerName ?? request.name };
    this.trend.configure(names, this.trendRequest.capacity, trigger, { known: !this.layout || triggerName !== undefined, rearm });
  }

  /** How the trend reads a name: the machine's (`tank.level`) from the machine, the others from the PLC. */
  private trendRead(plc: Plc): (name: string) => Value {
    const machine = this.trendPlantNames;
    return machine.size === 0 ? (n) => plc.read(n) : (n) => (machine.has(n) ? this.plant.read(n) : plc.read(n));
  }

  private requirePlc(): Plc {
    if (!this.plc) throw new Error('no program is loaded: press Run or Step first');
    return this.plc;
  }

  // ---- restarts and stops -------------------------------------------------------------------

  private refuseIfFaulted(): boolean {
    const fault = this.plc?.fault;
    if (!fault) return false;
    this.deps.post({ type: 'error', message: `the PLC is faulted (${fault.message}); press Reset or Warm restart to clear the fault` });
    this.postFrame();
    return true;
  }

  private stoppedAt(outcome: ScanOutcome): void {
    this.mode = outcome === 'fault' ? 'faulted' : 'paused';
    this.postFrame();
  }

  private coldRestart(): void {
    this.runner.stop();
    this.applyPending();
    this.carried = undefined;
    this.runner.clock.set(0);
    if (this.plc) {
      this.plc.clearFault();
      this.plc.coldRestart();
    }
    this.plant.coldRestart(this.plc);
    this.resetCounters();
    this.mode = 'stopped';
    this.postFrame();
  }

  private warmRestart(): void {
    const plc = this.requirePlc();
    const wasRunning = this.mode === 'running' && this.runner.runningLive;
    this.runner.stop();
    plc.clearFault();
    plc.warmRestart();
    this.carried = undefined;
    this.sinceColdStart.interruptedAt ??= { scan: this.scanBase + plc.scanCount, what: 'a warm restart' };
    this.runner.breakpointHit = undefined;
    this.mode = wasRunning ? 'running' : 'stopped';
    if (wasRunning) this.runner.startRun();
    this.postFrame();
  }

  private resetCounters(): void {
    this.sinceColdStart = { forced: new Set(this.plc?.forced().keys() ?? []) };
    this.runner.resetCounters();
    this.scanBase = 0;
    this.trend.clear();
    this.recorder?.history.clear();
  }

  // ---- posting ---------------------------------------------------------------------------------

  private postOutputs(): void {
    const plc = this.requirePlc();
    const outputs = plc.outputs();
    if (!outputsChanged(this.lastOutputs, outputs)) return;
    this.lastOutputs = outputs;
    this.deps.post({ type: 'outputs', scan: this.scanBase + plc.scanCount, timeMs: this.runner.timeMs(plc), outputs, program: this.programId ?? '' });
  }

  postFrame(): void {
    this.lastFrameAt = this.deps.scheduler.now();
    const frame = this.frame();
    this.deps.post({ type: 'frame', frame }, [frame.elements.buffer, frame.vlinks.buffer, frame.executed.buffer]);
  }

  /** What the replaced program's last scan showed, while the program an online change installed has not run. */
  private carriedShown(): ShownScan | undefined {
    const c = this.carried;
    if (c && c.plc === this.plc && c.plc.scanCount === 0 && c.plc.nextNetwork === -1 && !c.plc.fault) return c.shown;
    this.carried = undefined;
    return undefined;
  }

  private shownNow(plc: Plc, layout: SimLayout): ShownScan {
    return { values: readValues(plc, layout), power: packView(plc, layout, this.loaded?.program as CompiledProgram | undefined) };
  }

  private frame(): SimFrame {
    const plant = this.plant.frame();
    const frame = buildFrame({
      mode: this.mode,
      plc: this.plc,
      layout: this.layout,
      runner: this.runner,
      carried: this.carriedShown(),
      program: this.loaded?.program as CompiledProgram | undefined,
      trend: this.trend,
      scanBase: this.scanBase,
      programId: this.programId,
      epoch: this.epoch,
      history: historyRange(this.recorder),
      ...(this.loaded ? { project: this.loaded.project } : {}),
      text: this.textTarget(),
    });
    return plant ? { ...frame, plant } : frame;
  }

  // ---- scan history, "Why?" and scenario replay (issue 14) ------------------------------------

  /** A scenario run in the simulator from a cold restart, recorded, paused after the first divergent scan. */
  private replayScenario(id: number, project: Project, scenario: Scenario): void {
    const fail = (error: string) => this.deps.post({ type: 'scenarioReplayed', id, result: { name: scenario.name, ok: false, scans: 0, divergences: [], error } });
    this.dropProgram();
    if (!this.loadToStart(project)) return fail('the program does not compile; see the Problems panel');
    const plc = this.requirePlc();
    let result: ScenarioResult;
    try {
      const parsed = parseScenario(scenario.csv, scenario.name);
      const prep = prepareScenario(parsed, this.loaded!.program as CompiledProgram);
      const plantLoop = parsed.plant
        ? this.plant.forScenario(parsed.plant, project.plant?.id === parsed.plant ? project.plant.map : undefined)
        : undefined;
      const cycle = scenarioCycle(project, parsed, plc.pou, plc.schedule);
      this.runner.setCycle(cycle);
      if (this.layout) this.layout = { ...this.layout, cycleMs: cycle };
      const clock = this.runner.clock;
      let last = 0;
      const run = runPrepared(
        plcScanWithClock(plc, (scan) => clock.set((last = (scan - 1) * cycle))),
        prep,
        (scan) => this.recorder?.record(scan, (scan - 1) * cycle),
        plantLoop && { loop: plantLoop, cycleMs: cycle },
      );
      this.runner.continueAfter(last);
      result = { name: scenario.name, ...run };
    } catch (error) {
      this.mode = 'paused';
      this.postFrame();
      return fail(error instanceof Error ? error.message : String(error));
    }
    this.mode = plc.fault ? 'faulted' : 'paused';
    this.postFrame();
    this.deps.post({ type: 'scenarioReplayed', id, result });
  }
}

/** Resolves the layout's variable names in the PLC (it keeps them, runtime/scanner.ts), 64 between two yield points. */
function resolveNames(plc: Plc, layout: SimLayout): void {
  layout.variables.forEach((v, i) => {
    if (v.role === 'pin') return;
    try {
      plc.read(v.name);
    } catch {
      // A name the new program cannot read: carryValues skips it as well.
    }
    if (i % 64 === 63) yieldPoint();
  });
}
