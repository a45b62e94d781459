// Wires the ladder grid cannot route: drawn through IEC connector/continuation pairs (`>NAME>`).
// A cut input pin loses its wire on the grid: its sources feed a connector drawn right after them,
// and a continuation of the same name, drawn in the cell left of the pin, feeds the pin (a pin whose
// sources also feed other ORs gets one connector per source, and their continuations OR-ed at the
// pin; where those continuations, stacked below the pin, would reach another input pin of the
// same block, they are OR-ed into a relay connector drawn on its own, and one continuation of
// the relay feeds the pin). The engine carries a connector's state to its continuations one way
// (src/engine/compile/graph.ts, wires.ts), so the graph it compiles is the file's; evaluation
// follows that graph, not where the pair sits (LD-SEMANTICS section 1). Cuts are made on a view
// of the nodes: the file's nodes stay as read, for verification.
import type { GNode, GSource } from './ldNodes';
import { srcKey } from './ldNormalize';
import type { Mismatch } from './verifyLayout';

/** Rounds of cutting the pins the grid drew wrongly before every wire between elements is cut. */
export const CUT_ROUNDS = 3;

/** An input pin to draw through a connector pair. */
export interface CutPin {
  readonly node: number;
  readonly pin: string;
}

/** The nodes of a network with some input pins cut: a view over `nodes`, and the members to lay out. */
export interface CutView {
  readonly nodes: readonly GNode[];
  readonly members: readonly number[];
}

const IDENT = /^[A-Za-z_][A-Za-z0-9_]*$/;

/**
 * Rows free below an input pin for continuations stacked under it: the distance to the next input
 * pin of the same element below it (Infinity when there is none; see layoutRows.ts, fits).
 */
export type StackRoom = (node: GNode, pin: string) => number;

/**
 * The view with `cuts` drawn through connector pairs: one connector per distinct set of sources
 * (named after the file's own connector when the file wired the pin through one, else C1, C2, …,
 * unique in the network), one continuation per cut pin — or, for a pin fed by several connectors
 * whose continuations have no room to be stacked under it (`room`), one continuation of a relay
 * connector that ORs theirs.
 */
export function cutView(
  nodes: readonly GNode[],
  members: readonly number[],
  cuts: readonly CutPin[],
  room: StackRoom = () => Infinity,
): CutView {
  if (!cuts.length) return { nodes, members };
  const view = nodes.slice();
  const extra: number[] = [];
  const clones = new Map<number, GNode>();
  const connectorOf = new Map<string, GNode>();
  let setsOf: Map<string, Set<string>> | undefined;
  // Names the file gave its connectors are kept; generated names (C1, C2, …) avoid them.
  const reserved = new Set<string>();
  for (const c of cuts) {
    const wanted = nodes[c.node]!.via?.[c.pin];
    if (wanted && IDENT.test(wanted)) reserved.add(wanted.toUpperCase());
  }
  const used = new Set<string>();
  let counter = 0;
  const nameFor = (wanted: string | undefined): string => {
    if (wanted && IDENT.test(wanted) && !used.has(wanted.toUpperCase())) {
      used.add(wanted.toUpperCase());
      return wanted;
    }
    let name: string;
    do name = `C${++counter}`;
    while (used.has(name) || reserved.has(name));
    used.add(name);
    return name;
  };
  const add = (n: GNode) => {
    view.push(n);
    extra.push(n.index);
  };
  for (const { node, pin } of cuts) {
    const orig = nodes[node]!;
    const srcs = (clones.get(node) ?? orig).inputs.get(pin);
    if (!srcs?.length) continue;
    let clone = clones.get(node);
    if (!clone) {
      clone = { ...orig, inputs: new Map(orig.inputs) };
      clones.set(node, clone);
      view[node] = clone;
    }
    // One connector for the pin's whole set of sources, when each of them feeds only pins of that
    // same set; else one per source, OR-ed at the pin by their continuations (a vertical link is
    // one-way, so the continuations of a source shared by two ORs do not join those ORs).
    const key = srcs.map(srcKey).sort().join(' ');
    const groups = srcs.length > 1 && !onlyThisSet(key, srcs) ? srcs.map((x) => [x]) : [srcs];
    // Continuations stacked under a pin OR at its bar: where the stack would reach the block's
    // next input pin, that bar would join the two pins, so the stack feeds a relay instead.
    const relay = groups.length > 1 && room(orig, pin) < groups.length;
    const fed: GSource[] = [];
    for (const group of groups) {
      const gkey = group.length === srcs.length ? key : srcKey(group[0]!);
      let conn = connectorOf.get(gkey);
      if (!conn) {
        const first = group.find((x) => x.kind === 'node');
        const at = first && first.kind === 'node' ? nodes[first.node]! : orig;
        const name = nameFor(relay ? undefined : orig.via?.[pin]);
        conn = drawn(view.length, 'connector', name, at, 0.5, new Map([['in', [...group]]]));
        connectorOf.set(gkey, conn);
        add(conn);
      }
      const cont = drawn(view.length, 'continuation', conn.name!, orig, -0.5, new Map());
      add(cont);
      fed.push({ kind: 'node', node: cont.index, pin: 'out' });
    }
    if (relay) {
      // Drawn on rows of its own (placed by position: just left of the pin it feeds).
      const hub = drawn(view.length, 'connector', nameFor(orig.via?.[pin]), orig, -0.75, new Map([['in', fed]]));
      add(hub);
      const cont = drawn(view.length, 'continuation', hub.name!, orig, -0.5, new Map());
      add(cont);
      clone.inputs.set(pin, [{ kind: 'node', node: cont.index, pin: 'out' }]);
    } else clone.inputs.set(pin, fed);
  }
  return { nodes: view, members: [...members, ...extra] };

  /** True when every source of the set feeds only pins wired from exactly this set. */
  function onlyThisSet(key: string, srcs: readonly GSource[]): boolean {
    if (!setsOf) {
      setsOf = new Map();
      for (const i of members)
        for (const list of nodes[i]!.inputs.values()) {
          const k = list.map(srcKey).sort().join(' ');
          for (const x of list) {
            const sk = srcKey(x);
            const sets = setsOf.get(sk);
            if (sets) sets.add(k);
            else setsOf.set(sk, new Set([k]));
          }
        }
    }
    return srcs.every((x) => [...(setsOf!.get(srcKey(x)) ?? [])].every((k) => k === key));
  }
}

/** Every input pin of the network wired from another element (the cut that always draws). */
export function allNodeWires(nodes: readonly GNode[], members: readonly number[]): CutPin[] {
  const out: CutPin[] = [];
  for (const i of members)
    for (const [pin, srcs] of nodes[i]!.inputs) if (srcs.some((s) => s.kind === 'node')) out.push({ node: i, pin });
  return out;
}

/**
 * Adds to `cuts` the pins of these mismatches that the file wires, and every pin the file feeds
 * from a source the grid joined where it should not (that source's wire crossed another).
 */
export function addCuts(
  nodes: readonly GNode[],
  members: readonly number[],
  mismatches: readonly Mismatch[],
  cuts: CutPin[],
): void {
  const have = new Set(cuts.map((c) => `${c.node}<${c.pin}`));
  const cut = (node: number, pin: string) => {
    const k = `${node}<${pin}`;
    if (have.has(k) || !nodes[node]!.inputs.get(pin)?.length) return;
    have.add(k);
    cuts.push({ node, pin });
  };
  const stray = new Set<string>();
  for (const m of mismatches) {
    if (m.pin === 'in' && !m.extra.length && !m.missing.length && !m.leftward)
      for (const pin of nodes[m.node]!.inputs.keys()) cut(m.node, pin); // could not be placed
    cut(m.node, m.pin);
    for (const s of m.extra) if (s.kind === 'node') stray.add(srcKey(s));
  }
  if (stray.size)
    for (const i of members)
      for (const [pin, srcs] of nodes[i]!.inputs) if (srcs.some((s) => stray.has(srcKey(s)))) cut(i, pin);
}

/** A connector or continuation node drawn beside `at` (right of it: dx > 0; left: dx < 0). */
function drawn(
  index: number,
  kind: 'connector' | 'continuation',
  name: string,
  at: GNode,
  dx: number,
  inputs: Map<string, GSource[]>,
): GNode {
  return {
    index,
    obj: at.obj,
    kind,
    name,
    inputs,
    operandsIn: {},
    operandsOut: {},
    x: at.x + dx,
    y: at.y,
    order: at.order,
    feedsRightRail: false,
  };
}
