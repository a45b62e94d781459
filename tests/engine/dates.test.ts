// DATE, TIME_OF_DAY (TOD) and DATE_AND_TIME (DT): literals, the table 30 functions, comparisons,
// conversions as MATIEC's library has them, and a program that computes with them.
import { describe, expect, it } from 'vitest';
import { csvValue, formatValue, parseLiteral, parseValueText } from '../../src/engine/values/literals';
import { CONVERSION_SIGNATURES } from '../../src/model/blocks';
import { variable } from '../../src/model/factory';
import { call } from './library/fnHelpers';
import { ladder, plcOf, project, vars } from './ladder';

const D = (y: number, m: number, d: number) => Date.UTC(y, m - 1, d);
const H = 3_600_000;

describe('date and time literals', () => {
  it('reads D#, TOD#, DT# and their long forms', () => {
    expect(parseLiteral('D#2024-01-31')).toEqual({ ok: true, value: D(2024, 1, 31), type: 'DATE' });
    expect(parseLiteral('DATE#1970-01-02')).toEqual({ ok: true, value: 86_400_000, type: 'DATE' });
    expect(parseLiteral('TOD#12:30:15')).toEqual({ ok: true, value: 12 * H + 30 * 60_000 + 15_000, type: 'TOD' });
    expect(parseLiteral('TIME_OF_DAY#00:00:01.5')).toEqual({ ok: true, value: 1500, type: 'TOD' });
    expect(parseLiteral('DT#2024-02-29-23:59:59')).toEqual({ ok: true, value: D(2024, 2, 29) + 24 * H - 1000, type: 'DT' });
    expect(parseLiteral('date_and_time#1970-01-01-00:00:00', 'DT')).toMatchObject({ ok: true, value: 0 });
  });

  it('refuses impossible dates and times with the reason', () => {
    expect(parseLiteral('D#2023-02-29')).toMatchObject({ ok: false, message: expect.stringContaining('1 to 28') });
    expect(parseLiteral('D#2024-13-01')).toMatchObject({ ok: false, message: expect.stringContaining('month 13') });
    expect(parseLiteral('TOD#24:00:00')).toMatchObject({ ok: false, message: expect.stringContaining('hour 24') });
    expect(parseLiteral('TOD#12:30:15', 'DATE')).toMatchObject({ ok: false, message: expect.stringContaining('D#2024-01-31') });
    expect(parseLiteral('T#5s', 'TOD')).toMatchObject({ ok: false });
  });

  it('shows values as literals and reads them back', () => {
    expect(formatValue('DATE', D(2024, 1, 31))).toBe('D#2024-01-31');
    expect(formatValue('TOD', 1500)).toBe('TOD#00:00:01.5');
    expect(formatValue('DT', D(2024, 1, 31) + 12 * H)).toBe('DT#2024-01-31-12:00:00');
    expect(csvValue('DT', D(2024, 1, 31) + 12 * H)).toBe('DT#2024-01-31-12:00:00');
    expect(parseValueText('TOD', 'TOD#08:00:00')).toEqual({ ok: true, value: 8 * H });
  });
});

describe('functions of time data types (table 30)', () => {
  it('adds and subtracts as MATIEC does (a TOD is not wrapped at midnight)', () => {
    expect(call('ADD_TOD_TIME', ['TOD', 'TIME'], [23 * H, 2 * H])).toEqual([25 * H, true]);
    expect(call('ADD_DT_TIME', ['DT', 'TIME'], [D(2024, 1, 31), 36 * H])).toEqual([D(2024, 2, 1) + 12 * H, true]);
    expect(call('SUB_DATE_DATE', ['DATE', 'DATE'], [D(2024, 3, 1), D(2024, 2, 1)])).toEqual([29 * 24 * H, true]);
    expect(call('SUB_TOD_TOD', ['TOD', 'TOD'], [10 * H, 12 * H])).toEqual([-2 * H, true]);
    expect(call('SUB_TOD_TIME', ['TOD', 'TIME'], [10 * H, 1000])).toEqual([10 * H - 1000, true]);
    expect(call('SUB_DT_TIME', ['DT', 'TIME'], [D(2024, 1, 1), H])).toEqual([D(2023, 12, 31) + 23 * H, true]);
    expect(call('SUB_DT_DT', ['DT', 'DT'], [D(2024, 1, 2), D(2024, 1, 1)])).toEqual([24 * H, true]);
    expect(call('CONCAT_DATE_TOD', ['DATE', 'TOD'], [D(2024, 1, 31), 6 * H])).toEqual([D(2024, 1, 31) + 6 * H, true]);
  });

  it('compares dates and picks the later one', () => {
    expect(call('GT', 'DATE', [D(2024, 1, 2), D(2024, 1, 1)])).toEqual([true, true]);
    expect(call('EQ', 'TOD', [H, H])).toEqual([true, true]);
    expect(call('MAX', 'DT', [D(2020, 1, 1), D(2024, 1, 1)])).toEqual([D(2024, 1, 1), true]);
  });
});

describe('conversions of DATE, TOD and DT', () => {
  it('has the conversions MATIEC has, and not DATE_TO_TOD, TOD_TO_TIME ...', () => {
    const names = new Set(CONVERSION_SIGNATURES.map((s) => s.name));
    for (const n of ['DT_TO_DATE', 'DT_TO_TOD', 'DATE_TO_STRING', 'STRING_TO_DT', 'DINT_TO_DATE', 'TOD_TO_REAL']) expect(names).toContain(n);
    for (const n of ['DATE_TO_TOD', 'TOD_TO_TIME', 'TIME_TO_DT', 'DT_TO_TIME', 'DATE_TO_DT']) expect(names).not.toContain(n);
  });

  it('DT_TO_DATE and DT_TO_TOD keep the day or the time of day', () => {
    expect(call('DT_TO_DATE', 'DT', [D(2024, 1, 31) + 13 * H])).toEqual([D(2024, 1, 31), true]);
    expect(call('DT_TO_TOD', 'DT', [D(2024, 1, 31) + 13 * H])).toEqual([13 * H, true]);
  });

  it('numbers count milliseconds (iec) or seconds (openplc), as TIME does', () => {
    expect(call('TOD_TO_UDINT', 'TOD', [90_000])).toEqual([90_000, true]);
    expect(call('TOD_TO_UDINT', 'TOD', [90_000], 'openplc')).toEqual([90, true]);
    expect(call('UDINT_TO_DATE', 'UDINT', [86_400], 'openplc')).toEqual([86_400_000, true]);
  });

  it("text: an IEC literal (iec) or MATIEC's printf formats (openplc)", () => {
    expect(call('DATE_TO_STRING', 'DATE', [D(2024, 1, 31)])).toEqual(['D#2024-01-31', true]);
    expect(call('DATE_TO_STRING', 'DATE', [D(2024, 1, 31)], 'openplc')).toEqual(['D#2024-01-31', true]);
    expect(call('TOD_TO_STRING', 'TOD', [5500], 'openplc')).toEqual(['TOD#00:00:05.500000', true]);
    expect(call('TOD_TO_STRING', 'TOD', [5500])).toEqual(['TOD#00:00:05.5', true]);
    // MATIEC gives the text with ENO ON (__iec_error() leaves ENO alone; the reference agrees).
    expect(call('TOD_TO_STRING', 'TOD', [25 * H], 'openplc')).toEqual(['TOD#ERROR', true]);
    expect(call('TOD_TO_STRING', 'TOD', [25 * H], 'iec')).toEqual(['TOD#ERROR', false]);
    expect(call('DT_TO_STRING', 'DT', [D(2024, 1, 31) + 12 * H + 30 * 60_000], 'openplc')).toEqual(['DT#2024-01-31-12:30:00', true]);
    expect(call('STRING_TO_DATE', 'STRING', ['D#2024-01-31'])).toEqual([D(2024, 1, 31), true]);
    expect(call('STRING_TO_TOD', 'STRING', ['60'], 'openplc')).toEqual([60_000, true]);
  });
});

describe('RTC (MATIEC lib/rtc.txt)', () => {
  it('gives the PLC clock, or PDT plus the time since IN rose', () => {
    const p = project(
      [...vars('Set BOOL', 'T1 RTC'), variable('Now', 'DT'), variable('Preset', 'DT', { initial: 'DT#2024-01-31-12:00:00' })],
      [ladder(['[Set] # # -'], { boxes: [{ row: 0, col: 1, type: 'RTC', instance: 'T1', inputs: { PDT: 'Preset' }, outputs: { CDT: 'Now' } }] })],
    );
    const plc = plcOf(p, 100);
    plc.scan();
    expect(plc.read('Now')).toBe(0);
    plc.scan();
    expect(plc.read('Now')).toBe(100);
    plc.write('Set', true);
    plc.scan();
    expect(plc.read('Now')).toBe(D(2024, 1, 31) + 12 * H);
    plc.scans(10);
    expect(plc.read('Now')).toBe(D(2024, 1, 31) + 12 * H + 1000);
    expect(plc.read('T1.Q')).toBe(true);
    plc.write('Set', false);
    plc.scan();
    expect(plc.read('Now')).toBe(1300);
  });
});

describe('dates in a program', () => {
  it('keeps a DT, moves it by a TIME and splits it into DATE and TOD', () => {
    const p = project(
      [
        variable('Start', 'DATE_AND_TIME', { initial: 'DT#2024-01-31-22:00:00' }),
        variable('Later', 'DT'),
        variable('Day', 'DATE'),
        variable('Clock', 'TIME_OF_DAY'),
        variable('Text', 'STRING'),
      ],
      [
        ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'ADD_DT_TIME', inputs: { IN1: 'Start', IN2: 'T#3h' }, outputs: { OUT: 'Later' } }] }),
        ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'DT_TO_DATE', inputs: { IN: 'Later' }, outputs: { OUT: 'Day' } }] }),
        ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'DT_TO_TOD', inputs: { IN: 'Later' }, outputs: { OUT: 'Clock' } }] }),
        ladder(['- # # -'], { boxes: [{ row: 0, col: 1, type: 'DT_TO_STRING', inputs: { IN: 'Later' }, outputs: { OUT: 'Text' } }] }),
      ],
    );
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('Later')).toBe(D(2024, 2, 1) + H);
    expect(plc.read('Day')).toBe(D(2024, 2, 1));
    expect(plc.read('Clock')).toBe(H);
    expect(plc.read('Text')).toBe('DT#2024-02-01-01:00:00');
  });
});
