// Every machine there is, by id. A new machine is one module added here (docs/PLANTS.md).
import { boxes } from './boxes';
import { garage } from './garage';
import { intersection } from './intersection';
import { lift } from './lift';
import { mixer } from './mixer';
import { tank } from './tank';
import type { ProjectPlant } from '../model/project';
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

/**
 * A project's I/O map entries that name no point of its machine (a typo, a hand-edited file): they
 * change nothing, so the point stays at its default address. A warning sentence, or undefined.
 */
export function strayMapWarning(plant: ProjectPlant | undefined): string | undefined {
  const model = plant && plantById(plant.id);
  if (!model || !plant.map) return undefined;
  const stray = Object.keys(plant.map).filter((name) => !model.points.some((p) => p.name === name));
  if (stray.length === 0) return undefined;
  return `warning ${model.id}: the project's I/O map names ${stray.map((n) => `"${n}"`).join(', ')}, not ${stray.length === 1 ? 'a point' : 'points'} of the machine (${model.points.map((p) => p.name).join(', ')}): ${stray.length === 1 ? 'it changes' : 'they change'} nothing`;
}
