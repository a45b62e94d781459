// The road intersection (issue 26): the model's traffic and pedestrians, its conflict monitor,
// faults and consequences; the exercise's scenario; and the machine in closed loop, the worker's
// trace equal to the CLI's scan by scan, and `rungsmith test` on the reference and the wrong one.
import { senseRecord } from '../../src/plant/points';
import { describe, expect, test } from 'vitest';
import {
  HEADWAY_MS,
  intersection,
  MAIN_ARRIVALS_MS,
  SIDE_ARRIVALS_MS,
  arrivalTime,
  arrivalsUpTo,
  type IntersectionState,
} from '../../src/plant/intersection';
import {
  INTERSECTION_SCENARIO,
  intersectionReference,
  intersectionWrong,
} from '../../src/plant/intersectionExercise';
import { PLANT_EXAMPLES } from '../../src/plant/exercises';
import type { PlantConsequence } from '../../src/plant/types';
import { runScenario } from '../../src/sim/scenario';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { validateProject } from '../../src/model/load';
import type { PlantFrame } from '../../src/sim/sessionPlant';
import { rungsmith } from '../cli/memoryIo';
import { SimHarness } from '../sim/harness';
import { cliTrace, startedPlantDevice, workerTrace } from './traces';

const none = new Set<string>();
type Drive = Record<string, boolean>;
/** Main road green: side red, both crossings DON'T WALK. */
const MAIN_GO: Drive = { MainGreen: true, SideRed: true, DontWalkMain: true, DontWalkSide: true };
/** Side road green: main red, both crossings DON'T WALK. */
const SIDE_GO: Drive = { MainRed: true, SideGreen: true, DontWalkMain: true, DontWalkSide: true };
const ALL_RED: Drive = { MainRed: true, SideRed: true, DontWalkMain: true, DontWalkSide: true };

/** Runs `ms` of PLC time in `dt` steps, collecting the consequences as the loop would see them. */
function run(
  s: IntersectionState,
  drive: Drive,
  ms: number,
  faults: ReadonlySet<string> = none,
  dt = 100,
): { s: IntersectionState; events: PlantConsequence[] } {
  const events: PlantConsequence[] = [];
  for (let t = 0; t < ms; t += dt) {
    const next = intersection.step(s, drive, dt, faults);
    events.push(...intersection.check(s, next));
    s = next;
  }
  return { s, events };
}
const q = (s: IntersectionState, name: string) => intersection.quantity(s, name);
const messages = (events: PlantConsequence[]) => events.map((e) => e.message);

describe('the intersection model', () => {
  test('the schedule: arrivals repeat every minute, counted up to a time and timed by number', () => {
    expect(arrivalsUpTo(MAIN_ARRIVALS_MS, 0)).toBe(0);
    expect(arrivalsUpTo(MAIN_ARRIVALS_MS, 1500)).toBe(1);
    expect(arrivalsUpTo(MAIN_ARRIVALS_MS, 60_000)).toBe(12);
    expect(arrivalsUpTo(SIDE_ARRIVALS_MS, 125_000)).toBe(13);
    expect(arrivalTime(SIDE_ARRIVALS_MS, 6)).toBe(64_000);
    for (let i = 0; i < 30; i++)
      expect(arrivalsUpTo(SIDE_ARRIVALS_MS, arrivalTime(SIDE_ARRIVALS_MS, i))).toBe(i + 1);
  });

  test.each([
    {
      what: 'main road green for 60 s: every main road car goes through as it comes, the side road queues',
      phases: [[MAIN_GO, 60_000]] as const,
      expected: { served_main: 12, waiting_main: 0, served_side: 0, waiting_side: 6, max_wait: 56 },
      sensed: { LoopMain: false, LoopSide: true },
    },
    {
      what: 'then side road green for 10 s: the queue leaves one car every 2 s, the first after 1 s; more come',
      phases: [
        [MAIN_GO, 60_000],
        [SIDE_GO, 10_000],
      ] as const,
      expected: { served_main: 12, waiting_main: 2, served_side: 5, waiting_side: 4, max_wait: 57 },
      sensed: { LoopMain: true, LoopSide: true },
    },
    {
      what: 'all red for 20 s: nobody goes, both loops see the queues',
      phases: [[ALL_RED, 20_000]] as const,
      expected: { served: 0, waiting_main: 4, waiting_side: 3, max_wait: 18.5 },
      sensed: { LoopMain: true, LoopSide: true },
    },
  ])('$what', ({ phases, expected, sensed }) => {
    let s = intersection.initial();
    const events: PlantConsequence[] = [];
    for (const [drive, ms] of phases) {
      const r = run(s, drive, ms);
      s = r.s;
      events.push(...r.events);
    }
    for (const [name, value] of Object.entries(expected)) expect([name, q(s, name)]).toEqual([name, value]);
    expect(senseRecord(intersection, s, none)).toEqual(sensed);
    // The phases jump from one green to the other: only the clearance monitor speaks (tested below).
    expect(events.filter((e) => e.counter !== 'short_yellows' && e.counter !== 'short_reds')).toEqual([]);
  });

  test('a car waits its headway behind the one in front: five leave in 10 s of green', () => {
    const queued = run(intersection.initial(), ALL_RED, 30_000).s;
    expect(q(queued, 'waiting_main')).toBe(7);
    const green = run(queued, { ...MAIN_GO, SideRed: true }, 10_000).s;
    expect(q(green, 'served_main')).toBe(10_000 / HEADWAY_MS);
    expect(green.lastMainMs).toBe(39_000);
  });

  test('a pedestrian presses, waits for WALK, and crosses; WALK lit when nobody waits serves no one', () => {
    let { s } = run(intersection.initial(), { ...MAIN_GO, CrossMain: true }, 200);
    expect(q(s, 'peds_waiting')).toBe(1);
    // Holding the button is one pedestrian; a second press is another.
    s = run(s, { ...MAIN_GO }, 100).s;
    s = run(s, { ...MAIN_GO, CrossMain: true }, 100).s;
    expect(q(s, 'peds_waiting')).toBe(2);
    // Through the yellow and the all-red, then WALK with the side road green.
    s = run(s, { ...MAIN_GO, MainGreen: false, MainYellow: true }, 3000).s;
    s = run(s, ALL_RED, 2000).s;
    const walk = run(s, { ...SIDE_GO, DontWalkMain: false, WalkMain: true }, 4000);
    expect(q(walk.s, 'ped_served')).toBe(2);
    expect(q(walk.s, 'peds_waiting')).toBe(0);
    expect(walk.s.pedOnMain).toBe(8000 - 3900);
    expect(walk.events).toEqual([]);
  });

  test('dark: a step with no lamp driven leaves all four heads dark, counted once', () => {
    const r = run(intersection.initial(), {}, 500);
    expect(messages(r.events)).toEqual([
      'the main road signal went dark',
      'the side road signal went dark',
      'the pedestrian signal over the main road went dark',
      'the pedestrian signal over the side road went dark',
    ]);
    expect(r.events.every((e) => e.severity === 'error' && e.counter === 'dark_signals')).toBe(true);
    expect(q(r.s, 'dark_signals')).toBe(4);
    // Lit again, then dark again: counted again.
    const again = run(run(r.s, MAIN_GO, 100).s, { ...MAIN_GO, SideRed: false }, 100);
    expect(messages(again.events)).toEqual(['the side road signal went dark']);
    expect(q(again.s, 'dark_signals')).toBe(5);
  });

  test('conflicts: both roads going, WALK over a road with its traffic going; named by the lamps, counted where they start', () => {
    const r = run(
      intersection.initial(),
      { MainGreen: true, SideYellow: true, WalkMain: true, WalkSide: true },
      300,
    );
    expect(messages(r.events)).toEqual([
      'conflicting signals: main road green with side road yellow',
      'conflicting signals: WALK over the main road with main road green',
      'conflicting signals: WALK over the side road with side road yellow',
    ]);
    expect(r.events.every((e) => e.severity === 'error' && e.counter === 'conflicts')).toBe(true);
    expect(q(r.s, 'conflicts')).toBe(3);
    const yellow = run(intersection.initial(), { ...MAIN_GO, SideRed: false, MainYellow: true, SideGreen: true }, 100);
    expect(messages(yellow.events)).toEqual([
      'conflicting signals: main road green and yellow with side road green',
    ]);
  });

  test('a signal showing two things at once: red with green on one head, WALK with DON\'T WALK; red with yellow is a legal phase', () => {
    const r = run(intersection.initial(), { ...MAIN_GO, MainRed: true, WalkSide: true }, 300);
    expect(messages(r.events)).toEqual([
      'conflicting signals: the main road signal shows red and green together',
      "conflicting signals: WALK and DON'T WALK together over the side road",
    ]);
    expect(r.events.every((e) => e.severity === 'error' && e.counter === 'conflicts')).toBe(true);
    expect(q(r.s, 'conflicts')).toBe(2);
    const side = run(intersection.initial(), { ...SIDE_GO, SideRed: true, WalkMain: true }, 100);
    expect(messages(side.events)).toEqual([
      'conflicting signals: the side road signal shows red and green together',
      "conflicting signals: WALK and DON'T WALK together over the main road",
    ]);
    // Red and yellow together (before green, as in some countries) is no conflict.
    expect(run(intersection.initial(), { ...ALL_RED, MainYellow: true }, 300).events).toEqual([]);
  });

  test.each([
    { yellow: 3000, red: 2000, step: 100, events: [] },
    { yellow: 3000, red: 2000, step: 1, events: [] },
    { yellow: 3000, red: 2100, step: 30, events: [] },
    {
      yellow: 2900,
      red: 2000,
      step: 100,
      events: ['the main road went from green to red after 2.9 s of yellow (at least 3 s of yellow asked)'],
    },
    {
      yellow: 3000,
      red: 1900,
      step: 100,
      events: ['the side road got green 1.9 s after the main road turned red (both roads red at least 2 s asked)'],
    },
  ])(
    'the clearance monitor: $yellow ms of yellow, $red ms of all red ($step ms steps) before the side road green',
    ({ yellow, red, step, events }) => {
      const yellowDrive: Drive = { MainYellow: true, SideRed: true, DontWalkMain: true, DontWalkSide: true };
      const seen: PlantConsequence[] = [];
      let s = intersection.initial();
      for (const [drive, ms] of [
        [MAIN_GO, 30_000],
        [yellowDrive, yellow],
        [ALL_RED, red],
        [SIDE_GO, 1000],
      ] as const) {
        for (let t = 0; t < ms; t += step) {
          const next = intersection.step(s, drive, step, none);
          seen.push(...intersection.check(s, next));
          s = next;
        }
      }
      expect(messages(seen)).toEqual(events);
      expect(Number(q(s, 'short_yellows')) + Number(q(s, 'short_reds'))).toBe(events.length);
    },
  );

  test('near miss: green to the other road while a car is still in the intersection (no yellow, no all-red)', () => {
    const mainGoing = run(intersection.initial(), MAIN_GO, 2000).s;
    expect(q(mainGoing, 'served_main')).toBe(1);
    const r = run(mainGoing, SIDE_GO, 100);
    expect(messages(r.events)).toEqual([
      'the side road got green while a car from the main road was still in the intersection',
      'the main road went from green to red without yellow (at least 3 s of yellow asked)',
      'the side road got green 0.0 s after the main road turned red (both roads red at least 2 s asked)',
    ]);
    expect(q(r.s, 'near_misses')).toBe(1);
    // After the all-red the car is through: no near miss.
    const safe = run(run(mainGoing, ALL_RED, 2000).s, SIDE_GO, 100);
    expect(safe.events).toEqual([]);
  });

  test('pedestrians caught: their road gets green before they reach the far side', () => {
    const walking = run(
      intersection.initial(),
      { ...ALL_RED, DontWalkMain: false, WalkMain: true, CrossMain: true },
      500,
    ).s;
    expect(q(walking, 'ped_served')).toBe(1);
    const r = run(run(walking, ALL_RED, 3000).s, MAIN_GO, 100);
    expect(messages(r.events)).toEqual(['the main road got green while pedestrians were still crossing it']);
    expect(q(r.s, 'peds_caught')).toBe(1);
    // 8 s after they started they are across.
    expect(run(run(walking, ALL_RED, 8000).s, MAIN_GO, 100).events).toEqual([]);
  });

  test('long waits: a side road car that never gets green, a pedestrian who never gets WALK', () => {
    const r = run(intersection.initial(), { ...MAIN_GO, CrossSide: true }, 130_000);
    expect(r.events.map((e) => [e.id, e.message])).toEqual([
      ['long_ped_wait', 'a pedestrian waited more than 60 s to cross the side road'],
      ['long_wait', 'a vehicle waited more than 120 s on the side road'],
      ['long_wait', 'a vehicle waited more than 120 s on the side road'],
      ['long_wait', 'a vehicle waited more than 120 s on the side road'],
    ]);
    // The cars that arrived at 4 s, 6.5 s and 9 s; the pedestrian is counted once.
    expect(q(r.s, 'long_waits')).toBe(3);
    expect(q(r.s, 'long_ped_waits')).toBe(1);
    expect(q(r.s, 'max_wait')).toBe(126);
  });

  test('faults: a burnt-out green darkens its head and stops its traffic; detector loops stuck', () => {
    const burnt = run(intersection.initial(), MAIN_GO, 10_000, new Set(['main_green_out']));
    expect(messages(burnt.events)).toEqual(['the main road signal went dark']);
    expect(q(burnt.s, 'served_main')).toBe(0);
    expect(q(burnt.s, 'waiting_main')).toBe(2);
    expect(burnt.s.lamps & 4).toBe(4);
    expect(burnt.s.lit & 4).toBe(0);
    const queued = burnt.s;
    expect(senseRecord(intersection, queued, none)).toEqual({ LoopMain: true, LoopSide: true });
    expect(senseRecord(intersection, queued, new Set(['side_loop_stuck_off'])).LoopSide).toBe(false);
    expect(senseRecord(intersection, queued, new Set(['main_loop_stuck_off'])).LoopMain).toBe(false);
    expect(senseRecord(intersection, intersection.initial(), new Set(['side_loop_stuck_on'])).LoopSide).toBe(true);
    expect(senseRecord(intersection, intersection.initial(), none)).toEqual({ LoopMain: false, LoopSide: false });
  });

  test('"Why?" on a detector loop: the vehicles waiting at its stop line, or the fault that holds it', () => {
    const queued = run(intersection.initial(), MAIN_GO, 10_000, new Set(['main_green_out'])).s;
    const why = (point: string, faults: string[] = []) => intersection.explain!(queued, point, new Set(faults));
    expect(why('LoopMain')).toBe(
      'the main road detector loop is ON while a vehicle waits at the stop line; 2 vehicles wait at the main road stop line, so it is ON',
    );
    expect(why('LoopSide', ['side_loop_stuck_off'])).toBe(
      `the side road detector loop is stuck OFF (fault side_loop_stuck_off): it reads OFF whatever waits; ${q(queued, 'waiting_side')} vehicle${q(queued, 'waiting_side') === 1 ? ' waits' : 's wait'} at the side road stop line`,
    );
    expect(intersection.explain!(intersection.initial(), 'LoopSide', new Set(['side_loop_stuck_on']))).toBe(
      'the side road detector loop is stuck ON (fault side_loop_stuck_on): it reads ON whatever waits; 0 vehicles wait at the side road stop line',
    );
    expect(intersection.explain!(intersection.initial(), 'LoopMain', none)).toMatch(/; 0 vehicles wait at the main road stop line, so it is OFF$/);
    expect(why('CrossMain')).toBeUndefined();
  });

  test('a step is pure: the same state, drive and time give the same state, the input is not changed', () => {
    const s0 = run(intersection.initial(), ALL_RED, 12_000).s;
    const copy = JSON.stringify(s0);
    const a = intersection.step(s0, SIDE_GO, 100, none);
    const b = intersection.step(s0, SIDE_GO, 100, none);
    expect(a).toEqual(b);
    expect(JSON.stringify(s0)).toBe(copy);
    // One long step (after a pause) and many short ones reach the same traffic.
    const long = intersection.step(s0, SIDE_GO, 8000, none);
    const short = run(s0, SIDE_GO, 8000).s;
    expect(q(long, 'served_side')).toBe(q(short, 'served_side'));
    expect(q(long, 'waiting_side')).toBe(q(short, 'waiting_side'));
  });
});

describe('the intersection exercise', () => {
  test('the reference solution checks clean and is offered as an example', () => {
    const p = intersectionReference();
    expect(validateProject(JSON.parse(JSON.stringify(p)))).toMatchObject({ ok: true });
    expect(checkProject(p).map(formatDiagnostic)).toEqual([]);
    expect(checkProject(intersectionWrong()).filter((d) => d.severity === 'error')).toEqual([]);
    expect(PLANT_EXAMPLES.map((e) => e.id)).toContain('road-intersection');
  });

  test('the reference solution serves the side road and the pedestrians for 5 minutes with no conflict', () => {
    const { result } = runScenario(intersectionReference(), INTERSECTION_SCENARIO);
    expect(result).toMatchObject({ ok: true, scans: 3000 });
  });

  test('the wrong solution fails where the side road turns green with the main road yellow', () => {
    const { result } = runScenario(intersectionWrong(), INTERSECTION_SCENARIO);
    expect(result).toMatchObject({
      ok: false,
      scans: 201,
      error: 'conflicting signals: main road yellow with side road green at scan 201 (20.00 s)',
    });
  });

  test('faults from a scenario: a burnt-out green darkens the main road; a dead side loop strands the side road', () => {
    const dark = runScenario(intersectionReference(), {
      name: 'burnt',
      csv: '# plant: intersection\n# cycle: 100ms\nscan,fault main_green_out,expect intersection.dark_signals,expect intersection.served_main\n1,1,1,0\n300,,1,0\n',
    });
    expect(dark.result).toMatchObject({ ok: true, scans: 300 });
    // A pedestrian's press alone asks for the side phase (the dead loop sees no car): WALK comes.
    const walked = runScenario(intersectionReference(), {
      name: 'press',
      csv: '# plant: intersection\n# cycle: 100ms\nscan,intersection.CrossMain,fault side_loop_stuck_off,expect intersection.ped_served,expect SideGreen\n1,,1,0,0\n50,1,,0,\n52,0,,,\n260,,,1,1\n',
    });
    expect(walked.result).toMatchObject({ ok: true, scans: 260 });
    const stranded = runScenario(intersectionReference(), {
      name: 'loop',
      csv: '# plant: intersection\n# cycle: 100ms\nscan,fault side_loop_stuck_off,expect SideGreen\n1,1,0\n1500,,0\n',
    });
    expect(stranded.result).toMatchObject({
      ok: false,
      scans: 1240,
      error: 'a vehicle waited more than 120 s on the side road at scan 1,240 (123.90 s)',
    });
  });
});

const WATCH = [
  'CrossMain',
  'CrossSide',
  'LoopMain',
  'LoopSide',
  'MainRed',
  'MainYellow',
  'MainGreen',
  'SideRed',
  'SideYellow',
  'SideGreen',
  'WalkMain',
  'WalkSide',
  'Cycle',
  'Demand',
];
/** The operator's presses, before the scan given, as the panel sends them and as the CLI's stimulus has them. */
const PRESSES: readonly (readonly [number, string, boolean])[] = [
  [50, 'CrossMain', true],
  [52, 'CrossMain', false],
  [700, 'CrossSide', true],
  [703, 'CrossSide', false],
  [1500, 'CrossMain', true],
  [1501, 'CrossMain', false],
];
const lastOf = <T>(xs: T[]): T => xs[xs.length - 1]!;

function sessionRun(scans: number): SimHarness {
  const h = new SimHarness().send(
    { type: 'setCycle', cycleMs: 100 },
    { type: 'setPlant', plant: { id: 'intersection' } },
    { type: 'load', project: intersectionReference() },
  );
  let at = 0;
  for (const [scan, name, value] of [...PRESSES, [scans + 1, '', false] as const]) {
    if (scan - 1 > at) {
      h.send({ type: 'step', scans: scan - 1 - at });
      while (h.frame.scan < scan - 1) h.settle();
      at = scan - 1;
    }
    if (name) h.send({ type: 'plantOperator', name, value });
  }
  return h;
}

describe('the intersection in closed loop', () => {
  test('the worker trace of 2,000 scans equals the CLI trace scan by scan, machine included', () => {
    const h = sessionRun(2000);
    expect(h.frame.scan).toBe(2000);
    const worker = workerTrace(h, WATCH);
    const stimulus = ['scan,intersection.CrossMain,intersection.CrossSide'];
    for (const [scan, name, value] of PRESSES)
      stimulus.push(name === 'CrossMain' ? `${scan},${value ? 1 : 0},` : `${scan},,${value ? 1 : 0}`);
    const cli = cliTrace({
      project: intersectionReference(),
      plant: 'intersection',
      stimulus: `${stimulus.join('\n')}\n`,
      scans: 2000,
      cycle: '100ms',
      watch: [...WATCH, 'intersection.served', 'intersection.ped_served'],
    });
    expect(cli.code).toBe(0);
    expect(cli.err).toBe('');
    const rows = cli.out.trim().split('\n');
    expect(rows).toHaveLength(2001);
    expect(rows.map((r) => r.split(',').slice(0, -2).join(','))).toEqual(worker);
    // The machine itself, as the history shows it at some scans.
    for (const scan of [1, 51, 700, 1234, 2000]) {
      h.send({ type: 'historySeek', scan });
      const view = lastOf(h.of('historyView')).view;
      expect(view.plant?.scan).toBe(scan);
      const s = view.plant!.state as IntersectionState;
      expect([q(s, 'served'), q(s, 'ped_served')].join(',')).toBe(rows[scan]!.split(',').slice(-2).join(','));
    }
    // The side road was served more than once, and the three pedestrians crossed.
    const side = WATCH.indexOf('SideGreen') + 2;
    const greens = worker
      .slice(1)
      .filter((r, i, all) => i > 0 && r.split(',')[side] === '1' && all[i - 1]!.split(',')[side] === '0');
    expect(greens.length).toBeGreaterThanOrEqual(3);
    expect(rows[2000]!.split(',').at(-1)).toBe('3');
  });

  test('a fault set at the panel acts from the next step: the side loop stuck ON reads ON with no car waiting', () => {
    const h = sessionRun(10);
    h.send({ type: 'plantFault', id: 'side_loop_stuck_on', active: true }, { type: 'step', scans: 5 });
    while (h.frame.scan < 15) h.settle();
    const plant = h.frame.plant as PlantFrame;
    expect(plant.now.faults).toEqual(['side_loop_stuck_on']);
    expect(q(plant.now.state as IntersectionState, 'waiting_side')).toBe(0);
    expect(h.value('LoopSide')).toBe(true);
  });
});

describe('rungsmith and the intersection', () => {
  test('plants lists the intersection with its I/O map, faults and quantities, columns apart', () => {
    const all = rungsmith(['plants']);
    expect(all.code).toBe(0);
    expect(all.out).toContain('\nintersection: Road intersection\n  I/O:\n');
    expect(all.out).toContain(
      '    %IX0.0  CrossMain    BOOL  operator (button)  Pedestrian push button at the crossing over the main road',
    );
    expect(all.out).toContain(
      "    %QX1.1  DontWalkSide BOOL  actuator           Crossing over the side road, DON'T WALK lamp",
    );
    expect(all.out).toContain('    side_loop_stuck_off Side road detector loop stuck OFF');
    expect(all.out).toContain(
      '    intersection.long_ped_waits INT        Times pedestrians waited more than 60 s',
    );
    const one = rungsmith(['plants', 'intersection']);
    expect(one.out).toContain('Rest on main road green.');
    expect(one.out).toMatch(/I\/O:\n {4}%IX0\.0 +CrossMain/);
  });
});

describe("the intersection as the gateway's simulated device (npm start -- --plant intersection)", () => {
  test('every point fits the device; a master lighting the main road green lets its cars through, the side road queues on its loop', async () => {
    const device = await startedPlantDevice('intersection');
    try {
      const inputs = device.inputValues();
      const coils = device.writtenValues();
      for (const p of intersection.points)
        expect([p.name, p.kind === 'actuator' ? coils.has(p.address) : inputs.has(p.address)]).toEqual([
          p.name,
          true,
        ]);
      expect(inputs.get('%IX0.3')).toBe(false);
      // MainGreen, SideRed and both DON'T WALK lamps, as a controller resting on the main road would.
      device.drive(
        new Map([
          ['%QX0.2', true],
          ['%QX0.3', true],
          ['%QX0.7', true],
          ['%QX1.1', true],
        ]),
      );
      // In real time: the first main road car (1.5 s) goes through, the first side road car (4 s) waits on the loop.
      await expect.poll(() => device.plantRead('intersection.served_main'), { timeout: 20_000 }).toBe(1);
      await expect.poll(() => device.inputValues().get('%IX0.3'), { timeout: 20_000 }).toBe(true);
      expect(device.plantRead('intersection.dark_signals')).toBe(0);
    } finally {
      await device.close();
    }
  });
});
