// A value given by a user or a tool (an input from the I/O, a machine's sensor, a value written from
// the page) is stored as a PLC stores it: the quick path for whole numbers in range gives exactly
// what wrapping and checking give.
import { describe, expect, it } from 'vitest';
import type { ElementaryType } from '../../src/model/iecTypes';
import { coerce } from '../../src/engine/runtime/memory';
import { normalize, typeRange } from '../../src/engine/values/types';

const NUMBER_TYPES: ElementaryType[] = ['SINT', 'INT', 'DINT', 'USINT', 'UINT', 'UDINT', 'BYTE', 'WORD', 'DWORD'];

describe('coerce of numbers into the 8/16/32-bit types', () => {
  it.each(NUMBER_TYPES)('%s: every value stored is the wrapped value, -0 as 0, edges and beyond', (t) => {
    const { min, max } = typeRange(t as Parameters<typeof typeRange>[0]);
    const lo = Number(min);
    const hi = Number(max);
    for (const v of [lo, lo + 1, -1, -0, 0, 1, 100, hi - 1, hi, hi + 1, lo - 1, 2 ** 33 + 7, 12.9, -12.9]) {
      const stored = coerce(t, v, 'X');
      expect(Object.is(stored, normalize(t, v)), `${t} ${v} -> ${String(stored)}`).toBe(true);
    }
    expect(Object.is(coerce(t, -0, 'X'), 0)).toBe(true);
  });

  it('refuses what no integer type holds, naming the variable', () => {
    expect(() => coerce('INT', Number.NaN, 'Level')).toThrow('Level is INT; NaN is not a INT value');
    expect(() => coerce('INT', true, 'Level')).toThrow('Level is INT; true is not a INT value');
    expect(() => coerce('INT', 'x', 'Level')).toThrow('Level is INT; the text "x" is not a INT value');
  });

  it('leaves the other types to their own rules', () => {
    expect(coerce('REAL', 0.1, 'R')).toBe(Math.fround(0.1));
    expect(coerce('LINT', 5, 'L')).toBe(5n);
    expect(coerce('TIME', 1500.4, 'T')).toBe(1500);
    expect(coerce('BOOL', 1, 'B')).toBe(true);
  });
});
