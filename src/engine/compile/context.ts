// State shared while one POU is checked and lowered: symbols, labels, the function table,
// edge memories and the program-wide facts the warning rules need; where a POU's networks go in a
// program (Placement) and what lowering it gives (LoweredPou).
import type { LdElement } from '../../model/elements';
import type { Project, Profile } from '../../model/project';
import type { ResolvedFunction } from '../library/fnTypes';
import type { ElementaryType } from '../../model/iecTypes';
import type { Access, AggSymbol, FbSymbol, Store, SymbolTable, UfbSymbol, VarSymbol } from './symbols';
import type { NetworkIR } from './ir';

export type CoilFamily = 'assign' | 'negated' | 'pulse' | 'latch';

/** A |P| |N| contact or (P) (N) coil: the owner of one edge memory. */
export interface EdgeOwner {
  readonly elementId: string;
  /** 0-based network index in its POU. */
  readonly network: number;
  /** `|P|`, `|N|`, `(P)`, `(N)`. */
  readonly symbol: string;
  /** The operand as written on the element. */
  readonly operand: string;
  /** Path of the FB instance whose body holds the element (absent: the program). */
  readonly instance?: string;
  readonly pou: string;
}

/** Edge memories of a program: one per element per FB instance (every call of an instance shares them). */
export class EdgeTable {
  readonly owners: EdgeOwner[] = [];
  private readonly byKey = new Map<string, number>();
  /**
   * `trace` (openplc profile, LD-SEMANTICS.md section 6): the k-th reading of the same |P| |N|
   * contact in one scan (k >= 1) has a memory of its own, as each R_TRIG Beremiz generates.
   */
  allocate(el: LdElement, pou: string, network: number, instance: string | undefined, trace = 0): number {
    const id = trace > 0 ? `${el.id}#${trace + 1}` : el.id;
    const key = `${instance ?? ''}/${id}`;
    const hit = this.byKey.get(key);
    if (hit !== undefined) return hit;
    const symbol = el.kind === 'contact' ? `|${el.contact}|` : el.kind === 'coil' ? `(${el.coil})` : '?';
    const operand = el.kind === 'contact' || el.kind === 'coil' ? el.variable.trim() : '';
    this.owners.push({ elementId: id, network, symbol, operand, pou, ...(instance ? { instance } : {}) });
    this.byKey.set(key, this.owners.length - 1);
    return this.owners.length - 1;
  }
  get count(): number {
    return this.owners.length;
  }
}

export interface PouContext {
  readonly project: Project;
  readonly pouName: string;
  readonly pouKind: Project['pous'][number]['kind'];
  readonly profile: Profile;
  readonly symbols: SymbolTable;
  /** Upper-case label -> network index. */
  readonly labels: ReadonlyMap<string, number>;
  readonly functions: ResolvedFunction[];
  /** Edge memories of the program (one per P/N contact or coil per instance). */
  readonly edges: EdgeTable;
  /** Index of the POU's network 0 in the program's network array. */
  readonly first: number;
  /** Path of the FB instance being lowered (absent: a program or a POU checked on its own). */
  readonly instance?: string;
  /** Builds the bodies of user block calls; absent when a POU is only checked. */
  readonly calls?: CallBuilder;
  /** FB instance -> the first box that calls it (for LD-R10 uniqueness). */
  readonly fbCalls: Map<FbSymbol | UfbSymbol, { network: number; row: number; col: number }>;
  /** Variable -> coil families writing it (LD-R12). */
  readonly coilWrites: Map<VarSymbol, Map<CoilFamily, { network: number; row: number; col: number }>>;
  /** Variables written by retentive coils (M, SM, RM): kept over a warm restart. */
  readonly retentiveCoilVars: Set<VarSymbol>;
  /** Persistent slots holding function outputs wired to other blocks (initialised on cold restart). */
  readonly dataSlots: { store: Store; slot: number; type: ElementaryType }[];
  /** FB instance -> the hidden BOOL "EN was OFF at its last call" (box.ts enMemoryOf). */
  readonly enMemories: Map<FbSymbol | UfbSymbol, Access>;
}

/** Flattening (compile/flatten.ts): the body networks of one call, placed in the program's network array. */
export interface CallBuilder {
  /** Body of a call of a user FB instance, with its in-out names bound to the caller's variables (a struct/array one: its AggSymbol). */
  fbBody(instance: UfbSymbol, refs: ReadonlyMap<string, Access | AggSymbol>): { first: number; end: number } | undefined;
  /** A function call site: its own variables (scope) and body. */
  functionCall(pou: Project['pous'][number], site: string): FunctionSite;
}

export interface FunctionSite {
  readonly scope: SymbolTable;
  /** Lowers the body once the in-out references are known. */
  body(refs: ReadonlyMap<string, Access | AggSymbol>): { first: number; end: number } | undefined;
}

/** What a body lowering shares with the rest of the program (absent: a POU checked on its own). */
export interface SharedParts {
  readonly functions: ResolvedFunction[];
  readonly edges: EdgeTable;
  readonly retentiveCoilVars: Set<VarSymbol>;
  readonly dataSlots: { store: Store; slot: number; type: ElementaryType }[];
  readonly enMemories: Map<FbSymbol | UfbSymbol, Access>;
}

export function newPouContext(
  project: Project,
  pou: Project['pous'][number],
  profile: Profile,
  symbols: SymbolTable,
  labels: ReadonlyMap<string, number>,
  place: { first: number; instance?: string; calls?: CallBuilder; shared?: SharedParts } = { first: 0 },
): PouContext {
  const shared = place.shared ?? {
    functions: [],
    edges: new EdgeTable(),
    retentiveCoilVars: new Set(),
    dataSlots: [],
    enMemories: new Map(),
  };
  return {
    project,
    pouName: pou.name,
    pouKind: pou.kind,
    profile,
    symbols,
    labels,
    functions: shared.functions,
    edges: shared.edges,
    first: place.first,
    ...(place.instance ? { instance: place.instance } : {}),
    ...(place.calls ? { calls: place.calls } : {}),
    fbCalls: new Map(),
    coilWrites: new Map(),
    retentiveCoilVars: shared.retentiveCoilVars,
    dataSlots: shared.dataSlots,
    enMemories: shared.enMemories,
  };
}

export interface LoweredPou {
  readonly ctx: PouContext;
  /** One entry per network; undefined where the network has errors. */
  readonly networks: readonly (NetworkIR | undefined)[];
  /** No error anywhere in the POU (its variables and networks). */
  readonly ok: boolean;
}

/** Where a POU's networks go in a program, and what they share with it (absent: checked on its own). */
export interface Placement {
  readonly first: number;
  readonly instance?: string;
  readonly calls?: CallBuilder;
  readonly shared?: SharedParts;
}
