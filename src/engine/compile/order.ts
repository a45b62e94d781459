// Evaluation order within a network (LD-SEMANTICS.md section 6): a topological order of the
// element graph where, among the elements ready at the same time, the one on the upper row goes
// first, then the one further left (a box counts at its top-left cell). Parallel coils therefore
// run top to bottom, and a contact reads what a coil above it in the same network just wrote.
import { upstream, type NetworkGraph } from './graph';

/** Node indexes in evaluation order, or undefined when the graph has a cycle (a feedback wire). */
export function evaluationOrder(g: NetworkGraph): number[] | undefined {
  const n = g.nodes.length;
  // Producers of each net: nodes with an output terminal on it or on a net bridged into it.
  const producers: number[][] = g.nets.map((net) => {
    const up = net.feeds.length ? upstream(g, net.id).sources : net.sources;
    return [...new Set(up.map((s) => s.node))];
  });
  const dependents: number[][] = g.nodes.map(() => []);
  const waiting = new Int32Array(n);
  g.nodes.forEach((node, i) => {
    const deps = new Set<number>();
    for (const t of node.inputs) for (const p of producers[t.net]!) if (p !== i) deps.add(p);
    for (const t of node.inputs) if (producers[t.net]!.includes(i)) return void (waiting[i] = -1); // feeds itself
    waiting[i] = deps.size;
    for (const d of deps) dependents[d]!.push(i);
  });
  if (waiting.some((w) => w < 0)) return undefined;
  const before = (a: number, b: number) => {
    const ea = g.nodes[a]!.el;
    const eb = g.nodes[b]!.el;
    return ea.row !== eb.row ? ea.row < eb.row : ea.col < eb.col;
  };
  const ready: number[] = [];
  for (let i = 0; i < n; i++) if (waiting[i] === 0) ready.push(i);
  const order: number[] = [];
  while (ready.length) {
    let best = 0;
    for (let k = 1; k < ready.length; k++) if (before(ready[k]!, ready[best]!)) best = k;
    const next = ready.splice(best, 1)[0]!;
    order.push(next);
    for (const d of dependents[next]!) if (--waiting[d]! === 0) ready.push(d);
  }
  return order.length === n ? order : undefined;
}
