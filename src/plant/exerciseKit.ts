// What every machine's exercise is made of (issue 26): the machine's I/O as variables, as
// "Declare the machine's I/O" makes them, and the task text with its I/O table.
import { variable } from '../model/factory';
import type { Variable } from '../model/project';
import { mappedPoints, type PlantMap } from './loop';
import type { PlantModel } from './types';

/** The variables of a machine's points at their addresses (the machine's names, types and comments). */
export function plantVariables(model: PlantModel, map: PlantMap = {}): Variable[] {
  return mappedPoints(model, map).map((p) =>
    variable(p.name, p.type, { comment: p.comment, location: p.address }),
  );
}

/** The task as the project's description: the text, then the I/O table. */
export function taskText(model: PlantModel, map: PlantMap = {}): string {
  const points = mappedPoints(model, map);
  const nameWidth = Math.max(11, ...points.map((p) => p.name.length));
  const rows = points.map(
    (p) =>
      `${p.address.padEnd(7)} ${p.name.padEnd(nameWidth)} ${p.type.padEnd(4)} ${p.kind.padEnd(8)} ${p.comment}`,
  );
  return `${model.task}\n\nI/O:\n${rows.join('\n')}`;
}
