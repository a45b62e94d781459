// An SFC POU in a program: one network holding the chart's cycle (an `sfc` operation), followed by
// the bodies of its LD actions and conditions, lowered over the same instance's variables.
import type { Pou } from '../../model/project';
import type { Diagnostic } from '../api';
import type { NetworkIR } from '../compile/ir';
import { Reporter } from '../compile/report';
import type { SymbolTable } from '../compile/symbols';
import { lowerChart, type ChartStContext, type PieceLowering } from './chart';

export function lowerChartBody(
  pou: Pou,
  scope: SymbolTable,
  scopes: readonly SymbolTable[],
  out: Diagnostic[],
  index: number,
  lowerPiece: PieceLowering,
  st: Omit<ChartStContext, 'network'>,
): { networks: NetworkIR[]; ok: boolean } {
  const r = new Reporter(out, pou.name, -1);
  const chart = lowerChart(pou, scope, scopes, r, lowerPiece, { ...st, network: index });
  const network: NetworkIR = {
    index,
    ops: chart ? [{ op: 'sfc', node: -1, chart }] : [],
    netCount: 0,
    railNets: [],
    elementNets: [],
    vlinkNets: [],
    constants: [],
  };
  return { networks: [network], ok: chart !== undefined && r.errors === 0 };
}
