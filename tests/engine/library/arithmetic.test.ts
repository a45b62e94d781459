// Arithmetic as a PLC computes it: integers wrap at their width, REAL is rounded to 32 bits after
// every operation, DIV truncates toward zero, division by zero turns ENO OFF with OUT = 0.
import { describe, expect, it } from 'vitest';
import type { ElementaryType, Value } from '../../../src/model/iecTypes';
import type { Profile } from '../../../src/model/project';
import { call, resolved } from './fnHelpers';

describe('integer arithmetic wraps at the type width', () => {
  it.each<[string, ElementaryType, Value[], Value]>([
    ['ADD', 'INT', [32767, 1], -32768],
    ['ADD', 'USINT', [255, 1], 0],
    ['ADD', 'SINT', [100, 100], -56],
    ['ADD', 'UDINT', [4294967295, 2], 1],
    ['ADD', 'DINT', [2147483647, 1], -2147483648],
    ['ADD', 'LINT', [2n ** 63n - 1n, 1n], -(2n ** 63n)],
    ['ADD', 'ULINT', [2n ** 64n - 1n, 1n], 0n],
    ['SUB', 'UINT', [0, 1], 65535],
    ['SUB', 'INT', [-32768, 1], 32767],
    ['MUL', 'INT', [300, 300], 24464],
    ['MUL', 'DINT', [2147483647, 2147483647], 1], // exact low 32 bits, not a rounded double
    ['MUL', 'UDINT', [65536, 65537], 65536],
    ['MUL', 'LINT', [2n ** 62n, 4n], 0n],
    ['ABS', 'INT', [-32768], -32768], // |INT min| does not fit: wraps, as on the PLC
    ['ABS', 'DINT', [-7], 7],
    ['NEG', 'SINT', [-128], -128],
    ['NEG', 'LINT', [5n], -5n],
    ['DIV', 'INT', [-32768, -1], -32768],
  ])('%s %s %s = %s', (fn, t, args, out) => {
    expect(call(fn, t, args)).toEqual([out, true]);
  });

  it('extensible ADD and MUL take up to 16 inputs', () => {
    expect(call('ADD', 'INT', [1, 2, 3, 4, 5])).toEqual([15, true]);
    expect(call('MUL', 'SINT', [2, 4, 8, 2])).toEqual([-128, true]); // 128 wraps to -128
    expect(call('MUL', 'SINT', [2, 4, 8, 4])).toEqual([0, true]); // 256 wraps to 0
    expect(call('ADD', 'INT', Array(16).fill(1))).toEqual([16, true]);
  });
});

describe('DIV and MOD', () => {
  it.each<[string, ElementaryType, Value[], Value]>([
    ['DIV', 'INT', [7, 2], 3],
    ['DIV', 'INT', [-7, 2], -3], // truncates toward zero
    ['DIV', 'DINT', [2147483647, -2], -1073741823],
    ['DIV', 'LINT', [-7n, 2n], -3n],
    ['DIV', 'UINT', [65535, 256], 255],
    ['DIV', 'REAL', [1, 3], Math.fround(1 / 3)],
    ['MOD', 'INT', [7, 3], 1],
    ['MOD', 'INT', [-7, 3], -1], // sign of the dividend, as C and IEC
    ['MOD', 'ULINT', [10n, 4n], 2n],
  ])('%s %s %s = %s', (fn, t, args, out) => {
    expect(call(fn, t, args)).toEqual([out, true]);
  });

  it.each<[ElementaryType, Value[], Value]>([
    ['INT', [5, 0], 0],
    ['UDINT', [5, 0], 0],
    ['LINT', [5n, 0n], 0n],
    ['REAL', [1.5, 0], 0], // not infinity: an error, like integers (MATIEC's TEST_EN_COND)
    ['LREAL', [-1, 0], 0],
  ])('DIV %s by zero turns ENO OFF with OUT = 0 in both profiles', (t, args, out) => {
    expect(call('DIV', t, args, 'iec')).toEqual([out, false]);
    expect(call('DIV', t, args, 'openplc')).toEqual([out, false]);
  });

  it.each<[Profile, boolean]>([
    ['iec', false],
    ['openplc', true], // MATIEC returns 0 but leaves ENO ON
  ])('MOD by zero gives 0; ENO in %s is %s', (profile, eno) => {
    expect(call('MOD', 'INT', [5, 0], profile)).toEqual([0, eno]);
    expect(call('MOD', 'LINT', [5n, 0n], profile)).toEqual([0n, eno]);
  });
});

describe('REAL is rounded to 32 bits after every operation', () => {
  it('0.1 + 0.2 in REAL equals the single-precision result', () => {
    const a = Math.fround(0.1);
    const b = Math.fround(0.2);
    expect(call('ADD', 'REAL', [a, b])).toEqual([Math.fround(a + b), true]);
    expect(call('ADD', 'REAL', [a, b])[0]).not.toBe(0.1 + 0.2);
  });

  it('each step of an extensible ADD is rounded (not only the final sum)', () => {
    const big = Math.fround(16777216); // 2^24: adding 1 is lost in 32 bits
    expect(call('ADD', 'REAL', [big, 1, 1])[0]).toBe(16777216);
    expect(call('ADD', 'LREAL', [16777216, 1, 1])[0]).toBe(16777218);
  });

  it('MUL and SUB round too', () => {
    expect(call('MUL', 'REAL', [Math.fround(1.1), Math.fround(1.1)])[0]).toBe(Math.fround(Math.fround(1.1) * Math.fround(1.1)));
    expect(call('SUB', 'REAL', [Math.fround(1), Math.fround(0.9)])[0]).toBe(Math.fround(1 - Math.fround(0.9)));
  });
});

describe('TIME arithmetic and MOVE', () => {
  it('ADD and SUB work on TIME (ms)', () => {
    expect(call('ADD', 'TIME', [1500, 500])).toEqual([2000, true]);
    expect(call('SUB', 'TIME', [1000, 3000])).toEqual([-2000, true]);
  });

  it('MOVE copies any type', () => {
    expect(call('MOVE', 'LWORD', [5n])).toEqual([5n, true]);
    expect(call('MOVE', 'BOOL', [true])).toEqual([true, true]);
    expect(resolved('MOVE', ['TIME']).outType).toBe('TIME');
  });
});
