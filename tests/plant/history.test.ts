// The machine's history (issue 26) keeps per scan only what the step was given and replays the
// model from a keyframe: seeking a scan must show the machine exactly as it was. For every machine
// registered, a run with its actuators, operator controls and faults changing now and then: the
// state (and faults, operator controls, drive) recorded live after each scan equals what the
// history gives back for that scan, to the bit.
import { describe, expect, test } from 'vitest';
import type { Value } from '../../src/model/iecTypes';
import { PlantHistory, PLANT_HISTORY_CHUNK } from '../../src/plant/history';
import { PlantLoop, type PlantSnapshot } from '../../src/plant/loop';
import { PLANTS } from '../../src/plant/machines';
import { tank, type TankState } from '../../src/plant/tank';
import { copyPlantState } from '../../src/plant/points';

/** A small deterministic generator (no Math.random: the run is the same every time). */
function lcg(seed: number): () => number {
  let s = seed;
  return () => {
    s = (s * 1103515245 + 12345) % 2147483648;
    return s / 2147483648;
  };
}

function run(model: (typeof PLANTS)[number], scans: number, keep: number, cycleMs = 100) {
  const rnd = lcg(7);
  const actuators = model.points.filter((p) => p.kind === 'actuator');
  const operators = model.points.filter((p) => p.kind === 'operator');
  const image: Record<string, Value> = {};
  for (const p of actuators) image[p.address] = p.type === 'BOOL' ? false : 0;
  const loop = new PlantLoop(model, {}, keep);
  loop.bind({ outputs: () => image, setInputs: () => {} });
  const live: PlantSnapshot[] = [];
  for (let k = 1; k <= scans; k++) {
    // Outputs change every few scans, operator controls and faults now and then.
    for (const p of actuators)
      if (rnd() < 0.08) image[p.address] = p.type === 'BOOL' ? !image[p.address] : Math.floor(rnd() * 1000);
    for (const p of operators) if (rnd() < 0.01) loop.setOperator(p.name, rnd() < 0.5);
    for (const f of model.faults) if (rnd() < 0.002) loop.setFault(f.id, rnd() < 0.5);
    // Now and then a scan longer than the cycle (a pause in real time).
    const dt = rnd() < 0.01 ? cycleMs * 7 : cycleMs;
    const start = (live.at(-1)?.timeMs ?? 0) + dt - cycleMs;
    loop.afterScan(k, start, cycleMs);
    live.push(loop.snapshot());
  }
  return { loop, live };
}

describe('the machine history', () => {
  for (const model of PLANTS)
    test(`${model.id}: every recorded scan seeks to the machine exactly as it was live`, () => {
      const scans = 3 * PLANT_HISTORY_CHUNK + 77;
      const { loop, live } = run(model, scans, 100_000);
      for (const snap of live) {
        const seen = loop.at(snap.scan)!;
        expect(seen.scan).toBe(snap.scan);
        expect(seen.timeMs).toBe(snap.timeMs);
        expect(seen.state).toEqual(snap.state);
        expect(seen.faults).toEqual(snap.faults);
        expect(seen.operator).toEqual(snap.operator);
        expect(seen.drive).toEqual(snap.drive);
      }
      expect(loop.at(0)!.state).toEqual(model.initial());
      expect(loop.at(scans + 1)).toBeUndefined();
    });

  for (const model of PLANTS)
    test(`${model.id}: walking a range of recorded scans gives each scan's machine as a seek does`, () => {
      const { loop, live } = run(model, 3 * PLANT_HISTORY_CHUNK + 77, 100_000);
      const seen: number[] = [];
      loop.walk(100, 700, (snap) => {
        seen.push(snap.scan);
        const was = live[snap.scan - 1]!;
        expect(snap.timeMs).toBe(was.timeMs);
        expect(copyPlantState(snap.state)).toEqual(was.state);
        expect(snap.faults).toEqual(was.faults);
        expect(snap.operator).toEqual(was.operator);
        expect(snap.drive).toEqual(was.drive);
      });
      expect(seen).toEqual(Array.from({ length: 601 }, (_, i) => 100 + i));
    });

  test('the tank driven hard (overflows, faults, long scans): the seeked states are the live ones, to the bit', () => {
    const { loop, live } = run(tank, 5000, 100_000);
    const levels = live.map((s) => (s.state as TankState).level);
    // The run did exercise the machine: it filled and emptied.
    expect(Math.max(...levels)).toBeGreaterThan(300);
    for (const snap of live) {
      const seen = loop.at(snap.scan)!.state as TankState;
      const was = snap.state as TankState;
      for (const key of Object.keys(was) as (keyof TankState)[]) expect(Object.is(seen[key], was[key])).toBe(true);
    }
  });

  test('it keeps at least the latest `keep` scans, dropping whole keyframe chunks (their arrays used again)', () => {
    const keep = 600;
    const scans = 12 * PLANT_HISTORY_CHUNK + 31;
    const { loop, live } = run(tank, scans, keep);
    const kept = live.filter((s) => loop.at(s.scan) !== undefined);
    expect(kept.length).toBeGreaterThanOrEqual(keep);
    expect(kept.length).toBeLessThan(keep + PLANT_HISTORY_CHUNK);
    // The kept ones are the latest, one run of scans, each exact; the older ones are gone.
    expect(kept.at(-1)!.scan).toBe(scans);
    expect(kept[0]!.scan).toBe(scans - kept.length + 1);
    for (const s of kept) {
      const seen = loop.at(s.scan)!;
      expect(seen.scan).toBe(s.scan);
      expect(seen.state).toEqual(s.state);
      expect(seen.drive).toEqual(s.drive);
    }
    expect(loop.at(kept[0]!.scan - 1)).toBeUndefined();
    expect(loop.at(1)).toBeUndefined();
  });

  test('a program that no longer drives an actuator (an online change) leaves it off, live and in the history', () => {
    const loop = new PlantLoop(tank);
    loop.bind({ outputs: () => ({ '%QX0.0': true, '%QX0.1': true }), setInputs: () => {} });
    loop.setOperator('Stop', true);
    for (let k = 1; k <= 10; k++) loop.afterScan(k, (k - 1) * 100, 100);
    expect(loop.read('tank.Pump')).toBe(true);
    loop.bind({ outputs: () => ({ '%QX0.1': true }), setInputs: () => {} });
    for (let k = 11; k <= 20; k++) loop.afterScan(k, (k - 1) * 100, 100);
    expect(loop.read('tank.Pump')).toBe(false);
    expect(loop.at(10)!.drive).toEqual({ Pump: true, InletValve: true, DrainValve: false, RunLamp: false });
    expect(loop.at(11)!.drive).toEqual({ Pump: false, InletValve: true, DrainValve: false, RunLamp: false });
    expect(loop.at(11)!.operator).toEqual({ Start: false, Stop: true });
    // The pump ran down after the change: the history replays it as it happened.
    expect((loop.at(20)!.state as TankState).pump).toBe((loop.currentState() as TankState).pump);
    expect((loop.at(20)!.state as TankState).pump).toBe(0);
  });

  test('a cold restart starts the history over', () => {
    const { loop } = run(tank, 300, 100_000);
    loop.reset();
    expect(loop.at(5)).toBeUndefined();
    loop.afterScan(1, 0, 100);
    expect(loop.at(1)!.state).toEqual(loop.currentState());
  });

  test('a gap in the scan numbers starts a new keyframe; scans are found on both sides', () => {
    const h = new PlantHistory(tank, tank.points, 10_000);
    let s = tank.initial();
    const states = new Map<number, TankState>();
    let t = 0;
    const step = (scan: number, pump: boolean) => {
      const drive = { Pump: pump, InletValve: pump, DrainValve: false, RunLamp: false, Start: false, Stop: false };
      const next = tank.step(s, drive, 100, new Set());
      const record = h.newRecord();
      for (const name of ['Pump', 'InletValve']) if (pump) record.bits[0]! |= 1 << h.bitOf(name);
      h.push(scan, s, t, record, t + 100);
      t += 100;
      s = next;
      states.set(scan, s);
    };
    for (let k = 1; k <= 10; k++) step(k, true);
    for (let k = 50; k <= 60; k++) step(k, k % 3 === 0);
    expect(h.length).toBe(21);
    expect(h.at(20)).toBeUndefined();
    for (const [scan, state] of states) expect(h.at(scan)!.state).toEqual(state);
  });
});
