// The trend's lanes: each BOOL apart in a thin lane, each number in a taller lane on its own
// scale, and time written in ms or s.
import { describe, expect, test } from 'vitest';
import { fitLines, wrapName, formatTime, laneY, scaleMarks, trendData, trendLayout, type TrendLane } from '../../src/editor/sim/trendChart';
import type { TrendBuffer } from '../../src/sim/trendBuffer';

const buffer: TrendBuffer = {
  names: ['Run', 'Count', 'Done', 'Level'],
  scans: [1, 2, 3, 4],
  timesMs: [10, 20, 30, 40],
  series: [
    [0, 1, 1, 0],
    [0, 5, 10, 20],
    [0, 0, 0, 1],
    [1000, 1000, 1000, 1000],
  ],
};
const signals = [
  { name: 'Run', type: 'BOOL' },
  { name: 'Count', type: 'INT' },
  { name: 'Done', type: 'BOOL' },
  { name: 'Level', type: 'REAL' },
];

describe('trend lanes', () => {
  test('one lane per signal, top to bottom in the order chosen; BOOL lanes thin, numbers taller', () => {
    const { lanes, total } = trendLayout(signals, buffer);
    expect(lanes.map((l) => `${l.name} ${l.top}-${l.bottom}`)).toEqual(['Run 8-7', 'Count 7-4', 'Done 4-3', 'Level 3-0']);
    expect(total).toBe(8);
  });

  test('every trace stays inside its own lane, whatever its values', () => {
    const layout = trendLayout(signals, buffer);
    const data = trendData(layout, buffer);
    expect(data[0]).toEqual([10, 20, 30, 40]);
    layout.lanes.forEach((lane, i) => {
      for (const y of data[i + 1] as number[]) {
        expect(y).toBeGreaterThan(lane.bottom);
        expect(y).toBeLessThan(lane.top);
      }
    });
  });

  test('a number spans its lane from its lowest to its highest value in the window', () => {
    const count = trendLayout(signals, buffer).lanes[1]!;
    expect([count.min, count.max]).toEqual([0, 20]);
    expect(laneY(count, 20) - laneY(count, 0)).toBeCloseTo(3 - 0.4);
    expect(laneY(count, 10)).toBeCloseTo((laneY(count, 0) + laneY(count, 20)) / 2);
  });

  test('BOOL FALSE and TRUE are the low and high edge of the thin lane; a constant number sits in the middle', () => {
    const [run, , , level] = trendLayout(signals, buffer).lanes;
    expect(laneY(run!, 0)).toBeCloseTo(7.2);
    expect(laneY(run!, 1)).toBeCloseTo(7.8);
    expect(laneY(level!, 1000)).toBeCloseTo(1.5);
  });
});

describe('time on the x axis', () => {
  test('ms for short windows, seconds for longer ones', () => {
    expect(formatTime(250, 1000)).toBe('250 ms');
    expect(formatTime(5250, 8000)).toBe('5.25 s');
    expect(formatTime(65000, 60000)).toBe('65 s');
    expect(formatTime(300000, 600000)).toBe('300 s');
  });
});

// Issue 22, section 2 item 16: lane names were cut at 90 px and the number scales' labels drawn
// over each other in short lanes.
describe('trend labels that fit', () => {
  const lane = (name: string, type: string, bottom: number, top: number, min: number, max: number): TrendLane => ({
    name, type, boolean: type === 'BOOL', bottom, top, min, max,
  });

  test('a long lane name wraps after the dots of its path, never cut; a short one stays on one line', () => {
    const width = (t: string) => t.length * 7;
    expect(wrapName('Lamp', 100, width)).toEqual(['Lamp']);
    const lines = wrapName('MainInstance.FillTimer.ET', 100, width);
    expect(lines.join('')).toBe('MainInstance.FillTimer.ET');
    expect(lines).toEqual(['MainInstance.', 'FillTimer.ET']);
    for (const line of lines) expect(width(line)).toBeLessThanOrEqual(100);
    // A segment longer than a line breaks where it reaches the edge, still whole when joined.
    const long = wrapName('AVeryLongVariableNameWithoutDots', 70, width);
    expect(long.join('')).toBe('AVeryLongVariableNameWithoutDots');
    for (const line of long) expect(width(line)).toBeLessThanOrEqual(70);
  });

  test('a lane too low for every line keeps the end of the name after …', () => {
    expect(fitLines(['A.', 'B.', 'C'], 3)).toEqual(['A.', 'B.', 'C']);
    expect(fitLines(['A.', 'B.', 'C'], 2)).toEqual(['…B.', 'C']);
    expect(fitLines(['A.', 'B.', 'C'], 1)).toEqual(['…C']);
  });

  test('scale labels closer than a label height give way; tall lanes keep both', () => {
    const lanes = [lane('Level', 'INT', 3, 6, 0, 100), lane('Speed', 'INT', 0, 3, -5, 5)];
    // Tall: 40 px per lane unit, every label fits.
    expect(scaleMarks(lanes, 40).map((m) => m.text)).toEqual(['100', '0', '5', '-5']);
    // Short: 6 px per unit (a lane 18 px high): the labels are at least 14 px apart.
    const kept = scaleMarks(lanes, 6);
    for (let i = 1; i < kept.length; i++) expect((kept[i - 1]!.y - kept[i]!.y) * 6).toBeGreaterThanOrEqual(14);
    expect(kept[0]!.text).toBe('100');
    expect(kept.length).toBeLessThan(4);
  });
});
