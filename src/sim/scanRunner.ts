// Executes scans for the session: the PLC clock, Run paced by the wall clock, Step N in slices,
// single-network steps, breakpoints and execution-time statistics. The session owns the mode and
// the program; the runner reports back through RunnerHost.
import type { Fault, Plc, StepFrame } from '../engine/api';
import { breakpointAt, needsStepInto, nextStop, step, type Breakpoint, type StepKind } from '../engine/runtime/breakpoints';
import type { ExecStats } from './protocol';
import type { Scheduler } from './scheduler';
import { SimClock } from './simClock';

/** One burst of scans never holds the worker longer than this, so Pause is handled promptly. */
const SLICE_MS = 12;
/** When the worker falls further behind than this many cycles, older scans are dropped (counted as overruns). */
const MAX_BEHIND_SCANS = 50;

export type ScanOutcome = 'done' | 'break' | 'fault';

export interface RunnerHost {
  /** The PLC to scan (the session replaces it on an online change). */
  current(): Plc;
  /** At every scan boundary, before the next scan starts: a pending online change goes in here. */
  atBoundary(): void;
  /** After every completed scan (not after a fault). */
  scanCompleted(plc: Plc, startTimeMs: number): void;
  /** Execution stopped by itself: at a breakpoint, on a fault, or at the end of Step N ('done'). */
  stopped(outcome: ScanOutcome): void;
  /** Between bursts while running (frames at display rate). */
  progress(): void;
  /** An unexpected error stopped execution (a bug, not a PLC fault): it is reported, never swallowed. */
  crashed(error: unknown): void;
}

interface RunTimeline {
  /** Wall time and PLC time when Run started (or the cycle changed). */
  readonly startWall: number;
  readonly baseTime: number;
  /** Scans started since then. */
  k: number;
}

export class ScanRunner {
  readonly clock = new SimClock();
  cycleMs = 10;
  /** Breakpoints by POU and network (in a body: every instance, or the one named). */
  breakpoints: readonly Breakpoint[] = [];
  /** Where execution stopped at a breakpoint: the POU, the instance and the network. */
  breakpointHit: StepFrame | undefined;
  overruns = 0;
  /** Scans that started a cycle or more after their time (the worker was busy): missed cycles, caught up or dropped. */
  late = 0;
  /** A breakpoint being resumed from (its position): the next check there lets it run. */
  private resumeAt: string | undefined;
  private nextScanTime = 0;
  private scanStartTime = 0;
  private lastScanTime = 0;
  private stepExecMs = 0;
  private stats = { last: 0, sum: 0, count: 0, max: 0 };
  private timeline: RunTimeline | undefined;
  private batchRemaining = 0;
  private cancelTimer: (() => void) | undefined;
  /** A poll is running the due scans (never re-entered). */
  private polling = false;

  constructor(
    private readonly host: RunnerHost,
    private readonly scheduler: Scheduler,
    private readonly wallNow: () => number,
  ) {}

  /** True while Run is pacing scans (not Step N). */
  get runningLive(): boolean {
    return this.timeline !== undefined;
  }

  /** PLC time of the scan in progress, or of the last completed scan at a boundary. */
  timeMs(plc: Plc | undefined): number {
    return plc && plc.nextNetwork !== -1 ? this.scanStartTime : this.lastScanTime;
  }

  exec(): ExecStats {
    const s = this.stats;
    return { lastMs: s.last, avgMs: s.count ? s.sum / s.count : 0, maxMs: s.max, late: this.late };
  }

  resetCounters(): void {
    this.nextScanTime = 0;
    this.scanStartTime = 0;
    this.lastScanTime = 0;
    this.stats = { last: 0, sum: 0, count: 0, max: 0 };
    this.overruns = 0;
    this.late = 0;
    this.breakpointHit = undefined;
    this.resumeAt = undefined;
  }

  /** Scans were run outside the runner (a scenario replay) up to one that started at `lastScanTime`: go on from there. */
  continueAfter(lastScanTime: number): void {
    this.lastScanTime = lastScanTime;
    this.scanStartTime = lastScanTime;
    this.nextScanTime = lastScanTime + this.cycleMs;
  }

  setCycle(cycleMs: number): void {
    this.cycleMs = cycleMs;
    if (this.timeline) this.timeline = { startWall: this.scheduler.now(), baseTime: this.nextScanTime, k: 0 };
  }

  stop(): void {
    this.cancelTimer?.();
    this.cancelTimer = undefined;
    this.timeline = undefined;
    this.batchRemaining = 0;
  }

  /** Run: scans paced by the wall clock; PLC time is real time (Run start + k cycles, or the wall clock at 0 ms). */
  startRun(): void {
    this.stop();
    this.resume();
    this.timeline = { startWall: this.scheduler.now(), baseTime: this.nextScanTime, k: 0 };
    this.schedule(() => this.runTick(), 0);
  }

  /**
   * Called from long work on the scanning thread (an online change's compile, at its yield points):
   * while Run paces scans, the scans that are due run now instead of waiting for that work to end.
   */
  poll(): void {
    const tl = this.timeline;
    if (!tl || this.polling || this.cycleMs === 0) return;
    if (this.scheduler.now() < tl.startWall + tl.k * this.cycleMs) return;
    this.polling = true;
    try {
      this.cancelTimer?.();
      this.cancelTimer = undefined;
      this.guarded(() => this.runTick());
    } finally {
      this.polling = false;
    }
  }

  /** Step N scans: as fast as possible on the virtual clock (one cycle per scan), in slices. */
  startBatch(scans: number): void {
    this.stop();
    this.resume();
    this.batchRemaining = Math.max(1, Math.floor(scans));
    this.guarded(() => this.batchTick());
  }

  /**
   * Executes one network or ST/IL statement (starting a scan if needed), ignoring breakpoints
   * (engine/runtime/breakpoints.ts step). Over: it runs whole, calls included (after a body's last
   * one the step comes back out to the caller). Into: a call stops before its body's first network
   * or statement. Out: the rest of the body runs, to the caller's next stop.
   */
  stepNetwork(kind: StepKind = 'over'): Fault | undefined {
    this.stop();
    if (this.host.current().nextNetwork === -1) this.host.atBoundary();
    const plc = this.host.current();
    if (plc.nextNetwork === -1) this.beginScan(this.nextScanTime);
    this.breakpointHit = undefined;
    this.resumeAt = undefined;
    const t0 = this.wallNow();
    // Over inside a body: on until execution stands at this depth again (next network or statement) or above.
    const report = step(plc, kind);
    this.stepExecMs += this.wallNow() - t0;
    if (report.fault) this.endScan(plc, this.stepExecMs, report.fault);
    else if (report.scanDone) this.endScan(plc, this.stepExecMs, undefined);
    return report.fault;
  }

  private resume(): void {
    this.resumeAt = this.breakpointHit ? positionKey(this.host.current()) : undefined;
    this.breakpointHit = undefined;
  }

  private beginScan(startTime: number): void {
    this.clock.set(startTime);
    this.scanStartTime = startTime;
    this.stepExecMs = 0;
  }

  private endScan(plc: Plc, execMs: number, fault: Fault | undefined): ScanOutcome {
    const s = this.stats;
    s.last = execMs;
    s.sum += execMs;
    s.count++;
    if (execMs > s.max) s.max = execMs;
    this.lastScanTime = this.scanStartTime;
    this.nextScanTime = this.scanStartTime + this.cycleMs;
    if (fault) {
      this.stop();
      return 'fault';
    }
    this.host.scanCompleted(plc, this.scanStartTime);
    return 'done';
  }

  /** Finishes the current scan or runs a whole one, pausing before a network with a breakpoint. */
  private scanOnce(startTime: number): ScanOutcome {
    if (this.host.current().nextNetwork === -1) this.host.atBoundary();
    const plc = this.host.current();
    if (this.breakpoints.length === 0 && plc.nextNetwork === -1) {
      this.beginScan(startTime);
      const report = plc.scan();
      return this.endScan(plc, report.execMs, report.fault);
    }
    // Breakpoints inside bodies are reached by stepping into calls.
    const step = needsStepInto(plc, this.breakpoints) ? { into: true } : undefined;
    for (;;) {
      const atBoundary = plc.nextNetwork === -1;
      const hit = breakpointAt(plc, this.breakpoints);
      if (hit) {
        const at = positionKey(plc);
        if (this.resumeAt !== at) {
          this.breakpointHit = nextStop(plc);
          this.resumeAt = undefined;
          return 'break';
        }
      }
      this.resumeAt = undefined;
      if (atBoundary) this.beginScan(startTime);
      const t0 = this.wallNow();
      const report = plc.stepNetwork(step);
      this.stepExecMs += this.wallNow() - t0;
      if (report.fault) return this.endScan(plc, this.stepExecMs, report.fault);
      if (report.scanDone) return this.endScan(plc, this.stepExecMs, undefined);
    }
  }

  private schedule(fn: () => void, delayMs: number): void {
    this.cancelTimer = this.scheduler.schedule(() => {
      this.cancelTimer = undefined;
      this.guarded(fn);
    }, delayMs);
  }

  private guarded(fn: () => void): void {
    try {
      fn();
    } catch (error) {
      this.stop();
      this.host.crashed(error);
    }
  }

  private runTick(): void {
    const tl = this.timeline;
    if (!tl) return;
    const sliceEnd = this.wallNow() + SLICE_MS;
    let outcome: ScanOutcome = 'done';
    if (this.cycleMs === 0) {
      do {
        tl.k++;
        outcome = this.scanOnce(tl.baseTime + (this.scheduler.now() - tl.startWall));
      } while (outcome === 'done' && this.wallNow() < sliceEnd);
    } else {
      const dueK = Math.floor((this.scheduler.now() - tl.startWall) / this.cycleMs) + 1;
      if (dueK - tl.k > 1) this.late += dueK - tl.k - 1;
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
      this.stop();
      this.host.stopped(outcome);
      return;
    }
    this.host.progress();
    if (this.timeline !== tl) return; // paused or restarted by the host meanwhile
    const wait = this.cycleMs === 0 ? 0 : tl.startWall + tl.k * this.cycleMs - this.scheduler.now();
    this.schedule(() => this.runTick(), Math.max(0, wait));
  }

  private batchTick(): void {
    const sliceEnd = this.wallNow() + SLICE_MS;
    let outcome: ScanOutcome = 'done';
    while (this.batchRemaining > 0 && outcome === 'done') {
      outcome = this.scanOnce(this.nextScanTime);
      if (outcome === 'done') this.batchRemaining--;
      if (this.wallNow() >= sliceEnd) break;
    }
    if (outcome !== 'done' || this.batchRemaining === 0) {
      this.stop();
      this.host.stopped(outcome);
      return;
    }
    this.host.progress();
    this.schedule(() => this.batchTick(), 0);
  }
}

/** Where execution stands, as a key (a scan boundary: empty). */
function positionKey(plc: Plc): string {
  return plc
    .position()
    .map((f) => `${f.pou}/${f.instance ?? ''}/${f.network}/${f.line ?? ''}`)
    .join('>');
}
