// The character string functions (IEC 61131-3 table 29), string comparisons and the conversions to
// and from STRING, as MATIEC's lib/C/iec_std_functions.h and iec_std_lib.h compute them (the
// library under Beremiz and OpenPLC Runtime). Positions count from 1. Every result is cut at
// STRING_MAX_LEN (126) characters, MATIEC's STR_MAX_LEN.
//
// Both profiles:
// - LEFT/RIGHT/MID/DELETE/REPLACE with L < 0 or P < 0, INSERT with P < 0: an error (ENO OFF),
//   MATIEC's TEST_EN_COND. MID, DELETE and REPLACE with P = 0 are an error too: MATIEC reads the
//   byte before the text there (its length byte) or copies past it.
// - L longer than what is left takes what is left; MID with P beyond the end gives ''; DELETE and
//   REPLACE with P beyond the end append or keep, as the C does.
// - X_TO_STRING writes MATIEC's formats: BOOL 'TRUE'/'FALSE', bit strings '16#ff' (printf %llx),
//   integers in decimal, REAL/LREAL as printf("%.10g") ('0.1000000015' for REAL 0.1, '1e+20').
// Comparisons and FIND follow MATIEC's library since its 2020 fixes (the one Beremiz builds).
// Profiles (profiles.ts): FIND after a partial match (string-find), TIME_TO_STRING
// (time-to-string), STRING_TO_<number, TIME> (string-to-number); openplc also takes INSERT, DELETE
// and REPLACE's L and P modulo 256 (MATIEC casts them to its 8-bit length type).
import type { DateType, ElementaryType, Value } from '../../model/iecTypes';
import type { Profile } from '../../model/project';
import { parseLiteral } from '../values/literals';
import { formatTime } from '../values/time';
import { clipString, defaultValue, isDateType, isStringType, isTimeLike, normalize } from '../values/types';
import { brokenDown, DAY_MS, formatDate } from '../values/dateText';
import { num, type FnContext, type FnImpl, type FnImpl1, type FnImpl2 } from './fnTypes';

export const STRING_FUNCTIONS = ['LEN', 'LEFT', 'RIGHT', 'MID', 'CONCAT', 'INSERT', 'DELETE', 'REPLACE', 'FIND'] as const;
export type StringFunction = (typeof STRING_FUNCTIONS)[number];

export const isStringFunction = (name: string): name is StringFunction => (STRING_FUNCTIONS as readonly string[]).includes(name);

const str = (v: Value): string => (typeof v === 'string' ? v : String(v));
const int = (v: Value): number => Math.trunc(num(v));
/** MATIEC's (__strlen_t) cast of a length or position: an unsigned byte. */
const byte = (n: number): number => n & 0xff;

/** Where an IN1 prefix of `p` characters ends: MATIEC's `P > len ? len : P-1` for DELETE and REPLACE. */
const cut = (p: number, len: number): number => (p > len ? len : p - 1);

/**
 * The implementation of a string function; `outType` is the integer type LEN and FIND give.
 * Arguments come in the order of the signature (model/blocks.ts STRING_FUNCTION_SIGNATURES).
 */
export function stringFunction(
  name: StringFunction,
  outType: ElementaryType,
  profile: Profile,
): { impl: FnImpl; impl1?: FnImpl1; impl2?: FnImpl2 } {
  const matiec = profile === 'openplc';
  const lp = (v: Value): number => (matiec ? byte(int(v)) : int(v));
  switch (name) {
    case 'LEN': {
      const f: FnImpl1 = (_c, a) => normalize(outType, str(a).length);
      return { impl: (c, args) => f(c, args[0]!), impl1: f };
    }
    case 'LEFT': {
      const f: FnImpl2 = (c, a, l) => {
        const n = int(l);
        if (n < 0) return fail(c);
        return str(a).slice(0, n);
      };
      return { impl: (c, args) => f(c, args[0]!, args[1]!), impl2: f };
    }
    case 'RIGHT': {
      const f: FnImpl2 = (c, a, l) => {
        const n = int(l);
        if (n < 0) return fail(c);
        const s = str(a);
        return n >= s.length ? s : s.slice(s.length - n);
      };
      return { impl: (c, args) => f(c, args[0]!, args[1]!), impl2: f };
    }
    case 'MID':
      return {
        impl: (c, [a, l, p]) => {
          const s = str(a!);
          const n = int(l!);
          const at = int(p!);
          if (n < 0 || at < 0) return fail(c);
          if (at > s.length) return '';
          if (at === 0) return fail(c);
          return s.slice(at - 1, at - 1 + n);
        },
      };
    case 'CONCAT': {
      const f: FnImpl2 = (_c, a, b) => clipString(str(a) + str(b));
      return { impl: (_c, args) => clipString(args.map(str).join('')), impl2: f };
    }
    case 'INSERT':
      return {
        impl: (c, [a, b, p]) => {
          if (int(p!) < 0) return fail(c);
          const s = str(a!);
          const at = Math.min(lp(p!), s.length);
          return clipString(s.slice(0, at) + str(b!) + s.slice(at));
        },
      };
    case 'DELETE':
      return {
        impl: (c, [a, l, p]) => {
          if (int(l!) < 0 || int(p!) < 0) return fail(c);
          const s = str(a!);
          const n = lp(l!);
          const at = lp(p!);
          if (at === 0) return fail(c);
          const keep = cut(at, s.length);
          return s.slice(0, keep) + (s.length > keep + n ? s.slice(keep + n) : '');
        },
      };
    case 'REPLACE':
      return {
        impl: (c, [a, b, l, p]) => {
          if (int(l!) < 0 || int(p!) < 0) return fail(c);
          const s = str(a!);
          const n = lp(l!);
          const at = lp(p!);
          if (at === 0) return fail(c);
          const keep = cut(at, s.length);
          return clipString(s.slice(0, keep) + str(b!).slice(0, n) + (keep + n < s.length ? s.slice(keep + n) : ''));
        },
      };
    case 'FIND': {
      const find = matiec ? matiecFind : iecFind;
      const f: FnImpl2 = (_c, a, b) => normalize(outType, find(str(a), str(b)));
      return { impl: (c, args) => f(c, args[0]!, args[1]!), impl2: f };
    }
  }
}

/** ENO OFF; the output is not assigned (the value is MATIEC's __INIT_STRING). */
function fail(ctx: FnContext): string {
  ctx.error = true;
  return '';
}

/**
 * FIND in the standard's words: the position of the first occurrence of IN2 in IN1, 0 when there is
 * none; an empty IN2 is not an occurrence (0), as in MATIEC's library since 2020.
 */
const iecFind = (s: string, sub: string): number => (sub.length === 0 ? 0 : s.indexOf(sub) + 1);

/**
 * MATIEC's __pfind (its library since 2020, which Beremiz builds; OpenPLC v3's runtime bundles the
 * older one, see docs/simulation.md): 0 when IN2 is empty or longer than IN1 or not found; after a
 * mismatch the scan resumes past the partial match, so an occurrence that starts inside one is
 * missed: FIND('aab', 'ab') = 0 (iec: 2).
 */
export function matiecFind(s: string, sub: string): number {
  if (sub.length === 0 || s.length < sub.length) return 0;
  let count1 = 0;
  let count2 = 0;
  while (count1 + count2 < s.length && count2 < sub.length) {
    if (s[count1 + count2] !== sub[count2]) {
      count1 += count2 + 1;
      count2 = 0;
    } else count2++;
  }
  return count2 === sub.length ? count1 + 1 : 0;
}

/**
 * How two strings compare: below 0, 0 or above 0. Character by character (character codes, as
 * MATIEC's memcmp of unsigned bytes), a string that is the start of a longer one before it:
 * 'abc' < 'abcd'. Both profiles: MATIEC's __str_cmp since 2020 compares the common length and then
 * the lengths (before, '' equalled every string; OpenPLC v3's runtime still bundles that library).
 */
export const compareStrings = (a: string, b: string): number => (a < b ? -1 : a > b ? 1 : 0);

// ---- conversions ----

/** A value as MATIEC's X_TO_STRING writes it (TIME: profile time-to-string). */
export function toStringText(from: ElementaryType, v: Value, profile: Profile): string {
  if (from === 'BOOL') return v === true ? 'TRUE' : 'FALSE';
  if (from === 'BYTE' || from === 'WORD' || from === 'DWORD' || from === 'LWORD') return `16#${BigInt.asUintN(64, BigInt(v as number | bigint)).toString(16)}`;
  if (from === 'REAL' || from === 'LREAL') return printfG(num(v), 10);
  if (from === 'TIME') return profile === 'openplc' ? matiecTimeText(num(v)) : formatTime(num(v));
  if (isDateType(from)) return profile === 'openplc' ? matiecDateText(from, num(v)) : formatDate(from, num(v));
  if (isStringType(from)) return str(v);
  return String(v);
}

/** C's printf("%.<precision>g") of a double, as glibc writes it. */
export function printfG(x: number, precision: number): string {
  if (Number.isNaN(x)) return 'nan';
  if (!Number.isFinite(x)) return x < 0 ? '-inf' : 'inf';
  if (x === 0) return Object.is(x, -0) ? '-0' : '0';
  const exp = Number(x.toExponential(precision - 1).split('e')[1]);
  if (exp < -4 || exp >= precision) {
    const [mantissa, e] = x.toExponential(precision - 1).split('e') as [string, string];
    const sign = e.startsWith('-') ? '-' : '+';
    const digits = e.replace(/^[+-]/, '').padStart(2, '0');
    return `${stripZeros(mantissa)}e${sign}${digits}`;
  }
  return stripZeros(x.toFixed(Math.max(0, precision - 1 - exp)));
}

const stripZeros = (t: string): string => (t.includes('.') ? t.replace(/0+$/, '').replace(/\.$/, '') : t);

/**
 * MATIEC's __time_to_string: T#<d>d<h>h<m>m<s>s<ms>ms, stopping after the last non-zero part
 * (T#0d for zero, T#0d0h0m1s500ms for 1.5 s), each part of a negative TIME negative.
 */
export function matiecTimeText(ms: number): string {
  const sec = Math.trunc(ms / 1000);
  const fracMs = ms - sec * 1000;
  const days = { quot: Math.trunc(sec / 86400), rem: sec % 86400 };
  if (days.rem === 0 && fracMs === 0) return `T#${days.quot}d`;
  const hours = { quot: Math.trunc(days.rem / 3600), rem: days.rem % 3600 };
  if (hours.rem === 0 && fracMs === 0) return `T#${days.quot}d${hours.quot}h`;
  const minutes = { quot: Math.trunc(hours.rem / 60), rem: hours.rem % 60 };
  if (minutes.rem === 0 && fracMs === 0) return `T#${days.quot}d${hours.quot}h${minutes.quot}m`;
  const head = `T#${days.quot}d${hours.quot}h${minutes.quot}m${minutes.rem}s`;
  return fracMs === 0 ? head : `${head}${printfG(fracMs, 6)}ms`;
}

/**
 * MATIEC's __date_to_string, __tod_to_string and __dt_to_string: D#2024-01-31, TOD#12:30:15 or
 * with a fraction TOD#12:30:05.500000 (printf %09.6f seconds), DT#2024-01-31-12:30:15.
 */
export function matiecDateText(type: DateType, ms: number): string {
  const b = brokenDown(ms);
  const date = `${b.y}-${pad2(b.mo)}-${pad2(b.d)}`;
  if (type === 'DATE') return `D#${date}`;
  const seconds = b.milli === 0 ? pad2(b.s) : (b.s + b.milli / 1000).toFixed(6).padStart(9, '0');
  const clock = `${pad2(b.h)}:${pad2(b.mi)}:${seconds}`;
  return type === 'TOD' ? `TOD#${clock}` : `DT#${date}-${clock}`;
}

const pad2 = (n: number) => String(n).padStart(2, '0');

/** MATIEC's __pstring_to_sint: a LINT read from 2#.., 8#.., 16#.. or decimal text, skipping what it cannot read. */
export function matiecStringToInt(s: string): bigint {
  let res = 0n;
  const based = (start: number, bits: number, digit: (c: string) => number) => {
    let shift = 0;
    for (let l = s.length - 1; l >= start && shift < 64; l--) {
      const d = digit(s[l]!);
      if (d >= 0) {
        res |= BigInt(d) << BigInt(shift);
        shift += bits;
      }
    }
    return BigInt.asIntN(64, res);
  };
  if (s.length < 1) return 0n;
  if (s.length > 1 && s.startsWith('2#')) return based(2, 1, (c) => (c === '0' || c === '1' ? Number(c) : -1));
  if (s.length > 1 && s.startsWith('8#')) return based(2, 3, (c) => (c >= '0' && c <= '7' ? Number(c) : -1));
  if (s.length > 2 && s.startsWith('16#')) return based(3, 4, (c) => (/^[0-9a-fA-F]$/.test(c) ? parseInt(c, 16) : -1));
  const sign = s[0] === '-' ? -1n : 1n;
  let fac = sign;
  let shift = 0;
  for (let l = s.length; l > 0 && shift < 20; l--) {
    const c = s[l - 1]!;
    const code = c.charCodeAt(0);
    if (c >= '0' && c <= '9') {
      res = BigInt.asIntN(64, res + BigInt(code - 48) * fac);
      fac = BigInt.asIntN(64, fac * 10n);
      shift++;
    } else if (code >= 0x2e && code < 0x80) {
      // Any other character from '.' up (a signed char: bytes above 127 are below '.') starts over.
      res = 0n;
      fac = sign;
      shift = 0;
    }
  }
  return res;
}

/** C's atof: the longest number at the start of the text (after spaces), 0 when there is none. */
function atof(s: string): number {
  const m = /^[ \t\n\v\f\r]*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)/.exec(s);
  return m ? Number(m[1]) : 0;
}

/** MATIEC's __string_to_real: atof when a '.' follows the first character, else the integer reading. */
function matiecStringToReal(s: string): number {
  let l = s.length;
  while (--l > 0 && s[l] !== '.');
  return l > 0 ? atof(s) : Number(matiecStringToInt(s));
}

/** STRING_TO_<to>. openplc: MATIEC's lenient readers; iec: an IEC literal of the type (else ENO OFF, 0). */
export function fromStringConversion(to: ElementaryType, profile: Profile): FnImpl1 {
  if (to === 'BOOL')
    return (_c, a) => {
      const s = str(a);
      return s.length === 1 ? s === '1' : s.toUpperCase() === 'TRUE';
    };
  if (profile === 'iec') {
    // A TIME, DATE, TOD or DT may also be a plain number of milliseconds (the iec unit of their conversions).
    return (ctx, a) => {
      const text = str(a).trim();
      if (isTimeLike(to) && /^[+-]?\d+$/.test(text)) return normalize(to, Number(text));
      const r = parseLiteral(text, to);
      if (r.ok) return r.value;
      ctx.error = true;
      return defaultValue(to);
    };
  }
  if (to === 'REAL') return (_c, a) => Math.fround(matiecStringToReal(str(a)));
  if (to === 'LREAL') return (_c, a) => matiecStringToReal(str(a));
  if (isTimeLike(to)) {
    // __string_to_time (also for DATE, TOD, DT): seconds; with a '.', atof's whole seconds (its
    // fraction is lost to a cast).
    return (_c, a) => {
      const s = str(a);
      let l = s.length;
      while (l > 0 && s[--l] !== '.');
      const seconds = l !== 0 ? Math.trunc(atof(s)) : Number(matiecStringToInt(s));
      return normalize(to, seconds * 1000);
    };
  }
  // Integers and bit strings: the LINT read, cast to the type (wrapped to its width).
  return (_c, a) => normalize(to, matiecStringToInt(str(a)));
}

/** X_TO_STRING or STRING_TO_X. */
export function stringConversion(from: ElementaryType, to: ElementaryType, profile: Profile): FnImpl1 {
  // MATIEC's __tod_to_string: a TOD of a day or more gives 'TOD#ERROR' with ENO ON (it calls
  // __iec_error(), which does not touch ENO; checked against the reference); iec: an error (ENO OFF).
  if (from === 'TOD' && to === 'STRING')
    return (ctx, a) => {
      if (num(a) >= DAY_MS || num(a) < 0) {
        if (profile === 'iec') ctx.error = true;
        return 'TOD#ERROR';
      }
      return toStringText(from, a, profile);
    };
  if (to === 'STRING') return (_c, a) => clipString(toStringText(from, a, profile));
  return fromStringConversion(to, profile);
}

// ---- comparisons, MAX, MIN, LIMIT of strings ----

const STRING_COMPARISONS = ['GT', 'GE', 'EQ', 'NE', 'LE', 'LT', 'MAX', 'MIN', 'LIMIT'] as const;
type StringComparison = (typeof STRING_COMPARISONS)[number];
export const isStringComparison = (name: string): name is StringComparison => (STRING_COMPARISONS as readonly string[]).includes(name);

const TESTS: Record<Exclude<StringComparison, 'MAX' | 'MIN' | 'LIMIT'>, (d: number) => boolean> = {
  GT: (d) => d > 0,
  GE: (d) => d >= 0,
  EQ: (d) => d === 0,
  NE: (d) => d !== 0,
  LE: (d) => d <= 0,
  LT: (d) => d < 0,
};

/**
 * GT..LT (chained like MATIEC's __compare_), MAX, MIN (MATIEC's __extrem_: a later input replaces
 * the best only when strictly better) and LIMIT (MATIEC: IN > MN ? (IN < MX ? IN : MX) : MN, in
 * both profiles) over strings (compareStrings).
 */
export function stringComparison(
  name: StringComparison,
  _t: ElementaryType,
  argc: number,
): { impl: FnImpl; impl2?: FnImpl2 } {
  const cmp = (a: Value, b: Value) => compareStrings(str(a), str(b));
  if (name === 'LIMIT') return { impl: (_c, [mn, v, mx]) => (cmp(v!, mn!) > 0 ? (cmp(v!, mx!) < 0 ? v! : mx!) : mn!) };
  if (name === 'MAX' || name === 'MIN') {
    const better = name === 'MAX' ? (d: number) => d < 0 : (d: number) => d > 0;
    const impl: FnImpl = (_c, args) => {
      let best = args[0]!;
      for (let i = 1; i < args.length; i++) if (better(cmp(best, args[i]!))) best = args[i]!;
      return best;
    };
    return argc === 2 ? { impl, impl2: (_c, a, b) => (better(cmp(a, b)) ? b : a) } : { impl };
  }
  const test = TESTS[name];
  const impl: FnImpl = (_c, args) => {
    for (let i = 1; i < args.length; i++) if (!test(cmp(args[i - 1]!, args[i]!))) return false;
    return true;
  };
  return argc === 2 ? { impl, impl2: (_c, a, b) => test(cmp(a, b)) } : { impl };
}
