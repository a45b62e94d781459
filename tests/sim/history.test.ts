// The scan history store: key frames and deltas, seeking any scan exactly, changes, budget eviction.
import { describe, expect, it } from 'vitest';
import { ScanHistory } from '../../src/sim/history';
import type { Value } from '../../src/model/iecTypes';

/** A made-up process: value 0 toggles every 7 scans, value 1 counts, value 2 is a bigint, power word 0 mirrors value 0. */
function stateOf(scan: number): { values: Value[]; power: number[] } {
  const on = Math.floor(scan / 7) % 2 === 1;
  return { values: [on, scan * 10, BigInt(scan) * 3n, false], power: [on ? 5 : 0, 1] };
}

function recordScans(h: ScanHistory, from: number, to: number, state = stateOf): void {
  for (let s = from; s <= to; s++) {
    const { values, power } = state(s);
    h.record(s, (s - 1) * 10, values, power);
  }
}

describe('scan history', () => {
  it('gives back every scan exactly as recorded, across key frames', () => {
    const h = new ScanHistory(4, 2, { keyEvery: 16 });
    recordScans(h, 1, 200);
    expect([h.first, h.last, h.count]).toEqual([1, 200, 200]);
    expect(h.chunkCount).toBe(13);
    for (const s of [1, 2, 15, 16, 17, 33, 199, 200]) {
      const got = h.seek(s)!;
      expect(got.values).toEqual(stateOf(s).values);
      expect([...got.power]).toEqual(stateOf(s).power);
      expect(got.timeMs).toBe((s - 1) * 10);
    }
    expect(h.seek(0)).toBeUndefined();
    expect(h.seek(201)).toBeUndefined();
  });

  it('stores only changes between key frames', () => {
    const still = new ScanHistory(4, 2, { keyEvery: 1000 });
    recordScans(still, 1, 500, () => ({ values: [true, 1, 2n, false], power: [3, 1] }));
    const busy = new ScanHistory(4, 2, { keyEvery: 1000 });
    recordScans(busy, 1, 500);
    expect(still.bytes).toBeLessThan(500 * 20);
    expect(busy.bytes).toBeGreaterThan(still.bytes + 500 * 12 * 2);
  });

  it('finds the previous and next change of a value and when it last changed', () => {
    const h = new ScanHistory(4, 2, { keyEvery: 5 });
    recordScans(h, 1, 60);
    // value 0 is TRUE on scans 7..13, 21..27 ...
    expect(h.lastChange(0, 10)).toBe(7);
    expect(h.lastChange(0, 7)).toBe(7);
    expect(h.lastChange(0, 6)).toBeUndefined();
    expect(h.nextChange(0, 7, 1)).toBe(14);
    expect(h.nextChange(0, 14, -1)).toBe(7);
    expect(h.nextChange(0, 15, -1)).toBe(14);
    expect(h.nextChange(3, 1, 1)).toBeUndefined();
    expect(h.valueAt(22, 0)).toBe(true);
    expect(h.valueAt(22, 2)).toBe(66n);
  });

  it('finds the first scan where a condition holds, forwards and backwards', () => {
    const h = new ScanHistory(4, 2, { keyEvery: 8 });
    recordScans(h, 1, 100);
    expect(h.find(1, 1, (v) => v[0] === true && (v[1] as number) > 150)).toBe(21);
    expect(h.find(100, -1, (v) => v[0] === true)).toBe(97);
    expect(h.find(1, 1, (v) => v[3] === true)).toBeUndefined();
  });

  it('keeps at most maxScans scans, the oldest dropped first', () => {
    const h = new ScanHistory(4, 2, { keyEvery: 10, maxScans: 50 });
    recordScans(h, 1, 1000);
    expect([h.first, h.last, h.count]).toEqual([951, 1000, 50]);
    expect(h.seek(950)).toBeUndefined();
    expect(h.seek(951)!.values).toEqual(stateOf(951).values);
    expect(h.chunkCount).toBeLessThanOrEqual(7);
  });

  it('stays under its memory budget by dropping the oldest scans', () => {
    const h = new ScanHistory(100, 10, { keyEvery: 64, budgetBytes: 64 * 1024 });
    const values = new Array<Value>(100).fill(0);
    for (let s = 1; s <= 5000; s++) {
      values[s % 100] = s;
      h.record(s, s, values, [s & 0xff, 0, 0, 0, 0, 0, 0, 0, 0, 0]);
    }
    expect(h.bytes).toBeLessThanOrEqual(64 * 1024);
    expect(h.last).toBe(5000);
    expect(h.count).toBeGreaterThan(1000);
    expect(h.count).toBeLessThan(1300);
    expect(h.seek(h.first!)!.values[h.first! % 100]).toBe(h.first);
  });

  it('starts over when the scan numbers restart (cold restart)', () => {
    const h = new ScanHistory(4, 2);
    recordScans(h, 1, 30);
    recordScans(h, 1, 5);
    expect([h.first, h.last]).toEqual([1, 5]);
  });
});
