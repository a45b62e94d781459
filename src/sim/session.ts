// The simulation worker's logic, as a plain class so it runs (and is tested) in Node without a Worker:
// commands in (HostMessage), frames and events out (WorkerMessage) through an injected `post`.
import type { Diagnostic, Fault, Plc, PlcOptions } from '../engine/api';
import type { Value } from '../model/iecTypes';
import { parseLocation } from '../model/iecTypes';
import type { Project } from '../model/project';
import { outputsChanged, packPower, readValues } from './frames';
import { buildLayout, programFingerprint } from './layout';
import type { HostMessage, SimFrame, SimLayout, SimMode, SimValueInput, WorkerMessage } from './protocol';
import type { Scheduler } from './scheduler';
import { SimClock } from './simClock';
import { TrendRecorder } from './trendRecorder';

/** The engine as the session uses it (src/sim/engineAdapter.ts binds the real one). */
export interface SimEngine {
  compile(project: Project): { readonly program?: unknown; readonly diagnostics: readonly Diagnostic[] };
  createPlc(program: unknown, options: PlcOptions): Plc;
  parseValue(type: string, text: string): { ok: true; value: Value } | { ok: false; message: string };
}

export interface SessionDeps {
  readonly engine: SimEngine;
  readonly scheduler: Scheduler;
  post(message: WorkerMessage, transfer?: Transferable[]): void;
  /** Wall clock for measuring execution time; default performance.now. */
  readonly wallNow?: () => number;
}

/** Frames are posted at most this often while running (display rate, not scan rate). */
export const FRAME_INTERVAL_MS = 25;
/** One burst of scans never holds the worker longer than this, so Pause is handled promptly. */
const SLICE_MS = 12;
/** When the worker falls further behind than this many cycles, older scans are dropped (counted as overruns). */
const MAX_BEHIND_SCANS = 50;

type ScanOutcome = 'done' | 'break' | 'fault';

interface LoadedProgram {
  readonly plc: Plc;
  readonly layout: SimLayout;
  readonly fingerprint: string;
}

interface RunTimeline {
  /** Wall time and PLC time when Run started (or the cycle changed). */
  readonly startWall: number;
  readonly baseTime: number;
  /** Scans started since then. */
  k: number;
}

export class SimSession {
  private plc: Plc | undefined;
  private layout: SimLayout | undefined;
  private fingerprint = '';
  private pending: LoadedProgram | undefined;
  private pendingDiagnostics: readonly Diagnostic[] = [];
  private mode: SimMode = 'stopped';
  private cycleMs = 10;
  private breakpoints = new Set<number>();
  private breakpointHit: number | undefined;
  /** A resumed breakpoint: the next check for this network lets it run. */
  private resumeAt: number | undefined;
  private readonly clock = new SimClock();
  private nextScanTime = 0;
  private scanStartTime = 0;
  private lastScanTime = 0;
  private stepExecMs = 0;
  private scanBase = 0;
  private stats = { last: 0, sum: 0, count: 0, max: 0 };
  private overruns = 0;
  private timeline: RunTimeline | undefined;
  private batchRemaining = 0;
  private cancelTimer: (() => void) | undefined;
  private lastFrameWall = -Infinity;
  private readonly trend = new TrendRecorder();
  /** Signals the UI asked for; the trend samples those the loaded program has. */
  private trendRequest: { names: string[]; capacity: number } = { names: [], capacity: 1 };
  private outputsSubscribed = false;
  private lastOutputs: Record<string, Value> | undefined;
  private gatewayInputs: Record<string, Value> = {};
  private readonly wallNow: () => number;

  constructor(private readonly deps: SessionDeps) {
    this.wallNow = deps.wallNow ?? (() => performance.now());
  }

  handle(message: HostMessage): void {
    try {
      this.dispatch(message);
    } catch (error) {
      this.deps.post({ type: 'error', message: error instanceof Error ? error.message : String(error) });
      this.postFrame();
    }
  }

  private dispatch(m: HostMessage): void {
    switch (m.type) {
      case 'load':
        this.load(m.project);
        return;
      case 'run':
        if (m.project && !this.load(m.project)) return;
        this.run();
        return;
      case 'pause':
        this.pause();
        return;
      case 'step':
        if (m.project && !this.load(m.project)) return;
        this.startBatch(m.scans);
        return;
      case 'stepNetwork':
        if (m.project && !this.load(m.project)) return;
        this.stepOneNetwork();
        return;
      case 'reset':
        this.coldRestart();
        return;
      case 'warmRestart':
        this.warmRestart();
        return;
      case 'setCycle':
        this.setCycle(m.cycleMs);
        return;
      case 'setBreakpoints':
        this.breakpoints = new Set(m.networks);
        this.postFrame();
        return;
      case 'write':
        this.requirePlc().write(m.name, this.valueOf(m.name, m.input));
        this.postFrame();
        return;
      case 'force':
        this.requirePlc().force(m.name, this.valueOf(m.name, m.input));
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
        this.trendRequest = { names: [...m.names], capacity: m.capacity };
        this.configureTrend();
        return;
      case 'setInputs':
        this.gatewayInputs = { ...this.gatewayInputs, ...m.values };
        this.plc?.setInputs(m.values);
        return;
      case 'subscribeOutputs':
        this.outputsSubscribed = m.enabled;
        this.lastOutputs = undefined;
        if (m.enabled && this.plc) this.postOutputs();
        return;
    }
  }

  // ---- loading and online change -------------------------------------------------------

  /** Compiles the document. Returns false (and reports why) when it has errors. */
  private load(project: Project): boolean {
    const fingerprint = programFingerprint(project);
    if (this.plc && fingerprint === (this.pending?.fingerprint ?? this.fingerprint)) return true;
    const { program, diagnostics } = this.deps.engine.compile(project);
    const online = this.plc !== undefined && (this.mode !== 'stopped' || this.plc.scanCount > 0);
    if (!program || diagnostics.some((d) => d.severity === 'error')) {
      this.deps.post({ type: 'compiled', ok: false, online, diagnostics });
      return false;
    }
    this.clock.set(online ? this.clock.now() : 0);
    const plc = this.deps.engine.createPlc(program, { cycleMs: this.cycleMs, clock: this.clock });
    const layout = buildLayout(project, plc.pou, plc.variableNames(), this.cycleMs);
    const next: LoadedProgram = { plc, layout, fingerprint };
    if (online) {
      this.pending = next;
      // Applied at the next scan boundary: now if the PLC is between scans and not inside a burst.
      if (this.plc?.nextNetwork === -1) this.applyPending(diagnostics);
      else this.pendingDiagnostics = diagnostics;
    } else {
      this.install(next, false, diagnostics);
    }
    return true;
  }

  private applyPending(diagnostics: readonly Diagnostic[] = this.pendingDiagnostics): void {
    const next = this.pending;
    const old = this.plc;
    const oldLayout = this.layout;
    if (!next) return;
    this.pending = undefined;
    if (old && oldLayout) {
      // Online change: variables present in both programs with the same type keep their values;
      // FB instances and edge memories start fresh (the engine cannot move their internal state).
      const oldTypes = new Map(oldLayout.variables.map((v) => [v.name.toUpperCase(), v]));
      for (const v of next.layout.variables) {
        const before = oldTypes.get(v.name.toUpperCase());
        if (v.role === 'pin' || !before || before.type !== v.type) continue;
        try {
          next.plc.write(v.name, old.read(before.name));
        } catch {
          // A constant or a name the new program cannot write: it keeps its initial value.
        }
      }
      this.scanBase += old.scanCount;
    }
    this.install(next, true, diagnostics);
  }

  private install(
    next: LoadedProgram,
    online: boolean,
    diagnostics: readonly Diagnostic[],
  ): void {
    const old = this.plc;
    if (old) {
      for (const [name, value] of old.forced()) {
        try {
          next.plc.force(name, value);
        } catch {
          // The forced variable no longer exists.
        }
      }
    }
    if (Object.keys(this.gatewayInputs).length > 0) next.plc.setInputs(this.gatewayInputs);
    this.plc = next.plc;
    this.layout = next.layout;
    this.fingerprint = next.fingerprint;
    this.lastOutputs = undefined;
    this.configureTrend();
    if (!online) this.resetCounters();
    this.deps.post({ type: 'compiled', ok: true, online, diagnostics, layout: next.layout });
    this.postFrame();
  }

  private configureTrend(): void {
    const known = new Map((this.layout?.variables ?? []).map((v) => [v.name.toUpperCase(), v.name]));
    const names = this.trendRequest.names.flatMap((n) => known.get(n.toUpperCase()) ?? []);
    this.trend.configure(names, this.trendRequest.capacity);
  }

  private requirePlc(): Plc {
    if (!this.plc) throw new Error('no program is loaded: press Run or Step first');
    return this.plc;
  }

  // ---- commands ----------------------------------------------------------------------------

  private refuseIfFaulted(): boolean {
    const fault = this.plc?.fault;
    if (!fault) return false;
    this.deps.post({ type: 'error', message: `the PLC is faulted (${fault.message}); press Reset or Warm restart to clear the fault` });
    this.postFrame();
    return true;
  }

  private run(): void {
    if (!this.requirePlc() || this.refuseIfFaulted()) return;
    this.stopActivity();
    this.resumeAt = this.breakpointHit;
    this.breakpointHit = undefined;
    this.mode = 'running';
    this.timeline = { startWall: this.deps.scheduler.now(), baseTime: this.nextScanTime, k: 0 };
    this.postFrame();
    this.scheduleTick(0);
  }

  private pause(): void {
    if (this.mode !== 'running') return;
    this.stopActivity();
    this.mode = 'paused';
    this.postFrame();
  }

  private startBatch(scans: number): void {
    if (!this.requirePlc() || this.refuseIfFaulted()) return;
    this.stopActivity();
    this.resumeAt = this.breakpointHit;
    this.breakpointHit = undefined;
    this.batchRemaining = Math.max(1, Math.floor(scans));
    this.mode = 'running';
    this.batchTick();
  }

  private stepOneNetwork(): void {
    const plc = this.requirePlc();
    if (this.refuseIfFaulted()) return;
    this.stopActivity();
    if (plc.nextNetwork === -1 && this.pending) this.applyPending();
    const current = this.requirePlc();
    if (current.nextNetwork === -1) this.beginScan(this.nextScanTime);
    this.breakpointHit = undefined;
    this.resumeAt = undefined;
    const t0 = this.wallNow();
    const report = current.stepNetwork();
    this.stepExecMs += this.wallNow() - t0;
    if (report.fault) this.endScan(this.stepExecMs, report.fault);
    else if (report.scanDone) this.endScan(this.stepExecMs, undefined);
    if (this.mode !== 'faulted') this.mode = 'paused';
    this.postFrame();
  }

  private coldRestart(): void {
    this.stopActivity();
    if (this.pending) this.applyPending();
    this.clock.set(0);
    if (this.plc) {
      this.plc.clearFault();
      this.plc.coldRestart();
    }
    this.resetCounters();
    this.mode = 'stopped';
    this.postFrame();
  }

  private warmRestart(): void {
    const plc = this.requirePlc();
    const wasRunning = this.mode === 'running' && this.timeline !== undefined;
    this.stopActivity();
    plc.clearFault();
    plc.warmRestart();
    this.breakpointHit = undefined;
    this.resumeAt = undefined;
    this.mode = 'stopped';
    if (wasRunning) this.run();
    else this.postFrame();
  }

  private setCycle(cycleMs: number): void {
    if (!Number.isFinite(cycleMs) || cycleMs < 0 || cycleMs > 60_000) {
      throw new Error(`cycle time ${cycleMs} ms is out of range (0 to 60000 ms)`);
    }
    this.cycleMs = cycleMs;
    if (this.layout) this.layout = { ...this.layout, cycleMs };
    if (this.timeline) this.timeline = { startWall: this.deps.scheduler.now(), baseTime: this.nextScanTime, k: 0 };
    this.postFrame();
  }

  private resetCounters(): void {
    this.nextScanTime = 0;
    this.scanStartTime = 0;
    this.lastScanTime = 0;
    this.scanBase = 0;
    this.stats = { last: 0, sum: 0, count: 0, max: 0 };
    this.overruns = 0;
    this.breakpointHit = undefined;
    this.resumeAt = undefined;
    this.trend.clear();
  }

  private stopActivity(): void {
    this.cancelTimer?.();
    this.cancelTimer = undefined;
    this.timeline = undefined;
    this.batchRemaining = 0;
  }

  // ---- scanning ------------------------------------------------------------------------------

  private beginScan(startTime: number): void {
    this.clock.set(startTime);
    this.scanStartTime = startTime;
    this.stepExecMs = 0;
  }

  private endScan(execMs: number, fault: Fault | undefined): ScanOutcome {
    const s = this.stats;
    s.last = execMs;
    s.sum += execMs;
    s.count++;
    if (execMs > s.max) s.max = execMs;
    this.lastScanTime = this.scanStartTime;
    this.nextScanTime = this.scanStartTime + this.cycleMs;
    const plc = this.plc!;
    if (fault) {
      this.stopActivity();
      this.mode = 'faulted';
      return 'fault';
    }
    if (this.trend.active) this.trend.record(this.scanBase + plc.scanCount, this.scanStartTime, (n) => plc.read(n));
    if (this.outputsSubscribed) this.postOutputs();
    return 'done';
  }

  /** Finishes the current scan or runs a whole one, pausing before a network with a breakpoint. */
  private scanOnce(startTime: number): ScanOutcome {
    if (this.pending && this.plc!.nextNetwork === -1) this.applyPending();
    const plc = this.plc!;
    if (this.breakpoints.size === 0 && plc.nextNetwork === -1) {
      this.beginScan(startTime);
      const report = plc.scan();
      return this.endScan(report.execMs, report.fault);
    }
    for (;;) {
      const atBoundary = plc.nextNetwork === -1;
      const next = atBoundary ? 0 : plc.nextNetwork;
      if (this.breakpoints.has(next) && this.resumeAt !== next) {
        this.breakpointHit = next;
        return 'break';
      }
      this.resumeAt = undefined;
      if (atBoundary) this.beginScan(startTime);
      const t0 = this.wallNow();
      const report = plc.stepNetwork();
      this.stepExecMs += this.wallNow() - t0;
      if (report.fault) return this.endScan(this.stepExecMs, report.fault);
      if (report.scanDone) return this.endScan(this.stepExecMs, undefined);
    }
  }

  private scheduleTick(delayMs: number): void {
    this.cancelTimer = this.deps.scheduler.schedule(() => {
      this.cancelTimer = undefined;
      this.runTick();
    }, delayMs);
  }

  /** Run: paced by the wall clock; PLC time is real time (Run start + k cycles, or the wall clock at 0 ms). */
  private runTick(): void {
    const tl = this.timeline;
    if (this.mode !== 'running' || !tl) return;
    const sliceEnd = this.wallNow() + SLICE_MS;
    let outcome: ScanOutcome = 'done';
    if (this.cycleMs === 0) {
      do {
        tl.k++;
        outcome = this.scanOnce(tl.baseTime + (this.deps.scheduler.now() - tl.startWall));
      } while (outcome === 'done' && this.wallNow() < sliceEnd);
    } else {
      const dueK = Math.floor((this.deps.scheduler.now() - tl.startWall) / this.cycleMs) + 1;
      if (dueK - tl.k > MAX_BEHIND_SCANS) {
        this.overruns += dueK - tl.k - 1;
        tl.k = dueK - 1;
      }
      while (tl.k < dueK && outcome === 'done') {
        outcome = this.scanOnce(tl.baseTime + tl.k * this.cycleMs);
        tl.k++;
        if (this.wallNow() >= sliceEnd) break;
      }
    }
    if (outcome !== 'done') {
      this.stopAt(outcome);
      return;
    }
    this.maybePostFrame();
    const wait = this.cycleMs === 0 ? 0 : tl.startWall + tl.k * this.cycleMs - this.deps.scheduler.now();
    this.scheduleTick(Math.max(0, wait));
  }

  /** Step N scans: as fast as possible on the virtual clock (one cycle per scan), in slices. */
  private batchTick(): void {
    const sliceEnd = this.wallNow() + SLICE_MS;
    let outcome: ScanOutcome = 'done';
    while (this.batchRemaining > 0 && outcome === 'done') {
      outcome = this.scanOnce(this.nextScanTime);
      if (outcome === 'done') this.batchRemaining--;
      if (this.wallNow() >= sliceEnd) break;
    }
    if (outcome !== 'done') {
      this.stopAt(outcome);
      return;
    }
    if (this.batchRemaining > 0) {
      this.maybePostFrame();
      this.cancelTimer = this.deps.scheduler.schedule(() => {
        this.cancelTimer = undefined;
        if (this.mode === 'running') this.batchTick();
      }, 0);
      return;
    }
    this.mode = 'paused';
    this.postFrame();
  }

  private stopAt(outcome: 'break' | 'fault'): void {
    this.stopActivity();
    this.mode = outcome === 'fault' ? 'faulted' : 'paused';
    this.postFrame();
  }

  // ---- values ----------------------------------------------------------------------------------

  private valueOf(name: string, input: SimValueInput): Value {
    if ('value' in input) return input.value;
    const type = this.typeOf(name);
    if (!type) throw new Error(`unknown variable "${name}"`);
    const parsed = this.deps.engine.parseValue(type, input.text);
    if (!parsed.ok) throw new Error(`${name}: ${parsed.message}`);
    return parsed.value;
  }

  private typeOf(name: string): string | undefined {
    const key = name.toUpperCase();
    const known = this.layout?.variables.find((v) => v.name.toUpperCase() === key);
    if (known) return known.type;
    const loc = parseLocation(name);
    if (!loc) return undefined;
    return { X: 'BOOL', B: 'BYTE', W: 'WORD', D: 'DWORD', L: 'LWORD' }[loc.size];
  }

  // ---- posting ---------------------------------------------------------------------------------

  private postOutputs(): void {
    const plc = this.plc!;
    const outputs = plc.outputs();
    if (!outputsChanged(this.lastOutputs, outputs)) return;
    this.lastOutputs = outputs;
    this.deps.post({ type: 'outputs', scan: this.scanBase + plc.scanCount, timeMs: this.lastScanTime, outputs });
  }

  private maybePostFrame(): void {
    if (this.deps.scheduler.now() - this.lastFrameWall >= FRAME_INTERVAL_MS) this.postFrame();
  }

  postFrame(): void {
    this.lastFrameWall = this.deps.scheduler.now();
    const frame = this.frame();
    this.deps.post({ type: 'frame', frame }, [frame.elements.buffer, frame.vlinks.buffer, frame.executed.buffer]);
  }

  private frame(): SimFrame {
    const plc = this.plc;
    const layout = this.layout;
    const s = this.stats;
    const power = plc && layout ? packPower(plc, layout) : undefined;
    const trend = this.trend.take();
    const fault = plc?.fault;
    return {
      mode: this.mode,
      scan: this.scanBase + (plc?.scanCount ?? 0),
      timeMs: plc && plc.nextNetwork !== -1 ? this.scanStartTime : this.lastScanTime,
      cycleMs: this.cycleMs,
      exec: { lastMs: s.last, avgMs: s.count ? s.sum / s.count : 0, maxMs: s.max },
      ...(fault ? { fault } : {}),
      nextNetwork: plc?.nextNetwork ?? -1,
      ...(this.breakpointHit !== undefined ? { breakpointHit: this.breakpointHit } : {}),
      overruns: this.overruns,
      elements: power?.elements ?? new Uint8Array(0),
      vlinks: power?.vlinks ?? new Uint8Array(0),
      executed: power?.executed ?? new Uint8Array(0),
      values: plc && layout ? readValues(plc, layout) : [],
      forced: plc ? [...plc.forced()] : [],
      ...(trend ? { trend } : {}),
    };
  }
}
