// Operator actions and faults mid-run for every machine's reference solution (issue 26): the runs
// the determinism test (faultTraces.test.ts) and the check against MATIEC (matiecKit.ts) share.
import type { Project } from '../../src/model/project';
import { boxesReference } from '../../src/plant/boxesExercise';
import { tankReference } from '../../src/plant/exercises';
import { garageReference } from '../../src/plant/garageExercise';
import { intersectionReference } from '../../src/plant/intersectionExercise';
import { liftReference } from '../../src/plant/liftExercise';
import { mixerReference } from '../../src/plant/mixerExercise';

/** Before scan N: an operator control pressed or released, or a fault set or cleared. */
export type Action = readonly [scan: number, kind: 'op' | 'fault', name: string, on: boolean];

export const MACHINES: readonly { id: string; project: () => Project; cycleMs: number; actions: readonly Action[] }[] = [
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

/** The stimulus columns (`tank.Start`, `fault inlet_slow`) of `actions`, or of its operator actions only, as `rungsmith simulate --inputs` takes them. */
export function actionStimulus(id: string, actions: readonly Action[], only?: Action[1]): string {
  const chosen = only ? actions.filter(([, kind]) => kind === only) : actions;
  const column = (kind: Action[1], name: string) => (kind === 'op' ? `${id}.${name}` : `fault ${name}`);
  const columns = [...new Set(chosen.map(([, kind, name]) => column(kind, name)))];
  const rows = [
    `scan,${columns.join(',')}`,
    ...chosen.map(([scan, kind, name, on]) => `${scan},${columns.map((c) => (c === column(kind, name) ? (on ? 1 : 0) : '')).join(',')}`),
  ];
  return `${rows.join('\n')}\n`;
}
