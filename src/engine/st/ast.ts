// The syntax tree of a Structured Text body (IEC 61131-3 section 7.3), as the parser reads it.
// Instruction List bodies (il/translate.ts) are translated into the same tree: the current result
// is the expression `cr`, and IL's labels and jumps are the statements `label` and `goto`.

/** 1-based line and column in the body's text. */
export interface Pos {
  readonly line: number;
  readonly col: number;
}

export type BinaryOp =
  | '**'
  | '*'
  | '/'
  | 'MOD'
  | '+'
  | '-'
  | '<'
  | '>'
  | '<='
  | '>='
  | '='
  | '<>'
  | 'AND'
  | 'XOR'
  | 'OR';

export type Expr =
  /** A literal as written: 42, 16#FF, 1.5, INT#5, T#1s, TRUE. */
  | { readonly k: 'lit'; readonly text: string; readonly pos: Pos }
  /** A variable, `Instance.Pin`, `Word.3`, `P.X`, `A[3]` (constant indexes) or a location `%IX0.0`. */
  | { readonly k: 'name'; readonly text: string; readonly pos: Pos }
  /** An element chosen by index expressions: `A[i]`, `G[i, j + 1].X`; `head` is the text before the first `[`. */
  | { readonly k: 'path'; readonly head: string; readonly steps: readonly PathStep[]; readonly text: string; readonly pos: Pos }
  | { readonly k: 'unary'; readonly op: '-' | 'NOT'; readonly a: Expr; readonly pos: Pos }
  | { readonly k: 'binary'; readonly op: BinaryOp; readonly a: Expr; readonly b: Expr; readonly pos: Pos }
  | { readonly k: 'call'; readonly name: string; readonly args: readonly Arg[]; readonly pos: Pos }
  /** IL: the current result (slot 0) or a result saved by a deferred operator `AND(` (slot > 0). */
  | { readonly k: 'cr'; readonly slot: number; readonly pos: Pos };

/** A step of a path after its head: a member `.X` or an index list `[i, j]`. */
export type PathStep = { readonly member: string } | { readonly index: readonly Expr[] };

/** A call argument: positional (`a`), an input or in-out (`IN := a`), an output (`Q => y`, `NOT Q => y`). */
export interface Arg {
  readonly name?: string;
  readonly out?: boolean;
  /** `NOT Q => y`: the output is inverted. */
  readonly negated?: boolean;
  readonly value: Expr;
  readonly pos: Pos;
}

export interface CaseLabel {
  readonly lo: Expr;
  readonly hi?: Expr;
}

export type Stmt =
  | { readonly k: 'assign'; readonly target: Expr; readonly value: Expr; readonly pos: Pos }
  /** A call statement: an FB instance (`T1(IN := x)`) or a function whose result is dropped. */
  | { readonly k: 'call'; readonly name: string; readonly args: readonly Arg[]; readonly pos: Pos }
  | {
      readonly k: 'if';
      readonly branches: readonly { readonly cond: Expr; readonly body: readonly Stmt[] }[];
      readonly otherwise?: readonly Stmt[];
      readonly pos: Pos;
    }
  | {
      readonly k: 'case';
      readonly selector: Expr;
      readonly arms: readonly { readonly labels: readonly CaseLabel[]; readonly body: readonly Stmt[]; readonly pos: Pos }[];
      readonly otherwise?: readonly Stmt[];
      readonly pos: Pos;
    }
  | {
      readonly k: 'for';
      readonly control: Expr;
      readonly from: Expr;
      readonly to: Expr;
      readonly by?: Expr;
      readonly body: readonly Stmt[];
      readonly pos: Pos;
    }
  | { readonly k: 'while'; readonly cond: Expr; readonly body: readonly Stmt[]; readonly pos: Pos }
  | { readonly k: 'repeat'; readonly body: readonly Stmt[]; readonly until: Expr; readonly pos: Pos }
  | { readonly k: 'exit'; readonly pos: Pos }
  | { readonly k: 'continue'; readonly pos: Pos }
  | { readonly k: 'return'; readonly pos: Pos }
  /** The pragma `{__SET_VAR(data__->,X,,__CURRENT_TIME)}` (MATIEC's timers): X := the scan's time. */
  | { readonly k: 'now'; readonly target: Expr; readonly pos: Pos }
  /** IL: the current result (or a saved one) takes a value. */
  | { readonly k: 'setcr'; readonly slot: number; readonly value: Expr; readonly pos: Pos }
  | { readonly k: 'label'; readonly name: string; readonly pos: Pos }
  | { readonly k: 'goto'; readonly label: string; readonly pos: Pos };

/** A syntax error: where, and what was expected. */
export class StSyntaxError extends Error {
  constructor(
    readonly pos: Pos,
    readonly detail: string,
  ) {
    super(`line ${pos.line} col ${pos.col}: ${detail}`);
  }
}
