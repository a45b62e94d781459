// How the networks of a program are grouped into generated functions, and which networks write
// each variable (to regenerate them when it is forced).
import { slotKey } from '../compile/codegen';
import type { NetworkIR } from '../compile/ir';
import type { Access } from '../compile/symbols';

/**
 * First network of the segment holding each network. A segment is a run of consecutive networks
 * generated as one function: it ends before every jump target (so jumps land on a segment start)
 * and after `maxNetworks` networks or about `maxOps` operations (V8 optimises functions up to a size).
 */
export function planSegments(
  networks: readonly NetworkIR[],
  maxOps: number,
  maxNetworks: number,
): Int32Array {
  const segmentOf = new Int32Array(networks.length);
  const targets = new Set(
    networks.flatMap((ir) => ir.ops.flatMap((op) => (op.op === 'jump' ? [op.target] : []))),
  );
  let start = 0;
  let ops = 0;
  networks.forEach((ir, i) => {
    const size = ir.ops.length + 1;
    if (i > start && (targets.has(i) || ops + size > maxOps || i - start >= maxNetworks)) {
      start = i;
      ops = 0;
    }
    segmentOf[i] = start;
    ops += size;
  });
  return segmentOf;
}

/** Networks writing each variable slot (`b:3`) through a coil or a block output. */
export function writersBySlot(networks: readonly NetworkIR[]): Map<string, Set<number>> {
  const writers = new Map<string, Set<number>>();
  for (const ir of networks) {
    for (const op of ir.ops) {
      const dsts: (Access | undefined)[] =
        op.op === 'coil'
          ? [op.dst]
          : op.op === 'function'
            ? [op.out.dst, op.eno.dst]
            : op.op === 'fb'
              ? op.outs.map((o) => o.dst)
              : [];
      for (const d of dsts) {
        if (d?.kind !== 'var' && d?.kind !== 'bit') continue;
        const key = slotKey(d.v.store, d.v.slot);
        if (!writers.has(key)) writers.set(key, new Set());
        writers.get(key)!.add(ir.index);
      }
    }
  }
  return writers;
}
