// The machines' exercises under File > Examples (issue 26): per machine, the task, the machine's
// I/O declared, a reference solution in ladder and a scenario it passes (`# plant: tank`), run in
// CI by `rungsmith test`. Each machine's exercise is its own module (`<id>Exercise.ts`).
import type { Example } from '../model/examples';
import { BOXES_EXAMPLE } from './boxesExercise';
import { GARAGE_EXAMPLE } from './garageExercise';
import { INTERSECTION_EXAMPLE } from './intersectionExercise';
import { LIFT_EXAMPLE } from './liftExercise';
import { MIXER_EXAMPLE } from './mixerExercise';
import { TANK_EXAMPLE } from './tankExercise';

export { plantVariables, taskText } from './exerciseKit';
export { TANK_SCENARIO, tankReference, tankWrong } from './tankExercise';
export { LIFT_SCENARIO, liftReference, liftWrong } from './liftExercise';

export const PLANT_EXAMPLES: readonly Example[] = [
  TANK_EXAMPLE,
  LIFT_EXAMPLE,
  GARAGE_EXAMPLE,
  MIXER_EXAMPLE,
  BOXES_EXAMPLE,
  INTERSECTION_EXAMPLE,
];
