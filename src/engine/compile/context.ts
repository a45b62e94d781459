// State shared while one POU is checked and lowered: symbols, labels, the function table,
// edge memories and the program-wide facts the warning rules need.
import type { Profile } from '../../model/project';
import type { ResolvedFunction } from '../library/fnTypes';
import type { ElementaryType } from '../../model/iecTypes';
import type { FbSymbol, Store, SymbolTable, VarSymbol } from './symbols';

export type CoilFamily = 'assign' | 'negated' | 'pulse' | 'latch';

export interface PouContext {
  readonly pouName: string;
  readonly profile: Profile;
  readonly symbols: SymbolTable;
  /** Upper-case label -> network index. */
  readonly labels: ReadonlyMap<string, number>;
  readonly functions: ResolvedFunction[];
  /** Edge memories allocated so far (one per P/N contact or coil). */
  edgeCount: number;
  /** FB instance -> the first box that calls it (for LD-R10 uniqueness). */
  readonly fbCalls: Map<FbSymbol, { network: number; row: number; col: number }>;
  /** Variable -> coil families writing it (LD-R12). */
  readonly coilWrites: Map<VarSymbol, Map<CoilFamily, { network: number; row: number; col: number }>>;
  /** Variables written by retentive coils (M, SM, RM): kept over a warm restart. */
  readonly retentiveCoilVars: Set<VarSymbol>;
  /** Persistent slots holding function outputs wired to other blocks (initialised on cold restart). */
  readonly dataSlots: { store: Store; slot: number; type: ElementaryType }[];
}

export function newPouContext(
  pouName: string,
  profile: Profile,
  symbols: SymbolTable,
  labels: ReadonlyMap<string, number>,
): PouContext {
  return {
    pouName,
    profile,
    symbols,
    labels,
    functions: [],
    edgeCount: 0,
    fbCalls: new Map(),
    coilWrites: new Map(),
    retentiveCoilVars: new Set(),
    dataSlots: [],
  };
}
