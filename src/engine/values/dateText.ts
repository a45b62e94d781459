// DATE, TIME_OF_DAY (TOD) and DATE_AND_TIME (DT) literals (IEC 61131-3 table 9) and their text.
// Values are whole milliseconds, like TIME: a DATE counts from 1970-01-01 (a multiple of a day),
// a TOD from midnight, a DT from 1970-01-01-00:00:00 (UTC, no time zone). MATIEC holds seconds
// and nanoseconds; finer parts than a millisecond are rounded.

export const DAY_MS = 86_400_000;

export type DateKind = 'DATE' | 'TOD' | 'DT';
export type DateParse = { ok: true; ms: number } | { ok: false; message: string };

const DATE_RE = /^(\d{1,4})-(\d{1,2})-(\d{1,2})$/;
const TOD_RE = /^(\d{1,2}):(\d{1,2})(?::(\d{1,2})(?:\.(\d+))?)?$/;

const isLeap = (y: number) => (y % 4 === 0 && y % 100 !== 0) || y % 400 === 0;
const DAYS = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31];

function dateMs(text: string): DateParse {
  const m = DATE_RE.exec(text);
  if (!m) return { ok: false, message: `"${text}" is not a date; write it as year-month-day, e.g. D#2024-01-31` };
  const [y, mo, d] = [Number(m[1]), Number(m[2]), Number(m[3])];
  if (mo < 1 || mo > 12) return { ok: false, message: `"${text}": the month ${mo} is not 1 to 12` };
  const last = mo === 2 && isLeap(y) ? 29 : DAYS[mo - 1]!;
  if (d < 1 || d > last) return { ok: false, message: `"${text}": the day ${d} is not 1 to ${last}` };
  return { ok: true, ms: Date.UTC(y, mo - 1, d) };
}

function todMs(text: string): DateParse {
  const m = TOD_RE.exec(text);
  if (!m) return { ok: false, message: `"${text}" is not a time of day; write it as hours:minutes:seconds, e.g. TOD#12:30:15` };
  const [h, mi, s] = [Number(m[1]), Number(m[2]), Number(m[3] ?? 0)];
  if (h > 23) return { ok: false, message: `"${text}": the hour ${h} is not 0 to 23` };
  if (mi > 59) return { ok: false, message: `"${text}": the minutes ${mi} are not 0 to 59` };
  if (s > 59) return { ok: false, message: `"${text}": the seconds ${s} are not 0 to 59` };
  const frac = m[4] !== undefined ? Math.round(Number(`0.${m[4]}`) * 1000) : 0;
  return { ok: true, ms: ((h * 60 + mi) * 60 + s) * 1000 + frac };
}

/** Parses the part after D#, TOD# or DT#. */
export function parseDateBody(kind: DateKind, body: string): DateParse {
  if (kind === 'DATE') return dateMs(body);
  if (kind === 'TOD') return todMs(body);
  const m = /^(\d{1,4}-\d{1,2}-\d{1,2})-(.+)$/.exec(body);
  if (!m) return { ok: false, message: `"${body}" is not a date and time; write it as DT#2024-01-31-12:30:15` };
  const d = dateMs(m[1]!);
  if (!d.ok) return d;
  const t = todMs(m[2]!);
  return t.ok ? { ok: true, ms: d.ms + t.ms } : t;
}

/** The date kind a literal prefix names: D#, DATE#, TOD#, TIME_OF_DAY#, DT#, DATE_AND_TIME#. */
export function datePrefix(text: string): DateKind | undefined {
  const m = /^(D|DATE|TOD|TIME_OF_DAY|DT|DATE_AND_TIME)#/i.exec(text);
  if (!m) return undefined;
  const p = m[1]!.toUpperCase();
  return p === 'D' || p === 'DATE' ? 'DATE' : p === 'TOD' || p === 'TIME_OF_DAY' ? 'TOD' : 'DT';
}

const pad = (n: number, w = 2) => String(n).padStart(w, '0');

/** Year, month, day, hours, minutes, seconds, milliseconds of a count of ms from 1970 (UTC). */
export function brokenDown(ms: number): { y: number; mo: number; d: number; h: number; mi: number; s: number; milli: number } {
  const t = new Date(ms);
  return { y: t.getUTCFullYear(), mo: t.getUTCMonth() + 1, d: t.getUTCDate(), h: t.getUTCHours(), mi: t.getUTCMinutes(), s: t.getUTCSeconds(), milli: t.getUTCMilliseconds() };
}

const clock = (h: number, mi: number, s: number, milli: number) =>
  `${pad(h)}:${pad(mi)}:${pad(s)}${milli ? `.${pad(milli, 3).replace(/0+$/, '')}` : ''}`;

/** The literal of a value: D#2024-01-31, TOD#12:30:15.5, DT#2024-01-31-12:30:15. */
export function formatDate(kind: DateKind, ms: number): string {
  if (kind === 'TOD') {
    const t = ((Math.round(ms) % DAY_MS) + DAY_MS) % DAY_MS;
    return `TOD#${clock(Math.floor(t / 3_600_000), Math.floor(t / 60_000) % 60, Math.floor(t / 1000) % 60, t % 1000)}`;
  }
  const b = brokenDown(Math.round(ms));
  const date = `${b.y}-${pad(b.mo)}-${pad(b.d)}`;
  return kind === 'DATE' ? `D#${date}` : `DT#${date}-${clock(b.h, b.mi, b.s, b.milli)}`;
}
