// Trend (timing diagram) of chosen signals over the last N scans, drawn with uPlot: a lane per
// signal against the simulated time (src/editor/sim/trendChart.ts). A trigger (a BOOL's edge, a
// number crossing a level) evaluated on every scan in the worker captures a window around it with
// a share before it, once (single) or again and again (normal); the display can be frozen while
// the PLC runs on; two cursors read every signal and the time between them; CSV and PNG export.
import { useEffect, useMemo, useRef, useState } from 'react';
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import type { TrendTrigger } from '../../sim/protocol';
import type { TrendBuffer } from '../../sim/trendBuffer';
import type { SimState } from '../../store/simState';
import { MAX_TREND_SCANS } from '../../store/simStore';
import { downloadBlob, downloadText } from '../history/download';
import { useSim, useSimStore } from './simContext';
import { formatTime, trendData, trendLayout, trendOptions, type TrendMarks, type TrendSignal, type TrendView } from './trendChart';
import { trendImage } from './trendPng';
import { cursorReadout, nearestIndex, trendCsv } from './trendTools';
import { useConfigurationInstances, useWatchCandidates } from './useWatchCandidates';
import { VariablePicker } from './VariablePicker';
import { otherPlantNameInfo, plantNameInfo, usePlantCandidates } from '../plant/plantWatch';
import { useDocument, type DocumentState } from '../../store/documentStore';

const selectPlantConfig = (s: DocumentState) => s.project.plant;
import './sim.css';

const selectTrend = (s: SimState) => s.trend;
const selectTrendNames = (s: SimState) => s.trendNames;
const selectCapacity = (s: SimState) => s.trendCapacity;
const selectCapture = (s: SimState) => s.trendCapture;
const selectHistory = (s: SimState) => s.history;

interface Cursors {
  readonly a?: number | undefined;
  readonly b?: number | undefined;
}

export function TrendPanel() {
  const sim = useSimStore();
  const plant = useDocument(selectPlantConfig);
  const names = useSim(selectTrendNames);
  const capacity = useSim(selectCapacity);
  const live = useSim(selectTrend);
  const capture = useSim(selectCapture);
  const history = useSim(selectHistory);
  const readable = useWatchCandidates();
  const machine = usePlantCandidates();
  // The program's names, then the machine's (`tank.level`).
  const candidates = useMemo(() => [...readable, ...machine], [readable, machine]);
  const instances = useConfigurationInstances();
  const [capacityText, setCapacityText] = useState(String(capacity));
  const [capacityError, setCapacityError] = useState<string>();
  const [frozen, setFrozen] = useState<TrendBuffer>();
  const [cursors, setCursors] = useState<Cursors>({});
  const chart = useRef<uPlot | undefined>(undefined);
  useEffect(() => setCapacityText(String(capacity)), [capacity]);
  // What is drawn: a frozen picture, else the trigger's capture, else the live window.
  const shown: TrendBuffer = frozen ?? capture?.samples ?? live;
  const signals = useMemo<TrendSignal[]>(
    () => shown.names.map((name) => ({ name, type: (candidates.find((t) => t.name === name) ?? candidates.find((t) => t.name.toUpperCase() === name.toUpperCase()))?.type ?? 'LREAL' })),
    [shown.names, candidates],
  );
  const triggerTime = capture && !frozen ? capture.samples.timesMs[capture.triggerIndex] : undefined;
  const marks = useMemo<TrendMarks>(() => ({ ...cursors, trigger: triggerTime }), [cursors, triggerTime]);

  const add = (text: string) => {
    const typed = text.trim();
    // Spelt exactly first: `tank.Pump` (the contactor) is not `tank.pump` (its speed).
    const known = candidates.find((c) => c.name === typed) ?? candidates.find((c) => c.name.toUpperCase() === typed.toUpperCase());
    if (known && !names.includes(known.name)) sim.getState().toggleTrend(known.name);
  };
  const historyScans = history ? history.last - history.first + 1 : undefined;
  const commitCapacity = (text = capacityText) => {
    const n = Number.parseInt(text, 10);
    if (!Number.isFinite(n) || n < 10) {
      setCapacityError('The window needs at least 10 scans.');
      setCapacityText(String(capacity));
      return;
    }
    if (n > MAX_TREND_SCANS) {
      setCapacityError(`The window holds at most ${MAX_TREND_SCANS} scans (the scan history's length).`);
      setCapacityText(String(capacity));
      return;
    }
    setCapacityError(undefined);
    sim.getState().setTrendCapacity(n);
  };
  /** A click on the chart places cursor A, then B; later clicks move the nearer one (Shift: B). */
  const pick = (t: number, shift: boolean) => {
    const i = nearestIndex(shown.timesMs, t);
    if (i < 0) return;
    const at = shown.timesMs[i]!;
    setCursors((c) => {
      if (shift) return { ...c, b: at };
      if (c.a === undefined) return { ...c, a: at };
      if (c.b === undefined) return { ...c, b: at };
      return Math.abs(c.a - at) <= Math.abs(c.b - at) ? { ...c, a: at } : { ...c, b: at };
    });
  };
  const exportCsv = () => downloadText(`trend-${shown.scans[0] ?? 0}-${shown.scans[shown.scans.length - 1] ?? 0}.csv`, trendCsv(shown, signals));
  const exportPng = () => {
    const c = chart.current;
    if (!c) return;
    const style = getComputedStyle(c.root.parentElement ?? document.body);
    const background = getComputedStyle(document.body).backgroundColor;
    const span = (shown.timesMs[shown.timesMs.length - 1] ?? 0) - (shown.timesMs[0] ?? 0);
    const heading = `Trend: scans ${shown.scans[0] ?? 0}–${shown.scans[shown.scans.length - 1] ?? 0}, ${formatTime(span, span)}`;
    const image = trendImage(c, shown.names, heading, {
      background: background && background !== 'rgba(0, 0, 0, 0)' ? background : '#ffffff',
      text: style.color || '#1d232b',
    });
    image.toBlob((blob) => blob && downloadBlob(`trend-${shown.scans[0] ?? 0}.png`, blob), 'image/png');
  };
  const readout = cursorReadout(shown, signals, cursors.a, cursors.b);

  return (
    <div className="rs-sim-panel rs-sim-trend" data-testid="trend-panel">
      <div className="rs-sim-panel-bar">
        <VariablePicker testId="trend" placeholder="Signal to trend" label="Signal to trend" buttonLabel="Add signal"
          candidates={candidates} instances={instances} describe={(c) => c.type} onAdd={add} />
        <label className="rs-sim-group" title={`The window: up to ${MAX_TREND_SCANS} scans, the scan history's length`}>
          <span className="rs-sim-unit">last</span>
          <input className="rs-sim-number" aria-label="Scans shown in the trend" value={capacityText} inputMode="numeric"
            data-testid="trend-capacity"
            onChange={(e) => setCapacityText(e.target.value)} onBlur={() => commitCapacity()} onKeyDown={(e) => e.key === 'Enter' && commitCapacity()} />
          <span className="rs-sim-unit">scans</span>
        </label>
        <button type="button" className="rs-sim-btn" data-testid="trend-window-history"
          title={`Show as many scans as the history holds${historyScans ? ` (${historyScans} recorded now)` : ''}, at most ${MAX_TREND_SCANS}`}
          onClick={() => commitCapacity(String(Math.max(10, Math.min(MAX_TREND_SCANS, historyScans ?? MAX_TREND_SCANS))))}>
          Whole history
        </button>
        <button type="button" className="rs-sim-btn" data-testid="trend-freeze" aria-pressed={frozen !== undefined}
          title={frozen ? 'Show the live trend again' : 'Hold the picture; the PLC keeps running'}
          onClick={() => setFrozen(frozen ? undefined : shown)}>
          {frozen ? '▶ Resume' : '❚❚ Freeze'}
        </button>
        <button type="button" className="rs-sim-btn" data-testid="trend-export-csv" disabled={shown.scans.length === 0}
          title="Download the samples shown as CSV: time, scan and one column per signal" onClick={exportCsv}>
          CSV
        </button>
        <button type="button" className="rs-sim-btn" data-testid="trend-export-png" disabled={shown.scans.length === 0}
          title="Download the chart as shown, with its legend, as a PNG image" onClick={exportPng}>
          PNG
        </button>
        {names.map((n) => {
          // A machine name whose machine is not the project's now (tank.level, the garage chosen): no samples come, said.
          const other = plantNameInfo({ plant }, n) ? undefined : otherPlantNameInfo({ plant }, n);
          return (
            <button key={n} type="button" className="rs-sim-chip" data-testid={`trend-chip-${n}`}
              title={other ? `The machine ${other.machine} is not chosen: ${n} has no samples until it is. Remove ${n} from the trend` : `Remove ${n} from the trend`}
              onClick={() => sim.getState().toggleTrend(n)}>
              {n}{other ? ` (${other.machine} not chosen)` : ''} ×
            </button>
          );
        })}
      </div>
      {capacityError && <p className="rs-trend-error" role="alert" data-testid="trend-capacity-error">{capacityError}</p>}
      <TriggerBar candidates={candidates} frozen={frozen !== undefined} />
      {names.length === 0 ? (
        <p className="rs-sim-empty">Add signals to see them over time: each BOOL in its own thin lane, each number in a lane on its own scale.</p>
      ) : (
        <>
          <TrendChart buffer={shown} signals={signals} marks={marks} onPick={pick} chartRef={chart} />
          <CursorTable readout={readout} onClear={() => setCursors({})} />
        </>
      )}
    </div>
  );
}

const DIRECTION_LABEL = { rising: '↑', falling: '↓' } as const;

/** The trigger: a variable, its edge or crossing direction (and level for a number), the pre-trigger share, the mode; Arm and Off. */
function TriggerBar({ candidates, frozen }: { candidates: readonly { name: string; type: string }[]; frozen: boolean }) {
  const sim = useSimStore();
  const trigger = useSim((s) => s.trendTrigger);
  const state = useSim((s) => s.trendTriggerState);
  const capture = useSim(selectCapture);
  const [name, setName] = useState(trigger?.name ?? '');
  const [direction, setDirection] = useState<TrendTrigger['direction']>(trigger?.direction ?? 'rising');
  const [level, setLevel] = useState(trigger ? String(trigger.level) : '0');
  const [pre, setPre] = useState(trigger ? String(trigger.prePercent) : '20');
  const [mode, setMode] = useState<TrendTrigger['mode']>(trigger?.mode ?? 'single');
  const [error, setError] = useState<string>();
  const variable = candidates.find((c) => c.name.toUpperCase() === name.trim().toUpperCase());
  const isBool = variable?.type === 'BOOL';
  const arm = () => {
    if (!variable) {
      setError(name.trim() ? `Trigger: no variable "${name.trim()}" in the program.` : 'Trigger: choose the variable to trigger on.');
      return;
    }
    const levelValue = isBool ? 0.5 : Number(level);
    if (!Number.isFinite(levelValue)) {
      setError(`Trigger: the level "${level}" is not a number.`);
      return;
    }
    const prePercent = Number(pre);
    if (!Number.isFinite(prePercent) || prePercent < 0 || prePercent > 100) {
      setError(`Trigger: the pre-trigger share "${pre}" must be 0 to 100 %.`);
      return;
    }
    setError(undefined);
    sim.getState().setTrendTrigger({ name: variable.name, direction, level: levelValue, prePercent, mode });
  };
  const what = trigger ? `${trigger.name} ${DIRECTION_LABEL[trigger.direction]}${candidates.find((c) => c.name === trigger.name)?.type === 'BOOL' ? '' : ` ${trigger.level}`}` : '';
  const at = capture ? capture.samples.scans[capture.triggerIndex] : undefined;
  const status = !trigger
    ? 'No trigger: the trend runs on.'
    : state === 'unknown'
      ? `Trigger: ${trigger.name} is not in the running program.`
      : state === 'capturing'
        ? `Triggered on ${what}: recording the rest of the window…`
        : capture
          ? `Triggered on ${what} at scan ${at}${trigger.mode === 'normal' ? ` (capture ${capture.count}; armed for the next)` : ' (single: press Arm to capture again)'}`
          : `Armed: waiting for ${what}`;
  return (
    <div className="rs-sim-panel-bar rs-trend-trigger" data-testid="trend-trigger">
      <span className="rs-sim-unit">Trigger</span>
      <input className="rs-sim-text rs-sim-narrow" list="rs-trend-trigger-candidates" aria-label="Trigger variable" placeholder="Variable"
        value={name} onChange={(e) => setName(e.target.value)} onKeyDown={(e) => e.key === 'Enter' && arm()} data-testid="trend-trigger-name" />
      <datalist id="rs-trend-trigger-candidates">
        {candidates.filter((c) => c.type === 'BOOL' || /INT|REAL|TIME|BYTE|WORD/.test(c.type)).map((c) => <option key={c.name} value={c.name}>{c.type}</option>)}
      </datalist>
      <select aria-label="Trigger direction" value={direction} onChange={(e) => setDirection(e.target.value as TrendTrigger['direction'])} data-testid="trend-trigger-direction">
        <option value="rising">{isBool ? 'rising edge ↑' : 'rising through ↑'}</option>
        <option value="falling">{isBool ? 'falling edge ↓' : 'falling through ↓'}</option>
      </select>
      {!isBool && (
        <input className="rs-sim-number" aria-label="Trigger level" value={level} inputMode="decimal" title="The value the variable crosses"
          onChange={(e) => setLevel(e.target.value)} data-testid="trend-trigger-level" />
      )}
      <label className="rs-sim-group" title="Share of the window recorded before the trigger">
        <span className="rs-sim-unit">pre</span>
        <input className="rs-sim-number" aria-label="Pre-trigger percent" value={pre} inputMode="numeric"
          onChange={(e) => setPre(e.target.value)} data-testid="trend-trigger-pre" />
        <span className="rs-sim-unit">%</span>
      </label>
      <select aria-label="Trigger mode" value={mode} onChange={(e) => setMode(e.target.value as TrendTrigger['mode'])} data-testid="trend-trigger-mode"
        title="Single: capture once and hold. Normal: capture at every trigger, showing the last">
        <option value="single">Single</option>
        <option value="normal">Normal</option>
      </select>
      <button type="button" className="rs-sim-btn" onClick={arm} data-testid="trend-trigger-arm" title="Arm the trigger (again)">Arm</button>
      <button type="button" className="rs-sim-btn" disabled={!trigger} onClick={() => sim.getState().setTrendTrigger(undefined)}
        data-testid="trend-trigger-off" title="Remove the trigger: the trend runs live">Off</button>
      <span className="rs-trend-status" data-testid="trend-trigger-status" aria-live="polite">
        {error ?? status}
        {frozen ? ' · display frozen' : ''}
      </span>
    </div>
  );
}

/** The cursors' readings: time and scan at A and B, Δt, and each signal's value at both (and B − A for numbers). */
function CursorTable({ readout, onClear }: { readout: ReturnType<typeof cursorReadout>; onClear: () => void }) {
  if (!readout.a && !readout.b)
    return <p className="rs-sim-empty rs-trend-cursor-hint">Click the chart to place cursor A, click again for B (Shift+click moves B).</p>;
  return (
    <table className="rs-sim-table rs-trend-cursors" aria-label="Trend cursors" data-testid="trend-cursors">
      <thead>
        <tr>
          <th>Signal</th>
          <th data-testid="trend-cursor-a">A{readout.a ? `: ${readout.a.timeMs} ms, scan ${readout.a.scan}` : ''}</th>
          <th data-testid="trend-cursor-b">B{readout.b ? `: ${readout.b.timeMs} ms, scan ${readout.b.scan}` : ''}</th>
          <th>
            <span data-testid="trend-cursor-dt">Δt = {readout.dtMs === undefined ? '—' : `${readout.dtMs} ms`}</span>{' '}
            <button type="button" className="rs-sim-icon" aria-label="Remove the cursors" onClick={onClear}>×</button>
          </th>
        </tr>
      </thead>
      <tbody>
        {readout.rows.map((r) => (
          <tr key={r.name} data-testid={`trend-cursor-row-${r.name}`}>
            <td className="rs-trend-name">{r.name}</td>
            <td>{r.a}</td>
            <td>{r.b}</td>
            <td>{r.delta && `Δ ${r.delta}`}</td>
          </tr>
        ))}
      </tbody>
    </table>
  );
}

const selectHistoryScan = (s: SimState) => s.historyScan;

function TrendChart({ buffer, signals, marks, onPick, chartRef }: {
  buffer: TrendBuffer;
  signals: readonly TrendSignal[];
  marks: TrendMarks;
  onPick: (timeMs: number, shift: boolean) => void;
  chartRef: { current: uPlot | undefined };
}) {
  const host = useRef<HTMLDivElement>(null);
  const plot = useRef<uPlot | undefined>(undefined);
  const signalKey = signals.map((s) => `${s.name}:${s.type}`).join(',');
  /** The samples and lanes drawn now; the chart's axes, legend and tip read them. */
  const view = useRef<TrendView | undefined>(undefined);
  const picked = useRef(onPick);
  picked.current = onPick;

  useEffect(() => {
    const el = host.current;
    if (!el) return;
    const text = getComputedStyle(el).color || '#333';
    view.current = { buffer, layout: trendLayout(signals, buffer), marks };
    const current = () => view.current!;
    const chart = new uPlot(trendOptions(signals, 400, 120, current, text), trendData(current().layout, buffer), el);
    plot.current = chart;
    chartRef.current = chart;
    const click = (e: MouseEvent) => picked.current(chart.posToVal(e.offsetX, 'x'), e.shiftKey);
    chart.over.addEventListener('click', click);
    // Fill the panel: the plot gets the host's size less the legend under it.
    const fit = () => {
      const legend = chart.root.querySelector<HTMLElement>('.u-legend')?.offsetHeight ?? 28;
      chart.setSize({ width: Math.max(200, el.clientWidth), height: Math.max(100, el.clientHeight - legend - 6) });
    };
    fit();
    const resize = new ResizeObserver(fit);
    resize.observe(el);
    return () => {
      resize.disconnect();
      chart.over.removeEventListener('click', click);
      chart.destroy();
      plot.current = undefined;
      chartRef.current = undefined;
    };
    // Rebuilt only when the signal set changes; data updates go through setData below.
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [signalKey]);

  useEffect(() => {
    if (!plot.current) return;
    view.current = { buffer, layout: trendLayout(signals, buffer), marks };
    plot.current.setData(trendData(view.current.layout, buffer));
  }, [buffer, signals, marks]);

  // Scan history: the cursor stands on the recorded scan shown on the canvas (issue 14).
  const historyScan = useSim(selectHistoryScan);
  useEffect(() => {
    const chart = plot.current;
    const at = historyScan === undefined ? -1 : buffer.scans.indexOf(historyScan);
    const t = buffer.timesMs[at];
    if (!chart || t === undefined) return;
    chart.setCursor({ left: chart.valToPos(t, 'x'), top: 0 });
  }, [historyScan, buffer]);

  return <div ref={host} className="rs-sim-chart" data-testid="trend-chart" data-scans={`${buffer.scans[0] ?? ''}-${buffer.scans[buffer.scans.length - 1] ?? ''}`} />;
}
