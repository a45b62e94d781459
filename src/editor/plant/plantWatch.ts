// The machine's names in the watch table and the trend (issue 26): `tank.level`, `tank.Pump`,
// offered by the add fields as the program's names are, read off the machine the worker last
// showed (live) or as it was at the recorded scan viewed.
import { useMemo } from 'react';
import { PLANTS, plantById } from '../../plant/machines';
import { findPlantName, formatPlantValue, plantNames, plantValue, type PlantName } from '../../plant/values';
import type { SimVariable } from '../../sim/protocol';
import type { DocumentState } from '../../store/documentStore';
import { useDocument } from '../../store/documentStore';
import type { SimState } from '../../store/simState';

const selectPlantConfig = (s: DocumentState) => s.project.plant;

/** The project's machine's names as watch and trend candidates (type shown beside each); none without a machine. */
export function usePlantCandidates(): readonly SimVariable[] {
  const config = useDocument(selectPlantConfig);
  return useMemo(() => {
    const model = config ? plantById(config.id) : undefined;
    return model ? plantNames(model).map(candidateOf) : [];
  }, [config]);
}

const candidateOf = (n: PlantName): SimVariable => ({
  name: n.name,
  type: n.type,
  role: n.kind === 'actuator' ? 'output' : n.kind === 'quantity' ? 'memory' : 'input',
});

/** `tank.level` and the like when the project has that machine, with what it is; undefined otherwise. */
export function plantNameInfo(project: { readonly plant?: { readonly id: string } }, name: string): PlantName | undefined {
  const model = project.plant ? plantById(project.plant.id) : undefined;
  const ref = model && findPlantName(model, name);
  if (!model || !ref) return undefined;
  const spelt = `${model.id}.${ref.quantity?.name ?? ref.point!.name}`;
  return plantNames(model).find((n) => n.name === spelt);
}

/**
 * `tank.level` when the project's machine is another one (or none): the name of which machine, and
 * what it is, so the watch says the machine is not chosen instead of offering to write or force an
 * unknown variable ("unknown variable \"tank.level\""). Undefined for any other name.
 */
export function otherPlantNameInfo(
  project: { readonly plant?: { readonly id: string } },
  name: string,
): { readonly machine: string; readonly title: string; readonly info: PlantName } | undefined {
  for (const model of PLANTS) {
    if (model.id === project.plant?.id) continue;
    const ref = findPlantName(model, name);
    if (!ref) continue;
    const spelt = `${model.id}.${ref.quantity?.name ?? ref.point!.name}`;
    const info = plantNames(model).find((n) => n.name === spelt);
    if (info) return { machine: model.id, title: model.title, info };
  }
  return undefined;
}

/**
 * A machine name's value as the watch shows it (`812.4 L`, `TRUE`): the machine at the recorded
 * scan viewed, else as the worker last showed it; undefined when there is nothing to show.
 */
export function plantWatchText(s: SimState, name: string): string | undefined {
  const model = s.plant ? plantById(s.plant.id) : undefined;
  if (!model) return undefined;
  const snapshot = s.historyScan !== undefined ? s.plantAtScan : s.plant!.now;
  const ref = findPlantName(model, name);
  if (!snapshot || !ref) return undefined;
  const value = plantValue(model, snapshot, name);
  if (value === undefined) return undefined;
  return ref.quantity ? formatPlantValue(ref.quantity.type, value, ref.quantity.unit) : formatPlantValue(ref.point.type, value);
}
