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
