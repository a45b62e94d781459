// What ST checking (check.ts) works against and reports: the scope a body is checked in (StScope),
// its errors (StError, thrown as Fail), an expression in words for messages (describe), and what
// places.ts needs from the checker (ExprChecker, implemented by StChecker).
import type { ElementaryType } from '../../model/iecTypes';
import type { Profile } from '../../model/project';
import type { ResolvedFunction } from '../library/functions';
import type { CallBuilder } from '../compile/context';
import type { SymbolTable } from '../compile/symbols';
import type { AggNode } from '../compile/aggregates';
import type { RuleId } from '../api';
import type { Expr, Pos } from './ast';
import type { TExpr, TStmt } from './lowered';

/** What ST statements are checked against. */
export interface StScope {
  readonly symbols: SymbolTable;
  readonly profile: Profile;
  /** The program's function table (standard functions used are appended). */
  readonly functions: ResolvedFunction[];
  /** Builds the bodies of user FB and function calls; absent when a POU is only checked. */
  readonly calls?: CallBuilder;
  /** The POU whose body this is (a FUNCTION's result variable has its name). */
  readonly pouName: string;
}

export interface StError {
  readonly pos: Pos;
  readonly message: string;
  /** The rule broken, when it is not LD-E50 (a body that does not compile). */
  readonly rule?: RuleId;
}

export class Fail extends Error {
  constructor(
    readonly pos: Pos,
    message: string,
    readonly rule?: RuleId,
  ) {
    super(message);
  }
}

export const describe = (e: Expr): string => {
  switch (e.k) {
    case 'lit':
      return e.text;
    case 'name':
    case 'path':
      return `"${e.text}"`;
    case 'call':
      return `${e.name}(...)`;
    case 'cr':
      return 'the current result';
    default:
      return 'the expression';
  }
};

/** What places.ts needs from the checker: expressions (array indexes, values) and aggregate calls. */
export interface ExprChecker {
  expr(e: Expr, hint?: ElementaryType): TExpr;
  to(e: TExpr, t: ElementaryType, pos: Pos, what: string): TExpr;
  aggregateCall(e: Expr): { call?: TStmt; node?: AggNode; type: string; key: string } | undefined;
}
