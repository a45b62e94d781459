// Run/Pause/Step/Reset controls and the status line (mode, scan, PLC time, execution time).
import { useEffect, useState } from 'react';
import { taskSchedule } from '../../engine/compile/taskSchedule';
import { useDocument, type DocumentState } from '../../store/documentStore';
import type { SimState } from '../../store/simState';
import { useSimCommands } from '../hardware/useHardwareStepping';
import { useSim, useSimStore } from './simContext';
import './sim.css';

const selectMode = (s: SimState) => s.mode;
const selectScan = (s: SimState) => s.scan;
const selectTime = (s: SimState) => s.timeMs;
const selectCycle = (s: SimState) => s.cycleMs;
const selectExecLast = (s: SimState) => s.exec.lastMs;
const selectExecAvg = (s: SimState) => s.exec.avgMs;
const selectExecMax = (s: SimState) => s.exec.maxMs;
const selectOverruns = (s: SimState) => s.overruns;

/**
 * The project's cyclic task interval: the cycle a real PLC would run this program at; tasks at
 * different intervals: their common tick (one scan per tick), which the Cycle field then only shows.
 */
const selectTaskCycle = (s: DocumentState): number | undefined => {
  const schedule = taskSchedule(s.project.tasks);
  return schedule.multiRate ? schedule.tickMs : s.project.tasks[0]?.cycleMs;
};
const selectMultiRate = (s: DocumentState): boolean => taskSchedule(s.project.tasks).multiRate;

const MODE_LABEL = { stopped: 'Stopped', running: 'Running', paused: 'Paused', faulted: 'Faulted' } as const;

/**
 * Last / average / maximum execution time, always in ms with microsecond digits: the unit and the
 * number of decimals never change while the program runs (they used to follow the maximum, so the
 * figure jumped between µs and ms).
 */
export function formatExec(last: number, avg: number, max: number): string {
  return `${[last, avg, max].map((v) => (Number.isFinite(v) ? v : 0).toFixed(3)).join(' / ')} ms`;
}
export const formatPlcTime = (ms: number): string => (ms < 10_000 ? `${ms} ms` : `${(ms / 1000).toFixed(2)} s`);

export function SimToolbar() {
  const sim = useSimStore();
  // Run/Step/Reset go through the hardware stepping lease: stepping with the gateway attached asks first.
  const commands = useSimCommands();
  const mode = useSim(selectMode);
  const taskCycle = useDocument(selectTaskCycle);
  const [stepCount, setStepCount] = useState('10');
  useEffect(() => {
    // A project brings its task's cycle time; the field below can still override it for this session.
    if (taskCycle !== undefined && taskCycle >= 0 && taskCycle !== sim.getState().cycleMs) sim.getState().setCycle(taskCycle);
  }, [taskCycle, sim]);
  useEffect(() => {
    // Keep the scripting handle even if the shell assigned window.rungsmith after the store was made.
    const w = window as unknown as { rungsmith?: Record<string, unknown> };
    if (w.rungsmith?.simStore !== sim) w.rungsmith = { ...(w.rungsmith ?? {}), simStore: sim };
  }, [sim]);

  const running = mode === 'running';
  const faulted = mode === 'faulted';
  const n = Number.parseInt(stepCount, 10);
  const stepN = Number.isFinite(n) && n >= 1 ? Math.min(n, 1_000_000) : undefined;

  return (
    <div className="rs-sim-toolbar" role="toolbar" aria-label="Simulation" data-testid="sim-toolbar">
      <button type="button" className="rs-sim-btn rs-sim-run" title="Run (F5): compile the document and scan in real time"
        aria-keyshortcuts="F5" disabled={running || faulted} onClick={commands.run} data-testid="sim-run">
        ▶ Run
      </button>
      <button type="button" className="rs-sim-btn" title="Stop (Shift+F5): pause after the current scan" aria-keyshortcuts="Shift+F5" disabled={!running}
        onClick={() => sim.getState().pause()} data-testid="sim-pause">
        ❚❚ Pause
      </button>
      <button type="button" className="rs-sim-btn" title="Step one scan (virtual clock: PLC time advances by one cycle)"
        disabled={running || faulted} onClick={() => commands.step({ kind: 'scans', scans: 1 })} data-testid="sim-step-scan">
        Step scan
      </button>
      <span className="rs-sim-group">
        <button type="button" className="rs-sim-btn" title="Step N scans" disabled={running || faulted || stepN === undefined}
          onClick={() => stepN && commands.step({ kind: 'scans', scans: stepN })} data-testid="sim-step-n">
          Step
        </button>
        <input className="rs-sim-number" aria-label="Scans to step" value={stepCount} inputMode="numeric"
          onChange={(e) => setStepCount(e.target.value)} data-testid="sim-step-count" />
        <span className="rs-sim-unit">scans</span>
      </span>
      <button type="button" className="rs-sim-btn" title="Step over (F10): the next network runs whole, calls included (the next network is highlighted)"
        aria-keyshortcuts="F10" disabled={running || faulted} onClick={() => commands.step({ kind: 'network' })} data-testid="sim-step-network">
        Step network
      </button>
      <button type="button" className="rs-sim-btn" title="Step into (F11): a call of a function block or function stops before its body's first network, shown in the callee's tab"
        aria-keyshortcuts="F11" disabled={running || faulted} onClick={() => commands.step({ kind: 'network', into: true })} data-testid="sim-step-into">
        Step into
      </button>
      <button type="button" className="rs-sim-btn" title="Step out (Shift+F11): the rest of the function block's or function's body runs; execution stops at the caller's next network or statement"
        aria-keyshortcuts="Shift+F11" disabled={running || faulted} onClick={() => commands.step({ kind: 'network', out: true })} data-testid="sim-step-out">
        Step out
      </button>
      <button type="button" className="rs-sim-btn" title="Reset (cold restart): every variable to its initial value"
        onClick={commands.reset} data-testid="sim-reset">
        ■ Reset
      </button>
      <button type="button" className="rs-sim-btn" title="Warm restart: RETAIN and M/SM/RM variables keep their values, the others restart"
        onClick={commands.warmRestart} data-testid="sim-warm">
        Warm restart
      </button>
      <CycleInput />
      <SimStatus />
    </div>
  );
}

function CycleInput() {
  const sim = useSimStore();
  const cycle = useSim(selectCycle);
  const fixed = useDocument(selectMultiRate);
  const [text, setText] = useState(String(cycle));
  useEffect(() => setText(String(cycle)), [cycle]);
  const commit = () => {
    const value = Number(text);
    if (Number.isFinite(value) && value >= 0 && value <= 60_000) sim.getState().setCycle(Math.round(value));
    else setText(String(cycle));
  };
  return (
    <label className="rs-sim-group" title={fixed
      ? "Cycle time: the tasks run at different intervals or on a trigger, so a scan is their common tick (change the tasks in the Tasks dialog)"
      : 'Cycle time: a scan starts every cycle (0 = as fast as possible)'}>
      <span className="rs-sim-unit">Cycle</span>
      <input className="rs-sim-number" aria-label="Cycle time in ms" value={text} inputMode="numeric" data-testid="sim-cycle" readOnly={fixed}
        onChange={(e) => setText(e.target.value)} onBlur={commit} onKeyDown={(e) => e.key === 'Enter' && commit()} />
      <span className="rs-sim-unit">ms</span>
    </label>
  );
}

function SimStatus() {
  const mode = useSim(selectMode);
  const scan = useSim(selectScan);
  const time = useSim(selectTime);
  const last = useSim(selectExecLast);
  const avg = useSim(selectExecAvg);
  const max = useSim(selectExecMax);
  const overruns = useSim(selectOverruns);
  return (
    <span className="rs-sim-status" data-testid="sim-status" aria-live="polite">
      <span className={`rs-sim-mode rs-sim-mode-${mode}`} data-testid="sim-mode">{MODE_LABEL[mode]}</span>
      <span title="Scans since the last cold restart">scan <b data-testid="sim-scan">{scan}</b></span>
      <span title="PLC time at the start of the last scan">t <b data-testid="sim-time">{formatPlcTime(time)}</b></span>
      <span title="Execution time per scan: last / average / maximum">
        exec <b data-testid="sim-exec">{formatExec(last, avg, max)}</b>
      </span>
      {overruns > 0 && <span title="Scans dropped because the worker could not keep the cycle">overruns {overruns}</span>}
    </span>
  );
}
