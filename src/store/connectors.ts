// Connectors and continuations `>NAME>` in the editor: the name a new one gets, the partners of
// one (the continuations of a connector, the connector of a continuation), renaming a connector
// with its continuations as one undo step. Names compare as IEC identifiers (case-insensitive),
// within one network (LD-R14).
import type { ConnectorElement, ContinuationElement, LdElement } from '../model/elements';
import type { ElementId, PouId } from '../model/ids';
import type { Network } from '../model/project';
import type { DocumentStore } from './documentStore';
import type { ElementTemplate } from './networkEdits';

export type ConnectionElement = ConnectorElement | ContinuationElement;

export const isConnection = (el: Pick<LdElement, 'kind'>): el is ConnectionElement =>
  el.kind === 'connector' || el.kind === 'continuation';

const key = (name: string) => name.trim().toUpperCase();

const connections = (n: Network, kind: ConnectionElement['kind']): ConnectionElement[] =>
  n.elements.filter((e): e is ConnectionElement => e.kind === kind);

/**
 * The name a new connector or continuation gets in network `n`: a connector the first free
 * `C1`, `C2`… (free of every connector and continuation name); a continuation the name of the
 * network's only connector that no continuation reads yet, else '' (the user types it).
 */
export function defaultConnectionName(n: Network, kind: ConnectionElement['kind']): string {
  if (kind === 'connector') {
    const used = new Set(n.elements.filter(isConnection).map((e) => key(e.name)));
    let i = 1;
    while (used.has(`C${i}`)) i++;
    return `C${i}`;
  }
  const read = new Set(connections(n, 'continuation').map((e) => key(e.name)));
  const open = connections(n, 'connector').filter((c) => c.name.trim() && !read.has(key(c.name)));
  return open.length === 1 ? open[0]!.name.trim() : '';
}

/** Names offered while naming `el`: a continuation the network's connector names, a connector none. */
export function connectionNamesFor(n: Network, el: Pick<LdElement, 'kind'>): string[] {
  if (el.kind !== 'continuation') return [];
  return [...new Set(connections(n, 'connector').map((c) => c.name.trim()).filter(Boolean))];
}

/** The template with its default name when it is an unnamed connector or continuation. */
export function withDefaultName(n: Network, t: ElementTemplate): ElementTemplate {
  if ((t.kind !== 'connector' && t.kind !== 'continuation') || t.name.trim()) return t;
  return { ...t, name: defaultConnectionName(n, t.kind) };
}

/**
 * Elements pasted into network `n`: a pasted connector whose name the network already uses gets
 * the next free name, and the continuations pasted with it follow, so a copied pair stays a pair
 * and the original keeps its own (one connector per name, LD-R14). Other pasted continuations
 * keep their names: they read the network's connector of that name.
 */
export function renamePastedConnectors<T extends LdElement>(n: Network, pasted: readonly T[]): T[] {
  const taken = (name: string) => n.elements.some((e) => e.kind === 'connector' && key(e.name) === key(name));
  const renames = new Map<string, string>();
  let scratch: Network = n;
  for (const el of pasted) {
    if (el.kind !== 'connector' || !key(el.name) || !taken(el.name) || renames.has(key(el.name))) continue;
    const name = defaultConnectionName(scratch, 'connector');
    renames.set(key(el.name), name);
    scratch = { ...scratch, elements: [...scratch.elements, { ...el, name }] };
  }
  if (renames.size === 0) return [...pasted];
  return pasted.map((el) => (isConnection(el) && renames.has(key(el.name)) ? { ...el, name: renames.get(key(el.name))! } : el));
}

/** The other side(s) of a connector or continuation in its network, in grid order. */
export function partnersOf(n: Network, el: LdElement): ConnectionElement[] {
  if (!isConnection(el) || !key(el.name)) return [];
  const other = el.kind === 'connector' ? 'continuation' : 'connector';
  return connections(n, other)
    .filter((e) => key(e.name) === key(el.name))
    .sort((a, b) => a.row - b.row || a.col - b.col);
}

/** `R3C1`: a cell as the diagnostics name it (1-based). */
export const cellName = (el: Pick<LdElement, 'row' | 'col'>) => `R${el.row + 1}C${el.col + 1}`;

/** `Connector >C> → 2 continuations (R3C1, R4C1)`, `Continuation >C> ← connector (R1C3)`. */
export function partnerWords(n: Network, el: ConnectionElement): string {
  const partners = partnersOf(n, el);
  const name = `>${el.name.trim() || 'NAME'}>`;
  const at = partners.map(cellName).join(', ');
  if (el.kind === 'connector') {
    const count = partners.length === 1 ? '1 continuation' : `${partners.length} continuations`;
    return `Connector ${name} → ${partners.length ? `${count} (${at})` : 'no continuation'}`;
  }
  return `Continuation ${name} ← ${partners.length ? `connector (${at})` : 'no connector'}`;
}

/**
 * The network with connector/continuation `id` renamed to `name`; with `pair`, a connector's
 * continuations (those that read its old name) are renamed too. Undefined when `id` is not one.
 */
export function renameConnectionIn(n: Network, id: ElementId, name: string, pair: boolean): Network | undefined {
  const el = n.elements.find((e) => e.id === id);
  if (!el || !isConnection(el)) return undefined;
  const follow = new Set(pair && el.kind === 'connector' ? partnersOf(n, el).map((p) => p.id) : []);
  const to = name.trim();
  return {
    ...n,
    elements: n.elements.map((e) => (e.id === id || follow.has(e.id) ? { ...e, name: to } : e)),
  };
}

/** The network and POU holding element `id`. */
export function networkOfElement(
  doc: DocumentStore,
  id: ElementId,
): { pou: PouId; network: Network } | undefined {
  for (const pou of doc.getState().project.pous)
    for (const network of pou.networks)
      if (network.elements.some((e) => e.id === id)) return { pou: pou.id, network };
  return undefined;
}

/** Renames a connector (with its continuations when `pair`) or a continuation: one undo step. */
export function renameConnection(doc: DocumentStore, id: ElementId, name: string, pair = true): boolean {
  const found = networkOfElement(doc, id);
  const after = found && renameConnectionIn(found.network, id, name, pair);
  if (!found || !after) return false;
  const el = found.network.elements.find((e) => e.id === id)!;
  const what = pair && el.kind === 'connector' && partnersOf(found.network, el).length ? 'renameConnectorPair' : 'renameConnection';
  return doc.getState().replaceNetworks(what, [{ pou: found.pou, before: found.network, after }]);
}
