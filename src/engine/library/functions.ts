// Resolution of a standard function call to a concrete, typed implementation. Signatures come from
// model/blocks.ts: poly pins share one concrete type, the narrowest type every typed argument widens
// to (canWiden); untyped literals (argType undefined) adopt that type, or `outTypeHint` when no
// argument is typed. A generic pin that is not poly takes its own type: an input the type of its
// argument (an untyped literal: INT for ANY_INT, LREAL for ANY_NUM, so EXPT(x, 0.5) reads 0.5), the
// output (TRUNC's ANY_INT) the type of the variable OUT is written to, else DINT. Behaviour per
// function lives in arithmetic.ts, bitwise.ts, select.ts, convert.ts, numeric.ts, bcd.ts,
// timeFunctions.ts, strings.ts (string functions, and comparisons, MAX, MIN, LIMIT of strings).
import { blockSignature, conversionTypes, type BlockSignature, type PinSignature } from '../../model/blocks';
import { GENERIC_MEMBERS, isElementaryType, type ElementaryType, type GenericType, type Value } from '../../model/iecTypes';
import type { Profile } from '../../model/project';
import { canWiden, commonType, isSignedType, isStringType } from '../values/types';
import { absolute, arithmetic, negate, type ArithOp } from './arithmetic';
import { complement, logic, shift, type LogicOp, type ShiftOp } from './bitwise';
import { bcdToInt, intToBcd } from './bcd';
import { conversion, truncation } from './convert';
import { isRealFunction, power, realFunction } from './numeric';
import { isTimeFunction, timeFunction } from './timeFunctions';
import type { FnContext, FnImpl, FnImpl1, FnImpl2, ResolvedFunction } from './fnTypes';
import { compare, extreme, limit, multiplex, select, type CompareOp } from './select';
import { isStringComparison, isStringFunction, stringComparison, stringFunction } from './strings';

export type { FnContext, ResolvedFunction } from './fnTypes';

export type ResolveResult = { ok: true; fn: ResolvedFunction } | { ok: false; message: string };

const VERB: Record<string, string> = {
  ADD: 'add',
  SUB: 'subtract',
  MUL: 'multiply',
  DIV: 'divide',
  MOD: 'take the remainder of',
  ABS: 'take the absolute value of',
  NEG: 'negate',
  AND: 'combine',
  OR: 'combine',
  XOR: 'combine',
  NOT: 'invert',
  SHL: 'shift',
  SHR: 'shift',
  ROL: 'rotate',
  ROR: 'rotate',
  SEL: 'select between',
  MUX: 'select between',
  MAX: 'compare',
  GT: 'compare',
  GE: 'compare',
  EQ: 'compare',
  NE: 'compare',
  LE: 'compare',
  LT: 'compare',
  MIN: 'compare',
  LIMIT: 'limit',
  MOVE: 'copy',
  SQRT: 'take the square root of',
  LN: 'take the logarithm of',
  LOG: 'take the logarithm of',
  EXP: 'raise e to',
  SIN: 'take the sine of',
  COS: 'take the cosine of',
  TAN: 'take the tangent of',
  ASIN: 'take the arc sine of',
  ACOS: 'take the arc cosine of',
  ATAN: 'take the arc tangent of',
  EXPT: 'raise',
  TRUNC: 'truncate',
  LEN: 'measure',
  LEFT: 'cut',
  RIGHT: 'cut',
  MID: 'cut',
  CONCAT: 'join',
  INSERT: 'insert into',
  DELETE: 'delete from',
  REPLACE: 'replace in',
  FIND: 'search',
};

/** Type an untyped literal takes on a generic input that is not poly (MUX's K, EXPT's IN2). */
const OWN_LITERAL_DEFAULT: Partial<Record<GenericType, ElementaryType>> = { ANY_NUM: 'LREAL' };

/** Type of a generic output that is not poly (TRUNC's ANY_INT) when OUT is written to nothing typed. */
const OWN_OUTPUT_DEFAULT: Partial<Record<GenericType, ElementaryType>> = { ANY_INT: 'DINT' };

/** How a generic pin type reads in a message. */
const GENERIC_WORDS: Partial<Record<GenericType, string>> = {
  ANY: 'a value',
  ANY_ELEMENTARY: 'a value',
  ANY_MAGNITUDE: 'a number or a TIME',
  ANY_NUM: 'a number',
  ANY_INT: 'an integer',
  ANY_REAL: 'a REAL or LREAL',
  ANY_BIT: 'a bit string',
  ANY_STRING: 'a STRING or WSTRING',
};

/** Type an untyped literal takes when neither a typed argument nor a hint says more. */
const LITERAL_DEFAULT: Record<GenericType, ElementaryType> = {
  ANY: 'INT',
  ANY_ELEMENTARY: 'INT',
  ANY_MAGNITUDE: 'INT',
  ANY_NUM: 'INT',
  ANY_INT: 'INT',
  ANY_REAL: 'REAL',
  ANY_BIT: 'BOOL',
  ANY_STRING: 'STRING',
};

const admits = (pinType: PinSignature['type'], t: ElementaryType): boolean =>
  isElementaryType(pinType) ? pinType === t : GENERIC_MEMBERS[pinType].includes(t);

const listTypes = (types: readonly ElementaryType[]): string => {
  const distinct = [...new Set(types)];
  return distinct.length === 1 ? distinct[0]! : `${distinct.slice(0, -1).join(', ')} and ${distinct[distinct.length - 1]}`;
};

/** The input pins of a call with `count` inputs, extensible series expanded (ADD: IN1..INn; MUX: K, IN0..INn-1). */
function expandInputs(sig: BlockSignature, count: number): readonly PinSignature[] | string {
  const ext = sig.extensible;
  if (!ext) {
    if (count === sig.inputs.length) return sig.inputs;
    return `${sig.name} takes ${sig.inputs.length} input${sig.inputs.length === 1 ? '' : 's'} (${sig.inputs.map((p) => p.name).join(', ')}), not ${count}`;
  }
  const series = new RegExp(`^${ext.prefix}\\d+$`);
  const fixed = sig.inputs.filter((p) => !series.test(p.name));
  const repeated = sig.inputs[sig.inputs.length - 1]!;
  const n = count - fixed.length;
  if (n < ext.min || n > ext.max) {
    const first = `${ext.prefix}${ext.start}`;
    return `${sig.name} takes ${fixed.length ? `${fixed.map((p) => p.name).join(', ')} and ` : ''}${ext.min} to ${ext.max} inputs ${first}.., not ${n}`;
  }
  return [...fixed, ...Array.from({ length: n }, (_, i) => ({ ...repeated, name: `${ext.prefix}${ext.start + i}` }))];
}

const fold =
  (op: FnImpl2): FnImpl =>
  (ctx, args) => {
    let acc = op(ctx, args[0]!, args[1]!);
    for (let i = 2; i < args.length; i++) acc = op(ctx, acc, args[i]!);
    return acc;
  };
const fromImpl2 =
  (op: FnImpl2): FnImpl =>
  (ctx, args) =>
    op(ctx, args[0]!, args[1]!);
const fromImpl1 =
  (op: FnImpl1): FnImpl =>
  (ctx, args) =>
    op(ctx, args[0]!);

type Impls = { impl: FnImpl; impl1?: FnImpl1; impl2?: FnImpl2 } | string;

function implement(
  name: string,
  t: ElementaryType,
  argTypes: readonly ElementaryType[],
  outType: ElementaryType,
  profile: Profile,
): Impls {
  const one = (f: FnImpl1): Impls => ({ impl: fromImpl1(f), impl1: f });
  const two = (f: FnImpl2, extensible: boolean): Impls => ({ impl: extensible ? fold(f) : fromImpl2(f), impl2: f });
  if (isStringFunction(name)) return stringFunction(name, outType, profile);
  if (isStringType(t) && isStringComparison(name)) return stringComparison(name, t, argTypes.length);
  const conv = conversionTypes(name);
  if (conv) return one(conversion(conv.from, conv.to, profile));
  if (isRealFunction(name)) return one(realFunction(name, t));
  if (isTimeFunction(name)) return two(timeFunction(name), false);
  if (name.startsWith('BCD_TO_')) return one(bcdToInt(outType));
  if (name.endsWith('_TO_BCD')) return one(intToBcd(outType));
  switch (name) {
    case 'EXPT':
      return two(power(t), false);
    case 'TRUNC':
      return one(truncation(outType, profile));
    case 'MOVE':
      return one((_c, a) => a);
    case 'ADD':
    case 'SUB':
    case 'MUL':
    case 'DIV':
    case 'MOD': {
      const op = arithmetic(name as ArithOp, t, profile);
      if (!op) return `${name} cannot ${VERB[name]} ${t} values`;
      return two(op, name === 'ADD' || name === 'MUL');
    }
    case 'ABS':
      return one(absolute(t));
    case 'NEG':
      if (!isSignedType(t) || t === 'TIME') return `NEG cannot negate ${t}: it is unsigned`;
      return one(negate(t));
    case 'GT':
    case 'GE':
    case 'EQ':
    case 'NE':
    case 'LE':
    case 'LT': {
      const c = compare(name as CompareOp, t);
      return argTypes.length === 2 ? { impl: c.impl, impl2: c.impl2 } : { impl: c.impl };
    }
    case 'MAX':
    case 'MIN': {
      const e = extreme(name, t);
      return argTypes.length === 2 ? { impl: e.impl, impl2: e.impl2 } : { impl: e.impl };
    }
    case 'AND':
    case 'OR':
    case 'XOR':
      return two(logic(name as LogicOp, t), true);
    case 'NOT':
      return one(complement(t));
    case 'SHL':
    case 'SHR':
    case 'ROL':
    case 'ROR':
      return two(shift(name as ShiftOp, t), false);
    case 'SEL':
      return { impl: select };
    case 'MUX':
      return { impl: multiplex(t, profile) };
    case 'LIMIT':
      return { impl: limit(t, profile) };
    default:
      return `${name} has no implementation`;
  }
}

/**
 * MUL and DIV of a TIME (IN1) by a number (IN2): MATIEC's MUL__TIME__TIME__ANY_NUM and
 * DIV__TIME__TIME__ANY_NUM, listed in OpenPLC Editor's Time section (deprecated names of MULTIME
 * and DIVTIME, and what `T * 2` means in ST). An untyped IN2 literal is read as LREAL.
 */
function timeScaling(name: string, argTypes: readonly (ElementaryType | undefined)[]): ResolvedFunction | undefined {
  if ((name !== 'MUL' && name !== 'DIV') || argTypes.length !== 2 || argTypes[0] !== 'TIME') return undefined;
  const n = argTypes[1] ?? 'LREAL';
  if (!GENERIC_MEMBERS.ANY_NUM.includes(n)) return undefined;
  const impl2 = timeFunction(name === 'MUL' ? 'MULTIME' : 'DIVTIME');
  return { name, argTypes: ['TIME', n], outType: 'TIME', inputNames: ['IN1', 'IN2'], impl: fromImpl2(impl2), impl2 };
}

/** A generic output of its own (TRUNC's ANY_INT): the type of the variable OUT is written to, else the default. */
function ownOutputType(generic: GenericType, hint: ElementaryType | undefined): ElementaryType {
  if (hint && admits(generic, hint)) return hint;
  return OWN_OUTPUT_DEFAULT[generic] ?? LITERAL_DEFAULT[generic];
}

/**
 * Resolves a call of a standard function. `argTypes` are the types of the inputs in expanded
 * order without EN (undefined = untyped literal). The implementation expects values of the
 * returned `argTypes` (widen typed arguments with values/types.widen) and sets ctx.error for ENO.
 */
export function resolveFunction(
  name: string,
  argTypes: readonly (ElementaryType | undefined)[],
  profile: Profile,
  outTypeHint?: ElementaryType,
): ResolveResult {
  const sig = blockSignature(name);
  if (!sig || sig.kind !== 'function') return { ok: false, message: `${name} is not a standard function` };
  const fname = sig.name;
  const pins = expandInputs(sig, argTypes.length);
  if (typeof pins === 'string') return { ok: false, message: pins };
  const out = sig.outputs[0]!;

  const scaled = timeScaling(fname, argTypes);
  if (scaled) return { ok: true, fn: scaled };

  // The shared type of the poly pins.
  const polyIndexes = pins.flatMap((p, i) => (p.poly ? [i] : []));
  const typed = polyIndexes.flatMap((i) => (argTypes[i] ? [argTypes[i]] : []));
  const generic = (pins[polyIndexes[0] ?? 0]?.type ?? out.type) as PinSignature['type'];
  let poly: ElementaryType | undefined;
  if (typed.length) {
    poly = commonType(typed);
    if (!poly || !admits(generic, poly)) {
      const what = typed.length === 1 ? typed[0]! : listTypes(typed);
      // SQRT(INT) in MATIEC is a type error too: say how to get a REAL.
      const convert = generic === 'ANY_REAL' && poly && !GENERIC_MEMBERS.ANY_REAL.includes(poly) && poly !== 'BOOL' ? `: convert it first (${poly}_TO_REAL)` : '';
      return { ok: false, message: `${fname} cannot ${VERB[fname] ?? 'use'} ${what}${convert}` };
    }
  } else if (polyIndexes.length || out.poly) {
    // The hint is the type of the variable OUT is written to: it only says something when OUT shares the poly type.
    poly = out.poly && outTypeHint && admits(generic, outTypeHint) ? outTypeHint : isElementaryType(generic) ? generic : LITERAL_DEFAULT[generic];
  }

  const concrete: ElementaryType[] = [];
  for (const [i, pin] of pins.entries()) {
    const arg = argTypes[i];
    if (pin.poly) {
      concrete.push(poly!);
    } else if (isElementaryType(pin.type)) {
      if (arg && !canWiden(arg, pin.type)) return { ok: false, message: `${fname} input ${pin.name} needs ${pin.type}, not ${arg}` };
      concrete.push(pin.type);
    } else {
      if (arg && !admits(pin.type, arg))
        return { ok: false, message: `${fname} input ${pin.name} needs ${GENERIC_WORDS[pin.type] ?? 'a value'} (${pin.type}), not ${arg}` };
      concrete.push(arg ?? OWN_LITERAL_DEFAULT[pin.type] ?? LITERAL_DEFAULT[pin.type]);
    }
  }
  const outType = out.poly ? poly! : isElementaryType(out.type) ? out.type : ownOutputType(out.type, outTypeHint);
  const impls = implement(fname, poly ?? outType, concrete, outType, profile);
  if (typeof impls === 'string') return { ok: false, message: impls };
  const fn: ResolvedFunction = { name: fname, argTypes: concrete, outType, inputNames: pins.map((p) => p.name), ...impls };
  return { ok: true, fn };
}

/** Calls a resolved function once with a fresh context (for tests, constant folding and tools). */
export function callFunction(fn: ResolvedFunction, args: readonly Value[]): { value: Value; eno: boolean } {
  const ctx: FnContext = { error: false };
  const value = fn.impl(ctx, args);
  return { value, eno: !ctx.error };
}
