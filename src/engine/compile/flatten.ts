// Flattening: every call of a user FB instance or FUNCTION gets a copy of the callee's networks,
// lowered over the callee's variables as that call sees them (the instance's slots, in-out names
// bound to the caller's variables, a function call site's own slots), and appended to the
// program's network array after the programs. Bodies of one POU have one shape, so the dispatch
// loops share their code; a call runs its body as a nested range of networks.
import type { Pou, Profile, Project } from '../../model/project';
import type { Diagnostic } from '../api';
import { EdgeTable, type CallBuilder, type FunctionSite, type SharedParts } from './context';
import type { NetworkIR } from './ir';
import { lowerChartBody } from '../sfc/body';
import { lowerPouBody } from './pou';
import { bodyShapes } from '../st/body';
import { SymbolTable, type Access, type AggSymbol, type Sym, type UfbSymbol } from './symbols';

/** A range of the program's networks that runs one POU: a program, an FB instance's call, a function call. */
export interface BodyInfo {
  readonly kind: 'program' | 'fb' | 'function';
  readonly pou: string;
  /** Program instance name or FB instance path (`Motor1`, `Line.Motor1`); absent for the single program and functions. */
  readonly instance?: string;
  readonly first: number;
  readonly end: number;
  /** Body that calls this one (-1 for programs). */
  readonly parent: number;
}

/** A body's network range, allocated before it is lowered. */
export interface ReservedBody {
  readonly pou: Pou;
  readonly info: { readonly kind: BodyInfo['kind']; readonly instance?: string };
  readonly index: number;
  readonly first: number;
  readonly end: number;
}

/** Deeper than this, calls are certainly recursive (LD-E21 reports it); a guard, never reached otherwise. */
const MAX_DEPTH = 256;

export class Flattener implements CallBuilder {
  readonly networks: (NetworkIR | undefined)[] = [];
  readonly shapes: { elements: number; vlinks: number }[] = [];
  readonly bodies: BodyInfo[] = [];
  readonly bodyOf: number[] = [];
  readonly shared: SharedParts = {
    functions: [],
    edges: new EdgeTable(),
    retentiveCoilVars: new Set(),
    dataSlots: [],
    enMemories: new Map(),
  };
  /** Errors found while lowering bodies (their POU's own check normally reports them first). */
  readonly errors: Diagnostic[] = [];
  ok = true;
  private current = -1;
  private depth = 0;

  constructor(
    readonly project: Project,
    readonly profile: Profile,
  ) {}

  /** Lowers `pou` over `scope` as a new body; its diagnostics go to `out` (default: kept in `errors`). */
  body(
    pou: Pou,
    scope: SymbolTable,
    info: { kind: BodyInfo['kind']; instance?: string },
    out?: Diagnostic[],
    /** The instance's own table, when `scope` is this call's copy (a chart's step names are bound in both). */
    own: SymbolTable = scope,
  ): { first: number; end: number } | undefined {
    const reserved = this.reserve(pou, info);
    if (!reserved) return undefined;
    this.lower(reserved, scope, out, own);
    return { first: reserved.first, end: reserved.end };
  }

  /**
   * Allocates the network range of a body without lowering it. Program instances of a
   * configuration are reserved first, so their ranges are contiguous at the start of the network
   * array (their callees' bodies come after them) and run in task order.
   */
  reserve(pou: Pou, info: { kind: BodyInfo['kind']; instance?: string }): ReservedBody | undefined {
    if (this.depth >= MAX_DEPTH) {
      this.ok = false;
      return undefined;
    }
    const first = this.networks.length;
    const sfc = pou.language === 'SFC';
    const shapes = sfc ? [{ elements: 0, vlinks: 0 }] : bodyShapes(pou);
    const end = first + shapes.length;
    const index = this.bodies.length;
    this.bodies.push({
      kind: info.kind,
      pou: pou.name,
      ...(info.instance ? { instance: info.instance } : {}),
      first,
      end,
      parent: this.current,
    });
    for (const shape of shapes) {
      this.networks.push(undefined);
      this.shapes.push(shape);
      this.bodyOf.push(index);
    }
    return { pou, info, index, first, end };
  }

  /** Lowers a reserved body over `scope`. */
  lower(reserved: ReservedBody, scope: SymbolTable, out?: Diagnostic[], own: SymbolTable = scope): void {
    const { pou, info, index, first } = reserved;
    const sfc = pou.language === 'SFC';
    const sink: Diagnostic[] = out ?? [];
    const parent = this.current;
    this.current = index;
    this.depth++;
    const lowered = sfc
      ? lowerChartBody(pou, scope, scope === own ? [scope] : [own, scope], sink, first, (piece) =>
          this.body(piece, scope, { kind: 'fb', ...(info.instance ? { instance: info.instance } : {}) }, sink),
          { profile: this.profile, functions: this.shared.functions, calls: this },
        )
      : lowerPouBody(this.project, pou, this.profile, scope, sink, {
          first,
          ...(info.instance ? { instance: info.instance } : {}),
          calls: this,
          shared: this.shared,
        });
    this.depth--;
    this.current = parent;
    lowered.networks.forEach((n, k) => (this.networks[first + k] = n));
    if (!lowered.ok) {
      this.ok = false;
      if (!out) this.errors.push(...sink.filter((d) => d.severity === 'error'));
    }
  }

  fbBody(instance: UfbSymbol, refs: ReadonlyMap<string, Access | AggSymbol>): { first: number; end: number } | undefined {
    return this.body(instance.pou, withRefs(instance.scope, refs), { kind: 'fb', instance: instance.name }, undefined, instance.scope);
  }

  functionCall(pou: Pou, site: string): FunctionSite {
    const owner = new SymbolTable(this.rootStorage(), '', this.library(), true);
    const inst = owner.instantiate(pou, site, false);
    const scope = inst.scope;
    if (!scope.own(pou.name))
      scope.declare(
        { name: pou.name, type: pou.returnType ?? 'BOOL', varClass: 'output', retain: false, comment: '' },
        false,
        quiet(),
      );
    return {
      scope,
      body: (refs) => this.body(pou, withRefs(scope, refs), { kind: 'function' }),
    };
  }

  private root: SymbolTable | undefined;
  /** The program's root table (its storage holds every slot). */
  setRoot(root: SymbolTable): void {
    this.root = root;
  }
  private rootStorage() {
    return this.root!.storage;
  }
  private library() {
    return this.root!.library;
  }

  /** The program's networks, once every body lowered without error. */
  complete(): NetworkIR[] | undefined {
    if (!this.ok || this.networks.some((n) => n === undefined)) return undefined;
    return this.networks as NetworkIR[];
  }
}

function withRefs(scope: SymbolTable, refs: ReadonlyMap<string, Access | AggSymbol>): SymbolTable {
  if (refs.size === 0) return scope;
  const extra = new Map<string, Sym>();
  for (const [name, access] of refs) extra.set(name, access.kind === 'agg' ? access : { kind: 'ref', name, access });
  return scope.withRefs(extra);
}

function quiet(): import('./report').Reporter {
  return { errors: 0, error() {}, warning() {} } as unknown as import('./report').Reporter;
}
