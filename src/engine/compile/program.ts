// compileProgram: the checked, lowered form of one PROGRAM POU, ready for createPlc.
import type { Pou, Project } from '../../model/project';
import type { CompileOptions, Diagnostic } from '../api';
import type { ResolvedFunction } from '../library/fnTypes';
import type { ElementaryType } from '../../model/iecTypes';
import type { NetworkIR } from './ir';
import { lowerPou } from './pou';
import type { Store, SymbolTable, VarSymbol } from './symbols';
import { Reporter } from './report';

export interface CompiledProgram {
  readonly pou: string;
  readonly profile: Project['profile'];
  readonly networks: readonly NetworkIR[];
  /** Number of elements and vertical links per network, for the power snapshot. */
  readonly shapes: readonly { readonly elements: number; readonly vlinks: number }[];
  readonly symbols: SymbolTable;
  readonly functions: readonly ResolvedFunction[];
  readonly edgeCount: number;
  /** Who owns each edge memory (indexed like the memories): the element, for online change. */
  readonly edges: readonly EdgeOwner[];
  readonly dataSlots: readonly {
    readonly store: Store;
    readonly slot: number;
    readonly type: ElementaryType;
  }[];
  /** Variables kept over a warm restart: RETAIN ones and those written by M/SM/RM coils. */
  readonly retentive: ReadonlySet<VarSymbol>;
}

/** A |P| |N| contact or (P) (N) coil: the owner of one edge memory. */
export interface EdgeOwner {
  readonly elementId: string;
  readonly network: number;
  /** `|P|`, `|N|`, `(P)`, `(N)`. */
  readonly symbol: string;
  /** The operand as written on the element. */
  readonly operand: string;
}

function edgeOwners(pou: Pou, networks: readonly NetworkIR[], count: number): EdgeOwner[] {
  const owners = new Array<EdgeOwner>(count);
  for (const ir of networks)
    for (const op of ir.ops) {
      if ((op.op !== 'contact' && op.op !== 'coil') || op.edge === undefined) continue;
      const el = pou.networks[ir.index]!.elements[op.node]!;
      const symbol = op.op === 'contact' ? `|${op.contact}|` : `(${op.coil})`;
      const operand = el.kind === 'contact' || el.kind === 'coil' ? el.variable.trim() : '';
      owners[op.edge] = { elementId: el.id, network: ir.index, symbol, operand };
    }
  return owners;
}

export function assembleProgram(
  project: Project,
  opts: CompileOptions,
): { program?: CompiledProgram; diagnostics: Diagnostic[] } {
  const diagnostics: Diagnostic[] = [];
  const globals: Diagnostic[] = [];
  const pou = opts.pou
    ? project.pous.find((p) => p.name.toUpperCase() === opts.pou!.toUpperCase())
    : project.pous.find((p) => p.kind === 'PROGRAM');
  const r = new Reporter(diagnostics, opts.pou ?? project.name, -1);
  if (!pou) {
    r.error(
      'LD-E20',
      opts.pou
        ? `there is no POU named "${opts.pou}" in the project`
        : 'the project has no PROGRAM to run; add one',
    );
    return { diagnostics };
  }
  if (pou.kind !== 'PROGRAM') {
    r.error('LD-E20', `${pou.name} is a ${pou.kind}; only a PROGRAM can be run`);
    return { diagnostics };
  }
  const profile = opts.profile ?? project.profile;
  const lowered = lowerPou(project, pou, profile, diagnostics, globals);
  diagnostics.unshift(...globals);
  if (!lowered.ok) return { diagnostics };
  const { ctx } = lowered;
  const networks = lowered.networks.map((n) => n!);
  const retentive = new Set<VarSymbol>(ctx.retentiveCoilVars);
  for (const v of ctx.symbols.vars) if (v.retain) retentive.add(v);
  return {
    diagnostics,
    program: {
      pou: pou.name,
      profile,
      networks,
      shapes: pou.networks.map((n) => ({ elements: n.elements.length, vlinks: n.vlinks.length })),
      symbols: ctx.symbols,
      functions: ctx.functions,
      edgeCount: ctx.edgeCount,
      edges: edgeOwners(pou, networks, ctx.edgeCount),
      dataSlots: ctx.dataSlots,
      retentive,
    },
  };
}
