// Evaluation order within a network (LD-SEMANTICS.md section 6): a topological order of the
// element graph where, among the elements ready at the same time, the one on the upper row goes
// first, then the one further left (a box counts at its top-left cell). Parallel coils therefore
// run top to bottom, and a contact reads what a coil above it in the same network just wrote.
//
// Explicit feedback loops (IEC 61131-3 4.1.3, figure 23a): a loop in which every element waits
// for the next cannot be ordered, unless it passes through a block (a function, an FB, or the
// inverting contact, which Beremiz writes as a NOT function). Then one element of the loop reads
// the block's stored output, its value from the block's previous call (the initial value before
// the first): that output is the loop's feedback variable (rule 3 and 4 of 4.1.3), and the block
// runs after it. The feedback variable chosen is the one the text names: the output of a block
// used as the input of a block that precedes it, i.e. the wire that goes back furthest to the
// left (a wire into a block rather than into a contact, which would pass the old value on). A loop of contacts and coils alone has no stored value to read: it is not executable
// (LD-R01).
import { upstream, type GraphNode, type NetworkGraph } from './graph';

/** A block output read as its stored value: the wire from `producer`'s `pin` into `reader`'s input on `net`. */
export interface Feedback {
  readonly reader: number;
  readonly net: number;
  readonly producer: number;
  readonly pin: string;
}

export interface Plan {
  /** Node indexes in evaluation order. */
  readonly order: number[];
  /** The feedback wires cut to order the loops (empty without explicit loops). */
  readonly feedback: Feedback[];
}

/** Blocks whose outputs keep a value between calls: boxes and the inverting contact. */
export const holdsOutput = (node: GraphNode): boolean =>
  node.el.kind === 'box' || (node.el.kind === 'contact' && node.el.contact === 'NOT');

/**
 * Node indexes in evaluation order (explicit loops through blocks cut, see planOrder), or undefined
 * when a loop passes through no block: a feedback wire of contacts and coils (LD-R01).
 */
export function evaluationOrder(g: NetworkGraph): number[] | undefined {
  return planOrder(g)?.order;
}

const plans = new WeakMap<NetworkGraph, Plan | null>();

/**
 * The evaluation order with the explicit loops through blocks cut at their feedback variables;
 * undefined when a loop passes through no block (LD-R01).
 */
export function planOrder(g: NetworkGraph): Plan | undefined {
  let plan = plans.get(g);
  if (plan === undefined) plans.set(g, (plan = plan0(g) ?? null));
  return plan ?? undefined;
}

function plan0(g: NetworkGraph): Plan | undefined {
  const n = g.nodes.length;
  // Producers of each net: nodes with an output terminal on it or on a net bridged into it.
  const producers: readonly { node: number; pin: string }[][] = g.nets.map((net) => {
    const up = net.feeds.length ? upstream(g, net.id).sources : net.sources;
    const out: { node: number; pin: string }[] = [];
    for (const s of up) if (!out.some((o) => o.node === s.node && o.pin === s.pin)) out.push(s);
    return out;
  });
  const dependents: Set<number>[] = g.nodes.map(() => new Set());
  const deps: Set<number>[] = g.nodes.map(() => new Set());
  const feedback: Feedback[] = [];
  /** Cuts every wire from `p` into `i`. */
  const cut = (p: number, i: number): void => {
    for (const t of g.nodes[i]!.inputs)
      for (const s of producers[t.net]!) if (s.node === p) feedback.push({ reader: i, net: t.net, producer: p, pin: s.pin });
  };
  for (let i = 0; i < n; i++) {
    let self = false;
    for (const t of g.nodes[i]!.inputs)
      for (const p of producers[t.net]!) {
        if (p.node !== i) deps[i]!.add(p.node);
        else self = true;
      }
    // An element reading its own output: a block reads its stored output (fed back, cut here);
    // a contact or coil would feed itself power (LD-R01).
    if (self && !holdsOutput(g.nodes[i]!)) return undefined;
    if (self) cut(i, i);
    for (const d of deps[i]!) dependents[d]!.add(i);
  }
  const waiting = new Int32Array(n);
  for (let i = 0; i < n; i++) waiting[i] = deps[i]!.size;
  const before = (a: number, b: number) => {
    const ea = g.nodes[a]!.el;
    const eb = g.nodes[b]!.el;
    return ea.row !== eb.row ? ea.row < eb.row : ea.col < eb.col;
  };
  const ready: number[] = [];
  const done = new Uint8Array(n);
  for (let i = 0; i < n; i++) if (waiting[i] === 0) ready.push(i);
  const order: number[] = [];
  while (order.length < n) {
    if (!ready.length) {
      const next = feedbackWire(g, deps, done);
      if (!next) return undefined;
      const [p, i] = next;
      cut(p, i);
      deps[i]!.delete(p);
      dependents[p]!.delete(i);
      if (--waiting[i]! === 0) ready.push(i);
      continue;
    }
    let best = 0;
    for (let k = 1; k < ready.length; k++) if (before(ready[k]!, ready[best]!)) best = k;
    const next = ready.splice(best, 1)[0]!;
    order.push(next);
    done[next] = 1;
    for (const d of dependents[next]!) if (--waiting[d]! === 0) ready.push(d);
  }
  return { order, feedback };
}

/**
 * Among the elements left waiting (all in or behind loops), the wire to cut: from a block to an
 * element of the same loop (strongly connected component). A wire into a block first (a contact
 * reading a stored output would pass the old value on to whatever else its line feeds), then the
 * one going back furthest to the left, then the reader drawn first. Undefined when no loop passes
 * through a block.
 */
function feedbackWire(g: NetworkGraph, deps: readonly Set<number>[], done: Uint8Array): [number, number] | undefined {
  const comp = components(g.nodes.length, deps, done);
  let best: [number, number] | undefined;
  let bestScore: number[] = [];
  for (let i = 0; i < g.nodes.length; i++) {
    if (done[i]) continue;
    for (const p of deps[i]!) {
      if (done[p] || comp[p] !== comp[i] || !holdsOutput(g.nodes[p]!)) continue;
      const pe = g.nodes[p]!.el;
      const ie = g.nodes[i]!.el;
      const score = [holdsOutput(g.nodes[i]!) ? 1 : 0, pe.col - ie.col, -ie.row, -ie.col];
      if (!best || better(score, bestScore)) {
        best = [p, i];
        bestScore = score;
      }
    }
  }
  return best;
}

const better = (a: readonly number[], b: readonly number[]): boolean => {
  for (let k = 0; k < a.length; k++) if (a[k] !== b[k]) return a[k]! > b[k]!;
  return false;
};

/** Strongly connected components (Tarjan, iterative) of the nodes not done, edges from each node to its dependencies. */
function components(n: number, deps: readonly Set<number>[], done: Uint8Array): Int32Array {
  const index = new Int32Array(n).fill(-1);
  const low = new Int32Array(n);
  const comp = new Int32Array(n).fill(-1);
  const onStack = new Uint8Array(n);
  const stack: number[] = [];
  let counter = 0;
  let comps = 0;
  for (let root = 0; root < n; root++) {
    if (done[root] || index[root] !== -1) continue;
    const work: [number, number[]][] = [];
    const open = (v: number) => {
      index[v] = low[v] = counter++;
      stack.push(v);
      onStack[v] = 1;
      work.push([v, [...deps[v]!].filter((w) => !done[w])]);
    };
    open(root);
    while (work.length) {
      const top = work[work.length - 1]!;
      const [v, next] = top;
      if (next.length) {
        const w = next.pop()!;
        if (index[w] === -1) open(w);
        else if (onStack[w]) low[v] = Math.min(low[v]!, index[w]!);
        continue;
      }
      work.pop();
      if (work.length) {
        const u = work[work.length - 1]![0];
        low[u] = Math.min(low[u]!, low[v]!);
      }
      if (low[v] === index[v]) {
        let w: number;
        do {
          w = stack.pop()!;
          onStack[w] = 0;
          comp[w] = comps;
        } while (w !== v);
        comps++;
      }
    }
  }
  return comp;
}

/**
 * Where a network that cannot be ordered is reported (LD-R01): the element drawn first among those
 * on a loop of contacts and coils (none of them keeps a value to read).
 */
export function loopElement(g: NetworkGraph): GraphNode['el'] | undefined {
  const n = g.nodes.length;
  const deps: Set<number>[] = g.nodes.map(() => new Set());
  g.nodes.forEach((node, i) => {
    for (const t of node.inputs) for (const s of upstream(g, t.net).sources) deps[i]!.add(s.node);
  });
  const comp = components(n, deps, new Uint8Array(n));
  const size = new Map<number, number>();
  for (let i = 0; i < n; i++) size.set(comp[i]!, (size.get(comp[i]!) ?? 0) + 1);
  let best: GraphNode['el'] | undefined;
  for (let i = 0; i < n; i++) {
    const el = g.nodes[i]!.el;
    const onLoop = size.get(comp[i]!)! > 1 || deps[i]!.has(i);
    if (onLoop && !holdsOutput(g.nodes[i]!) && (!best || el.row < best.row || (el.row === best.row && el.col < best.col))) best = el;
  }
  return best;
}
