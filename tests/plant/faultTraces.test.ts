// Determinism with faults and operator actions (issue 26): for every machine, an operator working
// its controls and faults set and cleared mid-run give, in the worker's session (what the browser
// records and exports) and in `rungsmith simulate --plant`, the same trace scan by scan, at the
// exercise's cycle and at an odd one.
import { describe, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { boxesReference } from '../../src/plant/boxesExercise';
import { tankReference } from '../../src/plant/exercises';
import { garageReference } from '../../src/plant/garageExercise';
import { intersectionReference } from '../../src/plant/intersectionExercise';
import { liftReference } from '../../src/plant/liftExercise';
import { requirePlant } from '../../src/plant/machines';
import { mixerReference } from '../../src/plant/mixerExercise';
import { SimHarness } from '../sim/harness';
import { cliTrace, workerTrace } from './traces';

/** Before scan N: an operator control pressed or released, or a fault set or cleared. */
type Action = readonly [scan: number, kind: 'op' | 'fault', name: string, on: boolean];

const MACHINES: readonly { id: string; project: () => Project; cycleMs: number; actions: readonly Action[] }[] = [
  {
    id: 'tank',
    project: tankReference,
    cycleMs: 100,
    actions: [
      [1, 'op', 'Start', true],
      [3, 'op', 'Start', false],
      [300, 'fault', 'inlet_slow', true],
      [700, 'fault', 'inlet_slow', false],
      [900, 'fault', 'high_stuck_off', true],
      [1500, 'fault', 'high_stuck_off', false],
      [1600, 'op', 'Stop', true],
      [1602, 'op', 'Stop', false],
      [1700, 'op', 'Start', true],
      [1701, 'op', 'Start', false],
    ],
  },
  {
    id: 'boxes',
    project: boxesReference,
    cycleMs: 100,
    actions: [
      [1, 'op', 'Start', true],
      [3, 'op', 'Start', false],
      [200, 'fault', 'pusher_slow', true],
      [400, 'fault', 'pusher_slow', false],
      [600, 'fault', 'size_stuck_on', true],
      [800, 'fault', 'size_stuck_on', false],
      [1000, 'op', 'Stop', true],
      [1002, 'op', 'Stop', false],
      [1100, 'op', 'Start', true],
      [1102, 'op', 'Start', false],
    ],
  },
  {
    id: 'garage',
    project: garageReference,
    cycleMs: 100,
    actions: [
      [1, 'op', 'KeyOpen', true],
      [3, 'op', 'KeyOpen', false],
      [150, 'op', 'KeyClose', true],
      [152, 'op', 'KeyClose', false],
      [160, 'fault', 'eye_stuck_off', true],
      [170, 'op', 'Doorway', true],
      [400, 'op', 'Doorway', false],
      [410, 'fault', 'eye_stuck_off', false],
      [500, 'op', 'KeyOpen', true],
      [502, 'op', 'KeyOpen', false],
      [520, 'fault', 'motor_slow', true],
      [900, 'op', 'KeyClose', true],
      [902, 'op', 'KeyClose', false],
    ],
  },
  {
    id: 'mixer',
    project: mixerReference,
    cycleMs: 100,
    actions: [
      [1, 'op', 'Start', true],
      [3, 'op', 'Start', false],
      [100, 'fault', 'valve_a_slow', true],
      [500, 'fault', 'valve_a_slow', false],
      [700, 'fault', 'temp_frozen', true],
      [1200, 'fault', 'temp_frozen', false],
    ],
  },
  {
    id: 'lift',
    project: liftReference,
    cycleMs: 20,
    actions: [
      [1, 'op', 'Call3', true],
      [6, 'op', 'Call3', false],
      [200, 'fault', 'door_slow', true],
      [400, 'op', 'Call2', true],
      [405, 'op', 'Call2', false],
      [900, 'fault', 'door_slow', false],
      [1000, 'op', 'Call1', true],
      [1005, 'op', 'Call1', false],
      [1100, 'fault', 'floor2_stuck_on', true],
    ],
  },
  {
    id: 'intersection',
    project: intersectionReference,
    cycleMs: 100,
    actions: [
      [50, 'op', 'CrossMain', true],
      [52, 'op', 'CrossMain', false],
      [100, 'fault', 'side_loop_stuck_on', true],
      [600, 'fault', 'side_loop_stuck_on', false],
      [800, 'fault', 'main_green_out', true],
      [1000, 'op', 'CrossSide', true],
      [1001, 'op', 'CrossSide', false],
      [1300, 'fault', 'main_green_out', false],
    ],
  },
];

const SCANS = 2000;

describe.each([
  ['its exercise cycle', undefined],
  ['a 37 ms cycle', 37],
] as const)('at %s', (_what, odd) => {
  test.each(MACHINES)('$id: operator actions and faults give the same trace in the worker and the CLI', ({ id, project, cycleMs, actions }) => {
    const cycle = odd ?? cycleMs;
    const model = requirePlant(id);
    const names = model.points.map((p) => p.name);
    const h = new SimHarness().send({ type: 'setCycle', cycleMs: cycle }, { type: 'setPlant', plant: { id } }, { type: 'load', project: project() });
    let done = 0;
    for (const [scan, kind, name, on] of actions) {
      if (scan - 1 > done) {
        h.send({ type: 'step', scans: scan - 1 - done });
        while (h.frame.scan < scan - 1) h.settle();
        done = scan - 1;
      }
      h.send(kind === 'op' ? { type: 'plantOperator', name, value: on } : { type: 'plantFault', id: name, active: on });
    }
    h.send({ type: 'step', scans: SCANS - done });
    while (h.frame.scan < SCANS) h.settle();
    const worker = workerTrace(h, names);

    const column = (kind: Action[1], name: string) => (kind === 'op' ? `${id}.${name}` : `fault ${name}`);
    const columns = [...new Set(actions.map(([, kind, name]) => column(kind, name)))];
    const stimulus = [
      `scan,${columns.join(',')}`,
      ...actions.map(([scan, kind, name, on]) => `${scan},${columns.map((c) => (c === column(kind, name) ? (on ? 1 : 0) : '')).join(',')}`),
    ];
    const cli = cliTrace({ project: project(), plant: id, stimulus: `${stimulus.join('\n')}\n`, scans: SCANS, cycle: `${cycle}ms`, watch: names });
    expect(cli.code).toBe(0);
    const rows = cli.out.trim().split('\n');
    expect(rows).toHaveLength(SCANS + 1);
    expect(rows).toEqual(worker);
    // The faults acted: without them the same operator actions give another trace.
    const ops = actions.filter(([, kind]) => kind === 'op');
    const opColumns = [...new Set(ops.map(([, , name]) => `${id}.${name}`))];
    const noFaults = cliTrace({
      project: project(),
      plant: id,
      stimulus: `${[`scan,${opColumns.join(',')}`, ...ops.map(([scan, , name, on]) => `${scan},${opColumns.map((c) => (c === `${id}.${name}` ? (on ? 1 : 0) : '')).join(',')}`)].join('\n')}\n`,
      scans: SCANS,
      cycle: `${cycle}ms`,
      watch: names,
    });
    expect(noFaults.code).toBe(0);
    expect(noFaults.out.trim().split('\n')).not.toEqual(rows);
  });
});
