// The scan history store: segments of a key and the scans after it (times, changed input images),
// the seekable range, the depth and memory bounds (the oldest go first), a restart starting over.
// Rebuilding scans from it by replay: tests/sim/replay.test.ts.
import { describe, expect, it } from 'vitest';
import { ScanHistory } from '../../src/sim/history';

const key = (bytes = 100) => ({ bytes });

/** Records scans from..to, a key every `every` scans, the times scan x 10 (PLC time scan x 10 - 5). */
function recordScans(h: ScanHistory, from: number, to: number, every = 10, inputsAt: (s: number) => boolean = () => false): void {
  for (let s = from; s <= to; s++) {
    if (s === from || (s - from) % every === 0) h.key(s, s * 10, s * 10 - 5, key());
    else h.scan(s * 10, s * 10 - 5, inputsAt(s) ? { index: [1], values: [s] } : undefined);
  }
}

describe('scan history store', () => {
  it('finds the segment of any recorded scan with its key, times and input images', () => {
    const h = new ScanHistory();
    recordScans(h, 1, 95, 10, (s) => s % 7 === 0);
    expect([h.first, h.last, h.count, h.segmentCount]).toEqual([1, 95, 95, 10]);
    const seg = h.segmentOf(37)!;
    expect([seg.firstScan, seg.lastScan]).toEqual([31, 40]);
    expect(seg.timeAt(37 - 31)).toBe(370);
    expect(seg.plcTimeAt(37 - 31)).toBe(365);
    expect(seg.inputAt.map((k) => seg.firstScan + k)).toEqual([35]);
    expect(seg.inputs[0]).toEqual({ index: [1], values: [35] });
    expect(seg.inputIndex(36)).toBe(1);
    expect(h.timeOf(95)).toBe(950);
    expect(h.segmentOf(0)).toBeUndefined();
    expect(h.segmentOf(96)).toBeUndefined();
    expect(h.previous(seg)!.firstScan).toBe(21);
    expect(h.next(seg)!.firstScan).toBe(41);
    expect(h.next(h.open!)).toBeUndefined();
  });

  it('costs a few bytes per scan between keys, more for a changed input image', () => {
    const still = new ScanHistory();
    recordScans(still, 1, 1000, 1000);
    expect(still.bytes).toBeLessThanOrEqual(100 + 128 + 1000 * 16);
    const busy = new ScanHistory();
    recordScans(busy, 1, 1000, 1000, () => true);
    expect(busy.bytes).toBeGreaterThan(still.bytes + 1000 * 48);
  });

  it('keeps at most maxScans scans, the oldest dropped first', () => {
    const h = new ScanHistory({ maxScans: 50 });
    recordScans(h, 1, 1000);
    expect([h.first, h.last, h.count]).toEqual([951, 1000, 50]);
    expect(h.has(950)).toBe(false);
    expect(h.has(951)).toBe(true);
    // The segment holding the first scan is kept whole (its key is needed to rebuild it).
    expect(h.segmentOf(951)!.firstScan).toBe(951);
    expect(h.segmentCount).toBeLessThanOrEqual(6);
  });

  it('stays under its memory budget by dropping the oldest segments', () => {
    const h = new ScanHistory({ budgetBytes: 64 * 1024 });
    for (let s = 1; s <= 20_000; s++) {
      if (s % 100 === 1) h.key(s, s, s, key(1000));
      else h.scan(s, s, { index: [0, 1], values: [true, s] });
    }
    expect(h.bytes).toBeLessThanOrEqual(64 * 1024);
    expect(h.last).toBe(20_000);
    expect(h.count).toBeGreaterThan(500);
    expect(h.count).toBeLessThan(1000);
    expect(h.segmentOf(h.first!)!.firstScan).toBe(h.first);
  });

  it('starts over when the scan numbers restart (cold restart)', () => {
    const h = new ScanHistory();
    recordScans(h, 1, 30);
    recordScans(h, 1, 5);
    expect([h.first, h.last, h.segmentCount]).toEqual([1, 5, 1]);
    h.clear();
    expect([h.first, h.last, h.count, h.bytes]).toEqual([undefined, undefined, 0, 0]);
  });
});
