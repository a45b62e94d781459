// "Why?" with a machine in closed loop (issue 26): an input the machine writes (a sensor, an
// operator control) is explained as the machine's, with why it has its value and the machine's
// quantities as the scan read them; an output the machine reads says what it drives; and a
// machine name (`tank.level`) is explained from the recorded machine itself. Any PlantModel.
import type { Explanation, ExplainTarget } from '../engine/explain';
import { addressKey, type PlantSnapshot } from '../plant/loop';
import type { PlantModel, PlantPoint } from '../plant/types';
import { senseRecord } from '../plant/points';
import { describeQuantities, findPlantName, formatPlantValue, plantValue } from '../plant/values';

const scanWords = (scan: number): string => `scan ${scan.toLocaleString('en-US')}`;
const timeWords = (ms: number): string => `${(ms / 1000).toFixed(2)} s`;
const lowerFirst = (s: string): string => (s ? s[0]!.toLowerCase() + s.slice(1) : s);

export interface PlantWhyContext {
  readonly model: PlantModel;
  /** The machine's points at their addresses (the project's map applied). */
  readonly points: readonly PlantPoint[];
  /** The machine as it was after a recorded scan (0: its initial state), if still kept. */
  at(scan: number): PlantSnapshot | undefined;
  /**
   * The scan after which this machine, wired as it is, began driving the program (0: from the cold
   * start). The inputs of scans up to it were not the machine's: it was chosen or rewired later.
   */
  readonly since: number;
}

/** Why the machine has no state for `scan`: it came later, or the scan is too old to be kept. */
function missingWords(ctx: PlantWhyContext, scan: number): string {
  return scan <= ctx.since
    ? `The machine ${ctx.model.id} was chosen or rewired after ${scanWords(ctx.since)}: ${scanWords(scan)} came before it drove the program.`
    : `The machine is no longer kept for ${scanWords(scan)}.`;
}

function faultWords(model: PlantModel, snapshot: PlantSnapshot): string | undefined {
  if (snapshot.faults.length === 0) return undefined;
  const titles = snapshot.faults.map((id) => `${model.faults.find((f) => f.id === id)?.title ?? id} (${id})`);
  return `Fault${titles.length > 1 ? 's' : ''} set on the machine: ${titles.join(', ')}.`;
}

/** The explanation with the machine's lines added for each explained variable wired to one of its points. */
export function withPlantWhy(e: Explanation, ctx: PlantWhyContext): Explanation {
  const { model } = ctx;
  const lines: string[] = [];
  let shown: number | undefined;
  const machineAt = (scan: number, words: string) => {
    const snap = ctx.at(scan);
    if (!snap) {
      lines.push(missingWords(ctx, scan));
      return;
    }
    if (shown === snap.scan) return;
    shown = snap.scan;
    lines.push(`The machine ${words}: ${describeQuantities(model, snap)}.`);
    const faults = faultWords(model, snap);
    if (faults) lines.push(faults);
  };
  // A scan from before the machine drove the program: its inputs and outputs were not the
  // machine's then (another machine, another wiring, or none), so it says nothing of them.
  if (e.scan <= ctx.since) return e;
  for (const { name, location } of e.io ?? []) {
    const point = ctx.points.find((p) => addressKey(p.address) === addressKey(location));
    if (!point) continue;
    const what = `${point.name}, ${lowerFirst(point.comment)}`;
    if (point.kind === 'actuator') {
      lines.push(`${name} (${location}) drives the machine ${model.id}: ${what}.`);
      machineAt(e.scan, `after ${scanWords(e.scan)}, driven by it`);
      continue;
    }
    // The scan read its inputs as the machine presented them after the scan before.
    const before = e.scan - 1;
    if (point.kind === 'operator') {
      // The control as the operator held it during the scan (the machine steps with it after the scan).
      const snap = ctx.at(e.scan);
      const held = snap?.operator[point.name] === true;
      lines.push(
        `${name} (${location}) is written by the machine ${model.id}: ${what}, an operator ${point.control ?? 'control'}${snap ? ` ${point.control === 'switch' ? (held ? 'turned ON' : 'OFF') : held ? 'held' : 'not pressed'} when ${scanWords(e.scan)} read it` : ''}.`,
      );
      continue;
    }
    const snap = ctx.at(before);
    if (!snap) {
      lines.push(`${name} (${location}) is written by the machine ${model.id}: ${what}.`);
      lines.push(missingWords(ctx, before));
      continue;
    }
    const faults = new Set(snap.faults);
    const value = senseRecord(model, snap.state, faults)[point.name];
    const because = model.explain?.(snap.state, point.name, faults);
    lines.push(
      `${name} (${location}) is written by the machine ${model.id}: ${what}. It presented ${value === undefined ? '?' : formatPlantValue(point.type, value)} after ${scanWords(before)} (${timeWords(snap.timeMs)}), the input ${scanWords(e.scan)} read${because ? `: ${because}` : ''}.`,
    );
    machineAt(before, `after ${scanWords(before)}`);
  }
  return lines.length ? { ...e, lines: [...e.lines, ...lines] } : e;
}

/** "Why?" on a machine name (`tank.level`, `tank.HighLevel`) at a recorded scan; undefined for other names. */
export function plantNameWhy(scan: number, target: ExplainTarget, ctx: PlantWhyContext): Explanation | undefined {
  if (target.kind !== 'variable') return undefined;
  const { model } = ctx;
  const ref = findPlantName(model, target.name);
  if (!ref) return undefined;
  const snap = ctx.at(scan);
  const base = { scan, target, marks: [], links: [] };
  if (!snap) return { ...base, title: `${target.name} at ${scanWords(scan)}`, lines: [missingWords(ctx, scan)] };
  const value = plantValue(model, snap, target.name);
  const type = ref.quantity?.type ?? ref.point!.type;
  const shown = value === undefined ? '?' : formatPlantValue(type, value, ref.quantity?.unit);
  const lines: string[] = [];
  if (ref.quantity) lines.push(`${target.name} is a quantity of the machine ${model.id} (${lowerFirst(ref.quantity.comment)}), worked out by the machine at every scan from what the program drives.`);
  else {
    const p = ctx.points.find((x) => x.name === ref.point!.name) ?? ref.point!;
    lines.push(`${target.name} is the machine's point ${p.name} at ${p.address} (${lowerFirst(p.comment)}), ${p.kind === 'actuator' ? 'as the program drove it' : p.kind === 'operator' ? 'as the operator holds it' : 'as the machine senses it'}.`);
    if (p.kind === 'sensor') {
      const because = model.explain?.(snap.state, p.name, new Set(snap.faults));
      if (because) lines.push(`${because[0]!.toUpperCase()}${because.slice(1)}.`);
    }
  }
  lines.push(`The machine after ${scanWords(scan)} (${timeWords(snap.timeMs)}): ${describeQuantities(model, snap)}.`);
  const faults = faultWords(model, snap);
  if (faults) lines.push(faults);
  return { ...base, title: `${target.name} is ${shown} after ${scanWords(scan)}`, lines };
}
