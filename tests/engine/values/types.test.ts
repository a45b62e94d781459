// Value representation: integers wrap at their width as on a PLC, REAL is 32-bit, IEC implicit widenings.
import { describe, expect, it } from 'vitest';
import { ELEMENTARY_TYPES, type ElementaryType, type Value } from '../../../src/model/iecTypes';
import { canWiden, commonType, defaultValue, isValueOfType, normalize, typeRange, widen } from '../../../src/engine/values/types';

describe('normalize wraps integers at their width (two\'s complement)', () => {
  it.each<[ElementaryType, Value, Value]>([
    ['SINT', 128, -128],
    ['SINT', -129, 127],
    ['INT', 32768, -32768],
    ['INT', 65535, -1],
    ['DINT', 2 ** 31, -(2 ** 31)],
    ['USINT', 256, 0],
    ['USINT', -1, 255],
    ['UINT', 65536, 0],
    ['UDINT', -1, 4294967295],
    ['BYTE', 0x1ff, 0xff],
    ['WORD', -1, 0xffff],
    ['DWORD', 2 ** 32 + 5, 5],
    ['LINT', 2n ** 63n, -(2n ** 63n)],
    ['ULINT', -1n, 2n ** 64n - 1n],
    ['LWORD', 2n ** 64n + 3n, 3n],
    ['LINT', 5, 5n],
    ['INT', 12.9, 12],
    ['INT', -12.9, -12],
    ['DINT', 5n, 5],
    ['BOOL', 2, true],
    ['BOOL', 0n, false],
    ['REAL', 0.1, Math.fround(0.1)],
    ['LREAL', 0.1, 0.1],
    ['TIME', 1500.4, 1500],
    ['INT', Number.NaN, 0],
  ])('%s of %s is %s', (type, input, expected) => {
    expect(normalize(type, input)).toBe(expected);
  });

  it('every normalized value is a value of its type', () => {
    for (const t of ELEMENTARY_TYPES) {
      for (const v of [0, 1, -1, 300, 70000, 2 ** 40, 1.5] as const) expect(isValueOfType(t, normalize(t, v)), `${t} ${v}`).toBe(true);
    }
  });
});

describe('isValueOfType at the edges of every integer and bit-string type', () => {
  const sized: ElementaryType[] = ['SINT', 'INT', 'DINT', 'LINT', 'USINT', 'UINT', 'UDINT', 'ULINT', 'BYTE', 'WORD', 'DWORD', 'LWORD'];
  it.each(sized)('%s: its smallest and largest value are values of it, one beyond is not, nor a fraction or the other kind', (t) => {
    const { min, max } = typeRange(t as Parameters<typeof typeRange>[0]);
    const big = t === 'LINT' || t === 'ULINT' || t === 'LWORD';
    const as = (b: bigint): Value => (big ? b : Number(b));
    expect(isValueOfType(t, as(min))).toBe(true);
    expect(isValueOfType(t, as(max))).toBe(true);
    expect(isValueOfType(t, as(min - 1n))).toBe(false);
    expect(isValueOfType(t, as(max + 1n))).toBe(false);
    expect(isValueOfType(t, big ? 0 : 0n)).toBe(false);
    if (!big) {
      expect(isValueOfType(t, 1.5)).toBe(false);
      expect(isValueOfType(t, Number.NaN)).toBe(false);
      expect(isValueOfType(t, Number.POSITIVE_INFINITY)).toBe(false);
    }
  });
});

describe('typeRange and defaultValue', () => {
  it('gives the IEC ranges', () => {
    expect(typeRange('SINT')).toEqual({ min: -128n, max: 127n });
    expect(typeRange('UINT')).toEqual({ min: 0n, max: 65535n });
    expect(typeRange('LINT')).toEqual({ min: -(2n ** 63n), max: 2n ** 63n - 1n });
    expect(typeRange('LWORD')).toEqual({ min: 0n, max: 2n ** 64n - 1n });
  });

  it('initial values are FALSE, 0, 0n for 64-bit types, 0.0 and T#0s', () => {
    expect(defaultValue('BOOL')).toBe(false);
    expect(defaultValue('INT')).toBe(0);
    expect(defaultValue('ULINT')).toBe(0n);
    expect(defaultValue('REAL')).toBe(0);
    expect(defaultValue('TIME')).toBe(0);
  });

  it('isValueOfType refuses a wrong representation or an out-of-range value', () => {
    expect(isValueOfType('INT', 40000)).toBe(false);
    expect(isValueOfType('LINT', 5)).toBe(false);
    expect(isValueOfType('REAL', 0.1)).toBe(false); // not representable in 32 bits
    expect(isValueOfType('REAL', Math.fround(0.1))).toBe(true);
    expect(isValueOfType('BOOL', 1)).toBe(false);
    expect(isValueOfType('TIME', 1.5)).toBe(false);
  });
});

describe('implicit widening (IEC 61131-3 figure 11)', () => {
  it.each<[ElementaryType, ElementaryType, boolean]>([
    ['SINT', 'INT', true],
    ['INT', 'DINT', true],
    ['DINT', 'LINT', true],
    ['USINT', 'UINT', true],
    ['UINT', 'UDINT', true],
    ['UDINT', 'ULINT', true],
    ['USINT', 'INT', true], // unsigned into a wider signed
    ['UINT', 'DINT', true],
    ['UINT', 'INT', false], // same width: 65535 does not fit
    ['INT', 'UINT', false], // signed never becomes unsigned
    ['BYTE', 'WORD', true],
    ['DWORD', 'LWORD', true],
    ['INT', 'REAL', true], // exact: 16 bits fit a 24-bit mantissa
    ['DINT', 'REAL', false], // not exact
    ['DINT', 'LREAL', true],
    ['LINT', 'LREAL', false],
    ['REAL', 'LREAL', true],
    ['LREAL', 'REAL', false],
    ['BYTE', 'INT', false], // bit strings stay bit strings
    ['BOOL', 'BYTE', false],
    ['TIME', 'DINT', false],
    ['INT', 'INT', true],
  ])('%s -> %s: %s', (from, to, ok) => {
    expect(canWiden(from, to)).toBe(ok);
  });

  it('commonType picks the widest argument type, or the narrowest type covering all', () => {
    expect(commonType(['INT', 'DINT'])).toBe('DINT');
    expect(commonType(['INT', 'UINT'])).toBe('DINT');
    expect(commonType(['SINT', 'REAL'])).toBe('REAL');
    expect(commonType(['DINT', 'REAL'])).toBe('LREAL');
    expect(commonType(['INT', 'WORD'])).toBeUndefined();
    expect(commonType(['BOOL', 'INT'])).toBeUndefined();
  });

  it('widen converts the representation (INT -> LINT becomes a bigint)', () => {
    expect(widen('INT', 'LINT', -5)).toBe(-5n);
    expect(widen('INT', 'REAL', 7)).toBe(7);
  });
});
