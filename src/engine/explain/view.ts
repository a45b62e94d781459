// Reading one net's power from recorded packed words (the layout the generated code writes).
import { NETS_PER_WORD } from '../compile/codegen';
import type { CompiledProgram } from '../compile/program';

/**
 * Power of `net` in network `network`: `words[network]` is the network's first word in `power`;
 * a left-rail net is always on; nothing is on in a network that did not run.
 */
export function netOn(program: CompiledProgram, words: Int32Array, power: ArrayLike<number>, executed: boolean, network: number, net: number): boolean {
  if (!executed || net < 0) return false;
  const ir = program.networks[network];
  if (!ir) return false;
  if (ir.railNets.includes(net)) return true;
  return ((power[words[network]! + Math.floor(net / NETS_PER_WORD)]! >>> (net % NETS_PER_WORD)) & 1) === 1;
}
