// What an online change changes, document against document (the program running against the one
// shown): networks changed, added and removed per POU, POUs added and removed, variables new,
// removed or retyped. Shown before "apply on request" applies an edit and counted in the banner
// that says the running program is not the one on screen. Titles, comments and collapsed state are
// not changes (they change nothing the PLC does: programFingerprint leaves them out too, see behaviourPrint).
import type { Network, Pou, Project, Variable } from '../model/project';
import { behaviourPrint } from './layout';

export interface PouChanges {
  readonly pou: string;
  /** 1-based numbers in the shown document. */
  readonly changed: readonly number[];
  readonly added: readonly number[];
  /** 1-based numbers in the running document. */
  readonly removed: readonly number[];
  /** The whole body (ST, IL, SFC, or the POU's kind or return type) differs. */
  readonly body: boolean;
  readonly newVariables: readonly string[];
  readonly removedVariables: readonly string[];
  /** `Name: INT → DINT`, an address or initial value changed. */
  readonly changedVariables: readonly string[];
}

export interface ChangeList {
  readonly pous: readonly PouChanges[];
  readonly addedPous: readonly string[];
  readonly removedPous: readonly string[];
  readonly globals: Pick<PouChanges, 'newVariables' | 'removedVariables' | 'changedVariables'>;
  /** Anything else the program depends on (tasks, data types, the profile). */
  readonly other: readonly string[];
  /** How many edits: each network, POU, variable and other item counts once. */
  readonly count: number;
}

const NO_CHANGES: ChangeList = {
  pous: [],
  addedPous: [],
  removedPous: [],
  globals: { newVariables: [], removedVariables: [], changedVariables: [] },
  other: [],
  count: 0,
};

/** Networks and variables by what they do (fingerprints cached per object: documents are immutable). */
const prints = new WeakMap<object, string>();
function print(x: object): string {
  let p = prints.get(x);
  if (p === undefined) {
    p = behaviourPrint(x);
    prints.set(x, p);
  }
  return p;
}

const upper = (s: string) => s.toUpperCase();

function variableChanges(before: readonly Variable[], after: readonly Variable[]): Pick<PouChanges, 'newVariables' | 'removedVariables' | 'changedVariables'> {
  const old = new Map(before.map((v) => [upper(v.name), v]));
  const now = new Map(after.map((v) => [upper(v.name), v]));
  const newVariables: string[] = [];
  const changedVariables: string[] = [];
  for (const v of after) {
    const o = old.get(upper(v.name));
    if (!o) newVariables.push(v.name);
    else if (o !== v && print(o) !== print(v)) {
      const what: string[] = [];
      if (o.type !== v.type) what.push(`${o.type} → ${v.type}`);
      if ((o.location ?? '') !== (v.location ?? '')) what.push(`address ${o.location || 'none'} → ${v.location || 'none'}`);
      if ((o.initial ?? '') !== (v.initial ?? '')) what.push(`initial value ${o.initial || 'default'} → ${v.initial || 'default'}`);
      if (o.varClass !== v.varClass) what.push(`${o.varClass} → ${v.varClass}`);
      if (what.length === 0) what.push('declaration changed');
      changedVariables.push(`${v.name}: ${what.join(', ')}`);
    }
  }
  const removedVariables = before.filter((v) => !now.has(upper(v.name))).map((v) => v.name);
  return { newVariables, removedVariables, changedVariables };
}

function networkChanges(before: readonly Network[], after: readonly Network[]): Pick<PouChanges, 'changed' | 'added' | 'removed'> {
  const old = new Map(before.map((n, i) => [n.id, { n, i }]));
  const now = new Set(after.map((n) => n.id));
  const changed: number[] = [];
  const added: number[] = [];
  after.forEach((n, i) => {
    const o = old.get(n.id);
    if (!o) added.push(i + 1);
    else if (o.n !== n && print(o.n) !== print(n)) changed.push(i + 1);
  });
  const removed = before.flatMap((n, i) => (now.has(n.id) ? [] : [i + 1]));
  // Networks moved: their order is what runs, so a moved network counts as changed.
  const keptOrder = after.filter((n) => old.has(n.id)).map((n) => n.id);
  const oldOrder = before.filter((n) => now.has(n.id)).map((n) => n.id);
  keptOrder.forEach((id, k) => {
    if (oldOrder[k] !== id) {
      const i = after.findIndex((n) => n.id === id) + 1;
      if (!changed.includes(i)) changed.push(i);
    }
  });
  changed.sort((a, b) => a - b);
  return { changed, added, removed };
}

function pouChanges(before: Pou, after: Pou): PouChanges | undefined {
  if (before === after) return undefined;
  const nets = networkChanges(before.networks, after.networks);
  const { networks: _b, variables: _bv, ...beforeRest } = before;
  const { networks: _a, variables: _av, ...afterRest } = after;
  const body = print(beforeRest) !== print(afterRest);
  const vars = variableChanges(before.variables, after.variables);
  const c: PouChanges = { pou: after.name, ...nets, body, ...vars };
  return countOf(c) === 0 ? undefined : c;
}

function countOf(c: Pick<PouChanges, 'newVariables' | 'removedVariables' | 'changedVariables'> & Partial<PouChanges>): number {
  return (
    (c.changed?.length ?? 0) +
    (c.added?.length ?? 0) +
    (c.removed?.length ?? 0) +
    (c.body ? 1 : 0) +
    c.newVariables.length +
    c.removedVariables.length +
    c.changedVariables.length
  );
}

/** The changes from the running document to the shown one (POUs matched by id, networks by id, variables by name). */
export function changeList(running: Project, shown: Project): ChangeList {
  if (running === shown) return NO_CHANGES;
  const old = new Map(running.pous.map((p) => [p.id, p]));
  const now = new Set(shown.pous.map((p) => p.id));
  const pous: PouChanges[] = [];
  const addedPous: string[] = [];
  for (const p of shown.pous) {
    const o = old.get(p.id);
    if (!o) addedPous.push(p.name);
    else {
      const c = pouChanges(o, p);
      if (c) pous.push(c);
    }
  }
  const removedPous = running.pous.filter((p) => !now.has(p.id)).map((p) => p.name);
  const globals = running.globals === shown.globals ? NO_CHANGES.globals : variableChanges(running.globals, shown.globals);
  const other: string[] = [];
  if (running.tasks !== shown.tasks && print(running.tasks) !== print(shown.tasks)) other.push('tasks');
  if (running.dataTypes !== shown.dataTypes && print(running.dataTypes ?? []) !== print(shown.dataTypes ?? [])) other.push('data types');
  if (running.profile !== shown.profile) other.push(`profile ${running.profile} → ${shown.profile}`);
  if (running.externalBlocks !== shown.externalBlocks && print(running.externalBlocks ?? []) !== print(shown.externalBlocks ?? [])) other.push('external blocks');
  const count = pous.reduce((n, c) => n + countOf(c), 0) + addedPous.length + removedPous.length + countOf(globals) + other.length;
  return { pous, addedPous, removedPous, globals, other, count };
}

/** "N3 changed, N12 added" lines per POU, for the dialog and the banner's title. */
export function describeChanges(c: ChangeList): string[] {
  const nets = (label: string, ns: readonly number[]) => (ns.length ? [`${label} ${ns.map((n) => `${n}`).join(', ')}`] : []);
  const vars = (label: string, vs: readonly string[]) => (vs.length ? [`${label} ${vs.join(', ')}`] : []);
  const lines: string[] = [];
  for (const p of c.pous) {
    const parts = [
      ...nets(p.changed.length === 1 ? 'network changed:' : 'networks changed:', p.changed),
      ...nets(p.added.length === 1 ? 'network added:' : 'networks added:', p.added),
      ...nets(p.removed.length === 1 ? 'network removed:' : 'networks removed:', p.removed),
      ...(p.body ? ['body or interface changed'] : []),
      ...vars('new variables:', p.newVariables),
      ...vars('variables removed:', p.removedVariables),
      ...vars('variables changed:', p.changedVariables),
    ];
    lines.push(`${p.pou}: ${parts.join('; ')}`);
  }
  if (c.addedPous.length) lines.push(`POUs added: ${c.addedPous.join(', ')}`);
  if (c.removedPous.length) lines.push(`POUs removed: ${c.removedPous.join(', ')}`);
  const g = [...vars('new:', c.globals.newVariables), ...vars('removed:', c.globals.removedVariables), ...vars('changed:', c.globals.changedVariables)];
  if (g.length) lines.push(`Global variables: ${g.join('; ')}`);
  if (c.other.length) lines.push(`Also changed: ${c.other.join(', ')}`);
  return lines;
}

/** Network ids of the shown document that differ from the running one (changed, moved or added): the networks to mark. */
export function changedNetworkIds(running: Project, shown: Project): Set<string> {
  const out = new Set<string>();
  if (running === shown) return out;
  const old = new Map(running.pous.map((p) => [p.id, p]));
  for (const p of shown.pous) {
    const o = old.get(p.id);
    if (o === p) continue;
    const before = new Map((o?.networks ?? []).map((n) => [n.id, n]));
    for (const n of p.networks) {
      const b = before.get(n.id);
      if (!b || (b !== n && print(b) !== print(n))) out.add(n.id);
    }
  }
  return out;
}
