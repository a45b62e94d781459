// What survives when one compiled program replaces another (online change), and how typed text
// becomes a value for a name.
import type { Plc, StateTransfer } from '../engine/api';
import { planStateTransfer } from '../engine/plc';
import { parseLocation, type Value } from '../model/iecTypes';
import type { PackedPower } from './frames';
import type { OnlineChangePlan, SimLayout, SimValueInput } from './protocol';
import type { SimEngine } from './simEngine';

/**
 * Variables present in both programs with the same type keep their values (FB instances and edge
 * memories: carryInstances).
 */
export function carryValues(from: Plc, fromLayout: SimLayout, to: Plc, toLayout: SimLayout): void {
  const before = new Map(fromLayout.variables.map((v) => [v.name.toUpperCase(), v]));
  for (const v of toLayout.variables) {
    const old = before.get(v.name.toUpperCase());
    if (v.role === 'pin' || !old || old.type !== v.type) continue;
    try {
      to.write(v.name, from.read(old.name));
    } catch {
      // A constant, or a name the new program cannot write: it keeps its initial value.
    }
  }
}

/**
 * FB instances (by name, same FB type) and edge memories of |P| |N| contacts and (P) (N) coils (by
 * element id, same symbol and operand) keep their state, timers' elapsed time included; the others
 * start fresh. Call at a scan boundary, before `to` runs.
 */
export function carryInstances(from: Plc, to: Plc): OnlineChangePlan {
  return summarizeTransfer(to.importState(from.exportState()));
}

/** What carryInstances will keep and reset, without touching either PLC. */
export function planInstances(from: Plc, to: Plc): OnlineChangePlan {
  return summarizeTransfer(planStateTransfer(from.stateItems(), to.stateItems()));
}

export function summarizeTransfer(t: StateTransfer): OnlineChangePlan {
  return {
    kept: t.kept.length,
    reset: t.reset.map((r) => ({ name: r.item.label, reason: r.detail })),
    removed: t.removed.map((i) => i.label),
  };
}

const count = (n: number) => n.toLocaleString('en-US');
const MAX_NAMED = 8;

/** "kept 14 instances, reset 1: T3 (new)" */
export function describeTransfer(plan: OnlineChangePlan): string {
  const kept = `kept ${count(plan.kept)} instance${plan.kept === 1 ? '' : 's'}`;
  if (plan.reset.length === 0 && plan.removed.length === 0) return kept;
  if (plan.reset.length === 0) return `${kept}; removed ${plan.removed.slice(0, MAX_NAMED).join(', ')}${plan.removed.length > MAX_NAMED ? ' …' : ''}`;
  const named = plan.reset.slice(0, MAX_NAMED).map((r) => `${r.name} (${r.reason})`);
  if (plan.reset.length > MAX_NAMED) named.push(`and ${count(plan.reset.length - MAX_NAMED)} more`);
  const reset = `${kept}, reset ${count(plan.reset.length)}: ${named.join(', ')}`;
  return plan.removed.length === 0 ? reset : `${reset}; removed ${plan.removed.slice(0, MAX_NAMED).join(', ')}${plan.removed.length > MAX_NAMED ? ' …' : ''}`;
}

/** "Online change applied at scan 12,840; kept 14 instances, reset 1: T3 (new)" */
export function describeOnlineChange(scan: number, plan: OnlineChangePlan): string {
  return `Online change applied at scan ${count(scan)}; ${describeTransfer(plan)}`;
}

/** Forces stay in place across a program change, for the variables that still exist. */
export function carryForces(from: Plc, to: Plc): void {
  for (const [name, value] of from.forced()) {
    try {
      to.force(name, value);
    } catch {
      // The forced variable no longer exists.
    }
  }
}

/** The type of a readable name or an IEC location (%IX0.0 is BOOL, %IW2 a WORD). */
export function typeOfName(layout: SimLayout | undefined, name: string): string | undefined {
  const key = name.toUpperCase();
  const known = layout?.variables.find((v) => v.name.toUpperCase() === key);
  if (known) return known.type;
  const loc = parseLocation(name);
  if (!loc) return undefined;
  return { X: 'BOOL', B: 'BYTE', W: 'WORD', D: 'DWORD', L: 'LWORD' }[loc.size];
}

/** A value for `name` from a command: as given, or parsed from the user's text for the name's type. */
export function valueFor(engine: SimEngine, layout: SimLayout | undefined, name: string, input: SimValueInput): Value {
  if ('value' in input) return input.value;
  const type = typeOfName(layout, name);
  if (!type) throw new Error(`unknown variable "${name}"`);
  const parsed = engine.parseValue(type, input.text);
  if (!parsed.ok) throw new Error(`${name}: ${parsed.message}`);
  return parsed.value;
}

/** What the simulator shows: values in layout order and the packed power flow. */
export interface ShownScan {
  readonly values: readonly Value[];
  readonly power: PackedPower;
}

/**
 * The last scan's display mapped onto a new program's layout, for an online change applied while
 * paused: the new program has not run yet, so its own snapshot would mark every network "not run"
 * and read inputs as OFF. Values carry by name (same type), power by network id, element id and
 * vertical link; what is new shows the new program's value and no power.
 */
export function carryDisplay(from: SimLayout, shown: ShownScan, to: SimLayout, toValues: readonly Value[]): ShownScan {
  const oldVars = new Map(from.variables.map((v, i) => [v.name.toUpperCase(), i]));
  // An input renamed keeps its address: the value read there last scan.
  const oldInputs = new Map(from.variables.flatMap((v, i) => (v.location?.toUpperCase().startsWith('%I') ? [[v.location.toUpperCase(), i] as const] : [])));
  const values = to.variables.map((v, i) => {
    const k = oldVars.get(v.name.toUpperCase()) ?? (v.location ? oldInputs.get(v.location.toUpperCase()) : undefined);
    return k !== undefined && from.variables[k]!.type === v.type ? shown.values[k]! : toValues[i]!;
  });
  const networkCount = to.networkIds.length;
  const elements = new Uint8Array(to.elementOffsets[networkCount] ?? 0);
  const vlinks = new Uint8Array(to.vlinkOffsets[networkCount] ?? 0);
  const executed = new Uint8Array(networkCount);
  const oldNetworks = new Map(from.networkIds.map((id, n) => [id, n]));
  for (let n = 0; n < networkCount; n++) {
    const m = oldNetworks.get(to.networkIds[n]!);
    if (m === undefined) continue;
    executed[n] = shown.power.executed[m] ?? 0;
    const oldElements = new Map<string, number>();
    for (let k = from.elementOffsets[m]!; k < from.elementOffsets[m + 1]!; k++) oldElements.set(from.elementIds[k]!, k);
    for (let k = to.elementOffsets[n]!; k < to.elementOffsets[n + 1]!; k++) {
      const j = oldElements.get(to.elementIds[k]!);
      if (j !== undefined) elements[k] = shown.power.elements[j] ?? 0;
    }
    const oldVlinks = new Map<string, number>();
    for (let k = from.vlinkOffsets[m]!; k < from.vlinkOffsets[m + 1]!; k++) oldVlinks.set(from.vlinkKeys[k]!, k);
    for (let k = to.vlinkOffsets[n]!; k < to.vlinkOffsets[n + 1]!; k++) {
      const j = oldVlinks.get(to.vlinkKeys[k]!);
      if (j !== undefined) vlinks[k] = shown.power.vlinks[j] ?? 0;
    }
  }
  return { values, power: { elements, vlinks, executed } };
}
