// The loop steps every machine between two state objects (docs/PLANTS.md, "Keep it cheap"): each
// step writes the next state into the object that held the state before last. That is exact only
// if `step` writes every field of `into` and never changes `from`; and whoever keeps a state (a
// snapshot, a keyframe, the page's frame) must hold a copy no later step changes. For every
// machine registered, with its actuators, operator controls and faults changing now and then.
import { describe, expect, test } from 'vitest';
import type { Value } from '../../src/model/iecTypes';
import { PlantLoop } from '../../src/plant/loop';
import { PLANTS } from '../../src/plant/machines';
import { senseRecord, sensorSlots } from '../../src/plant/points';
import type { PlantModel, PlantPoint, Writable } from '../../src/plant/types';
import type { Project } from '../../src/model/project';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { tankReference } from '../../src/plant/exercises';
import { tank } from '../../src/plant/tank';

function lcg(seed: number): () => number {
  let s = seed;
  return () => {
    s = (s * 1103515245 + 12345) % 2147483648;
    return s / 2147483648;
  };
}

/** Every field of a state turned into a value no step could leave by chance (an old state, at worst). */
function poisoned(state: object): Record<string, unknown> {
  const out: Record<string, unknown> = {};
  for (const [k, v] of Object.entries(state))
    out[k] = typeof v === 'number' ? -987654.321 : typeof v === 'boolean' ? !v : typeof v === 'string' ? 'poison' : Array.isArray(v) ? [{ poison: true }] : { poison: true };
  return out;
}

/** Frozen, arrays and records inside too: a step writing to it throws (modules are strict). */
function frozen<T>(value: T): T {
  if (value && typeof value === 'object' && !Object.isFrozen(value)) {
    for (const v of Object.values(value)) frozen(v);
    Object.freeze(value);
  }
  return value;
}

/** A run's drives, times and faults, the same for every way of stepping it. */
function script(model: PlantModel, steps: number) {
  const rnd = lcg(11);
  const driven = model.points.filter((p) => p.kind !== 'sensor');
  const drive: Record<string, Value> = {};
  for (const p of driven) drive[p.name] = p.type === 'BOOL' ? false : 0;
  const faults = new Set<string>();
  const out: { drive: Record<string, Value>; dt: number; faults: Set<string> }[] = [];
  for (let i = 0; i < steps; i++) {
    for (const p of driven) if (rnd() < 0.06) drive[p.name] = p.type === 'BOOL' ? !drive[p.name] : Math.floor(rnd() * 1000);
    for (const f of model.faults)
      if (rnd() < 0.003) {
        if (rnd() < 0.5) faults.add(f.id);
        else faults.delete(f.id);
      }
    out.push({ drive: { ...drive }, dt: rnd() < 0.02 ? 700 : 100, faults: new Set(faults) });
  }
  return out;
}

describe('stepping into a second state object', () => {
  for (const model of PLANTS)
    test(`${model.id}: step writes every field of \`into\` and never changes \`from\``, () => {
      const steps = script(model, 3000);
      // Fresh objects every step (step without `into`), from frozen states.
      let fresh = frozen(model.initial());
      const expected: unknown[] = [];
      for (const s of steps) {
        fresh = frozen(model.step(fresh, s.drive, s.dt, s.faults));
        expected.push(fresh);
      }
      // Into a poisoned object every step: whatever it held must not show through.
      let state = model.initial();
      steps.forEach((s, i) => {
        const into = poisoned(state as object);
        state = model.step(frozen(state), s.drive, s.dt, s.faults, into as never);
        expect(state).toBe(into);
        expect(state, `step ${i + 1}`).toEqual(expected[i]);
        state = { ...(state as object) } as never;
      });
    });

  for (const model of PLANTS)
    test(`${model.id}: snapshots, the current state and seeked scans keep their values as the machine goes on`, () => {
      const rnd = lcg(3);
      const image: Record<string, Value> = {};
      for (const p of model.points) if (p.kind === 'actuator') image[p.address] = p.type === 'BOOL' ? false : 0;
      const loop = new PlantLoop(model, {}, 10_000);
      loop.bind({ outputs: () => image, setInputs: () => {} });
      const kept: { snap: ReturnType<PlantLoop['snapshot']>; copy: string; current: unknown; currentCopy: string }[] = [];
      for (let k = 1; k <= 600; k++) {
        for (const p of model.points)
          if (p.kind === 'actuator' && rnd() < 0.1) image[p.address] = p.type === 'BOOL' ? !image[p.address] : Math.floor(rnd() * 1000);
        loop.afterScan(k, (k - 1) * 100, 100);
        if (k % 50 === 0) {
          const snap = loop.snapshot();
          const current = loop.currentState();
          kept.push({ snap, copy: JSON.stringify(snap.state), current, currentCopy: JSON.stringify(current) });
        }
      }
      for (const { snap, copy, current, currentCopy } of kept) {
        expect(JSON.stringify(snap.state)).toBe(copy);
        expect(JSON.stringify(current)).toBe(currentCopy);
        // The history gives the same machine for that scan, and seeking it twice changes neither.
        const seek = loop.at(snap.scan)!;
        expect(seek.state).toEqual(snap.state);
        loop.at(snap.scan);
        expect(seek.state).toEqual(snap.state);
      }
    });

  for (const model of PLANTS)
    test(`${model.id}: sense writes every sensor at its slot, in the order of the points`, () => {
      const sensors = model.points.filter((p) => p.kind === 'sensor').map((p) => p.name);
      const out: Value[] = sensors.map(() => 'unwritten' as unknown as Value);
      model.sense(model.initial(), new Set(), out);
      expect(out).toHaveLength(sensors.length);
      for (const v of out) expect(typeof v === 'boolean' || typeof v === 'number').toBe(true);
      expect(Object.keys(senseRecord(model, model.initial(), new Set()))).toEqual(sensors);
    });

  for (const model of PLANTS)
    test(`${model.id}: check makes no list when nothing started (one shared empty list)`, () => {
      // Nothing driven: after the first step (where the intersection's dark heads start), nothing new.
      const a = model.step(model.initial(), {}, 100, new Set());
      const b = model.step(a, {}, 100, new Set());
      const first = model.check(a, b);
      expect(first).toEqual([]);
      expect(model.check(b, model.step(b, {}, 100, new Set()))).toBe(first);
    });

  test('a machine whose sense names are not its sensor points is refused when its module loads', () => {
    const points = PLANTS[0]!.points;
    const sensors = points.filter((p) => p.kind === 'sensor').map((p) => p.name);
    expect(sensorSlots(points, [...sensors].reverse())).toEqual(Object.fromEntries(sensors.map((n, i) => [n, i])));
    expect(() => sensorSlots(points, sensors.slice(1))).toThrow(`the sensor points are ${sensors.join(', ')}`);
    expect(() => sensorSlots(points, [...sensors, 'Nothing'])).toThrow('sense writes');
  });
});

describe('the loop on the engine’s I/O image', () => {
  const plcOf = (project: Project) => createPlc(compileProgram(project).program!, { cycleMs: 100 });

  test('sensors go into the input image by index; a hand-written input is overwritten next scan, a forced one keeps its force', () => {
    const plc = plcOf(tankReference());
    const loop = new PlantLoop(tank, {}, 1000);
    loop.bind(plc);
    const high = plc.ioPoint!('%IX0.3')!;
    const low = plc.ioPoint!('%IX0.2')!;
    const level = plc.ioPoint!('%IW0')!;
    // The initial tank: 100 L, both switches OFF, the transmitter 100.
    expect([low.read(), high.read(), level.read()]).toEqual([false, false, 100]);
    // Written by hand: overwritten by the machine after the next scan, as a wire would.
    plc.setInputs({ '%IX0.3': true });
    plc.scan();
    expect(plc.values().HighLevel).toBe(true);
    loop.afterScan(1, 0, 100);
    expect(high.read()).toBe(false);
    plc.scan();
    expect(plc.values().HighLevel).toBe(false);
    // Forced: the program reads the forced value whatever the machine writes.
    plc.force('HighLevel', true);
    for (let k = 3; k <= 5; k++) {
      plc.scan();
      loop.afterScan(k, (k - 1) * 100, 100);
      expect(plc.values().HighLevel).toBe(true);
    }
    plc.unforce('HighLevel');
    plc.scan();
    expect(plc.values().HighLevel).toBe(false);
  });

  test('an INT actuator is read as a number, recorded and replayed; the drive record changes by name only when the output does', () => {
    interface DialState {
      readonly speed: number;
      readonly turns: number;
    }
    const points: PlantPoint[] = [
      { name: 'Speed', address: '%QW0', type: 'INT', kind: 'actuator', comment: 'Speed setpoint' },
      { name: 'Run', address: '%QX0.0', type: 'BOOL', kind: 'actuator', comment: 'Run' },
      { name: 'Turns', address: '%IW0', type: 'INT', kind: 'sensor', comment: 'Turns counted' },
    ];
    const SENSE = sensorSlots(points, ['Turns']);
    const dial: PlantModel<DialState> = {
      id: 'dial',
      title: 'Dial',
      task: '',
      points,
      faults: [],
      quantities: [{ name: 'turns', type: 'REAL', comment: 'turns' }],
      initial: () => ({ speed: 0, turns: 0 }),
      step(s, drive, dtMs, _faults, into: Writable<DialState> = { ...s }) {
        into.speed = drive.Run === true ? Number(drive.Speed) : 0;
        into.turns = s.turns + (into.speed * dtMs) / 1000;
        return into;
      },
      sense(s, _faults, out) {
        out[SENSE.Turns] = Math.floor(s.turns);
      },
      check: () => [],
      quantity: (s) => s.turns,
    };
    const outputs: Record<string, Value> = { '%QW0': 0, '%QX0.0': false };
    const inputs: Record<string, Value> = {};
    const loop = new PlantLoop(dial as PlantModel, {}, 1000);
    loop.bind({ outputs: () => outputs, setInputs: (v) => Object.assign(inputs, v) });
    const speeds = [0, 30, 30, -12, 700, 700, 5];
    speeds.forEach((speed, i) => {
      outputs['%QW0'] = speed;
      outputs['%QX0.0'] = i > 0;
      loop.afterScan(i + 1, i * 100, 100);
      expect(loop.snapshot().drive).toEqual({ Speed: speed, Run: i > 0 });
    });
    const live = (loop.currentState() as DialState).turns;
    expect(live).toBeCloseTo((30 + 30 - 12 + 700 + 700 + 5) / 10, 9);
    expect(inputs['%IW0']).toBe(Math.floor(live));
    speeds.forEach((speed, i) => expect(loop.at(i + 1)!.drive).toEqual({ Speed: speed, Run: i > 0 }));
    expect(loop.at(speeds.length)!.state).toEqual(loop.currentState());
  });
});
