// Points several machines share (issue 26): the operator's Start and Stop push buttons on the
// first two inputs, as the tank, the box sorter and the batch mixer have them.
import type { Value } from '../model/iecTypes';
import type { PlantModel, PlantPoint } from './types';

/** Start (%IX0.0) and Stop (%IX0.1), both normally open push buttons held while pressed. */
export const START_STOP_BUTTONS: readonly PlantPoint[] = [
  {
    name: 'Start',
    address: '%IX0.0',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Start push button (NO)',
  },
  {
    name: 'Stop',
    address: '%IX0.1',
    type: 'BOOL',
    kind: 'operator',
    control: 'button',
    comment: 'Stop push button (NO)',
  },
];

/**
 * Where `sense` writes each sensor (docs/PLANTS.md): the sensor points in the order of `points`,
 * by name. `names` are the sensors `sense` writes; a name that is not a sensor point, or a sensor
 * point missing, is a mistake in the machine, caught when its module loads.
 */
export function sensorSlots<N extends string>(points: readonly PlantPoint[], names: readonly N[]): Readonly<Record<N, number>> {
  const sensors = points.filter((p) => p.kind === 'sensor').map((p) => p.name);
  const missing = sensors.filter((s) => !names.includes(s as N));
  const extra = names.filter((n) => !sensors.includes(n));
  if (missing.length || extra.length)
    throw new Error(`sensorSlots: sense writes ${names.join(', ')}; the sensor points are ${sensors.join(', ')}`);
  const slots = {} as Record<N, number>;
  for (const n of names) slots[n] = sensors.indexOf(n);
  return slots;
}

/** The sensors of a machine in a state, by point name (`sense` is by slot): for the page, "Why?" and tests. */
export function senseRecord<S>(model: PlantModel<S>, state: S, faults: ReadonlySet<string>): Record<string, Value> {
  const out: Value[] = [];
  model.sense(state, faults, out);
  const record: Record<string, Value> = {};
  let i = 0;
  for (const p of model.points) if (p.kind === 'sensor') record[p.name] = out[i++]!;
  return record;
}

/**
 * A copy of a machine's state that no later step changes (the loop steps into its own two
 * objects): a shallow copy, since a state's arrays and records are never changed once made.
 */
export function copyPlantState<S>(state: S): S {
  return { ...state };
}
