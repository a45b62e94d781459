// Trend (timing diagram) of chosen signals over the last N scans, drawn with uPlot: a lane per
// signal against the simulated time (src/editor/sim/trendChart.ts).
import { useEffect, useMemo, useRef, useState } from 'react';
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import type { SimState } from '../../store/simState';
import { useSim, useSimStore } from './simContext';
import { trendData, trendLayout, trendOptions, type TrendSignal, type TrendView } from './trendChart';
import { useConfigurationInstances, useWatchCandidates } from './useWatchCandidates';
import { VariablePicker } from './VariablePicker';
import './sim.css';

const selectTrend = (s: SimState) => s.trend;
const selectTrendNames = (s: SimState) => s.trendNames;
const selectCapacity = (s: SimState) => s.trendCapacity;

export function TrendPanel() {
  const sim = useSimStore();
  const names = useSim(selectTrendNames);
  const capacity = useSim(selectCapacity);
  const candidates = useWatchCandidates();
  const instances = useConfigurationInstances();
  const [capacityText, setCapacityText] = useState(String(capacity));
  useEffect(() => setCapacityText(String(capacity)), [capacity]);
  const add = (text: string) => {
    const known = candidates.find((c) => c.name.toUpperCase() === text.trim().toUpperCase());
    if (known && !names.some((n) => n.toUpperCase() === known.name.toUpperCase())) sim.getState().toggleTrend(known.name);
  };
  const commitCapacity = () => {
    const n = Number.parseInt(capacityText, 10);
    if (Number.isFinite(n) && n > 0) sim.getState().setTrendCapacity(n);
    else setCapacityText(String(capacity));
  };
  return (
    <div className="rs-sim-panel rs-sim-trend" data-testid="trend-panel">
      <div className="rs-sim-panel-bar">
        <VariablePicker testId="trend" placeholder="Signal to trend" label="Signal to trend" buttonLabel="Add signal"
          candidates={candidates} instances={instances} describe={(c) => c.type} onAdd={add} />
        <label className="rs-sim-group">
          <span className="rs-sim-unit">last</span>
          <input className="rs-sim-number" aria-label="Scans shown in the trend" value={capacityText} inputMode="numeric"
            onChange={(e) => setCapacityText(e.target.value)} onBlur={commitCapacity} onKeyDown={(e) => e.key === 'Enter' && commitCapacity()} />
          <span className="rs-sim-unit">scans</span>
        </label>
        {names.map((n) => (
          <button key={n} type="button" className="rs-sim-chip" title={`Remove ${n} from the trend`} onClick={() => sim.getState().toggleTrend(n)}>
            {n} ×
          </button>
        ))}
      </div>
      {names.length === 0 ? (
        <p className="rs-sim-empty">Add signals to see them over time: each BOOL in its own thin lane, each number in a lane on its own scale.</p>
      ) : (
        <TrendChart types={candidates} />
      )}
    </div>
  );
}

const selectHistoryScan = (s: SimState) => s.historyScan;

function TrendChart({ types }: { types: readonly { name: string; type: string }[] }) {
  const sim = useSimStore();
  const trend = useSim(selectTrend);
  const host = useRef<HTMLDivElement>(null);
  const plot = useRef<uPlot | undefined>(undefined);
  const signals = useMemo<TrendSignal[]>(
    () => trend.names.map((name) => ({ name, type: types.find((t) => t.name.toUpperCase() === name.toUpperCase())?.type ?? 'LREAL' })),
    [trend.names, types],
  );
  const signalKey = signals.map((s) => `${s.name}:${s.type}`).join(',');
  /** The samples and lanes drawn now; the chart's axes, legend and tip read them. */
  const view = useRef<TrendView | undefined>(undefined);

  useEffect(() => {
    const el = host.current;
    if (!el) return;
    const text = getComputedStyle(el).color || '#333';
    const buffer = sim.getState().trend;
    view.current = { buffer, layout: trendLayout(signals, buffer) };
    const current = () => view.current!;
    const chart = new uPlot(trendOptions(signals, 400, 120, current, text), trendData(current().layout, buffer), el);
    plot.current = chart;
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
      chart.destroy();
      plot.current = undefined;
    };
    // Rebuilt only when the signal set changes; data updates go through setData below.
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [signalKey, sim]);

  useEffect(() => {
    if (!plot.current) return;
    view.current = { buffer: trend, layout: trendLayout(signals, trend) };
    plot.current.setData(trendData(view.current.layout, trend));
  }, [trend, signals]);

  // Scan history: the cursor stands on the recorded scan shown on the canvas (issue 14).
  const historyScan = useSim(selectHistoryScan);
  useEffect(() => {
    const chart = plot.current;
    const at = historyScan === undefined ? -1 : trend.scans.indexOf(historyScan);
    const t = trend.timesMs[at];
    if (!chart || t === undefined) return;
    chart.setCursor({ left: chart.valToPos(t, 'x'), top: 0 });
  }, [historyScan, trend]);

  return <div ref={host} className="rs-sim-chart" data-testid="trend-chart" />;
}
