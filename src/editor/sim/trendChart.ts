// The trend as a uPlot timing diagram, one lane per signal stacked top to bottom in the order
// chosen: a BOOL signal is a thin digital trace in its own lane; a number has a taller lane on its
// own scale (the lane spans the lowest to the highest value in the window, both written on the
// right). x is the simulated time (ms, or s over longer windows); the legend and the hover tip give
// the time, the scan number and every value at the cursor.
import uPlot from 'uplot';
import type { TrendBuffer } from '../../sim/trendBuffer';
import { formatLive } from './liveValues';

const COLOURS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e', '#17becf', '#8c564b', '#e377c2', '#7f7f7f', '#bcbd22'];
/** Lane heights in lane units: a BOOL trace is thin, a number gets room for its shape. */
const BOOL_LANE = 1;
const NUMBER_LANE = 3;
/** Space between a trace and its lane's edges (lane units). */
const PAD = 0.2;
/** The axes' font (uPlot's default face), and the least room between two scale labels, px. */
const AXIS_FONT = '12px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
const LABEL_GAP_PX = 14;
/** A line of a wrapped lane name: the axis font's 12 px times uPlot's line gap (1.5). */
const NAME_LINE_PX = 18;

let measurer: CanvasRenderingContext2D | null | undefined;
/** Width of `text` in the axis font, px (a rough estimate where no canvas can measure). */
function textWidth(text: string): number {
  if (measurer === undefined) measurer = typeof document === 'undefined' ? null : document.createElement('canvas').getContext('2d');
  if (!measurer) return text.length * 7;
  measurer.font = AXIS_FONT;
  return measurer.measureText(text).width;
}

/**
 * `text` in lines no wider than `max` px, broken after a `.` of a path (or inside a segment longer
 * than a line): a lane name is never cut, only wrapped.
 */
export function wrapName(text: string, max: number, width: (t: string) => number = textWidth): string[] {
  if (width(text) <= max) return [text];
  const pieces = text.split(/(?<=\.)/);
  const lines: string[] = [];
  let line = '';
  for (const piece of pieces) {
    if (width(line + piece) <= max) {
      line += piece;
      continue;
    }
    if (line) lines.push(line);
    line = '';
    // A segment wider than a line is broken where it reaches the edge.
    for (const ch of piece) {
      if (line && width(line + ch) > max) {
        lines.push(line);
        line = '';
      }
      line += ch;
    }
  }
  if (line) lines.push(line);
  return lines;
}

/** The last `max` of a name's lines, the first of them after "…" when lines were left out. */
export function fitLines(lines: readonly string[], max: number): string[] {
  if (lines.length <= max) return [...lines];
  const kept = lines.slice(lines.length - max);
  kept[0] = `…${kept[0]}`;
  return kept;
}

/** Height of the plotting area, CSS px. */
function plotHeight(u: uPlot, fallback: number): number {
  const ratio = typeof devicePixelRatio === 'number' && devicePixelRatio > 0 ? devicePixelRatio : 1;
  return u.bbox?.height > 0 ? u.bbox.height / ratio : fallback;
}

/**
 * The number lanes' scale labels (highest and lowest value in the window) from the top down, each
 * kept only when it stands at least a label's height below the last one kept: in a short lane the
 * lowest value gives way, and no two labels are drawn over each other.
 */
export function scaleMarks(lanes: readonly TrendLane[], pxPerUnit: number): { y: number; text: string }[] {
  const marks = lanes.flatMap((l) =>
    l.boolean || !(l.max >= l.min)
      ? []
      : l.max > l.min
        ? [{ y: laneY(l, l.max), text: formatLive(l.type, l.max) }, { y: laneY(l, l.min), text: formatLive(l.type, l.min) }]
        : [{ y: laneY(l, l.min), text: formatLive(l.type, l.min) }],
  );
  marks.sort((a, b) => b.y - a.y);
  const kept: { y: number; text: string }[] = [];
  for (const m of marks) if (!kept.length || (kept[kept.length - 1]!.y - m.y) * pxPerUnit >= LABEL_GAP_PX) kept.push(m);
  return kept;
}

export interface TrendSignal {
  readonly name: string;
  readonly type: string;
}

export interface TrendLane {
  readonly name: string;
  readonly type: string;
  readonly boolean: boolean;
  /** Lane edges on the 'lanes' scale (0 at the bottom of the chart). */
  readonly bottom: number;
  readonly top: number;
  /** The window's lowest and highest value (numbers), drawn at the lane's lower and upper trace edges. */
  readonly min: number;
  readonly max: number;
}

export interface TrendLayout {
  readonly lanes: readonly TrendLane[];
  /** Height of all lanes (lane units). */
  readonly total: number;
}

/** What the chart draws now: the samples and their lanes (both change with every frame). */
export interface TrendView {
  readonly buffer: TrendBuffer;
  readonly layout: TrendLayout;
  /** Vertical marks at PLC times (ms): the measurement cursors A and B, and the trigger T. */
  readonly marks?: TrendMarks;
}

export interface TrendMarks {
  readonly a?: number | undefined;
  readonly b?: number | undefined;
  readonly trigger?: number | undefined;
}

const MARK_COLOURS = { a: '#0a7d36', b: '#b3127a', trigger: '#c05600' } as const;

/** Draws the cursors and the trigger as vertical lines with their letter at the top (on the canvas, so a PNG has them). */
function marksPlugin(view: () => TrendView): uPlot.Plugin {
  return {
    hooks: {
      draw: [
        (u) => {
          const marks = view().marks;
          if (!marks) return;
          const ctx = u.ctx;
          const ratio = typeof devicePixelRatio === 'number' && devicePixelRatio > 0 ? devicePixelRatio : 1;
          const { top, height } = u.bbox;
          const entries: [keyof TrendMarks, string][] = [['trigger', 'T'], ['a', 'A'], ['b', 'B']];
          for (const [key, letter] of entries) {
            const t = marks[key];
            if (t === undefined) continue;
            const x = Math.round(u.valToPos(t, 'x', true));
            ctx.save();
            ctx.strokeStyle = MARK_COLOURS[key];
            ctx.fillStyle = MARK_COLOURS[key];
            ctx.lineWidth = Math.max(1, ratio);
            if (key === 'trigger') ctx.setLineDash([4 * ratio, 3 * ratio]);
            ctx.beginPath();
            ctx.moveTo(x, top);
            ctx.lineTo(x, top + height);
            ctx.stroke();
            ctx.font = `bold ${11 * ratio}px system-ui, sans-serif`;
            ctx.fillText(letter, x + 3 * ratio, top + 12 * ratio);
            ctx.restore();
          }
        },
      ],
    },
  };
}

const seriesOf = (buffer: TrendBuffer, name: string): readonly number[] => buffer.series[buffer.names.indexOf(name)] ?? [];

/** Lanes for the signals, numbers scaled to the values in the buffer. */
export function trendLayout(signals: readonly TrendSignal[], buffer: TrendBuffer): TrendLayout {
  const total = signals.reduce((h, s) => h + (s.type === 'BOOL' ? BOOL_LANE : NUMBER_LANE), 0);
  let top = total;
  const lanes = signals.map((s): TrendLane => {
    const boolean = s.type === 'BOOL';
    const bottom = top - (boolean ? BOOL_LANE : NUMBER_LANE);
    let min = Infinity;
    let max = -Infinity;
    if (!boolean)
      for (const v of seriesOf(buffer, s.name)) {
        if (!Number.isFinite(v)) continue;
        if (v < min) min = v;
        if (v > max) max = v;
      }
    const lane = { name: s.name, type: s.type, boolean, bottom, top, min: boolean ? 0 : min, max: boolean ? 1 : max };
    top = bottom;
    return lane;
  });
  return { lanes, total };
}

/** Where value `v` of a lane is drawn on the 'lanes' scale. */
export function laneY(lane: TrendLane, v: number): number {
  const low = lane.bottom + PAD;
  const high = lane.top - PAD;
  if (lane.boolean) return v ? high : low;
  if (!(lane.max > lane.min)) return (low + high) / 2;
  return low + ((v - lane.min) / (lane.max - lane.min)) * (high - low);
}

/** uPlot's aligned data: x = time (ms), then one row per lane on the 'lanes' scale. */
export function trendData(layout: TrendLayout, buffer: TrendBuffer): uPlot.AlignedData {
  const rows = layout.lanes.map((lane) => seriesOf(buffer, lane.name).map((v) => laneY(lane, v)));
  return [[...buffer.timesMs], ...rows];
}

/** Time as the x axis and the tip write it: ms when the window spans under 2 s, else seconds. */
export function formatTime(ms: number, spanMs: number): string {
  if (spanMs < 2000) return `${Math.round(ms)} ms`;
  const s = ms / 1000;
  const digits = spanMs < 20000 ? 2 : spanMs < 200000 ? 1 : 0;
  return `${Number(s.toFixed(digits))} s`;
}

const span = (u: uPlot) => (u.scales.x!.max ?? 0) - (u.scales.x!.min ?? 0);

/** The value of lane `i` at sample `idx` as text ('—' when there is none). */
function valueText(view: () => TrendView, i: number, idx: number | null | undefined): string {
  if (idx === null || idx === undefined) return '—';
  const { buffer, layout } = view();
  const lane = layout.lanes[i];
  const value = lane ? seriesOf(buffer, lane.name)[idx] : undefined;
  if (!lane || value === undefined) return '—';
  return lane.boolean ? (value ? 'TRUE' : 'FALSE') : formatLive(lane.type, value);
}

/** The tip beside the cursor: time, scan number, and each signal's value at that scan. */
function tipPlugin(view: () => TrendView): uPlot.Plugin {
  let tip: HTMLDivElement | undefined;
  return {
    hooks: {
      init: [
        (u) => {
          tip = document.createElement('div');
          tip.className = 'rs-trend-tip';
          tip.setAttribute('data-testid', 'trend-tip');
          tip.style.display = 'none';
          u.over.appendChild(tip);
        },
      ],
      setCursor: [
        (u) => {
          const idx = u.cursor.idx;
          const { buffer, layout } = view();
          const t = idx === null || idx === undefined ? undefined : buffer.timesMs[idx];
          if (!tip || t === undefined || u.cursor.left === undefined || u.cursor.left < 0) {
            if (tip) tip.style.display = 'none';
            return;
          }
          tip.replaceChildren();
          const head = document.createElement('div');
          head.className = 'rs-trend-tip-head';
          head.textContent = `t = ${formatTime(t, span(u))} · scan ${buffer.scans[idx!]}`;
          tip.appendChild(head);
          layout.lanes.forEach((lane, i) => {
            const line = document.createElement('div');
            line.textContent = `${lane.name} = ${valueText(view, i, idx)}`;
            line.style.color = COLOURS[i % COLOURS.length]!;
            tip!.appendChild(line);
          });
          tip.style.display = 'block';
          const width = u.over.clientWidth;
          const left = u.cursor.left + 12;
          tip.style.left = `${left + tip.offsetWidth > width ? Math.max(0, u.cursor.left - 12 - tip.offsetWidth) : left}px`;
          tip.style.top = `${Math.max(0, Math.min((u.cursor.top ?? 0) + 12, u.over.clientHeight - tip.offsetHeight))}px`;
        },
      ],
    },
  };
}

/**
 * After each draw, what the chart shows is written on its host element for tests and tools:
 * data-lanes "Name:TYPE:top-bottom|...", data-time-labels "0 ms|250 ms|...", data-lane-names (as
 * drawn) and data-scale-labels "text@y|..." (the number scales' labels drawn, y in lane units).
 */
function describePlugin(
  view: () => TrendView,
  timeLabels: { current: string[] },
  names: (u: uPlot) => string[],
  scale: { current: Map<number, string> },
): uPlot.Plugin {
  return {
    hooks: {
      draw: [
        (u) => {
          const host = u.root.parentElement;
          if (!host) return;
          host.dataset.lanes = view()
            .layout.lanes.map((l) => `${l.name}:${l.type}:${l.top}-${l.bottom}`)
            .join('|');
          host.dataset.timeLabels = timeLabels.current.join('|');
          host.dataset.laneNames = names(u).join('|');
          host.dataset.scaleLabels = [...scale.current].map(([y, text]) => `${text}@${y}`).join('|');
        },
      ],
    },
  };
}

/** A signal's colour in the chart (the legend and the PNG use the same). */
export const signalColour = (i: number): string => COLOURS[i % COLOURS.length]!;

export function trendOptions(
  signals: readonly TrendSignal[],
  width: number,
  height: number,
  view: () => TrendView,
  textColour: string,
): uPlot.Options {
  const axisStyle = { font: AXIS_FONT, stroke: textColour, grid: { stroke: '#8884', width: 1 }, ticks: { stroke: '#8884', width: 1 } };
  const lanes = () => view().layout.lanes;
  const hasNumbers = signals.some((s) => s.type !== 'BOOL');
  const timeLabels = { current: [] as string[] };
  // Lane names get the width the longest needs (up to a third of the chart; longer ones wrap).
  const nameWidth = Math.min(Math.max(60, ...signals.map((s) => textWidth(s.name) + 14)), Math.max(90, Math.round(width / 3)));
  // Wrapped in as many lines as the lane has room for; a name longer still keeps its end after "…"
  // (the legend under the chart and the chips above it name it whole).
  const names = (u: uPlot) => {
    const pxPerUnit = plotHeight(u, height) / Math.max(1, view().layout.total);
    return lanes().map((l) => {
      const room = Math.max(1, Math.floor(((l.top - l.bottom) * pxPerUnit) / NAME_LINE_PX));
      const lines = wrapName(l.name, nameWidth - 14);
      // Cut lines make room for the "…" in front.
      return (lines.length > room ? fitLines(wrapName(l.name, nameWidth - 14 - textWidth('…')), room) : lines).join('\n');
    });
  };
  // The number scales' labels actually drawn (none closer than a label's height to the one above).
  const scale = { current: new Map<number, string>() };
  return {
    width,
    height,
    legend: { show: true, live: true },
    cursor: { drag: { x: false, y: false } },
    plugins: [tipPlugin(view), describePlugin(view, timeLabels, names, scale), marksPlugin(view)],
    scales: {
      x: { time: false },
      lanes: { range: () => [0, Math.max(1, view().layout.total)] },
    },
    axes: [
      {
        ...axisStyle,
        scale: 'x',
        size: 30,
        values: (u, splits) => (timeLabels.current = splits.map((v) => formatTime(v, span(u)))),
      },
      {
        // Lane names, at the middle of each lane; the grid lines are the lanes' edges.
        ...axisStyle,
        scale: 'lanes',
        size: nameWidth,
        // A wrapped name's lines go down from its split (uPlot): raise it by half the extra lines.
        splits: (u) => {
          const pxPerUnit = plotHeight(u, height) / Math.max(1, view().layout.total);
          const labels = names(u);
          return lanes().map((l, i) => (l.top + l.bottom) / 2 + (((labels[i] ?? '').split('\n').length - 1) * NAME_LINE_PX) / 2 / pxPerUnit);
        },
        values: (u) => names(u),
        grid: { show: false },
        ticks: { show: false },
      },
      {
        ...axisStyle,
        scale: 'lanes',
        size: 0,
        splits: () => lanes().slice(1).map((l) => l.top),
        values: (_u, splits) => splits.map(() => ''),
        ticks: { show: false },
      },
      {
        // Each number's scale: its lowest and highest value in the window, on the right.
        ...axisStyle,
        scale: 'lanes',
        side: 1,
        show: hasNumbers,
        size: 70,
        splits: (u) => {
          const kept = scaleMarks(lanes(), plotHeight(u, height) / Math.max(1, view().layout.total));
          scale.current = new Map(kept.map((m) => [m.y, m.text]));
          return kept.map((m) => m.y);
        },
        values: (_u, splits) => splits.map((y) => scale.current.get(y) ?? ''),
        grid: { show: false },
      },
    ],
    series: [
      {
        label: 'scan',
        value: (_u, _v, _s, idx) => {
          const { buffer } = view();
          const scan = idx === null ? undefined : buffer.scans[idx];
          const t = idx === null ? undefined : buffer.timesMs[idx];
          return scan === undefined ? '—' : `${scan}${t !== undefined ? ` (t = ${t} ms)` : ''}`;
        },
      },
      ...signals.map(
        (s, i): uPlot.Series => ({
          label: s.name,
          scale: 'lanes',
          stroke: COLOURS[i % COLOURS.length]!,
          width: s.type === 'BOOL' ? 2 : 1.5,
          paths: s.type === 'BOOL' ? uPlot.paths.stepped!({ align: 1 }) : undefined,
          points: { show: false },
          value: (_u, _v, seriesIdx, idx) => valueText(view, seriesIdx - 1, idx),
        }),
      ),
    ],
  };
}
