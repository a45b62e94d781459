// IEC literals as typed beside a pin or in a variable's initial value, and the text forms of values.
import { describe, expect, it } from 'vitest';
import type { ElementaryType, Value } from '../../../src/model/iecTypes';
import { csvValue, formatValue, isUntypedLiteral, parseLiteral, parseValueText } from '../../../src/engine/values/literals';

const ok = (text: string, expected?: ElementaryType) => {
  const r = parseLiteral(text, expected);
  if (!r.ok) throw new Error(`${text}: ${r.message}`);
  return [r.value, r.type];
};
const refused = (text: string, expected?: ElementaryType): string => {
  const r = parseLiteral(text, expected);
  if (r.ok) throw new Error(`${text} was accepted`);
  return r.message;
};

describe('parseLiteral accepts IEC literals', () => {
  it.each<[string, ElementaryType | undefined, Value, ElementaryType]>([
    ['TRUE', undefined, true, 'BOOL'],
    ['false', undefined, false, 'BOOL'],
    ['1', 'BOOL', true, 'BOOL'],
    ['0', 'BOOL', false, 'BOOL'],
    ['BOOL#1', undefined, true, 'BOOL'],
    ['42', undefined, 42, 'INT'], // untyped integer: smallest of INT, DINT, LINT
    ['100000', undefined, 100000, 'DINT'],
    ['1_000_000', 'DINT', 1000000, 'DINT'],
    ['-128', 'SINT', -128, 'SINT'],
    ['16#FF', 'BYTE', 255, 'BYTE'],
    ['16#ff', undefined, 255, 'INT'],
    ['8#17', 'INT', 15, 'INT'],
    ['2#1010_1010', 'USINT', 170, 'USINT'],
    ['INT#-5', undefined, -5, 'INT'],
    ['UINT#16#FF', undefined, 255, 'UINT'],
    ['LINT#-9223372036854775808', undefined, -(2n ** 63n), 'LINT'],
    ['16#FFFF_FFFF_FFFF_FFFF', 'LWORD', 2n ** 64n - 1n, 'LWORD'],
    ['5', 'LINT', 5n, 'LINT'],
    ['5', 'REAL', 5, 'REAL'],
    ['1.5', undefined, 1.5, 'REAL'],
    ['0.1', undefined, Math.fround(0.1), 'REAL'], // untyped real is REAL: rounded to 32 bits
    ['0.1', 'LREAL', 0.1, 'LREAL'],
    ['-2.0E3', undefined, -2000, 'REAL'],
    ['1.0e-2', 'LREAL', 0.01, 'LREAL'],
    ['REAL#1.5', undefined, 1.5, 'REAL'],
    ['REAL#2', undefined, 2, 'REAL'],
    ['INT#5', 'DINT', 5, 'DINT'], // a typed literal widens to the expected type
    ['INT#5', 'LREAL', 5, 'LREAL'],
    ['  7 ', 'INT', 7, 'INT'],
  ])('%s (expected %s) = %s : %s', (text, expected, value, type) => {
    expect(ok(text, expected)).toEqual([value, type]);
  });
});

describe('TIME literals are held in milliseconds', () => {
  it.each<[string, number]>([
    ['T#1s500ms', 1500],
    ['TIME#-2h', -7_200_000],
    ['t#1.5s', 1500],
    ['T#1d2h3m4s5ms', 86_400_000 + 7_200_000 + 180_000 + 4000 + 5],
    ['T#1h_30m', 5_400_000],
    ['time#250ms', 250],
    ['T#0s', 0],
    ['T#25h', 90_000_000], // the largest unit may overflow
    ['T#1.5ms', 2], // below 1 ms: rounded to the nearest ms
    ['T#1500us', 2],
    ['T#2m', 120_000],
    ['TIME#+3s', 3000],
    ['T# 30000ms', 30_000], // blanks after '#': MATIEC reads them (OpenPLC users write them)
    ['TIME#  -2s', -2000],
    ['T#- 2s', -2000], // and after the sign
  ])('%s = %i ms', (text, ms) => {
    expect(ok(text)).toEqual([ms, 'TIME']);
    expect(ok(text, 'TIME')).toEqual([ms, 'TIME']);
  });

  it.each<[string, RegExp]>([
    ['T#', /at least one number/],
    ['T#5', /not a TIME part/],
    ['T#1s1h', /largest to smallest/],
    ['T#1.5m30s', /only the last unit/],
    ['T#1x', /not a TIME part/],
    ['T#1m 30s', /not a TIME part/], // blanks between parts: MATIEC refuses them too
  ])('refuses %s', (text, message) => {
    expect(refused(text)).toMatch(message);
  });
});

describe('parseLiteral refuses bad literals in plain words', () => {
  it.each<[string, ElementaryType | undefined, string | RegExp]>([
    ['300', 'SINT', '300 does not fit SINT (-128..127)'],
    ['-1', 'UINT', '-1 does not fit UINT (0..65535)'],
    ['SINT#16#FF', undefined, 'SINT#16#FF does not fit SINT (-128..127)'],
    ['2', 'BOOL', /not a BOOL \(use TRUE, FALSE, 1 or 0\)/],
    ['1.5', 'INT', /real number, not an INT; INT needs a whole number/],
    ['TRUE', 'INT', /is a BOOL, not an INT/],
    ['5', 'TIME', /write a TIME as T#5s/],
    ['T#1s', 'DINT', /is a TIME, not a DINT/],
    ['DINT#5', 'INT', 'DINT#5 is a DINT, but INT is needed here'],
    ['16#FG', 'WORD', /not a value/],
    ['8#19', 'WORD', /digits that base 8 does not allow/],
    ['-16#FF', 'INT', /cannot have a sign/],
    ['FOO#1', undefined, /"FOO" in "FOO#1" is not a known type/],
    ['LTIME#5s', undefined, /LTIME values are not supported/],
    ['TOD#25:00:00', undefined, /the hour 25 is not 0 to 23/],
    ['1__0', 'INT', /not a value/],
    ['', undefined, 'the value is empty'],
    ['Motor', undefined, /not a value/],
    ['99999999999999999999999', undefined, /too large/],
    ['1.0E39', 'REAL', /too large for REAL/],
    ['INT#TRUE', undefined, /TRUE\/FALSE are BOOL values, not INT/],
  ])('%s (expected %s)', (text, expected, message) => {
    const m = refused(text, expected);
    if (typeof message === 'string') expect(m).toBe(message);
    else expect(m).toMatch(message);
  });
});

describe('formatValue shows values as a PLC programmer writes them', () => {
  it.each<[ElementaryType, Value, string]>([
    ['BOOL', true, 'TRUE'],
    ['BOOL', false, 'FALSE'],
    ['INT', -5, '-5'],
    ['WORD', 65535, '65535'],
    ['LINT', -(2n ** 63n), '-9223372036854775808'],
    ['TIME', 1500, 'T#1s500ms'],
    ['TIME', 0, 'T#0ms'],
    ['TIME', -7_200_000, 'T#-2h'],
    ['TIME', 90_061_001, 'T#1d1h1m1s1ms'],
    ['REAL', Math.fround(0.1), '0.1'], // shortest text that reads back to the same 32-bit float
    ['REAL', 2, '2.0'],
    ['REAL', Math.fround(1 / 3), '0.33333334'],
    ['LREAL', 0.1 + 0.2, '0.30000000000000004'],
    ['REAL', Math.fround(1e21), '1.0e+21'],
  ])('%s %s -> %s', (type, v, text) => {
    expect(formatValue(type, v)).toBe(text);
  });

  it('formatted values parse back to the same value', () => {
    const cases: [ElementaryType, Value][] = [
      ['BOOL', true],
      ['TIME', 93_784_005],
      ['TIME', -1500],
      ['REAL', Math.fround(3.14159)],
      ['LREAL', Math.PI],
      ['DINT', -123456],
      ['ULINT', 2n ** 64n - 1n],
    ];
    for (const [t, v] of cases) expect(parseValueText(t, formatValue(t, v))).toEqual({ ok: true, value: v });
  });
});

describe('csvValue', () => {
  it('writes BOOL as 0/1, TIME in ms and integers in decimal', () => {
    expect(csvValue('BOOL', true)).toBe('1');
    expect(csvValue('BOOL', false)).toBe('0');
    expect(csvValue('TIME', 1500)).toBe('1500');
    expect(csvValue('LWORD', 2n ** 64n - 1n)).toBe('18446744073709551615');
  });

  it('writes the shortest digits that round-trip a 32-bit REAL (not the float64 expansion)', () => {
    const values = [0.1, 1 / 3, 3.4e38, 1e-40, 123456.789, -0.000123, 16777217].map(Math.fround);
    for (const v of values) {
      const text = csvValue('REAL', v);
      expect(Math.fround(Number(text))).toBe(v);
      expect(text.replace(/^-|\.|e.*$/g, '').replace(/^0+/, '').length).toBeLessThanOrEqual(9);
    }
    expect(csvValue('REAL', Math.fround(0.1))).toBe('0.1');
    // REAL 0.1 + 0.2 rounded to 32 bits is the float nearest 0.3: written as 0.3, not 0.30000001192092896.
    expect(csvValue('REAL', Math.fround(Math.fround(0.1) + Math.fround(0.2)))).toBe('0.3');
  });

  it('writes LREAL with float64 round-trip digits', () => {
    expect(csvValue('LREAL', 0.1)).toBe('0.1');
    expect(Number(csvValue('LREAL', Math.PI))).toBe(Math.PI);
  });
});

describe('parseValueText reads stimulus and "write value" input', () => {
  it.each<[ElementaryType, string, Value]>([
    ['BOOL', '1', true],
    ['BOOL', '0', false],
    ['BOOL', 'true', true],
    ['BOOL', 'FALSE', false],
    ['BOOL', 'on', true],
    ['INT', '-42', -42],
    ['INT', '16#7F', 127],
    ['INT', '12.0', 12],
    ['REAL', '1.5', 1.5],
    ['REAL', '3', 3],
    ['LREAL', '1e-3', 0.001],
    ['TIME', '1500', 1500], // CSV: a TIME is a number of ms
    ['TIME', 'T#2s', 2000],
    ['ULINT', '18446744073709551615', 2n ** 64n - 1n],
  ])('%s "%s" -> %s', (type, text, value) => {
    expect(parseValueText(type, text)).toEqual({ ok: true, value });
  });

  it('refuses with the reason', () => {
    expect(parseValueText('SINT', '200')).toEqual({ ok: false, message: '200 does not fit SINT (-128..127)' });
    expect(parseValueText('BOOL', 'maybe')).toMatchObject({ ok: false });
    expect(parseValueText('INT', '1.5')).toMatchObject({ ok: false, message: expect.stringMatching(/whole number/) });
  });
});

describe('isUntypedLiteral', () => {
  it('tells literals that adopt the type of their use (42, 16#FF, 1.5) from typed ones (INT#5, T#1s, TRUE)', () => {
    for (const t of ['42', '-7', '16#FF', '2#1010', '8#17', '1.5', '1.0E3']) expect(isUntypedLiteral(t), t).toBe(true);
    for (const t of ['INT#5', 'T#1s', 'TIME#2s', 'TRUE', 'REAL#1.5', 'Motor', '16#FG']) expect(isUntypedLiteral(t), t).toBe(false);
  });
});
