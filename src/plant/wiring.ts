// Editing a machine's wiring (the Plant panel's I/O map, issue 26): checking an address typed for
// a point, and what "Declare the machine's I/O" adds, moves and leaves alone in a program.
import { locationText, parseLocation } from '../model/iecTypes';
import type { Variable } from '../model/project';
import { plantVariables } from './exerciseKit';
import { addressKey, addressProblem, mappedPoints, type PlantMap } from './loop';
import type { PlantModel, PlantPoint } from './types';

/**
 * An address typed for `point` (one of `points`, the machine as wired now): the address as the map
 * keeps it (canonical, %IX0.2 for "%ix00.2" or "%I0.2"), or why it cannot be: it does not fit the
 * point, or another point of the machine is at that very location however it is spelt.
 */
export function rewireAddress(
  points: readonly PlantPoint[],
  point: PlantPoint,
  text: string,
): { address: string; problem?: undefined } | { problem: string; address?: undefined } {
  const typed = text.trim();
  const problem = addressProblem(point, typed);
  if (problem) return { problem };
  const loc = parseLocation(typed)!;
  if (loc.levels?.length)
    return { problem: `${point.name}: ${typed} is a hierarchical address; a machine's point is at a plain one (%IX0.2, %IW1)` };
  const key = addressKey(typed);
  const clash = points.find((q) => q.name !== point.name && addressKey(q.address) === key);
  if (clash) return { problem: `${point.name}: ${typed} is already ${clash.name}'s address (${clash.address})` };
  return { address: locationText(loc) };
}

/** What "Declare the machine's I/O" does to a program: variables to add, to move, and names it leaves alone (and why). */
export interface DeclarePlan {
  readonly add: readonly Variable[];
  readonly moves: readonly { readonly name: string; readonly from: string; readonly to: string }[];
  readonly kept: readonly string[];
}

/**
 * The machine's points against the program's variables (`variables`) and the project's globals:
 * a point no variable is named after is added at its address; a variable of the point's name and
 * type at another address moves to the point's (a point rewired in the map); a variable of the
 * point's name that cannot carry it (another type, no address, or a global) is left as it is and
 * said, so the point is visibly not wired rather than wired to something of the wrong type.
 */
export function declarePlan(
  model: PlantModel,
  map: PlantMap,
  variables: readonly Variable[],
  globals: readonly Variable[],
): DeclarePlan {
  const points = mappedPoints(model, map);
  const add: Variable[] = [];
  const moves: { name: string; from: string; to: string }[] = [];
  const kept: string[] = [];
  const wanted = plantVariables(model, map);
  points.forEach((p, i) => {
    const upper = p.name.toUpperCase();
    const v = variables.find((x) => x.name.toUpperCase() === upper);
    const g = v ? undefined : globals.find((x) => x.name.toUpperCase() === upper);
    if (!v && !g) {
      add.push(wanted[i]!);
      return;
    }
    const at = v ?? g!;
    const global = v ? '' : 'global, ';
    if (at.type.toUpperCase() !== p.type) {
      kept.push(`${at.name} (${global}${at.type}; the machine's ${p.name} is ${p.type} at ${p.address})`);
      return;
    }
    if (!at.location) {
      kept.push(`${at.name} (${global}no address; the machine's ${p.name} is at ${p.address})`);
      return;
    }
    if (addressKey(at.location) === addressKey(p.address)) return;
    if (g) {
      kept.push(`${g.name} (global, at ${g.location}; the machine's ${p.name} is at ${p.address})`);
      return;
    }
    moves.push({ name: at.name, from: at.location, to: p.address });
  });
  return { add, moves, kept };
}
