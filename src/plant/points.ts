// Points several machines share (issue 26): the operator's Start and Stop push buttons on the
// first two inputs, as the tank, the box sorter and the batch mixer have them.
import type { PlantPoint } from './types';

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
