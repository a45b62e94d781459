// AND OR XOR NOT SHL SHR ROL ROR (IEC 61131-3 tables 25-26). BOOL is logical; BYTE..LWORD bitwise
// at their width. Shifts fill with 0 and give 0 once N reaches the width; rotates take N modulo the
// width. A negative N is an error (ENO OFF, OUT = IN): the standard does not define it.
import type { ElementaryType } from '../../model/iecTypes';
import { big, num, type FnImpl1, type FnImpl2 } from './fnTypes';

export type LogicOp = 'AND' | 'OR' | 'XOR';
export type ShiftOp = 'SHL' | 'SHR' | 'ROL' | 'ROR';

const WIDTH: Partial<Record<ElementaryType, number>> = { BYTE: 8, WORD: 16, DWORD: 32 };

export function logic(op: LogicOp, t: ElementaryType): FnImpl2 {
  if (t === 'BOOL') {
    if (op === 'AND') return (_c, a, b) => (a as boolean) && (b as boolean);
    if (op === 'OR') return (_c, a, b) => (a as boolean) || (b as boolean);
    return (_c, a, b) => (a as boolean) !== (b as boolean);
  }
  if (t === 'LWORD') {
    if (op === 'AND') return (_c, a, b) => big(a) & big(b);
    if (op === 'OR') return (_c, a, b) => big(a) | big(b);
    return (_c, a, b) => big(a) ^ big(b);
  }
  // >>> 0 keeps DWORD results unsigned; BYTE/WORD operands are already small and non-negative.
  if (op === 'AND') return (_c, a, b) => ((a as number) & (b as number)) >>> 0;
  if (op === 'OR') return (_c, a, b) => ((a as number) | (b as number)) >>> 0;
  return (_c, a, b) => ((a as number) ^ (b as number)) >>> 0;
}

export function complement(t: ElementaryType): FnImpl1 {
  if (t === 'BOOL') return (_c, a) => !a;
  if (t === 'LWORD') return (_c, a) => BigInt.asUintN(64, ~big(a));
  const mask = t === 'BYTE' ? 0xff : t === 'WORD' ? 0xffff : 0xffffffff;
  return (_c, a) => (~(a as number) & mask) >>> 0;
}

export function shift(op: ShiftOp, t: ElementaryType): FnImpl2 {
  if (t === 'BOOL') {
    // A single bit: shifting by N >= 1 brings in a 0, rotating leaves it (as MATIEC's SHL__BOOL).
    const moves = op === 'SHL' || op === 'SHR';
    return (ctx, a, nv) => {
      const n = num(nv);
      if (n < 0) ctx.error = true;
      return moves && n > 0 ? false : a;
    };
  }
  if (t === 'LWORD') {
    return (ctx, a, nv) => {
      const n = num(nv);
      if (n < 0) {
        ctx.error = true;
        return a;
      }
      const v = big(a);
      if (op === 'SHL') return n >= 64 ? 0n : BigInt.asUintN(64, v << BigInt(n));
      if (op === 'SHR') return n >= 64 ? 0n : v >> BigInt(n);
      const r = BigInt(n % 64);
      if (r === 0n) return v;
      return op === 'ROL' ? BigInt.asUintN(64, (v << r) | (v >> (64n - r))) : BigInt.asUintN(64, (v >> r) | (v << (64n - r)));
    };
  }
  const width = WIDTH[t] ?? 32;
  const mask = width === 32 ? 0xffffffff : (1 << width) - 1;
  return (ctx, a, nv) => {
    const n = num(nv);
    const v = a as number;
    if (n < 0) {
      ctx.error = true;
      return v;
    }
    if (op === 'SHL') return n >= width ? 0 : ((v << n) & mask) >>> 0;
    if (op === 'SHR') return n >= width ? 0 : v >>> n;
    const r = n % width;
    if (r === 0) return v;
    return op === 'ROL' ? (((v << r) | (v >>> (width - r))) & mask) >>> 0 : (((v >>> r) | (v << (width - r))) & mask) >>> 0;
  };
}
