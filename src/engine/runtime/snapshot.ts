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
  return program.networks.slice(first, end).map((ir, k) => {
    const i = first + k;
    const shape = program.shapes[i]!;
    const executed = ranInScan(t, i);
    const rails = new Set(ir.railNets);
    const base = t.words[i]!;
    const on = (net: number) =>
      executed && net >= 0
        ? rails.has(net)
          ? 1
          : (t.power[base + Math.floor(net / NETS_PER_WORD)]! >>> (net % NETS_PER_WORD)) & 1
        : 0;
    const elements = new Uint8Array(shape.elements);
    const vlinks = new Uint8Array(shape.vlinks);
    ir.elementNets.forEach(([a, b], k) => (elements[k] = on(a) | (on(b) << 1) | (executed ? 4 : 0)));
    ir.vlinkNets.forEach((net, k) => (vlinks[k] = on(net)));
    return { elements, vlinks, executed };
  });
}
