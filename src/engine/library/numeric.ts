// Numerical functions of one REAL/LREAL variable (IEC 61131-3 table 23: SQRT LN LOG EXP SIN COS TAN
// ASIN ACOS ATAN) and EXPT (table 24), as MATIEC's lib/C/iec_std_functions.h runs them: the C
// library function on a double, the result cast to the input's type (REAL: rounded to 32 bits).
// MATIEC checks nothing but EN: SQRT(-1) is NaN, LN(0) is -Inf, EXP(1000) is +Inf, all with ENO ON.
import type { ElementaryType } from '../../model/iecTypes';
import { num, type FnImpl1, type FnImpl2 } from './fnTypes';

export type RealFunctionName = 'SQRT' | 'LN' | 'LOG' | 'EXP' | 'SIN' | 'COS' | 'TAN' | 'ASIN' | 'ACOS' | 'ATAN';

const C_FUNCTION: Record<RealFunctionName, (x: number) => number> = {
  SQRT: Math.sqrt,
  LN: Math.log,
  LOG: Math.log10,
  EXP: Math.exp,
  SIN: Math.sin,
  COS: Math.cos,
  TAN: Math.tan,
  ASIN: Math.asin,
  ACOS: Math.acos,
  ATAN: Math.atan,
};

export const isRealFunction = (name: string): name is RealFunctionName => Object.hasOwn(C_FUNCTION, name);

/** The function for a REAL or LREAL input (the caller resolved t to one of them). */
export function realFunction(name: RealFunctionName, t: ElementaryType): FnImpl1 {
  const f = C_FUNCTION[name];
  return t === 'REAL' ? (_c, a) => Math.fround(f(a as number)) : (_c, a) => f(a as number);
}

/**
 * C's pow(): where JavaScript's Math.pow differs (C99 F.9.4.4): pow(1, y) is 1 for any y, NaN
 * included, and pow(-1, ±Inf) is 1; Math.pow gives NaN for both.
 */
export function cPow(x: number, y: number): number {
  if (x === 1) return 1;
  if (x === -1 && !Number.isFinite(y) && !Number.isNaN(y)) return 1;
  return Math.pow(x, y);
}

/** EXPT(IN1, IN2): IN1 REAL or LREAL (the result's type), IN2 any number, converted to a double. */
export function power(t: ElementaryType): FnImpl2 {
  return t === 'REAL'
    ? (_c, a, b) => Math.fround(cPow(a as number, num(b)))
    : (_c, a, b) => cPow(a as number, num(b));
}
