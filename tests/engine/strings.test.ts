// STRING and WSTRING: literals, the string functions and conversions as MATIEC's C library computes
// them (lib/C/iec_std_functions.h, iec_std_lib.h), comparisons per profile, programs that move
// strings through boxes, user FBs with STRING variables, write/force by name.
import { describe, expect, it } from 'vitest';
import { formatValue, parseLiteral, parseValueText, csvValue } from '../../src/engine/values/literals';
import { matiecFind, printfG } from '../../src/engine/library/strings';
import { STRING_MAX_LEN } from '../../src/model/iecTypes';
import { variable } from '../../src/model/factory';
import { call } from './library/fnHelpers';
import { ladder, plcOf, project, vars } from './ladder';
import { io, multiProject, pou } from './userBlocksHelpers';
import { checkProject } from '../../src/engine/check';
import { compileProgram } from '../../src/engine/plc';
import { ScanPlc } from '../../src/engine/runtime/scanner';
import { DEFAULT_TIERING } from '../../src/engine/runtime/tiering';

const S = 'STRING' as const;
const long = (n: number, c = 'x') => c.repeat(n);

describe('string literals', () => {
  it("reads 'abc' as a STRING and \"abc\" as a WSTRING", () => {
    expect(parseLiteral("'abc'")).toEqual({ ok: true, value: 'abc', type: 'STRING' });
    expect(parseLiteral('"abc"')).toEqual({ ok: true, value: 'abc', type: 'WSTRING' });
    expect(parseLiteral("''")).toEqual({ ok: true, value: '', type: 'STRING' });
    expect(parseLiteral("STRING#'ok'")).toEqual({ ok: true, value: 'ok', type: 'STRING' });
  });

  it('reads the $ escapes in either case', () => {
    expect(parseLiteral("'hello$N'")).toMatchObject({ value: 'hello\n' });
    expect(parseLiteral("'a$lb$rc$td$pe'")).toMatchObject({ value: 'a\nb\rc\td\fe' });
    expect(parseLiteral("'it$'s $$5'")).toMatchObject({ value: "it's $5" });
    expect(parseLiteral("'say \"hi\"'")).toMatchObject({ value: 'say "hi"' });
    expect(parseLiteral("'$41$0a'")).toMatchObject({ value: 'A\n' });
    expect(parseLiteral('"$20AC $"quoted$""')).toMatchObject({ value: '€ "quoted"', type: 'WSTRING' });
  });

  it('refuses bad strings with a reason', () => {
    expect(parseLiteral("'abc")).toMatchObject({ ok: false });
    expect(parseLiteral("'a$'")).toMatchObject({ ok: false });
    expect(parseLiteral("'$G'")).toMatchObject({ ok: false, message: expect.stringContaining('not an escape') });
    expect(parseLiteral("'a'b'")).toMatchObject({ ok: false, message: expect.stringContaining("$'") });
    expect(parseLiteral("'€'")).toMatchObject({ ok: false, message: expect.stringContaining('WSTRING') });
    expect(parseLiteral("'abc'", 'INT')).toMatchObject({ ok: false, message: "'abc' is a STRING, not an INT" });
    expect(parseLiteral('42', 'STRING')).toMatchObject({ ok: false, message: expect.stringContaining('single quotes') });
    expect(parseLiteral('"abc"', 'STRING')).toMatchObject({ ok: false, message: expect.stringContaining('WSTRING') });
  });

  it(`cuts a literal at ${STRING_MAX_LEN} characters, as MATIEC's STRING holds no more`, () => {
    expect(parseLiteral(`'${long(200)}'`)).toMatchObject({ ok: true, value: long(STRING_MAX_LEN) });
  });

  it('shows a string as its literal and reads the watch table text back', () => {
    expect(formatValue('STRING', "it's\n")).toBe("'it$'s$N'");
    expect(formatValue('WSTRING', 'a"b')).toBe('"a$"b"');
    expect(formatValue('STRING', '')).toBe("''");
    expect(parseValueText('STRING', 'plain text')).toEqual({ ok: true, value: 'plain text' });
    expect(parseValueText('STRING', "'two$Nlines'")).toEqual({ ok: true, value: 'two\nlines' });
    expect(parseValueText('STRING', "''")).toEqual({ ok: true, value: '' });
    expect(parseValueText('STRING', '€')).toMatchObject({ ok: false });
    expect(parseValueText('WSTRING', '€')).toEqual({ ok: true, value: '€' });
  });

  it('writes CSV cells that read back to the same string', () => {
    for (const s of ['hello', 'a,b', '', ' pad ', 'two\nlines', "'quoted'", 'say "x"'])
      expect(parseValueText('STRING', csvValue('STRING', s))).toEqual({ ok: true, value: s });
    expect(csvValue('STRING', 'hello')).toBe('hello');
    expect(csvValue('STRING', '')).toBe("''");
  });
});

describe('string functions (MATIEC semantics)', () => {
  it('LEN', () => {
    expect(call('LEN', S, ['hello'])).toEqual([5, true]);
    expect(call('LEN', S, [''])).toEqual([0, true]);
  });

  it('LEFT and RIGHT: L beyond the length takes the whole string; L < 0 turns ENO OFF', () => {
    expect(call('LEFT', [S, 'INT'], ['hello', 2])).toEqual(['he', true]);
    expect(call('LEFT', [S, 'INT'], ['hello', 9])).toEqual(['hello', true]);
    expect(call('LEFT', [S, 'INT'], ['hello', 0])).toEqual(['', true]);
    expect(call('LEFT', [S, 'INT'], ['hello', -1])[1]).toBe(false);
    expect(call('RIGHT', [S, 'INT'], ['hello', 3])).toEqual(['llo', true]);
    expect(call('RIGHT', [S, 'INT'], ['hello', 9])).toEqual(['hello', true]);
    expect(call('RIGHT', [S, 'INT'], ['hello', -2])[1]).toBe(false);
  });

  it('MID: from position P (1 = first); P beyond the end gives an empty string; P = 0 is an error', () => {
    expect(call('MID', [S, 'INT', 'INT'], ['hello', 3, 2])).toEqual(['ell', true]);
    expect(call('MID', [S, 'INT', 'INT'], ['hello', 10, 4])).toEqual(['lo', true]);
    expect(call('MID', [S, 'INT', 'INT'], ['hello', 2, 5])).toEqual(['o', true]);
    expect(call('MID', [S, 'INT', 'INT'], ['hello', 2, 6])).toEqual(['', true]);
    expect(call('MID', [S, 'INT', 'INT'], ['hello', 2, 0])[1]).toBe(false);
    expect(call('MID', [S, 'INT', 'INT'], ['hello', -1, 1])[1]).toBe(false);
  });

  it(`CONCAT joins any number of inputs and cuts at ${STRING_MAX_LEN}`, () => {
    expect(call('CONCAT', S, ['ab', 'cd'])).toEqual(['abcd', true]);
    expect(call('CONCAT', S, ['a', 'b', 'c', ''])).toEqual(['abc', true]);
    expect(call('CONCAT', S, [long(100), long(100, 'y')])).toEqual([long(100) + long(26, 'y'), true]);
  });

  it('INSERT after the first P characters (P beyond the end appends)', () => {
    expect(call('INSERT', [S, S, 'INT'], ['abcd', 'XY', 2])).toEqual(['abXYcd', true]);
    expect(call('INSERT', [S, S, 'INT'], ['abcd', 'XY', 0])).toEqual(['XYabcd', true]);
    expect(call('INSERT', [S, S, 'INT'], ['abcd', 'XY', 9])).toEqual(['abcdXY', true]);
    expect(call('INSERT', [S, S, 'INT'], ['abcd', 'XY', -1])[1]).toBe(false);
    expect((call('INSERT', [S, S, 'INT'], [long(120), long(10, 'y'), 60])[0] as string).length).toBe(STRING_MAX_LEN);
  });

  it('DELETE L characters from position P; P beyond the end keeps the string', () => {
    expect(call('DELETE', [S, 'INT', 'INT'], ['abcdef', 2, 3])).toEqual(['abef', true]);
    expect(call('DELETE', [S, 'INT', 'INT'], ['abcdef', 10, 3])).toEqual(['ab', true]);
    expect(call('DELETE', [S, 'INT', 'INT'], ['abcdef', 2, 7])).toEqual(['abcdef', true]);
    expect(call('DELETE', [S, 'INT', 'INT'], ['abcdef', 0, 2])).toEqual(['abcdef', true]);
    expect(call('DELETE', [S, 'INT', 'INT'], ['abcdef', 2, 0])[1]).toBe(false);
    expect(call('DELETE', [S, 'INT', 'INT'], ['abcdef', -1, 2])[1]).toBe(false);
  });

  it('REPLACE L characters from position P by IN2 (at most L of its characters, as the C copies)', () => {
    expect(call('REPLACE', [S, S, 'INT', 'INT'], ['abcdef', 'XY', 2, 3])).toEqual(['abXYef', true]);
    expect(call('REPLACE', [S, S, 'INT', 'INT'], ['abcdef', 'XYZ', 1, 1])).toEqual(['Xbcdef', true]);
    expect(call('REPLACE', [S, S, 'INT', 'INT'], ['abcdef', 'XY', 0, 3])).toEqual(['abcdef', true]);
    expect(call('REPLACE', [S, S, 'INT', 'INT'], ['abc', 'XY', 2, 9])).toEqual(['abcXY', true]);
    expect(call('REPLACE', [S, S, 'INT', 'INT'], ['abc', 'XY', -2, 1])[1]).toBe(false);
  });

  it('takes INSERT/DELETE/REPLACE lengths modulo 256 in the openplc profile (MATIEC casts them to a byte)', () => {
    expect(call('DELETE', [S, 'INT', 'INT'], ['abcdef', 258, 3], 'openplc')).toEqual(['abef', true]);
    expect(call('DELETE', [S, 'INT', 'INT'], ['abcdef', 258, 3], 'iec')).toEqual(['ab', true]);
  });

  it("FIND: the standard's first occurrence (iec); MATIEC's current __pfind with its partial-match miss (openplc)", () => {
    expect(call('FIND', S, ['hello', 'll'])).toEqual([3, true]);
    expect(call('FIND', S, ['hello', 'x'])).toEqual([0, true]);
    expect(call('FIND', S, ['aab', 'ab'])).toEqual([2, true]);
    expect(call('FIND', S, ['abc', ''])).toEqual([0, true]);
    expect(call('FIND', S, ['hello', 'll'], 'openplc')).toEqual([3, true]);
    expect(call('FIND', S, ['hello', 'x'], 'openplc')).toEqual([0, true]);
    // MATIEC since 2020 (the reference): 0 when IN2 is empty, longer than IN1 or not found; the scan
    // still resumes after a partial match, so 'ab' inside 'aab' is missed.
    expect(matiecFind('aab', 'ab')).toBe(0);
    expect(matiecFind('abc', 'xy')).toBe(0);
    expect(matiecFind('abc', '')).toBe(0);
    expect(matiecFind('', 'ab')).toBe(0);
    expect(matiecFind('ab', 'abc')).toBe(0);
    expect(matiecFind('abcabd', 'abd')).toBe(4);
    expect(call('FIND', S, ['abc', 'xy'], 'openplc')).toEqual([0, true]);
    expect(call('FIND', S, ['abc', 'c'], 'openplc')).toEqual([3, true]);
  });

  it('refuses mixing STRING and WSTRING, and numbers where strings are needed', () => {
    expect(() => call('CONCAT', ['STRING', 'WSTRING'], ['a', 'b'])).toThrow(/STRING and WSTRING/);
    expect(() => call('LEN', 'INT', [5])).toThrow(/STRING or WSTRING/);
  });
});

describe('string comparisons', () => {
  it('iec: character by character, a prefix is smaller', () => {
    expect(call('EQ', S, ['abc', 'abc'])).toEqual([true, true]);
    expect(call('EQ', S, ['abc', 'abcd'])).toEqual([false, true]);
    expect(call('LT', S, ['abc', 'abd'])).toEqual([true, true]);
    expect(call('LT', S, ['ab', 'abc'])).toEqual([true, true]);
    expect(call('GT', S, ['b', 'abc'])).toEqual([true, true]);
    expect(call('NE', S, ['x', ''])).toEqual([true, true]);
    expect(call('GE', S, ['c', 'b', 'a'])).toEqual([true, true]);
    expect(call('MAX', S, ['apple', 'pear', 'fig'])).toEqual(['pear', true]);
    expect(call('MIN', S, ['apple', 'pear', 'fig'])).toEqual(['apple', true]);
    expect(call('LIMIT', S, ['b', 'a', 'd'])).toEqual(['b', true]);
  });

  it("openplc: the same order (MATIEC's __str_cmp since 2020: the common length, then the lengths)", () => {
    expect(call('EQ', S, ['abc', 'abcd'], 'openplc')).toEqual([false, true]);
    expect(call('EQ', S, ['', 'hi'], 'openplc')).toEqual([false, true]);
    expect(call('EQ', S, ['', ''], 'openplc')).toEqual([true, true]);
    expect(call('NE', S, ['abc', 'abd'], 'openplc')).toEqual([true, true]);
    expect(call('LT', S, ['ab', 'abc'], 'openplc')).toEqual([true, true]);
    expect(call('GT', S, ['abc', 'ab'], 'openplc')).toEqual([true, true]);
    expect(call('LT', S, ['a', 'a\xff'], 'openplc')).toEqual([true, true]);
    expect(call('MAX', S, ['ab', 'abc'], 'openplc')).toEqual(['abc', true]);
    expect(call('MIN', S, ['', 'a'], 'openplc')).toEqual(['', true]);
  });
});

describe('conversions to and from STRING', () => {
  it("writes MATIEC's formats", () => {
    expect(call('BOOL_TO_STRING', 'BOOL', [true])).toEqual(['TRUE', true]);
    expect(call('BOOL_TO_STRING', 'BOOL', [false])).toEqual(['FALSE', true]);
    expect(call('INT_TO_STRING', 'INT', [-42])).toEqual(['-42', true]);
    expect(call('ULINT_TO_STRING', 'ULINT', [18446744073709551615n])).toEqual(['18446744073709551615', true]);
    expect(call('WORD_TO_STRING', 'WORD', [255])).toEqual(['16#ff', true]);
    expect(call('LREAL_TO_STRING', 'LREAL', [1.5])).toEqual(['1.5', true]);
    expect(call('REAL_TO_STRING', 'REAL', [Math.fround(0.1)])).toEqual(['0.1000000015', true]);
    expect(call('LREAL_TO_STRING', 'LREAL', [1e20])).toEqual(['1e+20', true]);
    expect(call('LREAL_TO_STRING', 'LREAL', [0.00001234])).toEqual(['1.234e-05', true]);
    expect(call('LREAL_TO_STRING', 'LREAL', [123456.789])).toEqual(['123456.789', true]);
  });

  it('printf %.10g', () => {
    expect(printfG(100, 10)).toBe('100');
    expect(printfG(1234567890, 10)).toBe('1234567890');
    expect(printfG(12345678901, 10)).toBe('1.23456789e+10');
    expect(printfG(0.0001, 10)).toBe('0.0001');
    expect(printfG(-2.5, 10)).toBe('-2.5');
    expect(printfG(Number.NaN, 10)).toBe('nan');
  });

  it('TIME_TO_STRING: an IEC literal (iec), MATIEC\'s T#0d0h0m1s500ms (openplc)', () => {
    expect(call('TIME_TO_STRING', 'TIME', [1500])).toEqual(['T#1s500ms', true]);
    expect(call('TIME_TO_STRING', 'TIME', [1500], 'openplc')).toEqual(['T#0d0h0m1s500ms', true]);
    expect(call('TIME_TO_STRING', 'TIME', [0], 'openplc')).toEqual(['T#0d', true]);
    expect(call('TIME_TO_STRING', 'TIME', [7_200_000], 'openplc')).toEqual(['T#0d2h', true]);
    expect(call('TIME_TO_STRING', 'TIME', [90_000], 'openplc')).toEqual(['T#0d0h1m30s', true]);
  });

  it('STRING_TO_BOOL: "1" or TRUE in any case', () => {
    for (const p of ['iec', 'openplc'] as const) {
      expect(call('STRING_TO_BOOL', S, ['1'], p)[0]).toBe(true);
      expect(call('STRING_TO_BOOL', S, ['true'], p)[0]).toBe(true);
      expect(call('STRING_TO_BOOL', S, ['yes'], p)[0]).toBe(false);
    }
  });

  it('iec: reads an IEC literal of the type, anything else turns ENO OFF', () => {
    expect(call('STRING_TO_INT', S, ['-42'])).toEqual([-42, true]);
    expect(call('STRING_TO_WORD', S, ['16#ff'])).toEqual([255, true]);
    expect(call('STRING_TO_REAL', S, ['1.5'])).toEqual([1.5, true]);
    expect(call('STRING_TO_TIME', S, ['T#1s500ms'])).toEqual([1500, true]);
    expect(call('STRING_TO_INT', S, ['12abc'])[1]).toBe(false);
    expect(call('STRING_TO_SINT', S, ['300'])[1]).toBe(false);
  });

  it("openplc: MATIEC's lenient readers", () => {
    const o = 'openplc';
    expect(call('STRING_TO_INT', S, ['-42'], o)).toEqual([-42, true]);
    expect(call('STRING_TO_INT', S, ['1 000'], o)).toEqual([1000, true]);
    // Read from the end: a character from '.' up that is not a digit starts over.
    expect(call('STRING_TO_INT', S, ['12abc34'], o)).toEqual([12, true]);
    expect(call('STRING_TO_INT', S, [''], o)).toEqual([0, true]);
    expect(call('STRING_TO_SINT', S, ['300'], o)).toEqual([44, true]);
    expect(call('STRING_TO_WORD', S, ['16#FF'], o)).toEqual([255, true]);
    expect(call('STRING_TO_BYTE', S, ['2#1010'], o)).toEqual([10, true]);
    expect(call('STRING_TO_INT', S, ['3.7'], o)).toEqual([3, true]);
    expect(call('STRING_TO_LREAL', S, ['3.75'], o)).toEqual([3.75, true]);
    expect(call('STRING_TO_LREAL', S, ['2.5e2x'], o)).toEqual([250, true]);
    expect(call('STRING_TO_LREAL', S, ['42'], o)).toEqual([42, true]);
    expect(call('STRING_TO_TIME', S, ['90'], o)).toEqual([90_000, true]);
    expect(call('STRING_TO_TIME', S, ['1.5'], o)).toEqual([1000, true]);
  });

  it('has no WSTRING conversions (MATIEC has none)', () => {
    expect(() => call('WSTRING_TO_STRING', 'WSTRING', ['a'])).toThrow();
    expect(() => call('INT_TO_WSTRING', 'INT', [1])).toThrow();
  });
});

describe('STRING in programs', () => {
  it('moves, joins and compares strings through boxes; declared initial values', () => {
    const p = project(
      [
        variable('Name', 'STRING', { initial: "'Motor'" }),
        variable('Msg', 'STRING'),
        variable('Wide', 'WSTRING', { initial: '"ok"' }),
        ...vars('N INT', 'Same BOOL', 'Found INT'),
      ],
      [
        ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'CONCAT', inputCount: 3, inputs: { IN1: 'Name', IN2: "' is '", IN3: "'on$N'" }, outputs: { OUT: 'Msg' } }] }),
        ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'LEN', inputs: { IN: 'Msg' }, outputs: { OUT: 'N' } }] }),
        ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'EQ', inputs: { IN1: 'Name', IN2: "'Motor'" }, outputs: { OUT: 'Same' } }] }),
        ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'FIND', inputs: { IN1: 'Msg', IN2: "'is'" }, outputs: { OUT: 'Found' } }] }),
      ],
    );
    const plc = plcOf(p);
    expect(plc.read('Msg')).toBe('');
    plc.scan();
    expect(plc.read('Msg')).toBe('Motor is on\n');
    expect(plc.read('N')).toBe(12);
    expect(plc.read('Same')).toBe(true);
    expect(plc.read('Found')).toBe(7);
    expect(plc.read('Wide')).toBe('ok');
    plc.write('Name', 'Pump');
    plc.scan();
    expect(plc.read('Msg')).toBe('Pump is on\n');
    expect(plc.read('Same')).toBe(false);
  });

  it('write, force and release by name; wrong kinds are refused', () => {
    const p = project([variable('Msg', 'STRING'), variable('Copy', 'STRING')], [
      ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'MOVE', inputs: { IN: 'Msg' }, outputs: { OUT: 'Copy' } }] }),
    ]);
    const plc = plcOf(p);
    plc.write('Msg', 'hello');
    plc.scan();
    expect(plc.read('Copy')).toBe('hello');
    plc.force('Copy', 'held');
    plc.write('Msg', 'other');
    plc.scan();
    expect(plc.read('Copy')).toBe('held');
    plc.unforce('Copy');
    plc.scan();
    expect(plc.read('Copy')).toBe('other');
    plc.write('Msg', long(300));
    expect(plc.read('Msg')).toBe(long(STRING_MAX_LEN));
    expect(() => plc.write('Msg', 5)).toThrow(/not text/);
    expect(() => plc.write('Msg', '€')).toThrow(/single-byte/);
    expect(() => plc.write('Copy' as string, true)).toThrow();
    expect(plc.values()).toMatchObject({ Msg: long(STRING_MAX_LEN) });
  });

  it('a user FB with a STRING input and output runs per instance', () => {
    const greet = pou(
      'Greet',
      'FUNCTION_BLOCK',
      [...io('input', 'Who STRING'), ...io('output', 'Text STRING')],
      [ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'CONCAT', inputs: { IN1: "'Hello, '", IN2: 'Who' }, outputs: { OUT: 'Text' } }] })],
    );
    const main = pou('Main', 'PROGRAM', [...vars('G1 Greet', 'G2 Greet'), variable('A', 'STRING'), variable('B', 'STRING')], [
      ladder(['. # # .'], { boxes: [{ row: 0, col: 1, type: 'Greet', instance: 'G1', inputs: { Who: "'Ann'" }, outputs: { Text: 'A' } }] }),
      ladder(['. # # .'], { boxes: [{ row: 0, col: 1, type: 'Greet', instance: 'G2', inputs: { Who: "'Bob'" }, outputs: { Text: 'B' } }] }),
    ]);
    const plc = plcOf(multiProject([main, greet]));
    plc.scan();
    expect(plc.read('A')).toBe('Hello, Ann');
    expect(plc.read('B')).toBe('Hello, Bob');
    expect(plc.read('G2.Who')).toBe('Bob');
  });

  it('reports a STRING wired to an INT pin, and STRING[n] lengths out of range', () => {
    const p = project([variable('Msg', 'STRING'), variable('Short', 'STRING[300]'), ...vars('N INT')], [
      ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: 'Msg', IN2: 'N' }, outputs: { OUT: 'N' } }] }),
    ]);
    const rules = checkProject(p).map((d) => `${d.rule} ${d.message}`);
    expect(rules.some((r) => r.startsWith('LD-E15') && r.includes('1 to 126'))).toBe(true);
    expect(rules.some((r) => /ADD cannot add/.test(r) && /STRING/.test(r))).toBe(true);
  });

  it('STRING[20] declares a STRING (the length is kept, as MATIEC keeps room for 126)', () => {
    const p = project([variable('Code', 'STRING[20]', { initial: "'A1'" }), variable('Out', 'STRING')], [
      ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'MOVE', inputs: { IN: 'Code' }, outputs: { OUT: 'Out' } }] }),
    ]);
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('Out')).toBe('A1');
  });

  it('runs the same on the dispatch loops and on straight-line segments, forced strings included', () => {
    const p = project([variable('A', 'STRING', { initial: "'x'" }), variable('B', 'STRING'), variable('C', 'STRING'), ...vars('N INT')], [
      ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'CONCAT', inputs: { IN1: 'A', IN2: "'-'" }, outputs: { OUT: 'B' } }] }),
      ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'RIGHT', inputs: { IN: 'B', L: '3' }, outputs: { OUT: 'C' } }] }),
      ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'LEN', inputs: { IN: 'B' }, outputs: { OUT: 'N' } }] }),
    ]);
    const { program } = compileProgram(p);
    const loops = new ScanPlc(program!, { cycleMs: 10 }, { ...DEFAULT_TIERING, startAfterEvals: Infinity });
    const segments = new ScanPlc(program!, { cycleMs: 10 }, { ...DEFAULT_TIERING, startAfterEvals: 0, minScans: 1, msPerNetwork: 0, batch: 1 });
    for (let k = 0; k < 40; k++) {
      for (const plc of [loops, segments]) {
        plc.write('A', `${k}`.repeat(k % 5));
        if (k === 20) plc.force('C', 'held');
        if (k === 30) plc.unforce('C');
        plc.scan();
      }
      expect(segments.values()).toEqual(loops.values());
    }
    expect(segments.read('B')).toBe('39393939-');
    expect(segments.read('C')).toBe('39-');
  });
});
