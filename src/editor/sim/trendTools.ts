// What the trend's measurement cursors read and what its CSV export writes, from the samples shown
// (no DOM: unit-tested in tests/editor/trendTools.test.ts).
import type { TrendBuffer } from '../../sim/trendBuffer';
import { isElementaryType } from '../../model/iecTypes';
import { csvValue } from '../../engine/values/literals';
import { formatLive } from './liveValues';

export interface TrendSignalType {
  readonly name: string;
  readonly type: string;
}

/** The index of the sample nearest to time `t` (ms), -1 when there are none. */
export function nearestIndex(times: readonly number[], t: number): number {
  if (times.length === 0) return -1;
  let lo = 0;
  let hi = times.length - 1;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (times[mid]! < t) lo = mid + 1;
    else hi = mid;
  }
  return lo > 0 && Math.abs(times[lo - 1]! - t) <= Math.abs(times[lo]! - t) ? lo - 1 : lo;
}

const valueOf = (buffer: TrendBuffer, name: string, idx: number): number | undefined => buffer.series[buffer.names.indexOf(name)]?.[idx];

/** A value as the cursors and the CSV write it: BOOL TRUE/FALSE, numbers as the PLC holds them. */
export function sampleText(type: string, value: number | undefined): string {
  if (value === undefined) return '';
  if (type === 'BOOL') return value ? 'TRUE' : 'FALSE';
  return formatLive(type, value);
}

export interface CursorReading {
  readonly name: string;
  readonly a: string;
  readonly b: string;
  /** B − A for numbers ('' for BOOL or a missing value). */
  readonly delta: string;
}

export interface CursorReadout {
  /** The cursors' samples: PLC time (ms) and scan number. */
  readonly a?: { readonly timeMs: number; readonly scan: number };
  readonly b?: { readonly timeMs: number; readonly scan: number };
  /** B − A in PLC time (ms), when both are placed. */
  readonly dtMs?: number;
  readonly rows: readonly CursorReading[];
}

/** What the two cursors (times in ms, snapped to the nearest sample) read on every signal, and Δt between them. */
export function cursorReadout(buffer: TrendBuffer, signals: readonly TrendSignalType[], aMs: number | undefined, bMs: number | undefined): CursorReadout {
  const at = (t: number | undefined) => (t === undefined ? -1 : nearestIndex(buffer.timesMs, t));
  const ia = at(aMs);
  const ib = at(bMs);
  const point = (i: number) => (i < 0 ? undefined : { timeMs: buffer.timesMs[i]!, scan: buffer.scans[i]! });
  const a = point(ia);
  const b = point(ib);
  const rows = signals.map((s): CursorReading => {
    const va = ia < 0 ? undefined : valueOf(buffer, s.name, ia);
    const vb = ib < 0 ? undefined : valueOf(buffer, s.name, ib);
    const delta = s.type !== 'BOOL' && va !== undefined && vb !== undefined ? formatLive(s.type, vb - va) : '';
    return { name: s.name, a: sampleText(s.type, va), b: sampleText(s.type, vb), delta };
  });
  return { ...(a ? { a } : {}), ...(b ? { b } : {}), ...(a && b ? { dtMs: b.timeMs - a.timeMs } : {}), rows };
}

const csvCell = (text: string): string => (/[",\n\r]/.test(text) ? `"${text.replace(/"/g, '""')}"` : text);

/**
 * The samples shown as CSV: PLC time in ms, the scan number, then one column per signal headed by
 * its full name; values as the trace CSV writes them (BOOL 0/1, REAL in the shortest digits that read
 * back exactly, TIME in ms).
 */
export function trendCsv(buffer: TrendBuffer, signals: readonly TrendSignalType[]): string {
  const lines = [['time_ms', 'scan', ...signals.map((s) => s.name)].map(csvCell).join(',')];
  for (let i = 0; i < buffer.scans.length; i++) {
    const cells = [String(buffer.timesMs[i]), String(buffer.scans[i])];
    for (const s of signals) {
      const v = valueOf(buffer, s.name, i);
      cells.push(v === undefined ? '' : isElementaryType(s.type) ? csvValue(s.type, v) : String(v));
    }
    lines.push(cells.map(csvCell).join(','));
  }
  return `${lines.join('\n')}\n`;
}
