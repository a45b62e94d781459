// What "Why?" reads of one scan (ScanView: values, nets, executed networks, as the history or the
// live PLC gives them), and reading one net's power from recorded packed words (the layout the
// generated code writes).
import type { Value } from '../../model/iecTypes';
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

/** What the engine computed in one scan, as the history recorded it. */
export interface ScanView {
  readonly scan: number;
  readonly timeMs: number;
  /** Value of a readable name (`Motor`, `T1.ET`) after the scan; undefined for an unknown name. */
  value(name: string): Value | undefined;
  /** Power of net `net` of network `network` as the scan left it. */
  net(network: number, net: number): boolean;
  /** Whether the network ran in the scan (a jump or RETURN can skip it). */
  executed(network: number): boolean;
  /** The last scan, at or before this one, at which the name's value changed (undefined: not in the recorded range). */
  changedAt?(name: string): number | undefined;
  /** Names forced now, upper case. */
  readonly forced?: ReadonlySet<string>;
}
