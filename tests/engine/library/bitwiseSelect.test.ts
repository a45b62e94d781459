// Bit-string, comparison and selection functions.
import { describe, expect, it } from 'vitest';
import type { ElementaryType, Value } from '../../../src/model/iecTypes';
import type { Profile } from '../../../src/model/project';
import { call } from './fnHelpers';

describe('AND OR XOR NOT', () => {
  it.each<[string, ElementaryType, Value[], Value]>([
    ['AND', 'BOOL', [true, true, false], false],
    ['OR', 'BOOL', [false, false, true], true],
    ['XOR', 'BOOL', [true, true, true], true], // chained: odd number of TRUE
    ['AND', 'BYTE', [0xf0, 0x3c], 0x30],
    ['OR', 'WORD', [0xff00, 0x00ff], 0xffff],
    ['XOR', 'DWORD', [0xffffffff, 0x0f0f0f0f], 0xf0f0f0f0], // stays unsigned above 2^31
    ['AND', 'DWORD', [0x80000000, 0xffffffff], 0x80000000],
    ['AND', 'LWORD', [2n ** 64n - 1n, 0xffn], 0xffn],
    ['NOT', 'BOOL', [false], true],
    ['NOT', 'BYTE', [0x0f], 0xf0],
    ['NOT', 'WORD', [0], 0xffff],
    ['NOT', 'DWORD', [0], 0xffffffff],
    ['NOT', 'LWORD', [0n], 2n ** 64n - 1n],
  ])('%s %s %s = %s', (fn, t, args, out) => {
    expect(call(fn, t, args)).toEqual([out, true]);
  });
});

describe('shifts and rotates work at the width of the type', () => {
  it.each<[string, ElementaryType, Value, number, Value]>([
    ['SHL', 'BYTE', 0x81, 1, 0x02], // the top bit falls out of a BYTE
    ['SHL', 'WORD', 0x8001, 4, 0x0010],
    ['SHL', 'DWORD', 1, 31, 0x80000000],
    ['SHL', 'DWORD', 1, 32, 0], // N >= width: all bits shifted out
    ['SHL', 'LWORD', 1n, 63, 2n ** 63n],
    ['SHL', 'LWORD', 1n, 64, 0n],
    ['SHR', 'BYTE', 0x80, 7, 1],
    ['SHR', 'DWORD', 0x80000000, 31, 1], // fills with 0, never sign-extends
    ['SHR', 'WORD', 0xffff, 16, 0],
    ['ROL', 'BYTE', 0x81, 1, 0x03],
    ['ROL', 'WORD', 0x8001, 4, 0x0018],
    ['ROL', 'DWORD', 0x80000001, 1, 0x00000003],
    ['ROL', 'BYTE', 0x81, 9, 0x03], // N taken modulo the width
    ['ROR', 'BYTE', 0x81, 1, 0xc0],
    ['ROR', 'DWORD', 1, 1, 0x80000000],
    ['ROR', 'LWORD', 1n, 1, 2n ** 63n],
    ['ROL', 'LWORD', 2n ** 63n, 1, 1n],
    ['ROR', 'WORD', 0x1234, 16, 0x1234],
    ['SHL', 'BOOL', true, 1, false],
    ['ROL', 'BOOL', true, 5, true],
  ])('%s %s %s by %i = %s', (fn, t, v, n, out) => {
    expect(call(fn, [t, 'INT'], [v, n])).toEqual([out, true]);
  });

  it('a negative N is an error: ENO OFF and OUT = IN', () => {
    expect(call('SHL', ['BYTE', 'INT'], [0x0f, -1])).toEqual([0x0f, false]);
    expect(call('ROR', ['LWORD', 'INT'], [5n, -2])).toEqual([5n, false]);
  });

  it('N may be any integer type, including LINT', () => {
    expect(call('SHL', ['WORD', 'LINT'], [1, 3n])).toEqual([8, true]);
  });
});

describe('comparisons', () => {
  it.each<[string, ElementaryType, Value[], boolean]>([
    ['GT', 'INT', [3, 2], true],
    ['GT', 'INT', [3, 2, 2], false], // chained: IN1 > IN2 AND IN2 > IN3
    ['GT', 'INT', [3, 2, 1], true],
    ['GE', 'REAL', [1.5, 1.5, -1], true],
    ['EQ', 'LINT', [5n, 5n, 5n], true],
    ['EQ', 'REAL', [Number.NaN, Number.NaN], false],
    ['NE', 'TIME', [1000, 1001], true],
    ['LE', 'UDINT', [1, 4294967295], true],
    ['LT', 'BOOL', [false, true], true],
    ['LT', 'ULINT', [2n ** 64n - 1n, 0n], false],
  ])('%s %s %s = %s', (fn, t, args, out) => {
    expect(call(fn, t, args)).toEqual([out, true]);
  });
});

describe('selection', () => {
  it('SEL gives IN0 when G is FALSE and IN1 when TRUE', () => {
    expect(call('SEL', ['BOOL', 'INT', 'INT'], [false, 10, 20])).toEqual([10, true]);
    expect(call('SEL', ['BOOL', 'TIME', 'TIME'], [true, 10, 20])).toEqual([20, true]);
  });

  it('MUX picks IN<K>; K out of range turns ENO OFF and gives the initial value (as MATIEC)', () => {
    const types: ElementaryType[] = ['INT', 'DINT', 'DINT', 'DINT'];
    expect(call('MUX', types, [2, 10, 20, 30])).toEqual([30, true]);
    expect(call('MUX', types, [3, 10, 20, 30])).toEqual([0, false]);
    expect(call('MUX', types, [-1, 10, 20, 30])).toEqual([0, false]);
    expect(call('MUX', ['INT', 'BOOL', 'BOOL'], [5, true, true])).toEqual([false, false]);
  });

  it('MAX and MIN over several inputs', () => {
    expect(call('MAX', 'INT', [3, 9, -2, 9])).toEqual([9, true]);
    expect(call('MIN', 'LINT', [3n, -9n, 2n])).toEqual([-9n, true]);
    expect(call('MAX', 'TIME', [1000, 500])).toEqual([1000, true]);
  });

  it.each<[Profile, Value]>([
    ['iec', 5], // MIN(MAX(IN, MN), MX)
    ['openplc', 10], // MATIEC: IN > MN ? (IN < MX ? IN : MX) : MN
  ])('LIMIT with MN above MX gives %s in %s', (profile, out) => {
    expect(call('LIMIT', 'INT', [10, 7, 5], profile)).toEqual([out, true]);
  });

  it('LIMIT clamps into MN..MX in both profiles', () => {
    for (const profile of ['iec', 'openplc'] as const) {
      expect(call('LIMIT', 'INT', [0, -5, 100], profile)[0]).toBe(0);
      expect(call('LIMIT', 'INT', [0, 50, 100], profile)[0]).toBe(50);
      expect(call('LIMIT', 'REAL', [0, 150, 100], profile)[0]).toBe(100);
    }
  });
});
