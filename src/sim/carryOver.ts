// What survives when one compiled program replaces another (online change), and how typed text
// becomes a value for a name.
import type { Plc } from '../engine/api';
import { parseLocation, type Value } from '../model/iecTypes';
import type { SimLayout, SimValueInput } from './protocol';
import type { SimEngine } from './session';

/**
 * Variables present in both programs with the same type keep their values. FB instances and edge
 * memories start fresh: the engine cannot move their internal state (a timer's start time).
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
