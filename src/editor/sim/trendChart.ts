// The trend as a uPlot timing diagram: x = scan number; each BOOL signal is a digital trace in its
// own lane (left axis names the lanes), numeric signals are lines against the right axis.
import uPlot from 'uplot';
import type { TrendBuffer } from '../../sim/trendBuffer';
import { formatLive } from './liveValues';

const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b', '#e377c2', '#7f7f7f', '#bcbd22'];
const LANE = 1.5;
const HIGH = 1;

export interface TrendSignal {
  readonly name: string;
  readonly type: string;
}

/** Lane index of every BOOL signal (-1 for numbers). */
const lanes = (signals: readonly TrendSignal[]): number[] => {
  let next = 0;
  return signals.map((s) => (s.type === 'BOOL' ? next++ : -1));
};

export function trendOptions(signals: readonly TrendSignal[], width: number, height: number, buffer: () => TrendBuffer, textColour: string): uPlot.Options {
  const laneOf = lanes(signals);
  const boolCount = laneOf.filter((l) => l >= 0).length;
  const hasNumbers = signals.some((s) => s.type !== 'BOOL');
  const raw = (seriesIdx: number, idx: number | null) => (idx === null ? undefined : buffer().series[seriesIdx - 1]?.[idx]);
  const axisStyle = { stroke: textColour, grid: { stroke: '#8884', width: 1 }, ticks: { stroke: '#8884', width: 1 } };
  return {
    width,
    height,
    legend: { show: true, live: true },
    cursor: { drag: { x: false, y: false } },
    // With both kinds, BOOL lanes take the upper half and numbers the lower half, so they never overlap.
    scales: {
      x: { time: false },
      bool: { range: [hasNumbers ? -Math.max(1, boolCount) * LANE - 0.3 : -0.3, Math.max(1, boolCount) * LANE] },
      num: {
        range: (_u, min, max) => {
          const span = max - min || Math.abs(max) || 1;
          return [min - span * 0.05, boolCount > 0 ? max + span * 1.15 : max + span * 0.05];
        },
      },
    },
    axes: [
      { ...axisStyle, scale: 'x', size: 30 },
      {
        ...axisStyle,
        scale: 'bool',
        show: boolCount > 0,
        size: 90,
        splits: () => signals.flatMap((_, i) => (laneOf[i]! >= 0 ? [laneOf[i]! * LANE + HIGH / 2] : [])),
        values: () => signals.filter((s) => s.type === 'BOOL').map((s) => s.name),
        grid: { show: false },
      },
      { ...axisStyle, scale: 'num', side: 1, show: hasNumbers, grid: { show: !boolCount } },
    ],
    series: [
      {
        label: 'scan',
        value: (_u, v, _s, idx) => {
          const t = idx === null ? undefined : buffer().timesMs[idx];
          return v === null || v === undefined ? '—' : `${v}${t !== undefined ? ` (t = ${t} ms)` : ''}`;
        },
      },
      ...signals.map((s, i): uPlot.Series => {
        const boolean = s.type === 'BOOL';
        return {
          label: s.name,
          scale: boolean ? 'bool' : 'num',
          stroke: COLOURS[i % COLOURS.length]!,
          width: boolean ? 2 : 1.5,
          paths: boolean ? uPlot.paths.stepped!({ align: 1 }) : undefined,
          points: { show: false },
          value: (_u, _v, seriesIdx, idx) => {
            const value = raw(seriesIdx, idx);
            if (value === undefined) return '—';
            return boolean ? (value ? 'TRUE' : 'FALSE') : formatLive(s.type, value);
          },
        };
      }),
    ],
  };
}

/** uPlot's aligned data: x = scans, then one row per signal (BOOL lifted into its lane). */
export function trendData(signals: readonly TrendSignal[], buffer: TrendBuffer): uPlot.AlignedData {
  const laneOf = lanes(signals);
  const rows = signals.map((s, i) => {
    const values = buffer.series[buffer.names.indexOf(s.name)] ?? [];
    const lane = laneOf[i]!;
    return lane >= 0 ? values.map((v) => lane * LANE + (v ? HIGH : 0)) : [...values];
  });
  return [[...buffer.scans], ...rows];
}
