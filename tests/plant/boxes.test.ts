// The box sorter (issue 26): the belt, the feeder, the eyes and the pusher as a table of cases,
// each fault, each consequence located, purity; the exercise (reference passes, wrong fails
// where it goes wrong, in-process and through `rungsmith test`); and the worker's trace of 2,000
// scans equal to the CLI's, machine included.
import { senseRecord } from '../../src/plant/points';
import { afterEach, describe, expect, test } from 'vitest';
import type { SimulatedDevice } from '../../src/gateway/simulatedDevice';
import {
  BELT_SPEED_MM_S,
  BOX_SPACING_MM,
  boxes,
  frontOf,
  PUSHER_MM,
  SIZE_PATTERN,
  type BoxesState,
} from '../../src/plant/boxes';
import { BOXES_SCENARIO, boxesReference, boxesWrong } from '../../src/plant/boxesExercise';
import { PLANT_EXAMPLES } from '../../src/plant/exercises';
import { plantById } from '../../src/plant/machines';
import { runScenario } from '../../src/sim/scenario';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { validateProject } from '../../src/model/load';
import type { Value } from '../../src/model/iecTypes';
import type { PlantFrame } from '../../src/sim/sessionPlant';
import { rungsmith } from '../cli/memoryIo';
import { SimHarness } from '../sim/harness';
import { cliTrace, startedPlantDevice, workerTrace } from './traces';
import { csvValue } from '../../src/engine/values/literals';

const none: ReadonlySet<string> = new Set();
type Sensed = Record<string, Value>;
/** A controller as a function of the sensors and its own memory: the Pusher output for the step. */
type Logic = (sensed: Sensed, m: Record<string, boolean>) => boolean;

/** Runs the machine in closed loop with `logic` for `scans` steps of 100 ms, the belt on all along. */
function closedLoop(logic: Logic, scans: number, faults: ReadonlySet<string> = none) {
  let s = boxes.initial();
  const m: Record<string, boolean> = {};
  const events: string[] = [];
  for (let k = 1; k <= scans; k++) {
    const push = logic(senseRecord(boxes, s, faults), m);
    const before = s;
    s = boxes.step(s, { Conveyor: true, Pusher: push, RunLamp: true }, 100, faults);
    for (const c of boxes.check(before, s)) events.push(`${c.id} ${k}: ${c.message}`);
  }
  return { s, events };
}

/** The reference solution's logic, in TypeScript: remember a large box, push it at the pusher until the out limit. */
const sorting: Logic = (x, m) => {
  if (x.SizeEye) m.large = true;
  if (x.PusherEye && m.large) m.pushing = true;
  if (x.PusherOut) m.pushing = m.large = false;
  return m.pushing === true;
};

describe('the box sorter model', () => {
  test('the belt ramps up in 0.5 s to 400 mm/s; the feeder puts a box on every 1.8 m of travel, sizes from the pattern', () => {
    let s = boxes.initial();
    s = boxes.step(s, { Conveyor: true }, 100, none);
    expect(s.speed).toBeCloseTo(0.2, 9);
    expect(s.fed).toBe(1);
    for (let i = 0; i < 4; i++) s = boxes.step(s, { Conveyor: true }, 100, none);
    expect(s.speed).toBe(1);
    // 10 s more at full speed: 4,000 mm of travel, two more boxes (every 1,800 mm).
    for (let i = 0; i < 100; i++) s = boxes.step(s, { Conveyor: true }, 100, none);
    expect(s.fed).toBe(3);
    // Box 1 has ridden off into the bin (it is small), 2 and 3 are on the belt, 1.8 m apart.
    expect(s.smallBin).toBe(1);
    expect(s.boxes.map((b) => [b.n, b.large])).toEqual([
      [2, SIZE_PATTERN[1] === 'L'],
      [3, SIZE_PATTERN[2] === 'L'],
    ]);
    expect(s.boxes[0]!.base - s.boxes[1]!.base).toBeCloseTo(BOX_SPACING_MM, 6);
    // Stopped: the belt coasts down and nothing moves after.
    for (let i = 0; i < 10; i++) s = boxes.step(s, { Conveyor: false }, 100, none);
    const still = boxes.step(s, {}, 100, none);
    expect(still.boxes).toEqual(s.boxes);
    expect(BELT_SPEED_MM_S).toBe(400);
  });

  test.each([
    // [what, box front at (mm), large, which eyes are ON]
    ['a small box at the entry eye', 500, false, { EntryEye: true, SizeEye: false, PusherEye: false }],
    ['a small box under the size eye', 900, false, { EntryEye: false, SizeEye: false, PusherEye: false }],
    ['a large box under the size eye', 900, true, { EntryEye: false, SizeEye: true, PusherEye: false }],
    [
      'a box whose centre is 50 mm before the pusher',
      2100,
      false,
      { EntryEye: false, SizeEye: false, PusherEye: true },
    ],
    ['a box 60 mm before that', 2040, true, { EntryEye: false, SizeEye: false, PusherEye: false }],
  ])('the eyes: %s', (_what, x, large, eyes) => {
    const s: BoxesState = {
      ...boxes.initial(),
      boxes: [{ n: 1, large, base: x, side: 0, blocked: false, jammed: false, pushed: false }],
    };
    expect(senseRecord(boxes, s, none)).toEqual({ ...eyes, PusherOut: false, PusherIn: true });
  });

  const pushEvery: Logic = (x, m) => {
    if (x.PusherEye) m.pushing = true;
    if (x.PusherOut) m.pushing = false;
    return m.pushing === true;
  };
  const pushOnSize: Logic = (x) => x.SizeEye === true;
  const tooShort: Logic = (x, m) => {
    if (x.SizeEye) m.large = true;
    if (x.PusherEye && m.large) {
      m.large = false;
      m.t1 = true;
      return true;
    }
    // Two steps of 100 ms only, whatever the out limit says.
    const out = m.t1 === true || m.t2 === true;
    m.t2 = m.t1 === true;
    m.t1 = false;
    return out;
  };
  const early: Logic = (x, m) => {
    // Pushes as soon as a large box leaves the size eye: the plate is out when the box arrives.
    if (x.SizeEye) m.large = true;
    else if (m.large) m.pushing = true;
    if (x.PusherOut) m.large = false;
    return m.pushing === true;
  };
  test.each([
    ['the reference logic sorts every box', sorting, none, 12, []],
    [
      'pushing every box puts small ones in the chute',
      pushEvery,
      none,
      6,
      ['missorted 61: box 1 (small) was pushed into the large-box chute'],
    ],
    [
      'pushing on the size sensor leaves the large box on the belt',
      pushOnSize,
      none,
      6,
      ['missorted 122: box 2 (large) ran into the small-box bin'],
    ],
    [
      'a pusher let go halfway drops the box',
      tooShort,
      none,
      6,
      ['fallen 104: box 2 (large) fell off the belt (pushed 45 % across, then let go)'],
    ],
    [
      "a plate already out in the box's way",
      early,
      none,
      1,
      ['jam 94: box 2 (large) jammed against the extended pusher'],
    ],
    [
      'the size sensor stuck OFF: large boxes ride on',
      sorting,
      new Set(['size_stuck_off']),
      6,
      ['missorted 122: box 2 (large) ran into the small-box bin'],
    ],
    [
      'the size sensor stuck ON: every box pushed',
      sorting,
      new Set(['size_stuck_on']),
      6,
      ['missorted 61: box 1 (small) was pushed into the large-box chute'],
    ],
    [
      'the eye at the pusher stuck OFF: nothing pushed',
      sorting,
      new Set(['station_stuck_off']),
      6,
      ['missorted 122: box 2 (large) ran into the small-box bin'],
    ],
    [
      'a slow pusher (3 s) is still out when the next large box comes',
      sorting,
      new Set(['pusher_slow']),
      5,
      ['jam 139: box 3 (large) jammed against the extended pusher'],
    ],
    ['the belt motor does not start: no box comes', sorting, new Set(['motor_dead']), 0, []],
  ] as const)('in closed loop for 60 s: %s', (_what, logic, faults, sorted, first) => {
    const { s, events } = closedLoop(logic, 600, faults);
    expect(s.sorted).toBe(sorted);
    expect(events.slice(0, 1)).toEqual(first);
  });

  test('the consequences count once each and name their counter; a jam is shown while it lasts', () => {
    const { s } = closedLoop(pushEvery, 600);
    expect(s.missorted).toBe(6);
    expect(s.largeChute).toBe(12);
    const jam = closedLoop((x, m) => {
      if (x.SizeEye) m.large = true;
      else if (m.large) m.pushing = true;
      return m.pushing === true;
    }, 200);
    expect(jam.s.jams).toBe(1);
    expect(boxes.quantity(jam.s, 'jammed')).toBe(true);
    // Boxes queue behind the jammed one, and the feeder goes on feeding while there is room.
    expect(jam.s.boxes.map((b) => [b.n, Math.round(frontOf(jam.s, b)), b.blocked, b.jammed])).toEqual([
      [2, 1850, true, true],
      [3, 1550, true, false],
      [4, 1250, true, false],
      [5, 700, false, false],
    ]);
    expect(boxes.check(boxes.initial(), jam.s).map((c) => [c.id, c.severity, c.counter])).toEqual([
      ['jam', 'error', 'jams'],
    ]);
  });

  test.each([
    // [what, the box's centre from the pusher's centre line (mm), what happens]
    ['a box square in front of the pusher goes into the chute', 0, { largeChute: 1, jams: 0 }],
    ['a box 100 mm off is still pushed square', -100, { largeChute: 1, jams: 0 }],
    [
      'a box 150 mm past is struck off the station: a jam, the plate stops against it',
      150,
      { largeChute: 0, jams: 1 },
    ],
  ])('the plate across the belt: %s', (_what, offset, outcome) => {
    let s: BoxesState = {
      ...boxes.initial(),
      boxes: [
        {
          n: 7,
          large: true,
          base: PUSHER_MM + offset + 150,
          side: 0,
          blocked: false,
          jammed: false,
          pushed: false,
        },
      ],
    };
    const messages: string[] = [];
    for (let i = 0; i < 8; i++) {
      const before = s;
      s = boxes.step(s, { Pusher: true }, 100, none);
      messages.push(...boxes.check(before, s).map((c) => c.message));
    }
    expect({ largeChute: s.largeChute, jams: s.jams }).toEqual(outcome);
    if (outcome.jams) {
      expect(messages).toEqual(['the pusher struck box 7 (large) off the station']);
      expect(s.pusher).toBeLessThan(0.1);
      expect(senseRecord(boxes, s, none).PusherOut).toBe(false);
      // Back in, the plate lets go of the box: it rides on.
      for (let i = 0; i < 3; i++) s = boxes.step(s, { Conveyor: true }, 100, none);
      expect(s.boxes[0]).toMatchObject({ jammed: false, blocked: false });
    } else expect(s.sorted).toBe(1);
  });

  test('the slow pusher fault: 0.6 s of stroke reaches 20 %, the limits follow the stroke', () => {
    let s = boxes.initial();
    for (let i = 0; i < 6; i++) s = boxes.step(s, { Pusher: true }, 100, new Set(['pusher_slow']));
    expect(s.pusher).toBeCloseTo(0.2, 9);
    expect(senseRecord(boxes, s, none)).toMatchObject({ PusherIn: false, PusherOut: false });
    for (let i = 0; i < 6; i++) s = boxes.step(s, { Pusher: true }, 100, none);
    expect(senseRecord(boxes, s, none)).toMatchObject({ PusherIn: false, PusherOut: true });
    expect(senseRecord(boxes, boxes.initial(), new Set(['entry_stuck_on'])).EntryEye).toBe(true);
  });

  test('a step is pure: the same state, drive and time give the same state, the input is not changed', () => {
    const { s } = closedLoop(sorting, 95);
    const copy = JSON.stringify(s);
    const a = boxes.step(s, { Conveyor: true, Pusher: true }, 100, none);
    const b = boxes.step(s, { Conveyor: true, Pusher: true }, 100, none);
    expect(a).toEqual(b);
    expect(JSON.stringify(s)).toBe(copy);
    expect(plantById('BOXES')).toBe(boxes);
  });
});

describe('the box sorter exercise', () => {
  test('the reference solution checks clean and is offered as an example', () => {
    const p = boxesReference();
    expect(validateProject(JSON.parse(JSON.stringify(p)))).toMatchObject({ ok: true });
    expect(checkProject(p).map(formatDiagnostic)).toEqual([]);
    expect(PLANT_EXAMPLES.find((e) => e.id === 'box-sorter')?.build().plant).toEqual({ id: 'boxes' });
  });

  test('the reference solution sorts 10 boxes; the wrong one fails where the first large box rides on', () => {
    expect(runScenario(boxesReference(), BOXES_SCENARIO).result).toMatchObject({ ok: true, scans: 570 });
    const wrong = runScenario(boxesWrong(), BOXES_SCENARIO).result;
    expect(wrong).toMatchObject({ ok: false, scans: 122 });
    expect(wrong.error).toBe('box 2 (large) ran into the small-box bin at scan 122 (12.10 s)');
  });

  test.each([1, 10, 50, 100, 200, 250])(
    'the reference solution sorts 10 boxes with no jam at a %i ms scan (the eye at the pusher leaves time for a slow scan)',
    (cycle) => {
      // The 10th box is sorted at 48.0 to 48.2 s whatever the scan; a jam, a box fallen or missorted fails where it happens.
      const end = Math.round(48_400 / cycle) + 1;
      const csv = `# plant: boxes\n# cycle: ${cycle}ms\nscan,boxes.Start,expect boxes.sorted,expect boxes.jams\n1,1,,\n${Math.round(200 / cycle) + 1},0,,0\n${end},,10,0\n`;
      expect(runScenario(boxesReference(), { name: `at ${cycle} ms`, csv }).result).toMatchObject({ ok: true, scans: end });
    },
  );

  test('a fault from the scenario: the slow pusher jams the reference; expecting the count checks it', () => {
    const csv =
      '# plant: boxes\n# cycle: 100ms\nscan,boxes.Start,fault pusher_slow,expect boxes.jams\n1,1,1,\n3,0,,0\n150,,,1\n';
    expect(runScenario(boxesReference(), { name: 'slow', csv }).result).toMatchObject({
      ok: true,
      scans: 150,
    });
    const unexpected =
      '# plant: boxes\n# cycle: 100ms\nscan,boxes.Start,fault pusher_slow\n1,1,1\n3,0,\n200,,\n';
    expect(runScenario(boxesReference(), { name: 'slow', csv: unexpected }).result.error).toMatch(
      /^box 3 \(large\) jammed against the extended pusher at scan 1\d\d \(\d+\.\d\d s\)$/,
    );
  });

  test('rungsmith plants boxes lists the sorter with its I/O map, faults and quantities', () => {
    const r = rungsmith(['plants', 'boxes']);
    expect(r.code).toBe(0);
    expect(r.out).toMatch(/^boxes: Box sorter/);
    expect(r.out).toContain('Sort the boxes by size');
    expect(r.out).toMatch(/%IX0\.3 +SizeEye +BOOL +sensor +Size sensor, high photo-eye/);
    expect(r.out).toMatch(/%QX0\.1 +Pusher +BOOL +actuator +Pusher cylinder solenoid valve/);
    expect(r.out).toMatch(/pusher_slow +Pusher slow/);
    expect(r.out).toMatch(/boxes\.sorted +INT/);
  });
});

const WATCH = [
  'Start',
  'Running',
  'EntryEye',
  'SizeEye',
  'PusherEye',
  'PusherOut',
  'PusherIn',
  'Conveyor',
  'Pusher',
  'Large',
  'Pushing',
];
const lastOf = <T>(xs: T[]): T => xs[xs.length - 1]!;

describe('the box sorter in the simulation session', () => {
  test('the worker trace of 2,000 scans equals the CLI trace scan by scan, machine included', () => {
    const h = new SimHarness().send(
      { type: 'setCycle', cycleMs: 100 },
      { type: 'setPlant', plant: { id: 'boxes' } },
      { type: 'load', project: boxesReference() },
    );
    h.send({ type: 'plantOperator', name: 'Start', value: true }, { type: 'step', scans: 2 }).settle();
    h.send({ type: 'plantOperator', name: 'Start', value: false }, { type: 'step', scans: 1998 });
    while (h.frame.scan < 2000) h.settle();
    const worker = workerTrace(h, WATCH);
    const cli = cliTrace({
      project: boxesReference(),
      plant: 'boxes',
      stimulus: 'scan,boxes.Start\n1,1\n3,0\n',
      scans: 2000,
      cycle: '100ms',
      watch: [...WATCH, 'boxes.sorted', 'boxes.pusher'],
    });
    expect(cli.code).toBe(0);
    expect(cli.err).toBe('');
    const rows = cli.out.trim().split('\n');
    expect(rows).toHaveLength(2001);
    expect(rows.map((r) => r.split(',').slice(0, -2).join(','))).toEqual(worker);
    // The machine itself, as the history shows it after some scans.
    for (const scan of [1, 2, 3, 106, 482, 1234, 2000]) {
      h.send({ type: 'historySeek', scan });
      const state = lastOf(h.of('historyView')).view.plant!.state as BoxesState;
      const [sorted, pusher] = rows[scan]!.split(',').slice(-2);
      expect(String(state.sorted)).toBe(sorted);
      expect(csvValue('REAL', state.pusher * 100)).toBe(pusher);
    }
    // 2,000 scans of 100 ms: the feeder's 44 boxes, all sorted or on the belt, the pusher out for every large one.
    const end = (h.frame.plant as PlantFrame).now.state as BoxesState;
    expect(end.missorted + end.jams + end.fallen).toBe(0);
    expect(end.sorted + end.boxes.length).toBe(end.fed);
    expect(end.sorted).toBeGreaterThanOrEqual(40);
    const pushes = worker
      .slice(1)
      .filter((r, i, all) => i > 0 && r.split(',')[10] === '1' && all[i - 1]!.split(',')[10] === '0');
    expect(pushes.length).toBe(end.largeChute);
  });
});

describe("the box sorter as the gateway's simulated device (npm start -- --plant boxes)", () => {
  let device: SimulatedDevice | undefined;
  afterEach(async () => {
    await device?.close();
    device = undefined;
  });

  test('every point fits the device: the eyes and limits are its inputs, the motor and pusher its coils, boxes ride in real time', async () => {
    device = await startedPlantDevice('boxes');
    const inputs = device.inputValues();
    const coils = device.writtenValues();
    for (const p of boxes.points)
      expect(p.kind === 'actuator' ? coils.has(p.address) : inputs.has(p.address)).toBe(true);
    // At rest: the pusher in (%IX0.6), no box at the entry eye (%IX0.2).
    expect([inputs.get('%IX0.6'), inputs.get('%IX0.2')]).toEqual([true, false]);
    // A master switches the belt motor on: the first box rides into the entry eye.
    device.drive(new Map([['%QX0.0', true]]));
    await expect.poll(() => device!.plantRead('boxes.fed'), { timeout: 20_000 }).toBe(1);
    await expect.poll(() => device!.inputValues().get('%IX0.2'), { timeout: 20_000 }).toBe(true);
  });
});
