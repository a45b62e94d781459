// TIME literals (IEC 61131-3 table 8): T#1d2h3m4s5ms, TIME#-2h, t#1.5s, T#1h_30m.
// The engine holds TIME as a whole number of milliseconds; finer parts (us, ns, fractions of a ms)
// are rounded to the nearest ms (half away from zero).

const UNITS = [
  { unit: 'd', ms: 86_400_000 },
  { unit: 'h', ms: 3_600_000 },
  { unit: 'm', ms: 60_000 },
  { unit: 's', ms: 1000 },
  { unit: 'ms', ms: 1 },
  { unit: 'us', ms: 1e-3 },
  { unit: 'ns', ms: 1e-6 },
] as const;

const PART = /(\d(?:_?\d)*)(?:\.(\d(?:_?\d)*))?(ms|us|ns|d|h|m|s)_?/iy;

export type TimeParse = { ok: true; ms: number } | { ok: false; message: string };

/** Parses the part after `T#` / `TIME#`: an optional sign then number-unit pairs, largest unit first. */
export function parseTimeBody(body: string): TimeParse {
  // MATIEC's lexer skips blanks after the '#' (`T# 30000ms`, written by OpenPLC Editor users) and
  // after the sign (`T#- 30ms` compiles), not between parts (`T#1m 30s` is refused there too).
  let text = body.replace(/^[ \t]+/, '');
  let sign = 1;
  if (text.startsWith('-') || text.startsWith('+')) {
    sign = text.startsWith('-') ? -1 : 1;
    text = text.slice(1).trimStart();
  }
  if (text === '') return { ok: false, message: 'a TIME needs at least one number with a unit, e.g. T#1s500ms' };
  let pos = 0;
  let total = 0;
  let lastRank = -1;
  let sawFraction = false;
  while (pos < text.length) {
    PART.lastIndex = pos;
    const m = PART.exec(text);
    if (!m) {
      return { ok: false, message: `"${text.slice(pos)}" is not a TIME part; use numbers with units d, h, m, s, ms (e.g. T#1m30s)` };
    }
    if (sawFraction) return { ok: false, message: 'only the last unit of a TIME may have a fraction (write T#1m30s, not T#1.5m30s)' };
    const unit = m[3]!.toLowerCase();
    const rank = UNITS.findIndex((u) => u.unit === unit);
    if (rank <= lastRank) return { ok: false, message: `TIME units must go from largest to smallest, each once (d, h, m, s, ms); "${unit}" is out of order` };
    lastRank = rank;
    const whole = Number(m[1]!.replaceAll('_', ''));
    const frac = m[2] !== undefined ? Number(`0.${m[2].replaceAll('_', '')}`) : 0;
    if (m[2] !== undefined) sawFraction = true;
    total += (whole + frac) * UNITS[rank]!.ms;
    pos = PART.lastIndex;
  }
  if (text.endsWith('_')) return { ok: false, message: 'a TIME cannot end with "_"' };
  const ms = Math.round(total);
  if (!Number.isSafeInteger(ms)) return { ok: false, message: 'this TIME is too long to represent' };
  return { ok: true, ms: sign * ms === 0 ? 0 : sign * ms };
}

/** Formats milliseconds as an IEC TIME literal: 1500 -> T#1s500ms, 0 -> T#0ms, -7200000 -> T#-2h. */
export function formatTime(ms: number): string {
  if (!Number.isFinite(ms)) return 'T#0ms';
  let rest = Math.abs(Math.round(ms));
  if (rest === 0) return 'T#0ms';
  let text = ms < 0 ? 'T#-' : 'T#';
  for (const { unit, ms: size } of UNITS.slice(0, 5)) {
    const n = Math.floor(rest / size);
    if (n > 0) text += `${n}${unit}`;
    rest -= n * size;
  }
  return text;
}
