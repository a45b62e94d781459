// The functions of OpenPLC Editor's palette that came after the base set, as MATIEC runs them
// (lib/C/iec_std_functions.h, iec_std_lib.h): numerical functions of one REAL/LREAL (the C library
// function on a double, cast back: REAL rounded to 32 bits), EXPT (C pow), TRUNC (toward zero),
// BCD_TO_* / *_TO_BCD, and ADD_TIME / SUB_TIME / MULTIME / DIVTIME. Expected values are worked out
// by hand: the mathematical value, then Math.fround where the result is a REAL.
import { describe, expect, it } from 'vitest';
import { callFunction, resolveFunction } from '../../../src/engine/library/functions';
import { MORE_FUNCTION_SIGNATURES, conversionTypes } from '../../../src/model/blocks';
import type { ElementaryType, Value } from '../../../src/model/iecTypes';
import type { Profile } from '../../../src/model/project';
import { call, resolved } from './fnHelpers';

const f = Math.fround;
const refusal = (name: string, types: readonly (ElementaryType | undefined)[]): string => {
  const r = resolveFunction(name, types, 'iec');
  if (r.ok) throw new Error(`${name} resolved`);
  return r.message;
};

describe('numerical functions (SQRT LN LOG EXP SIN COS TAN ASIN ACOS ATAN)', () => {
  it.each<[string, number, number, number]>([
    // name, IN, LREAL result, REAL result
    ['SQRT', 2, 1.4142135623730951, 1.4142135381698608],
    ['SQRT', 0, 0, 0],
    ['SQRT', 16, 4, 4],
    ['LN', 1, 0, 0],
    ['LOG', 1000, 3, 3],
    ['LOG', 0.001, -3, -3],
    ['EXP', 0, 1, 1],
    ['EXP', 1, 2.718281828459045, f(2.718281828459045)],
    ['SIN', 0, 0, 0],
    ['COS', 0, 1, 1],
    ['ACOS', 1, 0, 0],
    ['ASIN', 1, Math.PI / 2, f(Math.PI / 2)],
    ['ATAN', 1, Math.PI / 4, f(Math.PI / 4)],
  ])('%s(%s): LREAL %s, REAL rounded to 32 bits', (name, x, lreal, real) => {
    expect(call(name, 'LREAL', [x])).toEqual([lreal, true]);
    expect(call(name, 'REAL', [f(x)])).toEqual([real, true]);
  });

  it('keeps ENO ON where C gives NaN or an infinity (MATIEC tests only EN)', () => {
    for (const t of ['REAL', 'LREAL'] as const) {
      expect(call('SQRT', t, [-1])).toEqual([NaN, true]);
      expect(call('LN', t, [0])).toEqual([-Infinity, true]);
      expect(call('LN', t, [-1])).toEqual([NaN, true]);
      expect(call('LOG', t, [0])).toEqual([-Infinity, true]);
      expect(call('ASIN', t, [2])).toEqual([NaN, true]);
      expect(call('ACOS', t, [-1.5])).toEqual([NaN, true]);
    }
    expect(call('EXP', 'LREAL', [710])).toEqual([Infinity, true]);
  });

  it('REAL overflows and loses precision where LREAL does not', () => {
    // e^89 = 4.49e38: beyond the largest REAL (3.40e38), within LREAL.
    expect(call('EXP', 'REAL', [89])).toEqual([Infinity, true]);
    expect(call('EXP', 'LREAL', [89])[0]).toBeCloseTo(4.4896128191743455e38, -24);
    // SIN of the REAL nearest pi (3.1415927410...) is pi - that = -8.74e-8, not 0.
    expect(call('SIN', 'REAL', [f(Math.PI)])).toEqual([f(-8.742278000372475e-8), true]);
    expect(call('SIN', 'LREAL', [Math.PI])[0]).toBeCloseTo(1.2246467991473532e-16, 30);
    expect(call('TAN', 'LREAL', [Math.PI / 4])[0]).toBeCloseTo(1, 15);
  });

  it('takes REAL or LREAL only: an integer is refused with the conversion to use', () => {
    expect(refusal('SQRT', ['INT'])).toBe('SQRT cannot take the square root of INT: convert it first (INT_TO_REAL)');
    expect(refusal('LN', ['TIME'])).toContain('LN cannot take the logarithm of TIME');
    expect(resolved('COS', ['REAL']).outType).toBe('REAL');
    expect(resolved('COS', ['LREAL']).outType).toBe('LREAL');
    // An untyped literal takes the type of the variable OUT is written to, else REAL.
    expect(resolved('SQRT', [undefined], 'iec', 'LREAL').argTypes).toEqual(['LREAL']);
    expect(resolved('SQRT', [undefined]).outType).toBe('REAL');
  });
});

describe('EXPT', () => {
  it('raises IN1 (REAL or LREAL, the result type) to IN2 (any number) as C pow', () => {
    expect(call('EXPT', ['REAL', 'INT'], [2, 10])).toEqual([1024, true]);
    expect(call('EXPT', ['LREAL', 'LREAL'], [2, 0.5])).toEqual([1.4142135623730951, true]);
    expect(call('EXPT', ['REAL', 'LREAL'], [2, 0.5])).toEqual([1.4142135381698608, true]);
    expect(call('EXPT', ['LREAL', 'SINT'], [-2, 3])).toEqual([-8, true]);
    expect(call('EXPT', ['LREAL', 'INT'], [10, -2])).toEqual([0.01, true]);
    expect(call('EXPT', ['LREAL', 'LINT'], [2, 62n])).toEqual([2 ** 62, true]);
    expect(call('EXPT', ['LREAL', 'ULINT'], [3, 0n])).toEqual([1, true]);
  });

  it('gives NaN and infinities with ENO ON, as C pow: no check in MATIEC', () => {
    expect(call('EXPT', ['LREAL', 'LREAL'], [-8, 1 / 3])).toEqual([NaN, true]);
    expect(call('EXPT', ['LREAL', 'INT'], [0, -1])).toEqual([Infinity, true]);
    // 10^39 fits an LREAL, not a REAL.
    expect(call('EXPT', ['REAL', 'INT'], [10, 39])).toEqual([Infinity, true]);
    // (JavaScript's pow may differ from the C library's in the last bit: compared to 15 digits.)
    expect((call('EXPT', ['LREAL', 'INT'], [10, 39])[0] as number) / 1e39).toBeCloseTo(1, 15);
    // C's pow(1, NaN) = 1 and pow(-1, +-Inf) = 1 (JavaScript's Math.pow gives NaN for both).
    expect(call('EXPT', ['LREAL', 'LREAL'], [1, NaN])).toEqual([1, true]);
    expect(call('EXPT', ['LREAL', 'LREAL'], [-1, -Infinity])).toEqual([1, true]);
  });

  it('types its pins: IN1 REAL/LREAL, IN2 any number; an untyped IN2 literal is read as LREAL (so 0.5 works)', () => {
    expect(resolved('EXPT', ['REAL', undefined]).argTypes).toEqual(['REAL', 'LREAL']);
    expect(resolved('EXPT', ['LREAL', 'DINT']).argTypes).toEqual(['LREAL', 'DINT']);
    expect(refusal('EXPT', ['INT', 'INT'])).toBe('EXPT cannot raise INT: convert it first (INT_TO_REAL)');
    expect(refusal('EXPT', ['REAL', 'TIME'])).toBe('EXPT input IN2 needs a number (ANY_NUM), not TIME');
    // MUX's K, also a generic pin of its own, still reads an untyped literal as INT.
    expect(resolved('MUX', [undefined, 'REAL', 'REAL']).argTypes).toEqual(['INT', 'REAL', 'REAL']);
  });
});

describe('TRUNC', () => {
  const trunc = (x: number, out: ElementaryType | undefined, profile: Profile = 'iec', from: ElementaryType = 'LREAL') => {
    const fn = resolved('TRUNC', [from], profile, out);
    return [callFunction(fn, [x]).value, callFunction(fn, [x]).eno, fn.outType];
  };

  it('truncates toward zero to the type of the variable OUT is written to', () => {
    expect(trunc(-2.7, 'INT')).toEqual([-2, true, 'INT']);
    expect(trunc(2.999, 'SINT', 'iec', 'REAL')).toEqual([2, true, 'SINT']);
    expect(trunc(-0.5, 'DINT')).toEqual([0, true, 'DINT']);
    expect(trunc(123456789012.9, 'LINT')).toEqual([123456789012n, true, 'LINT']);
    expect(trunc(65535.9, 'UINT')).toEqual([65535, true, 'UINT']);
  });

  it('gives DINT when OUT is written to nothing typed or to a non-integer', () => {
    expect(trunc(7.5, undefined)).toEqual([7, true, 'DINT']);
    expect(trunc(7.5, 'REAL')).toEqual([7, true, 'DINT']);
  });

  it('out of range: the wrapped value, ENO OFF in iec and ON in openplc (the C cast)', () => {
    expect(trunc(300.5, 'USINT', 'iec')).toEqual([44, false, 'USINT']);
    expect(trunc(300.5, 'USINT', 'openplc')).toEqual([44, true, 'USINT']);
    expect(trunc(-1.5, 'UINT', 'iec')).toEqual([65535, false, 'UINT']);
    expect(trunc(1e10, 'DINT', 'iec')).toEqual([1410065408, false, 'DINT']); // 1e10 mod 2^32
    expect(trunc(NaN, 'INT', 'iec')).toEqual([0, false, 'INT']);
    expect(trunc(Infinity, 'INT', 'openplc')).toEqual([0, true, 'INT']);
  });

  it('is not mistaken for an A_TO_B conversion (nor are the BCD conversions)', () => {
    for (const name of ['TRUNC', 'BCD_TO_UINT', 'UINT_TO_BCD']) expect(conversionTypes(name)).toBeUndefined();
    expect(conversionTypes('REAL_TO_INT')).toEqual({ from: 'REAL', to: 'INT' });
  });
});

describe('BCD conversions', () => {
  it.each<[string, ElementaryType, Value, Value]>([
    ['BCD_TO_USINT', 'BYTE', 0x42, 42],
    ['BCD_TO_USINT', 'BYTE', 0x99, 99],
    ['BCD_TO_UINT', 'WORD', 0x9999, 9999],
    ['BCD_TO_UINT', 'WORD', 0x0105, 105],
    ['BCD_TO_UDINT', 'DWORD', 0x12345678, 12345678],
    ['BCD_TO_ULINT', 'LWORD', 0x9999999999999999n, 9999999999999999n],
    ['USINT_TO_BCD', 'USINT', 42, 0x42],
    ['USINT_TO_BCD', 'USINT', 0, 0],
    ['UINT_TO_BCD', 'UINT', 9999, 0x9999],
    ['UDINT_TO_BCD', 'UDINT', 12345678, 0x12345678],
    ['ULINT_TO_BCD', 'ULINT', 1234567890123456n, 0x1234567890123456n],
  ])('%s(%s %s) = %s', (name, t, x, out) => {
    expect(call(name, t, [x])).toEqual([out, true]);
  });

  it('BCD_TO_*: a nibble above 9 is no BCD digit: ENO OFF (MATIEC __test_bcd), in both profiles', () => {
    for (const profile of ['iec', 'openplc'] as const) {
      expect(call('BCD_TO_USINT', 'BYTE', [0x4a], profile)).toEqual([0, false]);
      expect(call('BCD_TO_UINT', 'WORD', [0xf000], profile)).toEqual([0, false]);
      expect(call('BCD_TO_ULINT', 'LWORD', [0xa000000000000001n], profile)).toEqual([0n, false]);
    }
  });

  it('*_TO_BCD: digits beyond the target width are lost, ENO stays ON', () => {
    // 255 is BCD 16#255, 12 bits: a BYTE keeps 16#55.
    expect(call('USINT_TO_BCD', 'USINT', [255])).toEqual([0x55, true]);
    // 65535 is 16#65535: a WORD keeps 16#5535.
    expect(call('UINT_TO_BCD', 'UINT', [65535])).toEqual([0x5535, true]);
    // 4294967295 is 16#4294967295: a DWORD keeps 16#94967295.
    expect(call('UDINT_TO_BCD', 'UDINT', [4294967295])).toEqual([0x94967295, true]);
  });

  it('types: the palette pairs BYTE-USINT, WORD-UINT, DWORD-UDINT, LWORD-ULINT; narrower inputs widen', () => {
    expect(resolved('BCD_TO_UINT', ['BYTE']).argTypes).toEqual(['WORD']);
    expect(resolved('BCD_TO_UINT', ['WORD']).outType).toBe('UINT');
    expect(resolved('UDINT_TO_BCD', ['UDINT']).outType).toBe('DWORD');
    expect(refusal('BCD_TO_USINT', ['WORD'])).toBe('BCD_TO_USINT input IN needs BYTE, not WORD');
  });
});

describe('functions of TIME', () => {
  it('ADD_TIME and SUB_TIME add and subtract durations (negative results allowed)', () => {
    expect(call('ADD_TIME', 'TIME', [1500, 250])).toEqual([1750, true]);
    expect(call('SUB_TIME', 'TIME', [1000, 1500])).toEqual([-500, true]);
    expect(refusal('ADD_TIME', ['INT', 'TIME'])).toBe('ADD_TIME input IN1 needs TIME, not INT');
  });

  it('MULTIME and DIVTIME scale a TIME by any number, to whole milliseconds', () => {
    expect(call('MULTIME', ['TIME', 'LREAL'], [1000, 1.5])).toEqual([1500, true]);
    expect(call('MULTIME', ['TIME', 'INT'], [100, 3])).toEqual([300, true]);
    expect(call('MULTIME', ['TIME', 'REAL'], [10, f(0.33)])).toEqual([3, true]); // 3.3 ms
    expect(call('MULTIME', ['TIME', 'DINT'], [250, -2])).toEqual([-500, true]);
    expect(call('DIVTIME', ['TIME', 'INT'], [1000, 4])).toEqual([250, true]);
    expect(call('DIVTIME', ['TIME', 'INT'], [1000, 3])).toEqual([333, true]);
    expect(call('DIVTIME', ['TIME', 'LREAL'], [1000, 0.5])).toEqual([2000, true]);
    expect(resolved('MULTIME', ['TIME', undefined]).argTypes).toEqual(['TIME', 'LREAL']);
  });

  it('MUL and DIV of a TIME by a number are MULTIME and DIVTIME (the palette’s Time section)', () => {
    expect(call('MUL', ['TIME', 'INT'], [100, 3])).toEqual([300, true]);
    expect(call('DIV', ['TIME', 'LREAL'], [1000, 0.5])).toEqual([2000, true]);
    expect(call('DIV', ['TIME', 'DINT'], [1000, 0])[1]).toBe(false);
    const mul = resolved('MUL', ['TIME', undefined]);
    expect([mul.argTypes, mul.outType]).toEqual([['TIME', 'LREAL'], 'TIME']);
    // Only TIME by a number: a number times a TIME, or TIME by TIME, is refused as before.
    expect(refusal('MUL', ['INT', 'TIME'])).toBe('MUL cannot multiply INT and TIME');
    expect(refusal('DIV', ['TIME', 'TIME'])).toBe('DIV cannot divide TIME values');
    expect(refusal('MUL', ['TIME', 'INT', 'INT'])).toBe('MUL cannot multiply TIME and INT');
  });

  it('DIVTIME by 0 is an error: ENO OFF (undefined behaviour in MATIEC)', () => {
    expect(call('DIVTIME', ['TIME', 'INT'], [1000, 0])[1]).toBe(false);
    expect(call('DIVTIME', ['TIME', 'LREAL'], [1000, 0], 'openplc')[1]).toBe(false);
  });
});

describe('every added function', () => {
  it('resolves with its own pin types and has a category and a description', () => {
    for (const sig of MORE_FUNCTION_SIGNATURES) {
      const types = sig.inputs.map((p) => (p.type.startsWith('ANY') ? undefined : (p.type as ElementaryType)));
      const r = resolveFunction(sig.name, types, 'iec');
      expect(r.ok, sig.name).toBe(true);
      expect(sig.kind).toBe('function');
      expect(sig.description.length).toBeGreaterThan(10);
    }
  });
});
