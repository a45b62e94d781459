// ADD SUB MUL DIV MOD ABS NEG MOVE for one concrete type (IEC 61131-3 tables 23-24).
// Integers wrap at their width as on a PLC; REAL is rounded to 32 bits after every operation;
// integer DIV truncates toward zero; DIV by zero is an error (ENO OFF) with result 0.
import type { ElementaryType } from '../../model/iecTypes';
import type { Profile } from '../../model/project';
import { isSignedType } from '../values/types';
import { big, type FnImpl1, type FnImpl2 } from './fnTypes';

type NumOp = (a: number, b: number) => number;

/** Wrap of an exact integer result to the width of an 8/16/32-bit type. */
export const WRAP32: Partial<Record<ElementaryType, (n: number) => number>> = {
  SINT: (n) => (n << 24) >> 24,
  INT: (n) => (n << 16) >> 16,
  DINT: (n) => n | 0,
  USINT: (n) => n & 0xff,
  BYTE: (n) => n & 0xff,
  UINT: (n) => n & 0xffff,
  WORD: (n) => n & 0xffff,
  UDINT: (n) => n >>> 0,
  DWORD: (n) => n >>> 0,
};

const wrap64 = (t: ElementaryType, n: bigint): bigint => (t === 'LINT' ? BigInt.asIntN(64, n) : BigInt.asUintN(64, n));
const is64 = (t: ElementaryType): boolean => t === 'LINT' || t === 'ULINT' || t === 'LWORD';

export type ArithOp = 'ADD' | 'SUB' | 'MUL' | 'DIV' | 'MOD';

function numberOp(op: ArithOp, t: ElementaryType, profile: Profile): FnImpl2 | undefined {
  if (t === 'REAL' || t === 'LREAL') {
    const r: (n: number) => number = t === 'REAL' ? Math.fround : (n) => n;
    switch (op) {
      case 'ADD':
        return (_c, a, b) => r((a as number) + (b as number));
      case 'SUB':
        return (_c, a, b) => r((a as number) - (b as number));
      case 'MUL':
        return (_c, a, b) => r((a as number) * (b as number));
      case 'DIV':
        return (ctx, a, b) => {
          if (b === 0) {
            ctx.error = true;
            return 0;
          }
          return r((a as number) / (b as number));
        };
      case 'MOD':
        return undefined;
    }
  }
  if (t === 'TIME') {
    if (op === 'ADD') return (_c, a, b) => (a as number) + (b as number);
    if (op === 'SUB') return (_c, a, b) => (a as number) - (b as number);
    return undefined;
  }
  const w = WRAP32[t];
  if (!w) return undefined;
  // Products of two 32-bit values can exceed 2^53; Math.imul gives the exact low 32 bits.
  const mul: NumOp = t === 'DINT' ? (a, b) => Math.imul(a, b) : t === 'UDINT' || t === 'DWORD' ? (a, b) => Math.imul(a, b) >>> 0 : (a, b) => w(a * b);
  switch (op) {
    case 'ADD':
      return (_c, a, b) => w((a as number) + (b as number));
    case 'SUB':
      return (_c, a, b) => w((a as number) - (b as number));
    case 'MUL':
      return (_c, a, b) => mul(a as number, b as number);
    case 'DIV':
      return (ctx, a, b) => {
        if (b === 0) {
          ctx.error = true;
          return 0;
        }
        return w(Math.trunc((a as number) / (b as number)));
      };
    case 'MOD':
      return (ctx, a, b) => {
        if (b === 0) {
          if (profile === 'iec') ctx.error = true;
          return 0;
        }
        return w((a as number) % (b as number));
      };
  }
}

function bigintOp(op: ArithOp, t: ElementaryType, profile: Profile): FnImpl2 {
  switch (op) {
    case 'ADD':
      return (_c, a, b) => wrap64(t, big(a) + big(b));
    case 'SUB':
      return (_c, a, b) => wrap64(t, big(a) - big(b));
    case 'MUL':
      return (_c, a, b) => wrap64(t, big(a) * big(b));
    case 'DIV':
      return (ctx, a, b) => {
        const d = big(b);
        if (d === 0n) {
          ctx.error = true;
          return 0n;
        }
        return wrap64(t, big(a) / d);
      };
    case 'MOD':
      return (ctx, a, b) => {
        const d = big(b);
        if (d === 0n) {
          if (profile === 'iec') ctx.error = true;
          return 0n;
        }
        return wrap64(t, big(a) % d);
      };
  }
}

/** The two-input operation for type t, or undefined when t has no such operation (MOD on REAL, MUL on TIME). */
export function arithmetic(op: ArithOp, t: ElementaryType, profile: Profile): FnImpl2 | undefined {
  return is64(t) ? bigintOp(op, t, profile) : numberOp(op, t, profile);
}

/** ABS: |IN|; the most negative integer stays itself (wraps), as on a PLC. */
export function absolute(t: ElementaryType): FnImpl1 {
  if (t === 'REAL' || t === 'LREAL') return (_c, a) => Math.abs(a as number);
  if (!isSignedType(t)) return (_c, a) => a;
  if (t === 'LINT') return (_c, a) => BigInt.asIntN(64, big(a) < 0n ? -big(a) : big(a));
  const w = WRAP32[t]!;
  return (_c, a) => ((a as number) < 0 ? w(-(a as number)) : a);
}

/** NEG: -IN for signed integers and reals (unsigned types are refused at resolution). */
export function negate(t: ElementaryType): FnImpl1 {
  if (t === 'REAL' || t === 'LREAL') return (_c, a) => -(a as number);
  if (t === 'LINT') return (_c, a) => BigInt.asIntN(64, -big(a));
  const w = WRAP32[t]!;
  return (_c, a) => w(-(a as number));
}
