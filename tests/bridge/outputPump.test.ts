// The controller's output pump on a virtual clock: a 1 kHz stream of changing images is sent at most
// once per gateway poll, never two sends within one period, and the last image is always sent.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { OutputPump, type WireImage } from '../../src/bridge/outputPump';

describe('OutputPump', () => {
  beforeEach(() => vi.useFakeTimers());
  afterEach(() => vi.useRealTimers());

  it('sends a 1 kHz stream at most once per 50 ms period, and the last image after the burst', () => {
    const sent: { at: number; image: WireImage }[] = [];
    const pump = new OutputPump((image) => (sent.push({ at: Date.now(), image }), true), { periodMs: () => 50 });
    const t0 = Date.now();
    for (let scan = 1; scan <= 1000; scan++) {
      pump.offer({ '%QX0.1': scan % 2 === 1, '%QW0': scan });
      vi.advanceTimersByTime(1);
    }
    vi.advanceTimersByTime(60);
    const inBurst = sent.filter((s) => s.at - t0 <= 1060);
    // 1,000 images in a second: about one per period (21 at most), not 1,000.
    expect(inBurst.length).toBeGreaterThanOrEqual(19);
    expect(inBurst.length).toBeLessThanOrEqual(22);
    for (let i = 1; i < inBurst.length; i++) expect(inBurst[i]!.at - inBurst[i - 1]!.at).toBeGreaterThanOrEqual(50);
    expect(inBurst.at(-1)!.image).toEqual({ '%QX0.1': false, '%QW0': 1000 });
    pump.stop();
  });

  it('with nothing new, re-sends the last image as the heartbeat about every 100 ms', () => {
    const sent: number[] = [];
    const pump = new OutputPump(() => (sent.push(Date.now()), true), { periodMs: () => 50 });
    pump.offer({ '%QX0.0': true });
    vi.advanceTimersByTime(1000);
    expect(sent.length).toBeGreaterThanOrEqual(9);
    expect(sent.length).toBeLessThanOrEqual(12);
    pump.stop();
  });
});
