// A machine at rest (issue 26): when a step leaves every field of the state as it was, the loop
// does not step, check or sense it again until its drive, operator controls, faults, time step or
// wiring change (the model is deterministic, so the step would give the same state). Whatever the
// loop skips, the machine must be exactly the one stepped every scan: for every machine, long
// quiet stretches (outputs held, all off or some on until things stop moving), then changes, a
// fault, an operator control, a longer scan; the loop's state after each scan equals, to the bit,
// the model stepped after every scan with the same drive, faults and time; and the sensors it
// presents are the ones sensed in that state.
import { describe, expect, test } from 'vitest';
import type { Value } from '../../src/model/iecTypes';
import { PlantLoop } from '../../src/plant/loop';
import { PLANTS } from '../../src/plant/machines';
import { senseRecord } from '../../src/plant/points';
import { tank } from '../../src/plant/tank';
import type { PlantModel } from '../../src/plant/types';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { newProject } from '../../src/model/factory';
import { plantVariables } from '../../src/plant/exerciseKit';

/** A small deterministic generator (no Math.random: the run is the same every time). */
function lcg(seed: number): () => number {
  let s = seed;
  return () => {
    s = (s * 1103515245 + 12345) % 2147483648;
    return s / 2147483648;
  };
}

/** `model` with its steps counted (the loop steps it as it would the model itself). */
function counted<S>(model: PlantModel<S>): { model: PlantModel<S>; steps: () => number } {
  let steps = 0;
  return {
    model: {
      ...model,
      step: (from, drive, dtMs, faults, into) => {
        steps++;
        return model.step(from, drive, dtMs, faults, into);
      },
    },
    steps: () => steps,
  };
}

function run(model: PlantModel, scans: number, cycleMs = 10) {
  const rnd = lcg(11);
  const actuators = model.points.filter((p) => p.kind === 'actuator');
  const operators = model.points.filter((p) => p.kind === 'operator');
  const sensors = model.points.filter((p) => p.kind === 'sensor');
  const image: Record<string, Value> = {};
  for (const p of actuators) image[p.address] = p.type === 'BOOL' ? false : 0;
  const inputs: Record<string, Value> = {};
  const { model: stepped, steps } = counted(model);
  const loop = new PlantLoop(stepped);
  loop.bind({ outputs: () => image, setInputs: (v) => Object.assign(inputs, v) });
  // The reference: the model stepped after every scan.
  let state = model.initial();
  const faults = new Set<string>();
  const drive: Record<string, Value> = {};
  for (const p of operators) drive[p.name] = false;
  let time = 0;
  let skipped = 0;
  for (let k = 1; k <= scans; k++) {
    // Quiet stretches of 300 scans; between them, outputs, operator controls and faults change.
    if (k % 300 === 1) {
      for (const p of actuators)
        image[p.address] = p.type === 'BOOL' ? rnd() < 0.4 : rnd() < 0.5 ? 0 : Math.floor(rnd() * 1000);
      for (const p of operators)
        if (rnd() < 0.5) {
          const on = rnd() < 0.5;
          loop.setOperator(p.name, on);
          drive[p.name] = on;
        }
      for (const f of model.faults)
        if (rnd() < 0.15) {
          const on = rnd() < 0.5;
          loop.setFault(f.id, on);
          if (on) faults.add(f.id);
          else faults.delete(f.id);
        }
    }
    // Now and then a scan longer than the cycle (a pause in real time), then the cycle again.
    const long = k % 450 === 0;
    const start = k === 1 ? 0 : time + (long ? 5 * cycleMs : 0);
    const target = start + cycleMs;
    for (const p of actuators) drive[p.name] = p.type === 'BOOL' ? image[p.address] === true : Number(image[p.address]);
    const before = steps();
    loop.afterScan(k, start, cycleMs);
    if (steps() === before) skipped++;
    state = model.step(state, drive, target - time, faults);
    time = target;
    expect(loop.currentState(), `${model.id} after scan ${k}`).toEqual(state);
    const sensed = senseRecord(model, state, faults);
    // An INT input holds -0 as 0 (the image's value for the PLC: the loop writes only what differs).
    const plcValue = (v: Value | undefined) => (typeof v === 'number' ? v + 0 : v);
    for (const p of sensors)
      expect(plcValue(inputs[p.address]), `${model.id}.${p.name} after scan ${k}`).toBe(plcValue(sensed[p.name]));
  }
  return { skipped };
}

describe('a machine at rest', () => {
  for (const model of PLANTS)
    test(`${model.id}: the loop, at rest or not, gives the state of a model stepped every scan, to the bit`, () => {
      const { skipped } = run(model, 3000);
      // The machines that can stand still did, for many scans (the lift, the mixer and the
      // intersection keep time in their state: never at rest, stepped every scan).
      if (['tank', 'garage', 'boxes'].includes(model.id)) expect(skipped).toBeGreaterThan(500);
    });

  test('an idle tank is not stepped again while nothing changes, and steps again when something does', () => {
    const { model, steps } = counted(tank);
    const image: Record<string, Value> = { '%QX0.0': false, '%QX0.1': false, '%QX0.2': false, '%QX0.3': false };
    const loop = new PlantLoop(model);
    loop.bind({ outputs: () => image, setInputs: () => {} });
    for (let k = 1; k <= 500; k++) loop.afterScan(k, (k - 1) * 10, 10);
    // At rest from the first scans (the loop looks for it every 16 scans): 500 scans, a few steps.
    expect(steps()).toBeLessThanOrEqual(16);
    // The drain opens: the water runs out, every scan stepped.
    image['%QX0.2'] = true;
    const opened = steps();
    for (let k = 501; k <= 600; k++) loop.afterScan(k, (k - 1) * 10, 10);
    expect(steps() - opened).toBe(100);
    expect(loop.read('tank.level')).toBeLessThan(100);
    // A fault set on an idle tank: stepped again (a fault may change what a step gives).
    image['%QX0.2'] = false;
    for (let k = 601; k <= 800; k++) loop.afterScan(k, (k - 1) * 10, 10);
    const idle = steps();
    loop.setFault('pump_dead', true);
    loop.afterScan(801, 8000, 10);
    expect(steps()).toBe(idle + 1);
  });

  test('the history replays scans the loop skipped: a seek gives the state the machine had', () => {
    const image: Record<string, Value> = { '%QX0.0': false, '%QX0.1': false, '%QX0.2': true, '%QX0.3': false };
    const loop = new PlantLoop(tank);
    loop.bind({ outputs: () => image, setInputs: () => {} });
    const live: unknown[] = [];
    for (let k = 1; k <= 2000; k++) {
      // Drains to empty (then at rest, the drain open on a dry tank), refills now and then.
      if (k % 700 === 0) image['%QX0.0'] = image['%QX0.1'] = !image['%QX0.0'];
      loop.afterScan(k, (k - 1) * 10, 10);
      live.push(loop.currentState());
    }
    for (let k = 1; k <= 2000; k += 7) expect(loop.at(k)!.state, `scan ${k}`).toEqual(live[k - 1]);
  });

  test('scans at rest, told to the history later in one go, are recorded as they ran: across keyframes, an operator press, a fault, a seek in the middle of a rest', () => {
    const image: Record<string, Value> = { '%QX0.0': false, '%QX0.1': false, '%QX0.2': false, '%QX0.3': false };
    const loop = new PlantLoop(tank);
    loop.bind({ outputs: () => image, setInputs: () => {} });
    const live: ReturnType<PlantLoop['snapshot']>[] = [];
    for (let k = 1; k <= 2000; k++) {
      if (k === 700) loop.setOperator('Start', true);
      if (k === 701) loop.setOperator('Start', false);
      if (k === 900) image['%QX0.2'] = true;
      if (k === 1000) image['%QX0.2'] = false;
      if (k === 1300) loop.setFault('pump_dead', true);
      // Asked in the middle of a rest: what it has not been told yet is told first; the rest goes on.
      if (k === 1500) expect(loop.at(1400)!.state).toEqual(live[1399]!.state);
      // A scan that took longer (a pause in real time) breaks the run of equal steps.
      const start = k <= 1700 ? (k - 1) * 10 : (k - 1) * 10 + 35;
      loop.afterScan(k, start, 10);
      live.push(loop.snapshot());
    }
    for (const was of live) {
      const seen = loop.at(was.scan)!;
      expect(seen.timeMs, `scan ${was.scan}`).toBe(was.timeMs);
      expect(seen.state, `scan ${was.scan}`).toEqual(was.state);
      expect(seen.operator, `scan ${was.scan}`).toEqual(was.operator);
      expect(seen.faults, `scan ${was.scan}`).toEqual(was.faults);
      expect(seen.drive, `scan ${was.scan}`).toEqual(was.drive);
    }
    expect(live[699]!.operator.Start).toBe(true);
    expect(loop.at(700)!.operator.Start).toBe(true);
    expect(loop.at(699)!.operator.Start).toBe(false);
  });

  test('at rest, an input written over by anything else (a write by name, setInputs, the image, a restore) is the machine\'s again after the next scan', () => {
    // The program only declares the tank's points (its actuators stay off): the tank stands still.
    const project = newProject('idle tank');
    const plc = createPlc(compileProgram({ ...project, pous: [{ ...project.pous[0]!, variables: plantVariables(tank) }] }).program!, { cycleMs: 10 });
    const loop = new PlantLoop(tank);
    loop.bind(plc);
    let k = 0;
    const scan = () => {
      k++;
      plc.scan();
      loop.afterScan(k, (k - 1) * 10, 10);
    };
    for (let i = 0; i < 100; i++) scan();
    const probe = plc.probe!();
    const saved = probe.save();
    const io = plc.ioImage!();
    const level = io.input('%IW0');
    // The machine presents 100 L, the low switch OFF.
    expect(io.inputs[level]).toBe(100);
    const overwrites: [string, () => void][] = [
      ['a write by name', () => plc.write('Level', 555)],
      ['setInputs', () => plc.setInputs({ '%IW0': 555 })],
      ['the image', () => io.write(level, 555)],
      ['an input point', () => plc.ioPoint!('%IW0')!.write(555)],
      [
        'a restore',
        () => {
          plc.write('Level', 555);
          const written = probe.save();
          scan();
          probe.restore(written);
        },
      ],
    ];
    for (const [how, overwrite] of overwrites) {
      overwrite();
      expect(io.inputs[level], how).toBe(555);
      scan();
      expect(io.inputs[level], how).toBe(100);
      expect(plc.read('Level'), how).toBe(555);
      scan();
      expect(plc.read('Level'), how).toBe(100);
    }
    probe.restore(saved);
  });
});

