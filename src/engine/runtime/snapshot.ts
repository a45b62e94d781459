// Power-flow snapshot for the UI: decodes the packed net bits the generated code writes into one
// byte per element (bit 0 left side energised, bit 1 right side, bit 2 executed) and vertical link.
import type { NetworkPower } from '../api';
import { NETS_PER_WORD } from '../compile/codegen';
import type { CompiledProgram } from '../compile/program';

export interface PowerTrace {
  readonly scan: number;
  /** Packed power-flow nets; network i starts at words[i]. */
  readonly power: Int32Array;
  readonly words: Int32Array;
  /** Scan in which each network last ran. */
  readonly ranIn: Int32Array;
}

/** Whether network i ran in the trace's scan. */
function ranInScan(t: PowerTrace, i: number): boolean {
  return t.scan !== 0 && t.ranIn[i] === t.scan;
}

/** Power of networks [first, end) (default: every network of the program). */
export function networkPower(
  program: CompiledProgram,
  t: PowerTrace,
  first = 0,
  end = program.networks.length,
): NetworkPower[] {
  // Run for every shown network at display rate while the program runs: loops, no closures or sets.
  const out: NetworkPower[] = [];
  const last = Math.min(end, program.networks.length);
  for (let i = first; i < last; i++) {
    const ir = program.networks[i]!;
    const shape = program.shapes[i]!;
    const executed = ranInScan(t, i);
    const elements = new Uint8Array(shape.elements);
    const vlinks = new Uint8Array(shape.vlinks);
    if (executed) {
      const base = t.words[i]!;
      const nets = ir.elementNets;
      for (let k = 0; k < nets.length; k++) {
        const pair = nets[k]!;
        elements[k] = netOn(ir.railNets, t.power, base, pair[0]) | (netOn(ir.railNets, t.power, base, pair[1]) << 1) | 4;
      }
      const vnets = ir.vlinkNets;
      for (let k = 0; k < vnets.length; k++) vlinks[k] = netOn(ir.railNets, t.power, base, vnets[k]!);
    }
    out.push({ elements, vlinks, executed });
  }
  return out;
}

/** 1 when the net is powered in the network's packed words (a rail net always is); 0 for no net (-1). */
function netOn(rails: readonly number[], power: Int32Array, base: number, net: number): number {
  if (net < 0) return 0;
  for (let r = 0; r < rails.length; r++) if (rails[r] === net) return 1;
  return (power[base + Math.floor(net / NETS_PER_WORD)]! >>> (net % NETS_PER_WORD)) & 1;
}
