// A_TO_B conversions (IEC 61131-3 table 22) for every pair of supported elementary types.
//
// Decisions (both profiles unless noted; see profiles.ts for the differences):
// - BOOL_TO_x gives 0/1 (BOOL_TO_TIME: one time unit); x_TO_BOOL is TRUE for any non-zero value.
// - Integer to integer: the value wrapped to the target width. Out of the target's range is an
//   error in `iec` (ENO OFF, OUT still the wrapped value); `openplc` keeps ENO ON, as MATIEC's C cast.
// - Where a bit string (BYTE..LWORD) is the source or the target the conversion is a binary
//   transfer (WORD_TO_INT(16#FFFF) = -1, INT_TO_WORD(-1) = 16#FFFF): never an error.
// - REAL/LREAL to an integer or bit string rounds to nearest, ties to even (2.5 -> 2, 3.5 -> 4),
//   as MATIEC's __real_round; a negative value to an unsigned type gives 0; NaN gives 0. Out of
//   range: the wrapped value, and an error in `iec`.
// - LREAL_TO_REAL rounds to 32 bits; a finite value too large for REAL is an error in `iec`.
// - TIME counts milliseconds in `iec` and seconds in `openplc` (MATIEC's timespec tv_sec; its
//   TIME_TO_REAL keeps the fraction of a second, REAL_TO_TIME reads one).
// - DATE, TOD and DT convert like TIME (ms in `iec`, seconds in `openplc`); DT_TO_DATE and DT_TO_TOD
//   keep the day or the time of day. To and from STRING: strings.ts.
import { INT_INFO, type ElementaryType, type Value } from '../../model/iecTypes';
import type { Profile } from '../../model/project';
import { isBigIntType, isBitStringType, isRealType, isSizedType, isTimeLike, normalize, typeRange } from '../values/types';
import { DAY_MS } from '../values/dateText';
import { timeConversionUnitMs } from './profiles';
import { stringConversion } from './strings';
import { num, type FnContext, type FnImpl1 } from './fnTypes';

/** Round to nearest, ties to even. */
export function roundHalfEven(x: number): number {
  const r = Math.round(x);
  // `|| 0` turns -0 (Math.round(-0.4)) into 0 so results compare equal to a plain 0.
  return (Math.abs(x % 1) === 0.5 && r % 2 !== 0 ? r - 1 : r) || 0;
}

const isZero = (v: Value): boolean => v === false || v === 0 || v === 0n;
const mod = (a: number, m: number): number => ((a % m) + m) % m;

/**
 * An exact integer to a sized type: wrapped to its width, flagged as an error in `iec` when out of
 * range unless the conversion is a binary transfer. Numbers stay numbers for 8-32-bit targets (fast path).
 */
function toSized(to: ElementaryType, transfer: boolean, strict: boolean): (ctx: FnContext, v: number | bigint) => Value {
  const check = strict && !transfer && isSizedType(to);
  const range = isSizedType(to) ? typeRange(to) : { min: 0n, max: 0n };
  if (isBigIntType(to)) {
    return (ctx, v) => {
      const b = typeof v === 'bigint' ? v : BigInt(v);
      if (check && (b < range.min || b > range.max)) ctx.error = true;
      return normalize(to, b);
    };
  }
  const min = Number(range.min);
  const max = Number(range.max);
  return (ctx, v) => {
    if (check && (v < min || v > max)) ctx.error = true;
    return normalize(to, v);
  };
}

export function conversion(from: ElementaryType, to: ElementaryType, profile: Profile): FnImpl1 {
  if (from === 'STRING' || to === 'STRING') return stringConversion(from, to, profile);
  // MATIEC's __date_and_time_to_date / __date_and_time_to_time_of_day.
  if (from === 'DT' && to === 'DATE') return (_c, a) => num(a) - mod(num(a), DAY_MS);
  if (from === 'DT' && to === 'TOD') return (_c, a) => mod(num(a), DAY_MS);
  const strict = profile === 'iec';
  const unit = timeConversionUnitMs(profile);
  if (to === 'BOOL') return (_c, a) => !isZero(a);
  if (from === 'BOOL') {
    if (isTimeLike(to)) return (_c, a) => (a ? unit : 0);
    return (_c, a) => normalize(to, a ? 1 : 0);
  }

  if (isRealType(from)) {
    if (to === 'REAL') {
      return (ctx, a) => {
        const r = Math.fround(num(a));
        if (strict && !Number.isFinite(r) && Number.isFinite(num(a))) ctx.error = true;
        return r;
      };
    }
    if (to === 'LREAL') return (_c, a) => num(a);
    if (isTimeLike(to)) {
      return (ctx, a) => {
        const ms = num(a) * unit;
        if (!Number.isFinite(ms) || Math.abs(ms) > Number.MAX_SAFE_INTEGER) {
          if (strict) ctx.error = true;
          return 0;
        }
        return roundHalfEven(ms);
      };
    }
    const unsigned = !INT_INFO[to as keyof typeof INT_INFO].signed;
    const sized = toSized(to, false, strict);
    return (ctx, a) => {
      const x = num(a);
      if (Number.isNaN(x) || !Number.isFinite(x)) {
        if (strict) ctx.error = true;
        return normalize(to, 0);
      }
      const r = roundHalfEven(x);
      if (unsigned && r < 0) {
        if (strict) ctx.error = true;
        return normalize(to, 0);
      }
      return sized(ctx, r);
    };
  }

  if (isTimeLike(from)) {
    if (to === 'REAL') return (_c, a) => Math.fround(num(a) / unit);
    if (to === 'LREAL') return (_c, a) => num(a) / unit;
    // MATIEC's tv_sec of a normalised timespec: whole seconds, truncated toward zero.
    const sized = toSized(to, false, strict);
    return (ctx, a) => sized(ctx, Math.trunc(num(a) / unit));
  }

  // From an integer or bit string.
  const transferFrom = isBitStringType(from);
  if (to === 'REAL') return (_c, a) => Math.fround(num(a));
  if (to === 'LREAL') return (_c, a) => num(a);
  if (isTimeLike(to)) return (_c, a) => normalize(to, num(a) * unit);
  const sized = toSized(to, transferFrom || isBitStringType(to), strict);
  return (ctx, a) => sized(ctx, a as number | bigint);
}

/**
 * TRUNC (ANY_REAL -> ANY_INT): toward zero (TRUNC(-2.7) = -2), as MATIEC's C cast. A value out of
 * the target's range gives the wrapped value, an error in `iec` (ENO OFF) and not in `openplc`
 * (the C cast), as the A_TO_B conversions; NaN and infinities give 0 (an error in `iec`).
 */
export function truncation(to: ElementaryType, profile: Profile): FnImpl1 {
  const strict = profile === 'iec';
  const sized = toSized(to, false, strict);
  return (ctx, a) => {
    const x = num(a);
    if (!Number.isFinite(x)) {
      if (strict) ctx.error = true;
      return normalize(to, 0);
    }
    return sized(ctx, Math.trunc(x) || 0);
  };
}
