// Structured Text and Instruction List bodies in the engine.
//
// A POU written in ST or IL (`pou.language`, body text in `pou.source`) compiles to ONE network
// holding ONE operation `{ op: 'st' }` (compile/ir.ts StOp): the checked statement tree, every
// name resolved over the scope the body runs in (the program's, an FB instance's, a function call
// site's), so the Flattener places it like an LD body and calls of it run like calls of LD
// bodies. Code generation (st/emit.ts) writes the tree as JavaScript through the network emitter.
//
// Pipeline: text -> lexer.ts -> parser.ts (ST) or il/translate.ts (IL) -> ast.ts tree ->
// check.ts (types, names, calls; lowered.ts tree) -> emit.ts (JavaScript).
//
// API for other compilers (SFC transitions and actions written in ST):
// - `compileStStatements(text, scope)` -> `{ body?: TStmt[], errors }`: statements checked over
//   `scope` (StScope: the SymbolTable, the profile, the program's function table, the
//   CallBuilder that places bodies of user blocks called from the text, the POU's name).
// - `compileStExpression(text, scope, expected?)` -> `{ expr?: TExpr, errors }`: one expression
//   (a transition condition: pass 'BOOL'); its type is `expr.type`.
// - `stOp(body, network, language)` -> the StOp to put alone in a NetworkIR (`stNetwork`).
// Errors are `{ pos: { line, col }, message }`; `describeStError` words them for a diagnostic.
// Rule ids: LD-E50 (a body that does not compile), LD-W50 (a pragma the simulator ignores),
// LD-E51 (a body in a language the simulator does not run: SFC, FBD left as FBD).
import type { ElementaryType } from '../../model/iecTypes';
import type { Pou } from '../../model/project';
import type { NetworkIR } from '../compile/ir';
import { translateIl } from '../il/translate';
import { StSyntaxError, type Expr, type Pos, type Stmt } from './ast';
import { StChecker } from './check';
import type { StError, StScope } from './checkScope';
import { stFacts, type StOp, type TExpr, type TStmt } from './lowered';
import { parseExpression, parseStatements } from './parser';

export type { StScope, StError } from './checkScope';
export type { TExpr, TStmt } from './lowered';

/** The languages whose bodies this compiler runs. */
export const isTextPou = (pou: Pou): pou is Pou & { language: 'ST' | 'IL' } => pou.language === 'ST' || pou.language === 'IL';

/** "line 3 col 7: ..." */
export const describeStError = (e: StError): string => `line ${e.pos.line} col ${e.pos.col}: ${e.message}`;

export interface ParsedBody {
  readonly stmts?: readonly Stmt[];
  readonly errors: StError[];
  /** Pragmas the engine does not run. */
  readonly pragmas: { readonly pos: Pos; readonly text: string }[];
}

const parsedCache = new WeakMap<Pou, ParsedBody>();

/** The syntax tree of an ST or IL POU's body (cached per POU object). */
export function parseBody(pou: Pou): ParsedBody {
  let hit = parsedCache.get(pou);
  if (!hit) {
    const pragmas: { pos: Pos; text: string }[] = [];
    try {
      const text = pou.source ?? '';
      const stmts = pou.language === 'IL' ? translateIl(text) : parseStatements(text, { onPragma: (t, pos) => pragmas.push({ pos, text: t }) });
      hit = { stmts, errors: [], pragmas };
    } catch (e) {
      if (!(e instanceof StSyntaxError)) throw e;
      hit = { errors: [{ pos: e.pos, message: e.detail }], pragmas };
    }
    parsedCache.set(pou, hit);
  }
  return hit;
}

/** Names called in an ST/IL body (functions and instances), for the call graph. */
export function calledNames(pou: Pou): string[] {
  const body = parseBody(pou).stmts;
  if (!body) return [];
  const names: string[] = [];
  const expr = (e: Expr): void => {
    switch (e.k) {
      case 'call':
        names.push(e.name);
        e.args.forEach((a) => expr(a.value));
        return;
      case 'unary':
        expr(e.a);
        return;
      case 'binary':
        expr(e.a);
        expr(e.b);
        return;
      default:
        return;
    }
  };
  const stmts = (list: readonly Stmt[]): void => {
    for (const s of list) {
      switch (s.k) {
        case 'assign':
        case 'setcr':
          expr(s.value);
          break;
        case 'call':
          names.push(s.name);
          s.args.forEach((a) => expr(a.value));
          break;
        case 'if':
          s.branches.forEach((b) => (expr(b.cond), stmts(b.body)));
          if (s.otherwise) stmts(s.otherwise);
          break;
        case 'case':
          expr(s.selector);
          s.arms.forEach((a) => stmts(a.body));
          if (s.otherwise) stmts(s.otherwise);
          break;
        case 'for':
          [s.from, s.to, ...(s.by ? [s.by] : [])].forEach(expr);
          stmts(s.body);
          break;
        case 'while':
          expr(s.cond);
          stmts(s.body);
          break;
        case 'repeat':
          stmts(s.body);
          expr(s.until);
          break;
        default:
          break;
      }
    }
  };
  stmts(body);
  return names;
}

function check(stmts: readonly Stmt[], scope: StScope): { body: TStmt[]; errors: StError[]; crSlots: number } {
  const checker = new StChecker(scope);
  checker.declareLabels(stmts);
  const body = checker.statements(stmts);
  let crSlots = 0;
  for (const s of stmts) if (s.k === 'setcr') crSlots = Math.max(crSlots, s.slot + 1);
  return { body, errors: checker.errors, crSlots };
}

/** ST statements checked over a scope. */
export function compileStStatements(text: string, scope: StScope): { body?: TStmt[]; errors: StError[] } {
  let stmts: Stmt[];
  try {
    stmts = parseStatements(text);
  } catch (e) {
    if (!(e instanceof StSyntaxError)) throw e;
    return { errors: [{ pos: e.pos, message: e.detail }] };
  }
  const r = check(stmts, scope);
  return r.errors.length ? { errors: r.errors } : { body: r.body, errors: [] };
}

/** One ST expression checked over a scope; with `expected`, its value must widen to that type. */
export function compileStExpression(text: string, scope: StScope, expected?: ElementaryType): { expr?: TExpr; errors: StError[] } {
  try {
    const e = parseExpression(text);
    const checker = new StChecker(scope);
    const value = checker.expr(e, expected);
    return { expr: expected ? checker.to(value, expected, e.pos, 'use it') : value, errors: [] };
  } catch (e) {
    if (e instanceof StSyntaxError) return { errors: [{ pos: e.pos, message: e.detail }] };
    if (e instanceof Error && 'pos' in e) return { errors: [{ pos: (e as unknown as { pos: Pos }).pos, message: e.message }] };
    throw e;
  }
}

/** The operation running a checked body in network `network` (its index in the program). */
export function stOp(body: readonly TStmt[], network: number, language: 'ST' | 'IL', crSlots = 0): StOp {
  const facts = stFacts(body);
  return { op: 'st', node: 0, language, body, network, crSlots, labels: facts.labels, weight: facts.weight, calls: facts.calls };
}

/** A network holding one StOp. */
export function stNetwork(op: StOp, label?: string): NetworkIR {
  return {
    index: op.network,
    ops: [op],
    netCount: 0,
    railNets: [],
    elementNets: [],
    vlinkNets: [],
    constants: [],
    ...(label ? { label } : {}),
  };
}

/**
 * Most syntax nodes of the top-level statements one network of an ST body holds. A larger body
 * (without RETURN) is split into consecutive networks of whole top-level statements, so neither
 * its JavaScript nor the bodies its calls write in place make a function too large for V8 to
 * optimise (segments and dispatch functions are cut between networks). The split changes nothing
 * a program sees: the networks run in order, once each.
 */
export const ST_NETWORK_NODES = 48;

const nodeCount = (x: unknown): number => {
  if (Array.isArray(x)) return x.reduce((a: number, y) => a + nodeCount(y), 0);
  if (!x || typeof x !== 'object') return 0;
  let n = 'k' in x ? 1 : 0;
  for (const y of Object.values(x)) n += nodeCount(y);
  return n;
};
const hasReturn = (x: unknown): boolean =>
  Array.isArray(x) ? x.some(hasReturn) : !!x && typeof x === 'object' && ((x as { k?: string }).k === 'return' || Object.values(x).some(hasReturn));

const chunksCache = new WeakMap<Pou, number[]>();

/** Where the networks of an ST/IL body start: indexes of its top-level statements (one network: [0]). Cached per POU object. */
export function bodyChunks(pou: Pou): number[] {
  let hit = chunksCache.get(pou);
  if (!hit) chunksCache.set(pou, (hit = findChunks(pou)));
  return hit;
}

function findChunks(pou: Pou): number[] {
  const stmts = pou.language === 'ST' ? parseBody(pou).stmts : undefined;
  if (!stmts || stmts.length < 2 || hasReturn(stmts)) return [0];
  const starts = [0];
  let nodes = 0;
  stmts.forEach((st, k) => {
    const n = nodeCount(st);
    if (k > 0 && nodes + n > ST_NETWORK_NODES) {
      starts.push(k);
      nodes = 0;
    }
    nodes += n;
  });
  return starts;
}

/** Compiles the body of an ST or IL POU over `scope` into its networks (from index `network`; as many as bodyChunks). */
export function compileTextBody(
  pou: Pou & { language: 'ST' | 'IL' },
  scope: StScope,
  network: number,
): { networks?: NetworkIR[]; errors: StError[]; pragmas: ParsedBody['pragmas'] } {
  const parsed = parseBody(pou);
  if (!parsed.stmts) return { errors: parsed.errors, pragmas: parsed.pragmas };
  const starts = bodyChunks(pou);
  if (starts.length === 1) {
    const r = check(parsed.stmts, scope);
    if (r.errors.length) return { errors: r.errors, pragmas: parsed.pragmas };
    return { networks: [stNetwork(stOp(r.body, network, pou.language, r.crSlots))], errors: [], pragmas: parsed.pragmas };
  }
  // Each network's statements checked in order over the same scope (an ST body has no labels).
  const checker = new StChecker(scope);
  const networks: NetworkIR[] = [];
  starts.forEach((from, j) => {
    const body = checker.statements(parsed.stmts!.slice(from, starts[j + 1] ?? parsed.stmts!.length));
    networks.push(stNetwork(stOp(body, network + j, pou.language)));
  });
  if (checker.errors.length) return { errors: checker.errors, pragmas: parsed.pragmas };
  return { networks, errors: [], pragmas: parsed.pragmas };
}
