// The checked form of an ST (or IL) body that code generation turns into JavaScript: every name
// resolved to an Access, every operator to a typed operation (standard functions by their index
// in the program's function table), every call of a user block to its flattened body range.
// StOp, the operation holding such a body in a network (one of compile/ir.ts Op), is here too.
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { Access } from '../compile/symbols';

export type CompareOp = '<' | '>' | '<=' | '>=' | '===' | '!==';

export type TExpr =
  | { readonly k: 'const'; readonly type: ElementaryType; readonly value: Value; readonly literal?: string }
  | { readonly k: 'read'; readonly type: ElementaryType; readonly access: Access }
  /** A standard function (or an operator implemented by one: + is ADD) from the function table. */
  | { readonly k: 'fn'; readonly type: ElementaryType; readonly fn: number; readonly args: readonly TExpr[] }
  | { readonly k: 'logic'; readonly type: 'BOOL'; readonly op: 'AND' | 'OR' | 'XOR'; readonly a: TExpr; readonly b: TExpr }
  | { readonly k: 'not'; readonly type: 'BOOL'; readonly a: TExpr }
  | { readonly k: 'cmp'; readonly type: 'BOOL'; readonly op: CompareOp; readonly a: TExpr; readonly b: TExpr }
  /** A number-held integer used where a 64-bit (bigint-held) type is expected. */
  | { readonly k: 'big'; readonly type: ElementaryType; readonly a: TExpr }
  /** `/` on REAL or LREAL: IEEE division as MATIEC's C does it (x / 0 is +-Inf or NaN, not an error). */
  | { readonly k: 'rdiv'; readonly type: ElementaryType; readonly a: TExpr; readonly b: TExpr }
  /** `**` (EXPT): a REAL or LREAL base. */
  | { readonly k: 'pow'; readonly type: ElementaryType; readonly a: TExpr; readonly b: TExpr }
  /** IL's current result (slot 0) or a saved one. */
  | { readonly k: 'cr'; readonly type: ElementaryType; readonly slot: number }
  /** A value computed by statements first (a call of a user FUNCTION: its body runs, then its result is read). */
  | { readonly k: 'seq'; readonly type: ElementaryType; readonly pre: readonly TStmt[]; readonly value: TExpr };

export interface CaseArm {
  readonly labels: readonly { readonly lo: Value; readonly hi?: Value }[];
  readonly body: readonly TStmt[];
}

export type TStmt =
  | { readonly k: 'assign'; readonly dst: Access; readonly value: TExpr }
  /** A function call whose result is not used. */
  | { readonly k: 'eval'; readonly value: TExpr }
  | {
      readonly k: 'if';
      /** `line`: where an ELSIF's condition is (the instrumented code stops there). */
      readonly branches: readonly { readonly cond: TExpr; readonly body: readonly TStmt[]; readonly line?: number }[];
      readonly otherwise?: readonly TStmt[];
    }
  | { readonly k: 'case'; readonly selector: TExpr; readonly arms: readonly CaseArm[]; readonly otherwise?: readonly TStmt[] }
  | {
      readonly k: 'for';
      readonly control: Access;
      readonly from: TExpr;
      readonly to: TExpr;
      readonly by: TExpr;
      /** ADD of the control variable's type (the increment wraps like the variable). */
      readonly add: number;
      readonly body: readonly TStmt[];
      readonly line: number;
    }
  | { readonly k: 'while'; readonly cond: TExpr; readonly body: readonly TStmt[]; readonly line: number }
  | { readonly k: 'repeat'; readonly body: readonly TStmt[]; readonly until: TExpr; readonly line: number }
  | { readonly k: 'exit' }
  | { readonly k: 'continue' }
  | { readonly k: 'return' }
  /** A standard FB instance called: inputs set, executed, outputs assigned. */
  | {
      readonly k: 'fb';
      readonly fb: number;
      readonly ins: readonly { readonly pin: string; readonly value: TExpr }[];
      readonly outs: readonly { readonly pin: string; readonly type: ElementaryType; readonly dst: Access; readonly negated?: boolean }[];
    }
  /** A user FB instance or FUNCTION called: its body [first, end) runs between inputs and outputs. */
  | {
      readonly k: 'call';
      readonly inits: readonly { readonly dst: Access; readonly value: Value }[];
      readonly assigns: readonly { readonly dst: Access; readonly value: TExpr }[];
      readonly first: number;
      readonly end: number;
      readonly outs: readonly { readonly dst: Access; readonly src: Access; readonly negated?: boolean }[];
    }
  /** The scan's time into a TIME variable (MATIEC's __CURRENT_TIME pragma). */
  | { readonly k: 'now'; readonly dst: Access }
  | { readonly k: 'setcr'; readonly slot: number; readonly value: TExpr }
  | { readonly k: 'label'; readonly id: number }
  | { readonly k: 'goto'; readonly id: number; readonly back: boolean; readonly line: number }
  /**
   * Where the next statement starts in the body's text (1-based line). No code on the fast path;
   * the instrumented step code (emit.ts, `instrument`) records the line and may pause there.
   */
  | { readonly k: 'line'; readonly line: number };

/** Every body range the statements call (nested loops included), and their size in operations. */
export function stFacts(body: readonly TStmt[]): { calls: { first: number; end: number }[]; weight: number; labels: boolean } {
  const calls: { first: number; end: number }[] = [];
  let weight = 0;
  let labels = false;
  const expr = (e: TExpr): void => {
    weight++;
    switch (e.k) {
      case 'fn':
        e.args.forEach(expr);
        return;
      case 'logic':
      case 'cmp':
      case 'pow':
      case 'rdiv':
        expr(e.a);
        expr(e.b);
        return;
      case 'not':
      case 'big':
        expr(e.a);
        return;
      case 'seq':
        stmts(e.pre);
        expr(e.value);
        return;
      default:
        return;
    }
  };
  const stmts = (list: readonly TStmt[]): void => {
    for (const s of list) {
      if (s.k === 'line') continue;
      weight++;
      switch (s.k) {
        case 'assign':
        case 'eval':
        case 'setcr':
          expr(s.value);
          break;
        case 'if':
          for (const b of s.branches) {
            expr(b.cond);
            stmts(b.body);
          }
          if (s.otherwise) stmts(s.otherwise);
          break;
        case 'case':
          expr(s.selector);
          for (const a of s.arms) stmts(a.body);
          if (s.otherwise) stmts(s.otherwise);
          break;
        case 'for':
          expr(s.from);
          expr(s.to);
          expr(s.by);
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
        case 'fb':
          s.ins.forEach((i) => expr(i.value));
          break;
        case 'call':
          s.assigns.forEach((a) => expr(a.value));
          calls.push({ first: s.first, end: s.end });
          break;
        case 'label':
          labels = true;
          break;
        default:
          break;
      }
    }
  };
  stmts(body);
  return { calls, weight, labels };
}

/** The lines of every statement (and ELSIF condition) of a checked body, where the instrumented code stops. */
export function stLines(body: readonly TStmt[], out: Set<number> = new Set()): Set<number> {
  for (const s of body) {
    switch (s.k) {
      case 'line':
        out.add(s.line);
        break;
      case 'if':
        for (const b of s.branches) {
          if (b.line !== undefined) out.add(b.line);
          stLines(b.body, out);
        }
        if (s.otherwise) stLines(s.otherwise, out);
        break;
      case 'case':
        for (const a of s.arms) stLines(a.body, out);
        if (s.otherwise) stLines(s.otherwise, out);
        break;
      case 'for':
      case 'while':
      case 'repeat':
        stLines(s.body, out);
        break;
      default:
        break;
    }
  }
  return out;
}

/**
 * The body of a POU written in ST or IL (st/index.ts): one operation, the whole checked statement
 * tree, alone in its network. `calls`: the body ranges its calls run; `weight`: its size in operations.
 */
export interface StOp {
  readonly op: 'st';
  readonly node: number;
  readonly language: 'ST' | 'IL';
  readonly body: readonly TStmt[];
  /** The network holding it (named by the watchdog when a loop runs too long). */
  readonly network: number;
  /** IL: current-result registers used. */
  readonly crSlots: number;
  /** IL: the body has labels (jumps run as a state machine). */
  readonly labels: boolean;
  readonly weight: number;
  readonly calls: readonly { readonly first: number; readonly end: number }[];
}
