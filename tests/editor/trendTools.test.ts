// The trend's measurement cursors (values at A and B, Δt in PLC time) and its CSV export.
import { describe, expect, test } from 'vitest';
import type { TrendBuffer } from '../../src/sim/trendBuffer';
import { cursorReadout, nearestIndex, trendCsv } from '../../src/editor/sim/trendTools';

const buffer: TrendBuffer = {
  names: ['Start', 'Conveyor1.Count', 'Level'],
  scans: [5, 6, 7, 8],
  timesMs: [40, 50, 60, 70],
  series: [
    [0, 1, 1, 0],
    [2, 3, 7, 9],
    [0.1, 0.30000000000000004, 1.5, 2],
  ],
};
const signals = [
  { name: 'Start', type: 'BOOL' },
  { name: 'Conveyor1.Count', type: 'INT' },
  { name: 'Level', type: 'LREAL' },
];

describe('trend cursors', () => {
  test('a time snaps to the nearest sample', () => {
    expect(nearestIndex(buffer.timesMs, 0)).toBe(0);
    expect(nearestIndex(buffer.timesMs, 54)).toBe(1);
    expect(nearestIndex(buffer.timesMs, 56)).toBe(2);
    expect(nearestIndex(buffer.timesMs, 999)).toBe(3);
    expect(nearestIndex([], 5)).toBe(-1);
  });

  test('A and B read every signal; Δt is B − A in PLC time; numbers get B − A', () => {
    const r = cursorReadout(buffer, signals, 51, 69);
    expect(r.a).toEqual({ timeMs: 50, scan: 6 });
    expect(r.b).toEqual({ timeMs: 70, scan: 8 });
    expect(r.dtMs).toBe(20);
    expect(r.rows).toEqual([
      { name: 'Start', a: 'TRUE', b: 'FALSE', delta: '' },
      { name: 'Conveyor1.Count', a: '3', b: '9', delta: '6' },
      { name: 'Level', a: '0.30000000000000004', b: '2.0', delta: expect.any(String) },
    ]);
  });

  test('B before A gives a negative Δt; one cursor alone has no Δt', () => {
    expect(cursorReadout(buffer, signals, 70, 40).dtMs).toBe(-30);
    const one = cursorReadout(buffer, signals, 60, undefined);
    expect(one.dtMs).toBeUndefined();
    expect(one.rows[1]!.a).toBe('7');
    expect(one.rows[1]!.b).toBe('');
  });
});

describe('trend CSV', () => {
  test('time, scan and one column per signal with its full name; exact values', () => {
    const csv = trendCsv(buffer, signals);
    expect(csv.split('\n')).toEqual([
      'time_ms,scan,Start,Conveyor1.Count,Level',
      '40,5,0,2,0.1',
      '50,6,1,3,0.30000000000000004',
      '60,7,1,7,1.5',
      '70,8,0,9,2',
      '',
    ]);
  });
});
