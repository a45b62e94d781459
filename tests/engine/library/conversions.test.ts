// A_TO_B conversions: every pair resolves; ranges, rounding and TIME units per profile.
import { describe, expect, it } from 'vitest';
import { CONVERSION_SIGNATURES, conversionTypes } from '../../../src/model/blocks';
import type { Value } from '../../../src/model/iecTypes';
import type { Profile } from '../../../src/model/project';
import { defaultValue, isValueOfType } from '../../../src/engine/values/types';
import { callFunction } from '../../../src/engine/library/functions';
import { resolved } from './fnHelpers';

const conv = (name: string, v: Value, profile: Profile = 'iec'): [Value, boolean] => {
  const { from } = conversionTypes(name)!;
  const r = callFunction(resolved(name, [from], profile), [v]);
  return [r.value, r.eno];
};

describe('every conversion in CONVERSION_SIGNATURES', () => {
  it('resolves in both profiles and returns a value of its target type', () => {
    for (const sig of CONVERSION_SIGNATURES) {
      const { from, to } = conversionTypes(sig.name)!;
      for (const profile of ['iec', 'openplc'] as const) {
        const fn = resolved(sig.name, [from], profile);
        expect(fn.outType).toBe(to);
        // A STRING is read as text: '0' reads as every target type ('' is no number).
        const input = from === 'STRING' ? '0' : defaultValue(from);
        const out = callFunction(fn, [input]);
        expect(isValueOfType(to, out.value), `${sig.name}(${String(input)})`).toBe(true);
        expect(out.eno).toBe(true);
      }
    }
  });
});

describe('integer conversions', () => {
  it.each<[string, Value, Value, boolean]>([
    ['INT_TO_DINT', -5, -5, true],
    ['INT_TO_LINT', -5, -5n, true],
    ['LINT_TO_INT', 1234n, 1234, true],
    ['DINT_TO_INT', 40000, -25536, false], // out of range: error, OUT is the wrapped value
    ['INT_TO_SINT', 300, 44, false],
    ['INT_TO_UINT', -1, 65535, false],
    ['ULINT_TO_LINT', 2n ** 64n - 1n, -1n, false],
    ['UDINT_TO_REAL', 4294967295, Math.fround(4294967295), true],
    ['DINT_TO_REAL', 16777217, 16777216, true], // rounded to 32 bits, not an error
    ['BOOL_TO_INT', true, 1, true],
    ['INT_TO_BOOL', -3, true, true],
    ['LINT_TO_BOOL', 0n, false, true],
  ])('%s(%s) = %s, ENO %s', (name, v, out, eno) => {
    expect(conv(name, v)).toEqual([out, eno]);
  });

  it('out-of-range keeps ENO ON in openplc (a C cast) with the same wrapped value', () => {
    expect(conv('DINT_TO_INT', 40000, 'openplc')).toEqual([-25536, true]);
    expect(conv('INT_TO_USINT', -1, 'openplc')).toEqual([255, true]);
  });

  it('bit strings convert by binary transfer, never an error', () => {
    expect(conv('WORD_TO_INT', 0xffff)).toEqual([-1, true]);
    expect(conv('INT_TO_WORD', -1)).toEqual([0xffff, true]);
    expect(conv('DWORD_TO_BYTE', 0x12345678)).toEqual([0x78, true]);
    expect(conv('LWORD_TO_DINT', 2n ** 64n - 1n)).toEqual([-1, true]);
    expect(conv('BYTE_TO_LWORD', 0xff)).toEqual([0xffn, true]);
    expect(conv('WORD_TO_REAL', 0xffff)).toEqual([65535, true]);
  });
});

describe('REAL to integer rounds to nearest, ties to even (MATIEC __real_round)', () => {
  it.each<[string, number, Value, boolean]>([
    ['REAL_TO_INT', 1.4, 1, true],
    ['REAL_TO_INT', 1.6, 2, true],
    ['REAL_TO_INT', 2.5, 2, true],
    ['REAL_TO_INT', 3.5, 4, true],
    ['REAL_TO_INT', -2.5, -2, true],
    ['REAL_TO_INT', -1.6, -2, true],
    ['REAL_TO_INT', -0.5, 0, true], // not -0
    ['REAL_TO_INT', -1.5, -2, true],
    ['LREAL_TO_LINT', 1e15 + 0.5, 1000000000000000n, true],
    ['REAL_TO_INT', 40000, -25536, false],
    ['REAL_TO_UINT', -1, 0, false], // negative to unsigned: 0
    ['REAL_TO_BYTE', 255.4, 255, true],
    ['REAL_TO_DINT', Number.NaN, 0, false],
    ['LREAL_TO_REAL', 1e39, Number.POSITIVE_INFINITY, false],
    ['LREAL_TO_REAL', 0.1, Math.fround(0.1), true],
    ['REAL_TO_LREAL', Math.fround(0.1), Math.fround(0.1), true],
    ['REAL_TO_BOOL', 0.5, true, true],
  ])('%s(%s) = %s, ENO %s', (name, v, out, eno) => {
    expect(conv(name, v)).toEqual([out, eno]);
  });

  it('openplc rounds the same way but keeps ENO ON out of range', () => {
    expect(conv('REAL_TO_INT', 2.5, 'openplc')).toEqual([2, true]);
    expect(conv('REAL_TO_UINT', -1, 'openplc')).toEqual([0, true]);
    expect(conv('REAL_TO_SINT', 200, 'openplc')).toEqual([-56, true]);
  });
});

describe('TIME conversions: ms in iec, seconds in openplc (MATIEC timespec tv_sec)', () => {
  it.each<[string, Value, Value, Value]>([
    // name, input, iec output, openplc output
    ['TIME_TO_DINT', 1500, 1500, 1],
    ['TIME_TO_DINT', -1500, -1500, -1],
    ['TIME_TO_LINT', 7_200_000, 7_200_000n, 7200n],
    ['TIME_TO_WORD', 2000, 2000, 2],
    ['TIME_TO_REAL', 1500, 1500, 1.5],
    ['TIME_TO_LREAL', 250, 250, 0.25],
    ['DINT_TO_TIME', 250, 250, 250_000],
    ['LINT_TO_TIME', 3n, 3, 3000],
    ['REAL_TO_TIME', 1.5, 2, 1500], // iec: 1.5 ms rounds (ties to even) to 2 ms
    ['LREAL_TO_TIME', 0.25, 0, 250],
    ['BOOL_TO_TIME', true, 1, 1000],
    ['TIME_TO_BOOL', 1, true, true],
  ])('%s(%s) = %s (iec) / %s (openplc)', (name, v, iec, openplc) => {
    expect(conv(name, v, 'iec')).toEqual([iec, true]);
    expect(conv(name, v, 'openplc')).toEqual([openplc, true]);
  });

  it('iec: a TIME too long for the target is an error', () => {
    expect(conv('TIME_TO_INT', 40_000)).toEqual([-25536, false]);
    expect(conv('TIME_TO_INT', 40_000, 'openplc')).toEqual([40, true]);
  });
});
