// Layouts of repeated network shapes. Large programs repeat a few rung shapes thousands of times
// (a contact row into a coil, a timer into a coil); the layout of a network depends only on its
// shape: the kinds and block types of its nodes, their wiring, which of them feed the right rail,
// and the top-to-bottom order of their positions in the file. Networks of one shape get the same
// rows, columns, links and wiring check; only their element contents and ids differ.
import type { LdElement, VLink } from '../model/elements';
import { newId, type ElementId } from '../model/ids';
import type { GNode } from './ldNodes';
import { elementFor } from './layoutRows';
import type { LaidOut } from './layoutShapes';

/** A laid-out network in terms of its members' positions in the member list. */
export interface LayoutTemplate {
  readonly rows: number;
  readonly cols: number;
  /** Per element: member position (-1 for a link or a drawn connector/continuation), cell and id suffix. */
  readonly elements: readonly {
    readonly member: number;
    readonly row: number;
    readonly col: number;
    readonly suffix: string;
    /** A connector or continuation the layout drew (layoutCut.ts). */
    readonly pair?: { readonly kind: 'connector' | 'continuation'; readonly name: string };
  }[];
  readonly vlinks: readonly VLink[];
  /** Members placed where they touch another net. */
  readonly forced: readonly number[];
}

interface Entry {
  readonly needCols: number;
  readonly byCols: Map<number, LayoutTemplate>;
}

/** The shape of a network: equal keys, equal layouts. */
export function shapeKey(nodes: readonly GNode[], members: readonly number[]): string {
  const local = new Map<number, number>();
  for (let li = 0; li < members.length; li++) local.set(members[li]!, li);
  let key = '';
  for (const m of members) {
    const n = nodes[m]!;
    key += n.kind;
    if (n.kind === 'box') key += `:${n.blockType ?? ''}/${n.inputCount ?? ''}${n.executionControl ? '/en' : ''}`;
    if (n.feedsRightRail) key += '!';
    // An EN the file leaves out may be drawn open (importBody.ts): not the shape of a wired EN.
    if (n.implicitEn) key += '~';
    // The file's own connector names may name drawn pairs: networks with other names differ.
    if (n.via) key += JSON.stringify(n.via);
    key += '(';
    for (const [pin, srcs] of n.inputs) {
      key += `${pin}=`;
      for (const s of srcs) key += s.kind === 'rail' ? 'R,' : `${local.get(s.node) ?? 'X'}.${s.pin},`;
      key += ';';
    }
    key += ')';
  }
  // The order of the members by position in the file (rows follow it), ties marked.
  const order = members.map((_, li) => li);
  const cmp = (a: number, b: number): number => {
    const p = nodes[members[a]!]!;
    const q = nodes[members[b]!]!;
    return p.y - q.y || p.x - q.x || p.order - q.order;
  };
  order.sort((a, b) => cmp(a, b) || a - b);
  key += '|';
  for (let k = 0; k < order.length; k++)
    key += `${order[k]}${k + 1 < order.length && cmp(order[k]!, order[k + 1]!) === 0 ? '=' : ','}`;
  return key;
}

/** Layouts per shape key and width, for one import. */
export class LayoutCache {
  private readonly entries = new Map<string, Entry>();
  constructor(readonly enabled = true) {}

  needCols(key: string): number | undefined {
    return this.entries.get(key)?.needCols;
  }
  template(key: string, cols: number): LayoutTemplate | undefined {
    return this.entries.get(key)?.byCols.get(cols);
  }

  /** Records the layout of a network as the template of its shape (if it matches the file). */
  remember(
    key: string,
    needCols: number,
    members: readonly number[],
    laid: LaidOut,
    mismatches: readonly unknown[],
  ): void {
    if (!this.enabled) return;
    let entry = this.entries.get(key);
    if (!entry) this.entries.set(key, (entry = { needCols, byCols: new Map() }));
    // A layout that differs from the file is not shared: each network of the shape is laid out
    // and checked on its own, so its findings name its own elements.
    if (mismatches.length) return;
    const memberOf = new Map<ElementId, number>();
    const position = new Map<number, number>();
    members.forEach((m, li) => position.set(m, li));
    for (const [node, id] of laid.elementOf) memberOf.set(id, position.get(node)!);
    entry.byCols.set(laid.cols, {
      rows: laid.rows,
      cols: laid.cols,
      elements: laid.elements.map((e) => ({
        member: memberOf.get(e.id) ?? -1,
        row: e.row,
        col: e.col,
        suffix: e.id.slice(e.id.lastIndexOf('_')),
        ...(e.kind === 'connector' || e.kind === 'continuation' ? { pair: { kind: e.kind, name: e.name } } : {}),
      })),
      vlinks: laid.vlinks.map((v) => ({ ...v })),
      forced: laid.forced.map((node) => position.get(node)!),
    });
  }
}

/** A network of a known shape: the template's layout with this network's nodes. */
export function instantiate(t: LayoutTemplate, nodes: readonly GNode[], members: readonly number[]): LaidOut {
  const prefix = newId<'ElementId'>('e');
  const elementOf = new Map<number, ElementId>();
  const elements: LdElement[] = t.elements.map((e) => {
    const id = `${prefix}${e.suffix}` as ElementId;
    if (e.member === -1)
      return e.pair
        ? { id, kind: e.pair.kind, name: e.pair.name, row: e.row, col: e.col }
        : { id, kind: 'link', row: e.row, col: e.col };
    const node = members[e.member]!;
    elementOf.set(node, id);
    return elementFor(nodes[node]!, id, e.row, e.col);
  });
  return {
    rows: t.rows,
    cols: t.cols,
    elements,
    vlinks: t.vlinks.map((v) => ({ ...v })),
    elementOf,
    forced: t.forced.map((m) => members[m]!),
  };
}
