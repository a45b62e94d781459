// Prepared values of the watch table (as in CODESYS): a value typed in a row's "Prepared value"
// field waits there until it is written once (Ctrl+F7, or the row's Write) or forced (F7, or the
// row's Force). Writing or forcing all prepared values clears them. A field input of attached
// hardware is never written, and is forced only through its row's confirmed "Force on hardware".
import { createStore } from 'zustand/vanilla';
import { parseValueText } from '../../engine/values/literals';
import { isElementaryType } from '../../model/iecTypes';
import { typeOfName } from '../../sim/carryOver';
import { fieldInputAddress, fieldOutputAddress } from '../hardware/fieldIo';
import type { SimValueInput } from '../../sim/protocol';
import type { SimStore } from '../../store/simState';

export interface PreparedValue {
  /** The watch row's name (`Start`, `Conv1.Count`). */
  readonly name: string;
  /** As typed. */
  readonly text: string;
  /** What is written or forced. */
  readonly input: SimValueInput;
  /** The device address when the variable is a field input of attached hardware. */
  readonly field?: string | undefined;
  /** A function block pin: written, never forced. */
  readonly pin?: boolean;
}

interface PreparedState {
  /** By upper-case name, in the order prepared. */
  readonly values: ReadonlyMap<string, PreparedValue>;
  prepare(value: PreparedValue): void;
  discard(name: string): void;
  clear(): void;
}

export const preparedValues = createStore<PreparedState>()((set, get) => ({
  values: new Map(),
  prepare: (value) => {
    const values = new Map(get().values);
    if (value.text.trim() === '') values.delete(value.name.toUpperCase());
    else values.set(value.name.toUpperCase(), value);
    set({ values });
  },
  discard: (name) => {
    if (!get().values.has(name.toUpperCase())) return;
    const values = new Map(get().values);
    values.delete(name.toUpperCase());
    set({ values });
  },
  clear: () => set({ values: new Map() }),
}));

/**
 * The device address when the prepared value's variable is a field input now, as it is written or
 * forced: a value typed before the hardware was attached must not slip past the confirmation.
 */
function fieldOf(sim: SimStore, v: PreparedValue): string | undefined {
  const s = sim.getState();
  return fieldInputAddress(s.layout?.variables[s.variableIndex.get(v.name.toUpperCase()) ?? -1]) ?? v.field;
}

/** A field output of attached hardware: its write or force waits for the confirmation (outputForce.ts). */
function outputOf(sim: SimStore, v: PreparedValue): string | undefined {
  const s = sim.getState();
  return fieldOutputAddress(s.layout?.variables[s.variableIndex.get(v.name.toUpperCase()) ?? -1]);
}

/** What writing or forcing the prepared values did, as the status line says it. */
export interface PreparedOutcome {
  readonly done: readonly string[];
  /** Field outputs of attached hardware sent for confirmation ("Motor (%QX0.0)"). */
  readonly asked?: readonly string[];
  /** Names left prepared, with why. */
  readonly kept: readonly { readonly name: string; readonly why: string }[];
}

/**
 * Why a prepared value cannot be written as typed ("abc" for an INT, 2 for a BOOL), or undefined: it
 * is checked against the running program's type of the name before anything is sent, so a value the
 * simulator would refuse stays prepared with the reason instead of being reported written.
 */
function refusal(sim: SimStore, v: PreparedValue): string | undefined {
  if (!('text' in v.input)) return undefined;
  const type = typeOfName(sim.getState().layout, v.name);
  if (!type || !isElementaryType(type)) return undefined;
  const parsed = parseValueText(type, v.input.text);
  return parsed.ok ? undefined : parsed.message;
}

/** Ctrl+F7: writes every prepared value once (an input: at the next input read) and clears them. */
export function writePrepared(sim: SimStore): PreparedOutcome {
  const done: string[] = [];
  const asked: string[] = [];
  const kept: { name: string; why: string }[] = [];
  for (const v of preparedValues.getState().values.values()) {
    const field = fieldOf(sim, v);
    if (field) {
      kept.push({ name: v.name, why: `a field input (${field}) comes from the device: force it with its row's Force on hardware` });
      continue;
    }
    const why = refusal(sim, v);
    if (why) {
      kept.push({ name: v.name, why });
      continue;
    }
    const output = outputOf(sim, v);
    sim.getState().write(v.name, v.input);
    preparedValues.getState().discard(v.name);
    if (output) asked.push(`${v.name} (${output})`);
    else done.push(v.name);
  }
  return { done, kept, asked };
}

/** F7: forces every prepared value (it keeps the value whatever the program does) and clears them. */
export function forcePrepared(sim: SimStore): PreparedOutcome {
  const done: string[] = [];
  const asked: string[] = [];
  const kept: { name: string; why: string }[] = [];
  for (const v of preparedValues.getState().values.values()) {
    if (v.pin) {
      kept.push({ name: v.name, why: 'function block pins cannot be forced' });
      continue;
    }
    const field = fieldOf(sim, v);
    if (field) {
      kept.push({ name: v.name, why: `forcing a field input (${field}) drives outputs on the hardware: confirm with its row's Force on hardware` });
      continue;
    }
    const why = refusal(sim, v);
    if (why) {
      kept.push({ name: v.name, why });
      continue;
    }
    const output = outputOf(sim, v);
    sim.getState().force(v.name, v.input);
    preparedValues.getState().discard(v.name);
    if (output) asked.push(`${v.name} (${output})`);
    else done.push(v.name);
  }
  return { done, kept, asked };
}

/** The status line after writing or forcing. */
export function preparedMessage(verb: 'Wrote' | 'Forced', outcome: PreparedOutcome): string {
  const asked = outcome.asked ?? [];
  if (outcome.done.length === 0 && outcome.kept.length === 0 && asked.length === 0)
    return `No prepared values: type one in the Watch table's "Prepared value" column, then press ${verb === 'Wrote' ? 'Ctrl+F7' : 'F7'}.`;
  const done = outcome.done.length ? `${verb} ${outcome.done.join(', ')}.` : '';
  const kept = outcome.kept.map((k) => `${k.name} not ${verb === 'Wrote' ? 'written' : 'forced'}: ${k.why}.`).join(' ');
  const ask = asked.length ? `${asked.join(', ')}: a real output, ${verb === 'Wrote' ? 'written' : 'forced'} only when you confirm it.` : '';
  return [done, ask, kept].filter(Boolean).join(' ');
}
