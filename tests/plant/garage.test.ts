// The garage door (issue 26): its physics, faults and consequences; the exercise's reference
// solution and wrong one through the scenario runner and `rungsmith test`; and the simulation
// worker's trace of 2,000 scans equal to the CLI's, scan by scan, the door included.
import { senseRecord } from '../../src/plant/points';
import { afterEach, describe, expect, test } from 'vitest';
import type { SimulatedDevice } from '../../src/gateway/simulatedDevice';
import { CAR_TOP, CLOSED_LIMIT_AT, garage, PREWARN_MS, type GarageState } from '../../src/plant/garage';
import {
  GARAGE_EXAMPLE,
  GARAGE_SCENARIO,
  garageReference,
  garageWrong,
} from '../../src/plant/garageExercise';
import { PLANT_EXAMPLES } from '../../src/plant/exercises';
import { PlantLoop } from '../../src/plant/loop';
import { plantById } from '../../src/plant/machines';
import { runScenario } from '../../src/sim/scenario';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { validateProject } from '../../src/model/load';
import type { PlantFrame } from '../../src/sim/sessionPlant';
import { rungsmith } from '../cli/memoryIo';
import { SimHarness } from '../sim/harness';
import { cliTrace, startedPlantDevice, workerTrace } from './traces';
import { csvValue } from '../../src/engine/values/literals';

const none = new Set<string>();
type Drive = Partial<Record<'MotorUp' | 'MotorDown' | 'WarningLamp' | 'Doorway', boolean>>;
const run = (s: GarageState, drive: Drive, ms: number, faults: ReadonlySet<string> = none, dt = 100) => {
  for (let t = 0; t < ms; t += dt) s = garage.step(s, drive, dt, faults);
  return s;
};
/** Consequence ids over a run, step by step, as the loop reports them. */
const consequences = (s: GarageState, drive: Drive, ms: number, faults: ReadonlySet<string> = none) => {
  const ids: string[] = [];
  for (let t = 0; t < ms; t += 100) {
    const next = garage.step(s, drive, 100, faults);
    ids.push(...garage.check(s, next).map((c) => c.id));
    s = next;
  }
  return { state: s, ids };
};
const UP = { MotorUp: true, WarningLamp: true } as const;
const DOWN = { MotorDown: true, WarningLamp: true } as const;
/** The door at `position`, its warning lamp lit for `lampMs` already (the task's 1 s by default). */
const at = (position: number, lampMs = PREWARN_MS): GarageState => ({
  ...garage.initial(),
  position,
  lamp: lampMs > 0,
  lampMs,
});

describe('the garage door model', () => {
  test.each([
    // [what, from %, drive, ms, position after (to 0.01 %), speed % after]
    // The ramp (0.2, 0.4, … 1.0 of full speed in 0.1 s steps) costs 0.2 s of full-speed travel.
    ['the motor ramps up in 0.5 s, then 12 s end to end', 0, UP, 1000, 100 * (0.8 / 12), 100],
    ['up for 6.5 s: a little over half the travel', 10, UP, 6500, 10 + 100 * (6.3 / 12), 100],
    ['down from fully open', 100, DOWN, 3000, 100 - 100 * (2.8 / 12), -100],
    ['up stops at the end stop: the motor stalls there (speed 0)', 95, UP, 2000, 100, 0],
    ['down stops at the floor: the motor stalls there (speed 0)', 5, DOWN, 2000, 0, 0],
    ['no contactor: the door stays', 40, {}, 3000, 40, 0],
    ['both contactors: the motor does not turn', 40, { MotorUp: true, MotorDown: true }, 3000, 40, 0],
  ] as const)('%s', (_what, from, drive, ms, position, speed) => {
    const s = run(at(from), drive, ms);
    expect(s.position).toBeCloseTo(position, 2);
    expect(s.speed * 100).toBeCloseTo(speed, 5);
  });

  test('the limit switches and the photo-eye follow the door and the car', () => {
    expect(senseRecord(garage, garage.initial(), none)).toEqual({
      OpenLimit: false,
      ClosedLimit: true,
      Obstacle: false,
    });
    expect(senseRecord(garage, at(50), none)).toEqual({ OpenLimit: false, ClosedLimit: false, Obstacle: false });
    expect(senseRecord(garage, at(99.2), none)).toEqual({ OpenLimit: true, ClosedLimit: false, Obstacle: false });
    const car = run(at(100), { Doorway: true }, 100);
    expect(car.carIn).toBe(true);
    expect(senseRecord(garage, car, none).Obstacle).toBe(true);
    // The car leaves when the operator says.
    expect(senseRecord(garage, run(car, {}, 100), none).Obstacle).toBe(false);
  });

  test('a braking door stops within 0.1 s; reversing brakes first, then ramps up the other way', () => {
    const moving = run(at(50), UP, 2000);
    const stopped = run(moving, {}, 100);
    expect(stopped.speed).toBe(0);
    expect(stopped.position).toBe(moving.position);
    const reversing = run(moving, DOWN, 200);
    expect(reversing.speed).toBeCloseTo(-0.2, 10);
    expect(reversing.position).toBeLessThan(moving.position);
  });

  test('the car drives in only under a door open above its roof', () => {
    const low = run(at(CAR_TOP - 10), { Doorway: true }, 1000);
    expect(low.carWaiting).toBe(true);
    expect(low.carIn).toBe(false);
    expect(senseRecord(garage, low, none).Obstacle).toBe(false);
    // The door opens above it: in it comes.
    const opened = run(low, { ...UP, Doorway: true }, 3000);
    expect(opened.position).toBeGreaterThan(CAR_TOP);
    expect(opened.carIn).toBe(true);
  });

  test('a full cycle counts when the door closes after it was fully open', () => {
    let s = run(garage.initial(), UP, 14_000);
    expect(s.wasOpen).toBe(true);
    expect(s.cycles).toBe(0);
    s = run(s, DOWN, 14_000);
    expect(s.cycles).toBe(1);
    // Half open and closed again is no cycle.
    s = run(run(s, UP, 5000), DOWN, 8000);
    expect(s.cycles).toBe(1);
  });

  test('consequence: the door comes down on the car (error, once), resting on its roof', () => {
    const car = run(at(90), { Doorway: true, WarningLamp: true }, 100);
    const { state, ids } = consequences(car, { ...DOWN, Doorway: true }, 6000);
    expect(ids).toEqual(['hit']);
    expect(state.position).toBe(CAR_TOP);
    expect(state.onCar).toBe(true);
    expect(state.hits).toBe(1);
    const [hit] = garage.check(car, run(car, { ...DOWN, Doorway: true }, 6000));
    expect(hit).toMatchObject({
      severity: 'error',
      counter: 'hits',
      message: 'the door came down on the car in the doorway',
    });
    // Lifted off the car and lowered again: a second hit.
    const again = consequences(state, { ...UP, Doorway: true }, 1000).state;
    expect(consequences(again, { ...DOWN, Doorway: true }, 2000).ids).toEqual(['hit']);
  });

  test('consequence: both contactors on together is a short circuit (error, once per closing)', () => {
    const { ids, state } = consequences(at(40), { MotorUp: true, MotorDown: true, WarningLamp: true }, 2000);
    expect(ids).toEqual(['short']);
    expect(state.shorts).toBe(1);
    expect(garage.check(at(40), state)[0]).toMatchObject({ severity: 'error', counter: 'shorts' });
  });

  test('consequence: the motor kept on against an end stop for over 1 s overruns it (error, named end)', () => {
    const open = consequences(at(98), UP, 3000);
    expect(open.ids).toEqual(['overrun']);
    expect(open.state.overruns).toBe(1);
    // The contactor is on, the motor stalled: the door neither moves nor reads a speed.
    expect(open.state.up).toBe(true);
    expect(garage.quantity(open.state, 'speed')).toBe(0);
    expect(open.state.moving).toBe(false);
    const closed = consequences(at(2), DOWN, 3000);
    expect(closed.ids).toEqual(['overrun']);
    const s = run(at(2), DOWN, 3000);
    expect(garage.check(run(at(2), DOWN, 1000), s)[0]!.message).toBe(
      'the motor drove the door against its closed end stop for over 1 s (overrun)',
    );
    // Stopped at the end within the second: no overrun.
    expect(consequences(run(at(98), UP, 900), {}, 3000).ids).toEqual([]);
  });

  test('consequence: moving without the warning lamp, or less than 1 s after it lit, is a warning', () => {
    const dark = consequences(at(40, 0), { MotorUp: true }, 2000);
    expect(dark.ids).toEqual(['unwarned']);
    expect(garage.check(at(40, 0), dark.state)[0]!.message).toBe(
      'the door moved without the warning lamp lit',
    );
    const sudden = garage.step(at(40, 0), UP, 100, none);
    expect(garage.check(at(40, 0), sudden)).toEqual([
      {
        id: 'unwarned',
        severity: 'warning',
        message: 'the door started to move less than 1 s after the warning lamp lit',
        counter: 'unwarned',
      },
    ]);
    // Lit for 1 s first, then moving: no warning.
    const warned = run(at(40, 0), { WarningLamp: true }, 1000);
    expect(consequences(warned, UP, 3000).ids).toEqual([]);
  });

  test('a door braking to a stop after the motor and the lamp went off together is no unwarned move, at any scan', () => {
    // At full speed up, the contactor and the lamp dropped in one scan: 0.1 s of braking, in 10 ms steps.
    let s = run(at(40), UP, 2000);
    expect(s.speed).toBe(1);
    const ids: string[] = [];
    for (let t = 0; t < 200; t += 10) {
      const next = garage.step(s, {}, 10, none);
      ids.push(...garage.check(s, next).map((c) => c.id));
      s = next;
    }
    expect(s.speed).toBe(0);
    expect(s.position).toBeGreaterThan(40 + 100 * (1.8 / 12));
    expect(ids).toEqual([]);
    expect(s.unwarned).toBe(0);
    // Driven without the lamp it still is.
    expect(consequences(at(40, 0), { MotorUp: true }, 300).ids).toEqual(['unwarned']);
  });

  test.each([
    ['open_stuck_off', 'OpenLimit', false, at(100)],
    ['open_stuck_on', 'OpenLimit', true, at(0)],
    ['closed_stuck_off', 'ClosedLimit', false, at(0)],
    ['closed_stuck_on', 'ClosedLimit', true, at(100)],
    ['eye_stuck_off', 'Obstacle', false, run(at(100), { Doorway: true }, 100)],
  ] as const)('fault %s: %s reads %s whatever the door does', (fault, point, value, state) => {
    expect(senseRecord(garage, state, none)[point]).toBe(!value);
    expect(senseRecord(garage, state, new Set([fault]))[point]).toBe(value);
  });

  test('faults: the motor does not start; a slow motor takes 30 s end to end', () => {
    const dead = run(at(50), UP, 5000, new Set(['motor_dead']));
    expect(dead.position).toBe(50);
    expect(dead.speed).toBe(0);
    const slow = run(at(0), UP, 10_500, new Set(['motor_slow']));
    expect(slow.speed).toBeCloseTo(0.4, 10);
    // 0.2 s at a fifth of full speed, then 10.4 s at 40 %: 4.18 s of full-speed travel.
    expect(slow.position).toBeCloseTo((100 * 4.18) / 12, 6);
  });

  test('a step is pure: the same state, drive and time give the same state; the input is not changed', () => {
    const s0 = run(at(80), { Doorway: true }, 100);
    const copy = JSON.stringify(s0);
    const a = garage.step(s0, { ...DOWN, Doorway: true }, 100, none);
    const b = garage.step(s0, { ...DOWN, Doorway: true }, 100, none);
    expect(a).toEqual(b);
    expect(JSON.stringify(s0)).toBe(copy);
  });

  test('it is a machine of the registry, every quantity readable, with its own default I/O map', () => {
    expect(plantById('garage')).toBe(garage);
    const s = garage.initial();
    for (const q of garage.quantities)
      expect(typeof garage.quantity(s, q.name)).toBe(q.type === 'BOOL' ? 'boolean' : 'number');
    const addresses = garage.points.map((p) => p.address);
    expect(new Set(addresses).size).toBe(addresses.length);
    // The car in the doorway is the operator's (a switch on the drawing), the photo-eye the program's.
    expect(garage.points.find((p) => p.name === 'Doorway')).toMatchObject({
      kind: 'operator',
      control: 'switch',
    });
    expect(() => new PlantLoop(garage)).not.toThrow();
  });
});

describe('the garage door exercise', () => {
  test('the reference solution checks clean and is offered under File > Examples', () => {
    const p = garageReference();
    expect(validateProject(JSON.parse(JSON.stringify(p)))).toMatchObject({ ok: true });
    expect(checkProject(p).map(formatDiagnostic)).toEqual([]);
    expect(PLANT_EXAMPLES).toContain(GARAGE_EXAMPLE);
    expect(p.plant).toEqual({ id: 'garage' });
  });

  test('the reference solution opens and closes the door three times, reversing for the car', () => {
    const { result } = runScenario(garageReference(), GARAGE_SCENARIO);
    expect(result).toMatchObject({ ok: true, scans: 1200 });
  });

  test.each([10, 20, 50])('the reference solution opens the door at %i ms scans with no warning (it gave one as the door braked at the limit)', (cycle) => {
    const scans = Math.ceil(14_000 / cycle);
    const { result } = runScenario(garageReference(), {
      name: `open at ${cycle} ms`,
      csv: `# plant: garage\n# cycle: ${cycle}ms\nscan,garage.KeyOpen,expect OpenLimit,expect garage.unwarned\n1,1,0,0\n${Math.ceil(200 / cycle)},0,,\n${scans},,1,0\n`,
    });
    expect(result).toMatchObject({ ok: true, scans });
  });

  test('the wrong solution (it ignores the photo-eye) fails where the door comes down on the car', () => {
    const { result } = runScenario(garageWrong(), GARAGE_SCENARIO);
    expect(result.ok).toBe(false);
    expect(result.error).toBe('the door came down on the car in the doorway at scan 499 (49.80 s)');
  });

  test('a fault from the scenario: the photo-eye stuck OFF makes the reference hit the car too; expecting the count checks it', () => {
    // The door starts closing at scan 160; the car drives in at scan 170 (the door about 91 % open).
    const csv = `# plant: garage
# cycle: 100ms
scan,fault eye_stuck_off,garage.KeyOpen,garage.KeyClose,garage.Doorway,expect Obstacle,expect garage.car_in,expect garage.hits
1,1,1,0,0,0,0,0
3,,0,,,,,
150,,,1,,,,
152,,,0,,,,
170,,,,1,,,
175,,,,,0,1,0
260,,,,,0,1,1
`;
    expect(runScenario(garageReference(), { name: 'eye stuck', csv }).result).toMatchObject({
      ok: true,
      scans: 260,
    });
    // Without the count expected, the hit fails the run where it happens.
    const failing = csv
      .replace(',expect garage.hits', '')
      .replace(/,[01]\n/g, '\n')
      .replace(/,\n/g, '\n');
    expect(runScenario(garageReference(), { name: 'eye stuck', csv: failing }).result.error).toMatch(
      /^the door came down on the car in the doorway at scan 2\d\d \(2\d\.\d0 s\)$/,
    );
  });
});

describe('the garage door on the command line and in the simulation worker', () => {
  test('rungsmith plants garage lists the door: I/O map, faults, quantities and the task', () => {
    const r = rungsmith(['plants', 'garage']);
    expect(r.code).toBe(0);
    expect(r.out).toMatch(/^garage: Garage door\n/);
    expect(r.out).toMatch(/%IX0\.6 +Doorway +BOOL +operator \(switch\) +A car in the doorway/);
    expect(r.out).toMatch(/%QX0\.1 +MotorDown +BOOL +actuator +Motor contactor, door down/);
    expect(r.out).toMatch(/eye_stuck_off +Photo-eye stuck OFF/);
    expect(r.out).toMatch(/garage\.hits +INT +Times the door came down on the car/);
    expect(r.out).toContain('a closing door reverses and opens fully');
  });

  const WATCH = [
    'KeyOpen',
    'KeyClose',
    'Doorway',
    'Opening',
    'Closing',
    'WarningLamp',
    'MotorUp',
    'MotorDown',
    'OpenLimit',
    'ClosedLimit',
    'Obstacle',
  ];
  /** The operator's actions by scan (before that scan): a cycle, a second one interrupted by the car, a third. */
  const ACTIONS: readonly (readonly [number, string, boolean])[] = [
    [1, 'KeyOpen', true],
    [3, 'KeyOpen', false],
    [150, 'KeyClose', true],
    [152, 'KeyClose', false],
    [300, 'KeyOpen', true],
    [302, 'KeyOpen', false],
    [440, 'KeyClose', true],
    [442, 'KeyClose', false],
    [470, 'Doorway', true],
    [560, 'Doorway', false],
    [570, 'KeyClose', true],
    [572, 'KeyClose', false],
    [720, 'KeyOpen', true],
    [722, 'KeyOpen', false],
    [860, 'KeyClose', true],
    [862, 'KeyClose', false],
    [1200, 'KeyOpen', true],
    [1202, 'KeyOpen', false],
    [1350, 'KeyClose', true],
    [1352, 'KeyClose', false],
  ];

  test('the worker trace of 2,000 scans equals the CLI trace scan by scan, the door included', () => {
    const h = new SimHarness().send(
      { type: 'setCycle', cycleMs: 100 },
      { type: 'setPlant', plant: { id: 'garage' } },
      { type: 'load', project: garageReference() },
    );
    let done = 0;
    for (const [scan, name, value] of ACTIONS) {
      if (scan - 1 > done) {
        h.send({ type: 'step', scans: scan - 1 - done });
        while (h.frame.scan < scan - 1) h.settle();
        done = scan - 1;
      }
      h.send({ type: 'plantOperator', name, value });
    }
    h.send({ type: 'step', scans: 2000 - done });
    while (h.frame.scan < 2000) h.settle();
    expect(h.frame.scan).toBe(2000);
    const door = (h.frame.plant as PlantFrame).now.state as GarageState;
    expect(door.cycles).toBe(4);
    expect(door.hits).toBe(0);
    const worker = workerTrace(h, WATCH);
    const stim = ['scan,garage.KeyOpen,garage.KeyClose,garage.Doorway'];
    for (const [scan, name, value] of ACTIONS)
      stim.push(
        `${scan},${['KeyOpen', 'KeyClose', 'Doorway'].map((n) => (n === name ? (value ? 1 : 0) : '')).join(',')}`,
      );
    const cli = cliTrace({
      project: garageReference(),
      plant: 'garage',
      stimulus: `${stim.join('\n')}\n`,
      scans: 2000,
      cycle: '100ms',
      watch: [...WATCH, 'garage.position'],
    });
    expect(cli.code).toBe(0);
    expect(cli.err).toBe('');
    const rows = cli.out.trim().split('\n');
    expect(rows).toHaveLength(2001);
    expect(rows.map((r) => r.split(',').slice(0, -1).join(','))).toEqual(worker);
    // The door itself, as the history shows it, at some scans: the CLI's position to the last digit.
    for (const scan of [1, 11, 131, 280, 471, 480, 1000, 1999]) {
      h.send({ type: 'historySeek', scan });
      const view = h.of('historyView').at(-1)!.view;
      expect(view.plant?.scan).toBe(scan);
      expect(csvValue('REAL', (view.plant!.state as GarageState).position)).toBe(rows[scan]!.split(',').at(-1));
    }
    // The door reversed for the car: Obstacle ON, then MotorUp with the door not yet open.
    const col = (name: string) => WATCH.indexOf(name) + 2;
    const reversed = worker.slice(1).map((r) => r.split(','));
    const seen = reversed.findIndex((r) => r[col('Obstacle')] === '1');
    expect(reversed[seen + 1]![col('MotorUp')]).toBe('1');
    expect(reversed[seen + 1]![col('OpenLimit')]).toBe('0');
  });
});

describe("the garage door as the gateway's simulated device (npm start -- --plant garage)", () => {
  let device: SimulatedDevice | undefined;
  afterEach(async () => {
    await device?.close();
    device = undefined;
  });

  test('every point fits the device: the limits are its inputs, the contactors its coils, the door moves in real time', async () => {
    device = await startedPlantDevice('garage');
    const inputs = device.inputValues();
    const coils = device.writtenValues();
    for (const p of garage.points)
      expect(p.kind === 'actuator' ? coils.has(p.address) : inputs.has(p.address)).toBe(true);
    // The door stands closed: the closed limit is ON at %IX0.4, the open limit OFF.
    expect(inputs.get('%IX0.4')).toBe(true);
    expect(inputs.get('%IX0.3')).toBe(false);
    // The controller switches MotorUp and the lamp on: the door rises, the closed limit goes OFF.
    device.drive(
      new Map([
        ['%QX0.0', true],
        ['%QX0.2', true],
      ]),
    );
    await expect
      .poll(() => device!.plantRead('position'), { timeout: 20_000 })
      .toBeGreaterThan(CLOSED_LIMIT_AT);
    await expect.poll(() => device!.inputValues().get('%IX0.4'), { timeout: 20_000 }).toBe(false);
  });
});
