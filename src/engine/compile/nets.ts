// Facts about a network's power-flow nets that code generation relies on.
import type { NetworkIR, Op } from './ir';

/** Nets written exactly once, unconditionally (function outputs are written only when EN is ON). */
export function singleWriterNets(ir: NetworkIR, ops: readonly Op[] = ir.ops): Set<number> {
  const writes = new Map<number, number>();
  const add = (net: number | undefined, n = 1) => {
    if (net !== undefined) writes.set(net, (writes.get(net) ?? 0) + n);
  };
  for (const op of ops) {
    if (op.op === 'pass') add(op.outNet);
    else if (op.op === 'contact') {
      add(op.outNet);
      add(op.ownNet);
    } else if (op.op === 'coil' && op.outNet !== op.inNet) add(op.outNet);
    else if (op.op === 'fb') {
      for (const o of op.outs) add(o.net);
      if (op.eno) add(op.eno.net, 2);
    } else if (op.op === 'call') {
      for (const o of op.outs) add(o.out.net, 2);
      if (op.eno) add(op.eno.net, 2);
    }
    else if (op.op === 'function') {
      add(op.out.net, 2);
      add(op.eno.net, 2);
    }
  }
  return new Set([...writes].filter(([, n]) => n === 1).map(([net]) => net));
}

/** Every net the operations write. */
export function writtenNets(ops: readonly Op[]): Set<number> {
  const out = new Set<number>();
  const add = (net: number | undefined) => {
    if (net !== undefined) out.add(net);
  };
  for (const op of ops) {
    if (op.op === 'pass' || op.op === 'contact' || (op.op === 'coil' && op.outNet !== op.inNet)) add(op.outNet);
    if (op.op === 'contact') add(op.ownNet);
    if (op.op === 'fb') for (const o of op.outs) add(o.net);
    if (op.op === 'call') for (const o of op.outs) add(o.out.net);
    if (op.op === 'function') add(op.out.net);
    if ((op.op === 'fb' || op.op === 'call' || op.op === 'function') && op.eno) add(op.eno.net);
  }
  return out;
}
