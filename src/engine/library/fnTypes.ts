// Shapes shared by the standard function implementations.
import type { ElementaryType, Value } from '../../model/iecTypes';

/** Per-call state: an implementation sets `error` to turn ENO OFF (the engine clears it before each call). */
export interface FnContext {
  error: boolean;
}

export type FnImpl = (ctx: FnContext, args: readonly Value[]) => Value;
export type FnImpl1 = (ctx: FnContext, a: Value) => Value;
export type FnImpl2 = (ctx: FnContext, a: Value, b: Value) => Value;

export interface ResolvedFunction {
  readonly name: string;
  /** Concrete type of each input, in expanded input order (without EN); callers pass values of these types. */
  readonly argTypes: ElementaryType[];
  readonly outType: ElementaryType;
  /** Expanded input pin names aligned with argTypes (e.g. IN1, IN2, IN3 or K, IN0, IN1). */
  readonly inputNames: readonly string[];
  readonly impl: FnImpl;
  /** Same as impl for one input, without an argument array. */
  readonly impl1?: FnImpl1;
  /** Same as impl for two inputs, without an argument array. */
  readonly impl2?: FnImpl2;
}

/** Accepts a number where a bigint is expected, so a caller that skipped widening INT -> LINT still computes right. */
export const big = (v: Value): bigint =>
  typeof v === 'bigint' ? v : BigInt(typeof v === 'boolean' ? (v ? 1 : 0) : typeof v === 'string' ? 0 : Math.trunc(v));
/** A number (a string, which no numeric function is given, reads as NaN). */
export const num = (v: Value): number =>
  typeof v === 'number' ? v : typeof v === 'bigint' ? Number(v) : typeof v === 'string' ? Number.NaN : v ? 1 : 0;
