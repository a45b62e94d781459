// The three-floor lift (issue 26): its physics as a table of cases, each fault and consequence,
// purity; the exercise's reference and wrong solutions; the worker's trace equal to the CLI's.
import { senseRecord } from '../../src/plant/points';
import { describe, expect, test, vi } from 'vitest';
import { BUFFER_MM, lift, type LiftState } from '../../src/plant/lift';
import { PLANT_EXAMPLES, LIFT_SCENARIO, liftReference, liftWrong } from '../../src/plant/exercises';
import { runScenario } from '../../src/sim/scenario';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { validateProject } from '../../src/model/load';
import { rungsmith } from '../cli/memoryIo';
import { SimHarness } from '../sim/harness';
import type { PlantFrame } from '../../src/sim/sessionPlant';
import { cliTrace, startedPlantDevice, workerTrace } from './traces';

const none = new Set<string>();
type Drive = Record<string, boolean>;
/** `ms` of PLC time in steps of `dt`, driven by `drive`; `check` collects the consequences of every step. */
const run = (
  s: LiftState,
  drive: Drive,
  ms: number,
  faults = none,
  dt = 20,
  seen: string[] = [],
): LiftState => {
  for (let t = 0; t < ms; t += dt) {
    const next = lift.step(s, drive, dt, faults);
    for (const c of lift.check(s, next)) seen.push(`${c.severity} ${c.id}: ${c.message}`);
    s = next;
  }
  return s;
};
const at = (position: number, extra: Partial<LiftState> = {}): LiftState => ({
  ...lift.initial(),
  position,
  stopFloor: Math.round(position / 3000) + 1,
  ...extra,
});
const UP = { MotorUp: true };
const DOWN = { MotorDown: true };

describe('the lift model', () => {
  test.each<[string, LiftState, Drive, number, { position: number; speed: number; door?: number }]>([
    ['up from rest: 0.5 s ramp to 500 mm/s, 125 mm', at(0), UP, 500, { position: 125, speed: 500 }],
    ['up 6.5 s: past floor 2 (3,000 mm) by 125 mm', at(0), UP, 6500, { position: 3125, speed: 500 }],
    [
      'down 6.5 s from floor 3: past floor 2 by 125 mm',
      at(6000),
      DOWN,
      6500,
      { position: 2875, speed: -500 },
    ],
    [
      'braking from full speed: 0.1 s, 25 mm',
      at(1000, { speed: 500 }),
      {},
      200,
      { position: 1025, speed: 0 },
    ],
    [
      'reversing: brakes, then ramps the other way',
      at(1000, { speed: 500 }),
      DOWN,
      200,
      { position: 1020, speed: -100 },
    ],
    [
      'both contactors: the motor trips, the car brakes',
      at(1000, { speed: -500 }),
      { ...UP, ...DOWN },
      200,
      { position: 975, speed: 0 },
    ],
    ['the door opens in 2 s', at(0), { DoorOpen: true }, 1000, { position: 0, speed: 0, door: 0.5 }],
    ['and closes in 2 s', at(0, { door: 1 }), {}, 2000, { position: 0, speed: 0, door: 0 }],
  ])('%s', (_name, from, drive, ms, want) => {
    const s = run(from, drive, ms);
    expect(s.position).toBeCloseTo(want.position, 6);
    expect(s.speed).toBeCloseTo(want.speed, 6);
    if (want.door !== undefined) expect(s.door).toBeCloseTo(want.door, 6);
  });

  test.each<[number, Record<string, boolean | number>]>([
    [0, { AtFloor1: true, AtFloor2: false, AtFloor3: false, Position: 0 }],
    [-20, { AtFloor1: true, Position: -20 }],
    [21, { AtFloor1: false, Position: 21 }],
    [2980, { AtFloor2: true, Position: 2980 }],
    [3020.4, { AtFloor2: false, Position: 3020 }],
    [6000, { AtFloor3: true, AtFloor2: false }],
  ])('the floor sensors are ON within 20 mm of their floor: at %d mm', (position, want) => {
    expect(senseRecord(lift, at(position), none)).toMatchObject(want);
  });

  test('the door limit switches: closed only fully closed, opened only fully open', () => {
    expect(senseRecord(lift, at(0), none)).toMatchObject({ DoorClosed: true, DoorOpened: false });
    expect(senseRecord(lift, at(0, { door: 0.01 }), none)).toMatchObject({ DoorClosed: false, DoorOpened: false });
    expect(senseRecord(lift, at(0, { door: 1 }), none)).toMatchObject({ DoorClosed: false, DoorOpened: true });
  });

  test('a call is answered when the door stands fully open at its floor, with the wait', () => {
    let s = run(at(0), { Call2: true }, 100);
    expect(lift.quantity(s, 'waiting')).toBe(1);
    s = run(s, UP, 6200);
    s = run(s, {}, 300);
    expect(lift.quantity(s, 'floor')).toBe(2);
    expect(s.position).toBeCloseTo(3000, 6);
    // Not while the door is still opening.
    s = run(s, { DoorOpen: true }, 1980);
    expect(s.served).toBe(0);
    expect(lift.quantity(s, 'max_wait')).toBeCloseTo(8.58, 6);
    s = run(s, { DoorOpen: true }, 20);
    expect(s.served).toBe(1);
    expect(lift.quantity(s, 'waiting')).toBe(0);
    expect(lift.quantity(s, 'max_wait')).toBeCloseTo(8.6, 6);
    // A press at the floor while the door stands open there is answered at once; held, it is one call.
    s = run(s, { DoorOpen: true, Call2: true }, 1000);
    expect(s.served).toBe(2);
    // A call at another floor is not answered here.
    s = run(s, { DoorOpen: true, Call1: true }, 100);
    expect(s.served).toBe(2);
    expect(lift.quantity(s, 'waiting')).toBe(1);
  });

  test('running past the top floor: an overrun at 100 mm, then a crash into the buffer', () => {
    const seen: string[] = [];
    const s = run(at(0), UP, 20_000, none, 20, seen);
    expect(seen).toEqual([
      'error overrun: the car ran 100 mm past the top floor (floor 3)',
      'error crash: the car crashed into the buffer above floor 3',
    ]);
    expect(s).toMatchObject({ position: 6000 + BUFFER_MM, speed: 0, overruns: 1, crashes: 1, crashed: true });
    expect(lift.quantity(s, 'crashes')).toBe(1);
  });

  test('running below the bottom floor crashes into the pit buffer', () => {
    const seen: string[] = [];
    const s = run(at(0), DOWN, 3000, none, 20, seen);
    expect(seen).toEqual([
      'error overrun: the car ran 100 mm below the bottom floor (floor 1)',
      'error crash: the car crashed into the buffer in the pit',
    ]);
    expect(s.position).toBe(-BUFFER_MM);
  });

  test('moving with the door not closed, and both contactors on, are errors counted once each time', () => {
    const seen: string[] = [];
    let s = run(at(0), { DoorOpen: true }, 600, none, 20, seen);
    s = run(s, UP, 1000, none, 20, seen);
    expect(seen).toEqual(['error door_move: the car moved with the door 30 % open']);
    expect(s.doorMoves).toBe(1);
    s = run(s, { ...UP, ...DOWN }, 500, none, 20, seen);
    // The motor trips: the car brakes to a stop between floors (a warning of its own).
    expect(seen.slice(1)).toEqual([
      'error both_motors: MotorUp and MotorDown were on together (the motor tripped)',
      'warning misstop: the car stopped 400 mm above floor 1',
    ]);
    expect(lift.quantity(s, 'both_motors')).toBe(1);
  });

  test('a contactor dropped late stops the car off the floor: a warning with how far', () => {
    const seen: string[] = [];
    let s = run(at(0), UP, 6400, none, 20, seen);
    s = run(s, {}, 200, none, 20, seen);
    expect(seen).toEqual(['warning misstop: the car stopped 100 mm above floor 2']);
    expect(lift.quantity(s, 'misstops')).toBe(1);
    expect(lift.quantity(s, 'floor')).toBe(0);
    // Dropped as the sensor comes ON (20 ms scans): level, no warning.
    const level: string[] = [];
    s = at(6000);
    for (let i = 0; i < 2000 && !senseRecord(lift, s, none).AtFloor2; i++) s = run(s, DOWN, 20, none, 20, level);
    s = run(s, {}, 200, none, 20, level);
    expect(level).toEqual([]);
    expect(Math.abs(s.position - 3000)).toBeLessThanOrEqual(20);
  });

  test('faults: floor sensors stuck, a dead motor, a slow door, an obstructed door', () => {
    expect(senseRecord(lift, at(3000), new Set(['floor2_stuck_off'])).AtFloor2).toBe(false);
    expect(senseRecord(lift, at(0), new Set(['floor2_stuck_on'])).AtFloor2).toBe(true);
    expect(senseRecord(lift, at(6000), new Set(['floor3_stuck_off'])).AtFloor3).toBe(false);
    expect(run(at(0), UP, 2000, new Set(['motor_dead'])).position).toBe(0);
    expect(run(at(0), { DoorOpen: true }, 2000, new Set(['door_slow'])).door).toBeCloseTo(1 / 3, 6);
    const obstructed = new Set(['door_obstructed']);
    const stuck = run(at(0, { door: 1 }), {}, 3000, obstructed);
    expect(stuck.door).toBeCloseTo(0.3, 6);
    expect(senseRecord(lift, stuck, obstructed)).toMatchObject({ DoorClosed: false, DoorOpened: false });
    // A closed door has nothing in its way; an obstruction does not stop it opening.
    expect(run(at(0), {}, 1000, obstructed).door).toBe(0);
    expect(run(stuck, { DoorOpen: true }, 2000, obstructed).door).toBe(1);
  });

  test('a step is pure: the same state, drive and time give the same state, the input is not changed', () => {
    const s0 = at(1000, { speed: 300, door: 0, call2: 0 });
    const copy = JSON.stringify(s0);
    const a = lift.step(s0, { MotorUp: true, Call3: true }, 20, none);
    lift.step(at(5000), { MotorDown: true, Call1: true, DoorOpen: true }, 100, none);
    const b = lift.step(s0, { MotorUp: true, Call3: true }, 20, none);
    expect(a).toEqual(b);
    expect(JSON.stringify(s0)).toBe(copy);
    expect(JSON.parse(JSON.stringify(a))).toEqual(a);
  });

  test('every quantity is readable', () => {
    const s = lift.initial();
    for (const q of lift.quantities)
      expect(typeof lift.quantity(s, q.name)).toBe(q.type === 'BOOL' ? 'boolean' : 'number');
    expect(() => lift.quantity(s, 'altitude')).toThrow('lift has no quantity "altitude"');
  });
});

describe('the lift exercise', () => {
  test('the reference solution checks clean and is offered as an example', () => {
    const p = liftReference();
    expect(validateProject(JSON.parse(JSON.stringify(p)))).toMatchObject({ ok: true });
    expect(checkProject(p).map(formatDiagnostic)).toEqual([]);
    expect(checkProject(liftWrong()).map(formatDiagnostic)).toEqual([]);
    expect(PLANT_EXAMPLES.map((e) => e.id)).toContain('lift');
  });

  test('the reference solution answers the six calls level with the floors, without a crash or a door-open move', () => {
    const { result } = runScenario(liftReference(), LIFT_SCENARIO);
    expect(result).toMatchObject({ ok: true, scans: 5000 });
  });

  test('the wrong solution fails where the car leaves floor 2 with its door still open', () => {
    const { result } = runScenario(liftWrong(), LIFT_SCENARIO);
    expect(result.ok).toBe(false);
    expect(result.error).toBe('the car moved with the door 100 % open at scan 528 (10.54 s)');
  });

  test('timing matters: scanned every 100 ms (50 mm a scan at full speed), the reference misses the floor sensors', () => {
    const csv =
      '# plant: lift\n# cycle: 100ms\nscan,lift.Call2,lift.Call3,expect lift.served\n1,1,1,\n3,0,0,\n400,,,0\n';
    expect(runScenario(liftReference(), { name: 'slow scan', csv }).result.error).toBe(
      'the car ran 100 mm past the top floor (floor 3) at scan 125 (12.40 s)',
    );
  });

  test('a fault from the scenario: the top floor sensor stuck OFF runs the reference into the buffer; expecting the count checks it', () => {
    const csv =
      '# plant: lift\n# cycle: 20ms\nscan,lift.Call3,fault floor3_stuck_off,expect lift.overruns,expect lift.crashes\n1,1,1,,\n6,0,,0,0\n1000,,,1,1\n';
    expect(runScenario(liftReference(), { name: 'stuck', csv }).result).toMatchObject({
      ok: true,
      scans: 1000,
    });
    const located =
      '# plant: lift\n# cycle: 20ms\nscan,lift.Call3,fault floor3_stuck_off\n1,1,1\n6,0,\n1000,,\n';
    expect(runScenario(liftReference(), { name: 'stuck', csv: located }).result.error).toMatch(
      /^the car ran 100 mm past the top floor \(floor 3\) at scan \d+ \(\d+\.\d\d s\)$/,
    );
  });
});

const WATCH = [
  'Call3',
  'Call2',
  'AtFloor1',
  'AtFloor2',
  'AtFloor3',
  'DoorClosed',
  'DoorOpened',
  'Position',
  'MotorUp',
  'MotorDown',
  'DoorOpen',
  'Req3',
  'Standstill.Q',
];
const lastOf = <T>(xs: T[]): T => xs[xs.length - 1]!;
const liftState = (h: SimHarness) => (h.frame.plant as PlantFrame).now.state as LiftState;

/** Runs the session to scan `scan` (Step N, as the panel does). */
function stepTo(h: SimHarness, scan: number): void {
  h.send({ type: 'step', scans: scan - h.frame.scan });
  while (h.frame.scan < scan) h.settle();
}

describe('the lift in the simulation session', () => {
  test('the worker trace of 2,000 scans equals the CLI trace scan by scan, machine included', () => {
    const h = new SimHarness().send(
      { type: 'setCycle', cycleMs: 20 },
      { type: 'setPlant', plant: { id: 'lift' } },
      { type: 'load', project: liftReference() },
    );
    // Call 3 held for scans 1..5, call 2 for scans 200..204, as an operator at the panel would.
    h.send({ type: 'plantOperator', name: 'Call3', value: true });
    stepTo(h, 5);
    h.send({ type: 'plantOperator', name: 'Call3', value: false });
    stepTo(h, 199);
    h.send({ type: 'plantOperator', name: 'Call2', value: true });
    stepTo(h, 204);
    h.send({ type: 'plantOperator', name: 'Call2', value: false });
    stepTo(h, 2000);
    expect(h.frame.scan).toBe(2000);
    const worker = workerTrace(h, WATCH);
    const cli = cliTrace({
      project: liftReference(),
      plant: 'lift',
      stimulus: 'scan,lift.Call3,lift.Call2\n1,1,\n6,0,\n200,,1\n205,,0\n',
      scans: 2000,
      cycle: '20ms',
      watch: [...WATCH, 'lift.position'],
    });
    expect(cli.code).toBe(0);
    expect(cli.err).toBe('');
    const rows = cli.out.trim().split('\n');
    expect(rows).toHaveLength(2001);
    expect(rows.map((r) => r.split(',').slice(0, -1).join(','))).toEqual(worker);
    for (const scan of [1, 2, 300, 528, 1234, 2000]) {
      h.send({ type: 'historySeek', scan });
      const view = lastOf(h.of('historyView')).view;
      expect(view.plant?.scan).toBe(scan);
      expect(String((view.plant!.state as LiftState).position)).toBe(rows[scan]!.split(',').at(-1));
    }
    // Both calls answered: the car went to floor 2, then floor 3, and stands there.
    expect(liftState(h)).toMatchObject({ served: 2, speed: 0 });
    expect(Math.abs(liftState(h).position - 6000)).toBeLessThanOrEqual(20);
  });

  test('a fault set at the panel acts from the next step: a dead motor keeps the car at floor 1', () => {
    const h = new SimHarness().send(
      { type: 'setCycle', cycleMs: 20 },
      { type: 'setPlant', plant: { id: 'lift' } },
      { type: 'load', project: liftReference() },
      { type: 'plantFault', id: 'motor_dead', active: true },
      { type: 'plantOperator', name: 'Call2', value: true },
    );
    stepTo(h, 100);
    expect(h.frame.plant!.now.faults).toEqual(['motor_dead']);
    expect(h.value('MotorUp')).toBe(true);
    expect(liftState(h).position).toBe(0);
    h.send({ type: 'plantFault', id: 'motor_dead', active: false });
    stepTo(h, 200);
    expect(liftState(h).position).toBeGreaterThan(100);
  });
});

describe('rungsmith and the lift', () => {
  test('plants lift lists its I/O map, faults, quantities and task', () => {
    const r = rungsmith(['plants', 'lift']);
    expect(r.code).toBe(0);
    expect(r.out).toMatch(/^lift: Three-floor lift\n/);
    expect(r.out).toMatch(/%IX0\.0 +Call1 +BOOL +operator \(button\) +Call button, floor 1 landing \(NO\)/);
    expect(r.out).toMatch(
      /%IX0\.5 +AtFloor3 +BOOL +sensor +Floor 3 level sensor, ON within 20 mm of the floor/,
    );
    expect(r.out).toMatch(/%QX0\.1 +MotorDown +BOOL +actuator +Hoist motor contactor, down/);
    expect(r.out).toMatch(/floor3_stuck_off +Floor 3 \(top\) sensor stuck OFF/);
    expect(r.out).toMatch(/lift\.served +INT +Calls answered/);
    expect(r.out).toContain('Answer the calls of a three-floor lift');
    expect(rungsmith(['plants']).out).toContain('lift: Three-floor lift');
  });
});

describe("the lift as the gateway's simulated device (npm start -- --plant lift)", () => {
  test("its default I/O map fits the device: the sensors are its inputs, a master's coil runs the motor", async () => {
    const device = await startedPlantDevice('lift');
    try {
      const inputs = device.inputValues();
      expect([inputs.get('%IX0.3'), inputs.get('%IX0.4'), inputs.get('%IX0.6'), inputs.get('%IW0')]).toEqual([
        true,
        false,
        true,
        0,
      ]);
      device.drive(new Map([['%QX0.0', true]]));
      await vi.waitFor(() => expect(device.plantRead('lift.position')).toBeGreaterThan(20), {
        timeout: 20_000,
      });
      await vi.waitFor(() => expect(device.inputValues().get('%IX0.3')).toBe(false), { timeout: 20_000 });
    } finally {
      await device.close();
    }
  });
});
