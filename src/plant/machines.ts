// Every machine there is, by id. A new machine is one module added here (docs/PLANTS.md).
import { boxes } from './boxes';
import { garage } from './garage';
import { intersection } from './intersection';
import { lift } from './lift';
import { mixer } from './mixer';
import { tank } from './tank';
import type { PlantModel } from './types';

export const PLANTS: readonly PlantModel[] = [
  tank as PlantModel,
  lift as PlantModel,
  garage as PlantModel,
  mixer as PlantModel,
  boxes as PlantModel,
  intersection as PlantModel,
];

export function plantById(id: string): PlantModel | undefined {
  const key = id.trim().toLowerCase();
  return PLANTS.find((p) => p.id === key);
}

/** `tank` -> the model, or an error naming the machines there are. */
export function requirePlant(id: string): PlantModel {
  const p = plantById(id);
  if (!p)
    throw new Error(`there is no machine "${id}"; the machines are ${PLANTS.map((m) => m.id).join(', ')}`);
  return p;
}

/**
 * For a name no variable has: when it is a machine's (`tank.level`) and that machine is not the one
 * running, what to do about it (`add "# plant: tank"`), given how the machine is chosen there
 * (`add "# plant: tank" before the header` in a scenario, `add --plant tank` on the command line). Else undefined.
 */
export function machineNameHint(
  name: string,
  running: PlantModel | undefined,
  choose: (id: string) => string,
): string | undefined {
  const dot = name.indexOf('.');
  const model = dot > 0 ? PLANTS.find((p) => p.id === name.slice(0, dot).trim().toLowerCase()) : undefined;
  if (!model || model === running) return undefined;
  return running
    ? `${name} is the machine ${model.id}'s, and this runs ${running.id}`
    : `${name} is the machine ${model.id}'s: ${choose(model.id)}`;
}
