// Online change keeps instance state (issue 10): which FB instances and edge memories of a new
// program take over the old program's state. Identity, never position: an FB instance is its
// declared name (and must keep its FB type); an edge element is its element id in the document
// (and must keep its symbol and operand). Everything else starts from its initial state.
import type { PlcState, ResetReason, StateItem, StateTransfer } from '../api';
import type { CompiledProgram } from '../compile/program';
import type { Memory } from './memory';
import type { UfbSymbol, VarSymbol } from '../compile/symbols';

/**
 * The state items of a compiled program: standard FB instances in declaration order (nested ones
 * by path, `MOTOR1.T1`), then user FB instances (their variables), then edge elements (inside an
 * FB body: one per instance, keyed `MOTOR1/element id`).
 */
const itemsMemo = new WeakMap<CompiledProgram, readonly StateItem[]>();

/**
 * The state items of a compiled program (made once per program: planning an online change and
 * carrying the state at the scan boundary both ask, and a compiled program never changes).
 */
export function stateItemsOf(program: CompiledProgram): readonly StateItem[] {
  let items = itemsMemo.get(program);
  if (!items) {
    items = makeStateItems(program);
    itemsMemo.set(program, items);
  }
  return items;
}

function makeStateItems(program: CompiledProgram): StateItem[] {
  const items: StateItem[] = program.symbols.fbs.map((f) => ({
    kind: 'fb',
    key: f.name.toUpperCase(),
    type: f.type.toUpperCase(),
    label: f.name,
  }));
  for (const u of userInstances(program))
    items.push({ kind: 'fb', key: u.name.toUpperCase(), type: u.type.toUpperCase(), label: u.name });
  for (const e of program.edges)
    items.push({
      kind: 'edge',
      key: e.instance ? `${e.instance.toUpperCase()}/${e.elementId}` : e.elementId,
      type: e.symbol,
      operand: e.operand,
      network: e.network,
      label: `${e.symbol} ${e.operand || '?'} in network ${e.network + 1}${e.instance ? ` of ${e.instance} (${e.pou})` : ''}`,
    });
  return items;
}

/** User FB instances (not program instances of a configuration). */
function userInstances(program: CompiledProgram): UfbSymbol[] {
  return program.symbols.storage.ufbs.filter((u) => u.pou.kind === 'FUNCTION_BLOCK');
}

/** A user FB instance's own variables (not nested instances, which are items of their own). */
function ownVars(u: UfbSymbol): VarSymbol[] {
  const out: VarSymbol[] = [];
  for (const [, m] of u.scope.ownNames()) if (m.kind === 'var') out.push(m);
  return out;
}

function saveVars(u: UfbSymbol, mem: Memory): Record<string, number | boolean | string> {
  const out: Record<string, number | boolean | string> = {};
  for (const v of ownVars(u)) {
    const value = mem.load(v);
    const key = v.name.slice(u.name.length + 1).toUpperCase();
    if (typeof value === 'bigint') {
      out[`${key}$hi`] = Number(value >> 32n);
      out[`${key}$lo`] = Number(value & 0xffffffffn);
    } else out[key] = value;
  }
  return out;
}

function loadVars(u: UfbSymbol, mem: Memory, fields: Readonly<Record<string, number | boolean | string>>): void {
  for (const v of ownVars(u)) {
    const key = v.name.slice(u.name.length + 1).toUpperCase();
    const plain = fields[key];
    const hi = fields[`${key}$hi`];
    const lo = fields[`${key}$lo`];
    if (v.store === 'g' && typeof hi === 'number' && typeof lo === 'number')
      mem.store(v, BigInt.asIntN(64, (BigInt(hi) << 32n) + BigInt(lo)));
    else if (v.store === 'b' && typeof plain === 'boolean') mem.store(v, plain);
    else if (v.store === 'n' && typeof plain === 'number') mem.store(v, plain);
    else if (v.store === 'g' && typeof plain === 'string') mem.store(v, plain);
  }
}

const identity = (item: StateItem) => `${item.kind}:${item.key}`;
const sameOperand = (a: StateItem, b: StateItem) => (a.operand ?? '').toUpperCase() === (b.operand ?? '').toUpperCase();

/** Compares an old program's state items with a new one's: kept, reset (with the reason) and removed. */
export function planStateTransfer(from: readonly StateItem[], to: readonly StateItem[]): StateTransfer {
  const before = new Map<string, StateItem>();
  for (const item of from) if (!before.has(identity(item))) before.set(identity(item), item);
  const matched = new Set<string>();
  const kept: StateItem[] = [];
  const reset: { item: StateItem; reason: ResetReason; detail: string }[] = [];
  for (const item of to) {
    const id = identity(item);
    const old = matched.has(id) ? undefined : before.get(id);
    matched.add(id);
    if (!old) reset.push({ item, reason: 'new', detail: 'new' });
    else if (old.type !== item.type) reset.push({ item, reason: 'type-changed', detail: `${old.type} → ${item.type}` });
    else if (!sameOperand(old, item))
      reset.push({ item, reason: 'operand-changed', detail: `now ${item.operand || '?'}, was ${old.operand || '?'}` });
    else kept.push(item);
  }
  const removed = from.filter((item) => !matched.has(identity(item)));
  return { kept, reset, removed };
}

/** The state of a PLC's memory; `timeBase` is the time the next scan would start at. */
export function exportMemory(program: CompiledProgram, mem: Memory, timeBase: number): PlcState {
  const items = stateItemsOf(program);
  const fbCount = program.symbols.fbs.length;
  const users = userInstances(program);
  return {
    fbs: [
      ...program.symbols.fbs.map((f, i) => ({ item: items[i]!, fields: mem.fbs[f.index]!.saveState(timeBase) })),
      ...users.map((u, i) => ({ item: items[fbCount + i]!, fields: saveVars(u, mem) })),
    ],
    edges: program.edges.map((_, i) => ({ item: items[fbCount + users.length + i]!, memory: mem.edges[i] === 1 })),
  };
}

/** Loads the kept items of `state` into a PLC's memory (the others stay as they are). */
export function importMemory(program: CompiledProgram, mem: Memory, state: PlcState, timeBase: number): StateTransfer {
  const items = stateItemsOf(program);
  const plan = planStateTransfer(
    [...state.fbs.map((f) => f.item), ...state.edges.map((e) => e.item)],
    items,
  );
  const fbFields = new Map(state.fbs.map((f) => [identity(f.item), f.fields]));
  const edgeMemory = new Map(state.edges.map((e) => [identity(e.item), e.memory]));
  const fbIndex = new Map(program.symbols.fbs.map((f, i) => [identity(items[i]!), f.index]));
  const users = new Map(userInstances(program).map((u) => [`fb:${u.name.toUpperCase()}`, u]));
  const edgeIndex = new Map<string, number>();
  const fbCount = program.symbols.fbs.length + users.size;
  program.edges.forEach((_, i) => {
    const id = identity(items[fbCount + i]!);
    if (!edgeIndex.has(id)) edgeIndex.set(id, i);
  });
  for (const item of plan.kept) {
    const id = identity(item);
    const user = users.get(id);
    if (item.kind === 'fb' && user) loadVars(user, mem, fbFields.get(id)!);
    // A standard FB's fields are numbers and booleans (its saveState gave them).
    else if (item.kind === 'fb') mem.fbs[fbIndex.get(id)!]!.loadState(fbFields.get(id)! as Readonly<Record<string, number | boolean>>, timeBase);
    else mem.edges[edgeIndex.get(id)!] = edgeMemory.get(id) ? 1 : 0;
  }
  return plan;
}
