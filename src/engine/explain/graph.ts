// The power-flow graph of a compiled network, as the generated code evaluates it: nets are nodes,
// operations (contacts, coils, boxes) carry power from their input nets to their output nets.
// Used by "Why?" to list the paths from the left rail to a coil, and who writes a variable.
import type { Access } from '../compile/symbols';
import type { NetworkIR, Op, OutIR, Source } from '../compile/ir';

/** An operation as a graph arc: the element it belongs to, the nets it reads power from and those it drives. */
export interface Arc {
  readonly op: Op;
  /** Element index in the document network. */
  readonly element: number;
  readonly inNets: readonly number[];
  readonly outNets: readonly number[];
}

function arcOf(op: Op): Arc {
  switch (op.op) {
    case 'contact':
      return {
        op,
        element: op.node,
        inNets: op.inNet >= 0 ? [op.inNet] : [],
        outNets: [op.outNet],
      };
    case 'coil':
      return { op, element: op.node, inNets: op.inNet >= 0 ? [op.inNet] : [], outNets: op.outNet !== op.inNet ? [op.outNet] : [] };
    case 'pass':
      return { op, element: op.node, inNets: [op.inNet], outNets: [op.outNet] };
    case 'jump':
    case 'return':
      return { op, element: op.node, inNets: op.inNet >= 0 ? [op.inNet] : [], outNets: [] };
    default:
      return boxArc(op);
  }
}

/** Boxes (functions, FB instances, calls of user blocks): EN and power-wired inputs in, BOOL outputs wired as power out. */
interface BoxLike {
  readonly node: number;
  readonly en?: Source;
  readonly args?: readonly { readonly src: Source }[];
  readonly assigns?: readonly { readonly src: Source }[];
  readonly out?: OutIR;
  readonly eno?: OutIR;
  readonly outs?: readonly (OutIR | { readonly out: OutIR })[];
}

const outIR = (o: OutIR | { readonly out: OutIR }): OutIR => ('out' in o ? o.out : o);

function boxArc(op: Op): Arc {
  const b = op as unknown as BoxLike;
  const power = (src: Source | undefined): number[] => (src?.from === 'power' ? [src.net] : []);
  const outs = [...(b.out ? [b.out] : []), ...(b.outs ?? []).map(outIR), ...(b.eno ? [b.eno] : [])];
  return {
    op,
    element: b.node,
    inNets: [...power(b.en), ...(b.args ?? []).flatMap((a) => power(a.src)), ...(b.assigns ?? []).flatMap((a) => power(a.src))],
    outNets: outs.flatMap((o) => (o.net !== undefined ? [o.net] : [])),
  };
}

export interface NetworkGraph {
  readonly ir: NetworkIR;
  readonly arcs: readonly Arc[];
  readonly rails: ReadonlySet<number>;
  /** Arcs driving each net. */
  readonly drivers: ReadonlyMap<number, readonly Arc[]>;
}

const graphs = new WeakMap<NetworkIR, NetworkGraph>();

export function networkGraph(ir: NetworkIR): NetworkGraph {
  let g = graphs.get(ir);
  if (g) return g;
  // openplc: a network's early segments and late blocks (run at the start and the end of its POU
  // body) drive its nets too.
  const arcs = [...(ir.early ?? []).flat(), ...ir.ops, ...(ir.late ?? [])].map(arcOf);
  const drivers = new Map<number, Arc[]>();
  for (const arc of arcs)
    for (const net of arc.outNets) {
      const list = drivers.get(net) ?? [];
      if (!list.includes(arc)) list.push(arc);
      drivers.set(net, list);
    }
  g = { ir, arcs, rails: new Set(ir.railNets), drivers };
  graphs.set(ir, g);
  return g;
}

/**
 * One path from the left rail: the arcs in power-flow order, each with the net that carries its own
 * result on the path (a contact whose right side joins other branches: its own result, not the join).
 */
export type PowerPath = readonly { readonly arc: Arc; readonly outNet: number }[];

/** Paths are listed up to this many (a network with more is summarised). */
export const MAX_PATHS = 64;

/**
 * Every path from the left rail to `net` (power-flow order). A box with no powered input starts a
 * path by itself (its outputs do not come from the rail). Empty list: nothing drives the net.
 */
export function pathsTo(g: NetworkGraph, net: number, limit = MAX_PATHS): PowerPath[] {
  const out: PowerPath[] = [];
  const walk = (n: number, tail: PowerPath, depth: number): void => {
    if (out.length >= limit || depth > 256) return;
    if (g.rails.has(n)) {
      out.push(tail);
      return;
    }
    for (const arc of g.drivers.get(n) ?? []) {
      const own = arc.op.op === 'contact' && arc.op.ownNet !== undefined ? arc.op.ownNet : n;
      // openplc: a block output passed into a join is the block's own step (it drives the input net).
      const sameBlock = arc.op.op === 'pass' && (g.drivers.get(arc.inNets[0]!) ?? []).some((a) => a.element === arc.element);
      const step = sameBlock ? tail : [{ arc, outNet: own }, ...tail];
      if (arc.inNets.length === 0) out.push(step);
      else for (const i of arc.inNets) walk(i, step, depth + 1);
      if (out.length >= limit) return;
    }
  };
  walk(net, [], 0);
  return out;
}

/** The variable (or FB instance) an access touches, as a key: writers of `Motor` and of `Motor.3` share it. */
export function accessKey(a: Access): string | undefined {
  switch (a.kind) {
    case 'var':
    case 'bit':
      return `v:${a.v.store}:${a.v.slot}`;
    case 'pin':
      return `p:${a.fb.index}:${a.pin}`;
    case 'const':
    case 'elem':
      return undefined;
  }
}

/** Accesses an operation writes (coil operand, outputs assigned to variables, FB pins it sets by executing). */
export function writesOf(op: Op): { readonly access?: Access; readonly fb?: number }[] {
  if (op.op === 'coil') return [{ access: op.dst }];
  if (op.op === 'contact' || op.op === 'pass' || op.op === 'jump' || op.op === 'return') return [];
  const b = op as unknown as BoxLike & { readonly op: string; readonly fb?: number };
  const outs = [...(b.out ? [b.out] : []), ...(b.outs ?? []).map(outIR), ...(b.eno ? [b.eno] : [])];
  return [...(b.op === 'fb' && b.fb !== undefined ? [{ fb: b.fb }] : []), ...outs.flatMap((o) => (o.dst ? [{ access: o.dst }] : []))];
}
