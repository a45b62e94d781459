// Online change keeps instance state (issue 10): which FB instances and edge memories of a new
// program take over the old program's state. Identity, never position: an FB instance is its
// declared name (and must keep its FB type); an edge element is its element id in the document
// (and must keep its symbol and operand). Everything else starts from its initial state.
import type { PlcState, ResetReason, StateItem, StateTransfer } from '../api';
import type { CompiledProgram } from '../compile/program';
import type { Memory } from './memory';

/** The state items of a compiled program: FB instances in declaration order, then edge elements. */
export function stateItemsOf(program: CompiledProgram): StateItem[] {
  const items: StateItem[] = program.symbols.fbs.map((f) => ({
    kind: 'fb',
    key: f.name.toUpperCase(),
    type: f.type.toUpperCase(),
    label: f.name,
  }));
  for (const e of program.edges)
    items.push({
      kind: 'edge',
      key: e.elementId,
      type: e.symbol,
      operand: e.operand,
      network: e.network,
      label: `${e.symbol} ${e.operand || '?'} in network ${e.network + 1}`,
    });
  return items;
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
  return {
    fbs: program.symbols.fbs.map((f, i) => ({ item: items[i]!, fields: mem.fbs[f.index]!.saveState(timeBase) })),
    edges: program.edges.map((_, i) => ({ item: items[fbCount + i]!, memory: mem.edges[i] === 1 })),
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
  const edgeIndex = new Map<string, number>();
  program.edges.forEach((e, i) => edgeIndex.has(`edge:${e.elementId}`) || edgeIndex.set(`edge:${e.elementId}`, i));
  for (const item of plan.kept) {
    const id = identity(item);
    if (item.kind === 'fb') mem.fbs[fbIndex.get(id)!]!.loadState(fbFields.get(id)!, timeBase);
    else mem.edges[edgeIndex.get(id)!] = edgeMemory.get(id) ? 1 : 0;
  }
  return plan;
}
