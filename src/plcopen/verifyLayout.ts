// Checking a laid-out network against the file, on every import: the grid is compiled into its
// element graph exactly as the engine does (src/engine/compile/graph.ts), and the sources of every
// input pin in that graph must be those wired in the file — no wire missing, none invented — with
// power running left to right (every source of a net ends at or left of every pin it feeds, so the
// grid never holds a branch fed from its right, LD-R01). Where the grid differs, the import says
// which pin of which element gains or loses which source.
import { buildGraph, upstream, type NetworkGraph } from '../engine/compile/graph';
import type { BlockLibrary } from '../model/library';
import type { Network } from '../model/project';
import type { LaidOut } from './layoutShapes';
import type { Finding, GNode, GSource } from './ldNodes';

/** A pin whose drawn sources differ from the file's. */
export interface Mismatch {
  readonly node: number;
  readonly pin: string;
  /** Sources the grid joins to the pin that the file does not wire to it. */
  readonly extra: readonly GSource[];
  /** Sources the file wires to the pin that the grid does not join to it. */
  readonly missing: readonly GSource[];
  /** The grid feeds the pin from its right (a source ends right of the pin). */
  readonly leftward?: boolean;
}

const describe = (n: GNode): string => {
  switch (n.kind) {
    case 'contact':
      return n.contact === 'NOT' ? 'NOT contact' : `contact "${n.variable}"`;
    case 'coil':
      return `coil "${n.variable}"`;
    case 'box':
      return `block ${n.instance ?? n.blockType}`;
    case 'jump':
      return `jump to ${n.target}`;
    case 'return':
      return 'return';
    case 'connector':
      return `connector ${n.name ?? ''}`;
    case 'continuation':
      return `continuation ${n.name ?? ''}`;
  }
};

/** The import's pin name of an engine terminal: 1-cell elements have "IN"/"OUT" there, "in"/"out" here. */
const pinName = (g: NetworkGraph, node: number, p: string) =>
  g.nodes[node]!.el.kind === 'box' ? p : p === 'IN' ? 'in' : p === 'OUT' ? 'out' : p;
const RAIL: GSource = { kind: 'rail' };

/** Checks that the grid, compiled as the engine compiles it, is exactly the wiring of the file. */
export function verify(
  nodes: readonly GNode[],
  members: readonly number[],
  laid: LaidOut,
  library: BlockLibrary,
): Mismatch[] {
  const g = buildGraph(laid as Pick<Network, 'rows' | 'cols' | 'elements' | 'vlinks'> as Network, library);
  const W = laid.cols + 1;
  // Member node of each element (by element id), then of each graph node.
  const memberOfId = new Map<string, number>();
  for (const i of members) {
    const id = laid.elementOf.get(i);
    if (id) memberOfId.set(id, i);
  }
  const memberOf: number[] = g.nodes.map((gn) => memberOfId.get(gn.el.id) ?? -1);
  const memberSet = new Set(members);
  const out: Mismatch[] = [];
  const drawnOf = new Map<number, Map<string, { srcs: GSource[]; leftward: boolean }>>();
  let reach: ((net: (typeof g.nets)[number]) => Set<number>) | undefined;
  for (const net of g.nets) {
    // What drives the net, through one-way bridges too (src/engine/compile/wires.ts).
    const up = upstream(g, net.id);
    if (!net.sinks.length || !up.fed) continue;
    let maxSource = -1;
    for (const s of net.sources) maxSource = Math.max(maxSource, s.point % W);
    // Through a connector pair a net may run leftwards on the grid: then what counts is that
    // every source reaches every pin moving right (the engine's LD-R01 check).
    const unreached = g.connections.size && net.sinks.some((s) => maxSource > s.point % W)
      ? (reach ??= reachability(g, laid))(net)
      : undefined;
    const srcs: GSource[] = [];
    for (const s of up.sources) {
      const m = memberOf[s.node]!;
      if (m >= 0) srcs.push({ kind: 'node', node: m, pin: pinName(g, s.node, s.pin) });
    }
    if (up.leftRail) srcs.push(RAIL);
    for (const s of net.sinks) {
      const m = memberOf[s.node]!;
      if (m < 0) continue;
      let pins = drawnOf.get(m);
      if (!pins) drawnOf.set(m, (pins = new Map()));
      pins.set(pinName(g, s.node, s.pin), {
        srcs,
        leftward: unreached ? unreached.has(s.point) : maxSource > s.point % W,
      });
    }
  }
  for (const b of g.misplaced) {
    const m = memberOf.find((_, k) => g.nodes[k]!.index === b.index);
    if (m !== undefined && m >= 0) out.push({ node: m, pin: 'in', extra: [], missing: [] });
  }
  for (const i of members) {
    const n = nodes[i]!;
    const drawn = drawnOf.get(i);
    for (const pin of n.inputs.keys()) {
      const d = drawn?.get(pin);
      const m = compare(i, pin, inFile(n, pin, memberSet), d?.srcs ?? [], d?.leftward ?? false);
      if (m) out.push(m);
    }
    if (drawn)
      for (const [pin, d] of drawn) {
        if (n.inputs.has(pin)) continue;
        const m = compare(i, pin, [], d.srcs, d.leftward);
        if (m) out.push(m);
      }
  }
  return out;
}

/**
 * For a net, the sink points some source (or the left rail) of the net cannot reach moving right
 * along links, either way along vertical links, and from a connector to its continuations.
 */
function reachability(g: NetworkGraph, laid: LaidOut): (net: NetworkGraph['nets'][number]) => Set<number> {
  const W = g.cols + 1;
  const right = new Set<number>();
  for (const el of laid.elements) if (el.kind === 'link') right.add(el.row * W + el.col);
  const down = new Set<number>();
  for (const v of laid.vlinks) down.add(v.row * W + v.boundary);
  return (net) => {
    const starts = [...net.sources.map((s) => s.point), ...net.points.filter((p) => p % W === 0)];
    const unreached = new Set<number>();
    for (const start of starts) {
      const seen = new Set<number>([start]);
      const stack = [start];
      while (stack.length) {
        const p = stack.pop()!;
        const next = [right.has(p) ? p + 1 : -1, down.has(p) ? p + W : -1, down.has(p - W) ? p - W : -1];
        for (const q of [...next, ...(g.connections.get(p) ?? [])])
          if (q >= 0 && !seen.has(q)) {
            seen.add(q);
            stack.push(q);
          }
      }
      for (const s of net.sinks) if (!seen.has(s.point)) unreached.add(s.point);
    }
    return unreached;
  };
}

/** The sources of a pin in the file, within the network. */
function inFile(n: GNode, pin: string, memberSet: ReadonlySet<number>): GSource[] {
  const list = n.inputs.get(pin) ?? [];
  for (const s of list)
    if (s.kind === 'node' && !memberSet.has(s.node))
      return list.filter((x) => x.kind === 'rail' || memberSet.has(x.node));
  return list;
}

const same = (a: GSource, b: GSource): boolean =>
  a.kind === 'rail' ? b.kind === 'rail' : b.kind === 'node' && a.node === b.node && a.pin === b.pin;

function compare(
  node: number,
  pin: string,
  want: readonly GSource[],
  got: readonly GSource[],
  leftward: boolean,
): Mismatch | undefined {
  // One source each (most pins): compare directly.
  if (!leftward && want.length === 1 && got.length === 1 && same(want[0]!, got[0]!)) return undefined;
  const extra = got.filter((g) => !want.some((w) => same(w, g)));
  const missing = want.filter((w) => !got.some((g) => same(w, g)));
  if (!extra.length && !missing.length && !leftward) return undefined;
  return { node, pin, extra, missing, ...(leftward ? { leftward } : {}) };
}

/** Names a source for a finding. */
function sourceName(nodes: readonly GNode[], s: GSource): string {
  if (s.kind === 'rail') return 'the left rail';
  const n = nodes[s.node]!;
  return `${describe(n)}${s.pin === 'out' ? '' : ` (${s.pin})`}`;
}

/** The finding for a pin whose drawn wiring differs from the file. */
export function mismatchFinding(nodes: readonly GNode[], m: Mismatch): Finding {
  const n = nodes[m.node]!;
  const what: string[] = [];
  if (m.extra.length)
    what.push(`would join it to ${m.extra.map((s) => sourceName(nodes, s)).join(', ')}, which the file does not`);
  if (m.missing.length)
    what.push(`would leave out its wire from ${m.missing.map((s) => sourceName(nodes, s)).join(', ')}`);
  if (m.leftward) what.push('would feed it from its right');
  const detail = what.length ? what.join('; ') : 'could not place it';
  return {
    message: `${describe(n)}${m.pin === 'in' ? '' : ` pin ${m.pin}`}: this wiring cannot be drawn exactly on the ladder grid (the grid ${detail}); not imported rather than run with other wiring than the file's`,
    obj: n.obj,
  };
}
