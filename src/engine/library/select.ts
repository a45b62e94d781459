// Comparison (table 28) and selection (table 27) functions. Extensible comparisons chain:
// GT(IN1, IN2, IN3) = IN1 > IN2 AND IN2 > IN3, as in MATIEC's __compare_.
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { Profile } from '../../model/project';
import { defaultValue, isBigIntType } from '../values/types';
import { big, num, type FnContext, type FnImpl, type FnImpl2 } from './fnTypes';

export type CompareOp = 'GT' | 'GE' | 'EQ' | 'NE' | 'LE' | 'LT';

type Test = (a: Value, b: Value) => boolean;

// Values of one type share one representation (boolean, number or bigint), so JS operators compare
// them exactly; bigint types go through big() in case a caller passed a narrower number.
function test(op: CompareOp, t: ElementaryType): Test {
  const wide = isBigIntType(t);
  switch (op) {
    case 'GT':
      return wide ? (a, b) => big(a) > big(b) : (a, b) => a > b;
    case 'GE':
      return wide ? (a, b) => big(a) >= big(b) : (a, b) => a >= b;
    case 'EQ':
      return wide ? (a, b) => big(a) === big(b) : (a, b) => a === b;
    case 'NE':
      return wide ? (a, b) => big(a) !== big(b) : (a, b) => a !== b;
    case 'LE':
      return wide ? (a, b) => big(a) <= big(b) : (a, b) => a <= b;
    case 'LT':
      return wide ? (a, b) => big(a) < big(b) : (a, b) => a < b;
  }
}

export function compare(op: CompareOp, t: ElementaryType): { impl: FnImpl; impl2: FnImpl2 } {
  const cmp = test(op, t);
  return {
    impl2: (_c, a, b) => cmp(a, b),
    impl: (_c, args) => {
      for (let i = 1; i < args.length; i++) if (!cmp(args[i - 1]!, args[i]!)) return false;
      return true;
    },
  };
}

export function extreme(which: 'MAX' | 'MIN', t: ElementaryType): { impl: FnImpl; impl2: FnImpl2 } {
  const better = test(which === 'MAX' ? 'GT' : 'LT', t);
  return {
    impl2: (_c, a, b) => (better(b, a) ? b : a),
    impl: (_c, args) => {
      let best = args[0]!;
      for (let i = 1; i < args.length; i++) if (better(args[i]!, best)) best = args[i]!;
      return best;
    },
  };
}

/** LIMIT(MN, IN, MX); the profiles differ only when MN > MX (see profiles.ts, limit-crossed). */
export function limit(t: ElementaryType, profile: Profile): FnImpl {
  const gt = test('GT', t);
  const lt = test('LT', t);
  if (profile === 'openplc') return (_c, [mn, v, mx]) => (gt(v!, mn!) ? (lt(v!, mx!) ? v! : mx!) : mn!);
  return (_c, [mn, v, mx]) => {
    const atLeast = lt(v!, mn!) ? mn! : v!;
    return gt(atLeast, mx!) ? mx! : atLeast;
  };
}

export const select: FnImpl = (_c, args) => (args[0] ? args[2]! : args[1]!);

/**
 * MUX(K, IN0, IN1, ...): K outside 0..n-1 is an error (ENO OFF; OUT, the type's initial value, is
 * not assigned). Profile openplc (mux-negative): MATIEC tests only K >= n, so a negative K gives
 * OUT = the initial value with ENO ON.
 */
export function multiplex(t: ElementaryType, profile: Profile = 'iec'): FnImpl {
  const fallback = defaultValue(t);
  const negativeOk = profile === 'openplc';
  return (ctx: FnContext, args) => {
    const k = num(args[0]!);
    const n = args.length - 1;
    if (negativeOk && k < 0) return fallback;
    if (!(k >= 0 && k < n)) {
      ctx.error = true;
      return fallback;
    }
    return args[k + 1]!;
  };
}
