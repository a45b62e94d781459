// The wires of a ladder grid as nets, with IEC's one-way vertical links (LD-SEMANTICS.md section 1):
// a vertical link's state is the OR of what is attached on its left, copied to what is attached on
// its right, never to its left. So the points a vertical link joins (a "bar") share one state, and
// a horizontal link (or a connector-to-continuation jump) carries the state of the bar on its left
// into the bar on its right, not back.
//
// Most wiring means the same whether links are one-way or not: every source of a connected wire
// reaches every input on it moving right. Such a wire is one net, as before. A wire where some
// source cannot reach some input moving right (a fan-out that runs into two different ORs:
// X := Q OR B; Y := Q OR C) is split into nets joined by one-way bridges: the bars are merged
// wherever merging changes no input's state, and what stays apart is a bridge `from` -> `to`
// (the state of `to` is the OR of its own sources and of every net bridged into it).

/** One-way link between two nets: `to` gets the state of `from` OR-ed in. */
export interface Bridge {
  readonly from: number;
  readonly to: number;
  /** The element drawn for it: the horizontal link or the continuation (by element index). */
  readonly via: number;
}

/** A one-way wire piece between two points, drawn by element `via`. */
export interface WireEdge {
  readonly from: number;
  readonly to: number;
  readonly via: number;
}

export interface WireInput {
  /** Number of points. */
  readonly points: number;
  /** Pairs of points joined by a vertical link (both ways). */
  readonly bars: readonly (readonly [number, number])[];
  /** Horizontal links and connector -> continuation jumps (one way). */
  readonly edges: readonly WireEdge[];
  /** 1 where a source attaches: an element output or the left rail. */
  readonly sourceAt: Uint8Array;
  /** 1 where an input attaches: an element input or the right rail. */
  readonly sinkAt: Uint8Array;
}

export interface WireNets {
  /** Net of every point, numbered densely in point order. */
  readonly netOfPoint: Int32Array;
  readonly count: number;
  readonly bridges: readonly Bridge[];
}

/** `net` and every net whose state reaches it through bridges (`fromOf`: the nets bridged into one). */
export function feedingNets(net: number, fromOf: (net: number) => Iterable<number>): number[] {
  const seen = new Set<number>([net]);
  const stack = [net];
  const out: number[] = [];
  while (stack.length) {
    const m = stack.pop()!;
    out.push(m);
    for (const f of fromOf(m))
      if (!seen.has(f)) {
        seen.add(f);
        stack.push(f);
      }
  }
  return out;
}

class Sets {
  readonly parent: Int32Array;
  constructor(n: number) {
    this.parent = new Int32Array(n);
    for (let i = 0; i < n; i++) this.parent[i] = i;
  }
  find(a: number): number {
    let r = a;
    while (this.parent[r] !== r) r = this.parent[r]!;
    while (this.parent[a] !== r) {
      const next = this.parent[a]!;
      this.parent[a] = r;
      a = next;
    }
    return r;
  }
  union(a: number, b: number): boolean {
    const ra = this.find(a);
    const rb = this.find(b);
    if (ra === rb) return false;
    this.parent[ra] = rb;
    return true;
  }
}

/** The nets of a grid's wiring (see the file comment). */
export function wireNets(input: WireInput): WireNets {
  const { points, bars, edges, sourceAt, sinkAt } = input;
  const bar = new Sets(points);
  for (const [a, b] of bars) bar.union(a, b);
  const wire = new Sets(points);
  for (const [a, b] of bars) wire.union(a, b);
  for (const e of edges) wire.union(e.from, e.to);

  // Edges per connected wire; only wires with an edge between two different bars can differ.
  const byWire = new Map<number, WireEdge[]>();
  for (const e of edges) {
    if (bar.find(e.from) === bar.find(e.to)) continue;
    const w = wire.find(e.from);
    const list = byWire.get(w);
    if (list) list.push(e);
    else byWire.set(w, [e]);
  }

  const final = new Sets(points);
  for (const [a, b] of bars) final.union(a, b);
  const split: WireEdge[][] = [];
  if (byWire.size) {
    // Sources and inputs per bar.
    const barSource = new Uint8Array(points);
    const barSink = new Uint8Array(points);
    for (let p = 0; p < points; p++) {
      if (sourceAt[p]) barSource[bar.find(p)] = 1;
      if (sinkAt[p]) barSink[bar.find(p)] = 1;
    }
    const barsOfWire = new Map<number, number[]>();
    for (let p = 0; p < points; p++) {
      if (bar.find(p) !== p || !byWire.has(wire.find(p))) continue;
      const w = wire.find(p);
      const list = barsOfWire.get(w);
      if (list) list.push(p);
      else barsOfWire.set(w, [p]);
    }
    for (const [w, list] of byWire) {
      if (reachesEveryInput(list, barsOfWire.get(w)!, bar, barSource, barSink)) {
        for (const e of list) final.union(e.from, e.to);
      } else {
        mergeWhereSame(list, barsOfWire.get(w)!, final, barSource, barSink);
        split.push(list);
      }
    }
  }

  const netOfPoint = new Int32Array(points);
  const ids = new Map<number, number>();
  for (let p = 0; p < points; p++) {
    const root = final.find(p);
    let id = ids.get(root);
    if (id === undefined) ids.set(root, (id = ids.size));
    netOfPoint[p] = id;
  }
  const bridges: Bridge[] = [];
  const seen = new Set<string>();
  for (const list of split)
    for (const e of list) {
      const from = netOfPoint[e.from]!;
      const to = netOfPoint[e.to]!;
      if (from === to || seen.has(`${from}>${to}`)) continue;
      seen.add(`${from}>${to}`);
      bridges.push({ from, to, via: e.via });
    }
  return { netOfPoint, count: ids.size, bridges };
}

/** True when every source bar of a wire reaches every input bar moving along its one-way edges. */
function reachesEveryInput(
  list: readonly WireEdge[],
  barRoots: readonly number[],
  bar: Sets,
  barSource: Uint8Array,
  barSink: Uint8Array,
): boolean {
  const next = new Map<number, number[]>();
  for (const e of list) {
    const a = bar.find(e.from);
    const b = bar.find(e.to);
    const out = next.get(a);
    if (out) out.push(b);
    else next.set(a, [b]);
  }
  const sinks = barRoots.filter((b) => barSink[b]);
  for (const start of barRoots) {
    if (!barSource[start]) continue;
    const seen = new Set<number>([start]);
    const stack = [start];
    while (stack.length) {
      const b = stack.pop()!;
      for (const c of next.get(b) ?? [])
        if (!seen.has(c)) {
          seen.add(c);
          stack.push(c);
        }
    }
    for (const s of sinks) if (!seen.has(s)) return false;
  }
  return true;
}

/**
 * Merges the bars of a wire joined by an edge A -> B wherever that changes no state: B has no
 * input but A (B's state is A's), or A feeds nothing but B (A's state is read only through B).
 * Repeated until nothing more merges; groups merged in a round wait for the next one.
 */
function mergeWhereSame(
  list: readonly WireEdge[],
  barRoots: readonly number[],
  final: Sets,
  barSource: Uint8Array,
  barSink: Uint8Array,
): void {
  for (;;) {
    const hasSource = new Set<number>();
    const hasSink = new Set<number>();
    for (const r of barRoots) {
      if (barSource[r]) hasSource.add(final.find(r));
      if (barSink[r]) hasSink.add(final.find(r));
    }
    const ins = new Map<number, Set<number>>();
    const outs = new Map<number, Set<number>>();
    for (const e of list) {
      const a = final.find(e.from);
      const b = final.find(e.to);
      if (a === b) continue;
      let i = ins.get(b);
      if (!i) ins.set(b, (i = new Set()));
      i.add(a);
      let o = outs.get(a);
      if (!o) outs.set(a, (o = new Set()));
      o.add(b);
    }
    const dirty = new Set<number>();
    let merged = false;
    for (const e of list) {
      const a = final.find(e.from);
      const b = final.find(e.to);
      if (a === b || dirty.has(a) || dirty.has(b)) continue;
      const onlyFromA = !hasSource.has(b) && ins.get(b)!.size === 1;
      const onlyIntoB = !hasSink.has(a) && outs.get(a)!.size === 1;
      if (!onlyFromA && !onlyIntoB) continue;
      final.union(a, b);
      dirty.add(a).add(b);
      merged = true;
    }
    if (!merged) return;
  }
}
