// Calls of the project's own FUNCTION_BLOCKs and FUNCTIONs (boxes whose block is a user POU), as
// MATIEC runs them: inputs given on the box are assigned to the instance's VAR_INPUTs (an FB input
// left open keeps its value; a function's takes its declared initial value), VAR_IN_OUT pins name
// the caller's variable (by reference, LD-E23), the body runs, outputs are read after. A function
// keeps nothing: its variables start at their initial values on every call. With EN OFF, an FB is
// not executed and keeps its outputs; a function is not called and assigns nothing. Struct and
// array pins (aggregatePins.ts): inputs and outputs are copied leaf by leaf, in-outs bound to the
// caller's variable.
import type { BoxElement } from '../../model/elements';
import { isElementaryType, type ElementaryType } from '../../model/iecTypes';
import { isInOutPin } from '../../model/library';
import type { Pou } from '../../model/project';
import { canWiden } from '../values/types';
import { describeSource, initialText, lowerOutput, type InputInfo, type OutputInfo } from './boxPins';
import type { PouContext } from './context';
import type { GraphNode } from './graph';
import type { CallOp, OutIR, Source } from './ir';
import type { NetMap } from './netMap';
import { accessWords } from './operands';
import type { Reporter } from './report';
import type { Access, AggSymbol, SymbolTable, UfbSymbol } from './symbols';
import { aggregatePinShape, aggregateRef, leafCopies, lowerAggregateOutput, type AggValue } from './aggregatePins';
import { initialLeaves } from './aggregates';

export interface UserCallParts {
  readonly el: BoxElement;
  readonly name: string;
  readonly node: GraphNode;
  readonly nets: NetMap;
  readonly infos: readonly InputInfo[];
  readonly outputs: readonly OutputInfo[];
  readonly pou: Pou;
  /** The FB instance (undefined for a function, or when the instance is in error). */
  readonly instance: UfbSymbol | undefined;
  readonly network: number;
  readonly r: Reporter;
  /** Errors reported for this box before. */
  readonly before: number;
  /** The instance's kept EN (box.ts enMemoryOf). */
  readonly enMemory?: Access | undefined;
}

const memberAccess = (scope: SymbolTable, name: string): Access | undefined => {
  const m = scope.own(name);
  return m?.kind === 'var' ? { kind: 'var', v: m, type: m.type } : undefined;
};

export function lowerUserCall(ctx: PouContext, c: UserCallParts): CallOp | undefined {
  const { el, name, r, pou } = c;
  const isFb = pou.kind === 'FUNCTION_BLOCK';
  let en: Source | undefined;
  const refs = new Map<string, Access | AggSymbol>();
  const given: { pin: string; src: Source; type: ElementaryType }[] = [];
  const aggGiven: { pin: string; value: AggValue }[] = [];
  const open: string[] = [];
  for (const info of c.infos) {
    const pin = info.pin;
    if (pin.name === 'EN') {
      if (info.src) en = info.src;
      continue;
    }
    if (info.agg) {
      // A struct/array: an input is copied in; an in-out names the caller's variable itself.
      if (!isInOutPin(pin)) aggGiven.push({ pin: pin.name, value: info.agg });
      else if (!info.agg.variable)
        r.error('LD-E23', `the in-out ${pin.name} of ${name} must name a variable: it is passed by reference, and ${info.agg.what} carries a function's result`, el);
      else if (info.agg.constant)
        r.error('LD-E23', `the in-out ${pin.name} of ${name} cannot be ${info.agg.what}, which is CONSTANT`, el);
      else if (info.agg.node) refs.set(pin.name, aggregateRef(info.agg.node, info.agg.what));
      continue;
    }
    const pinType = pin.type as ElementaryType;
    if (isInOutPin(pin)) {
      const a = info.src?.from === 'access' ? info.src.access : undefined;
      if (!a || a.kind === 'const') {
        const why = !info.src
          ? 'it is not connected'
          : a
            ? `${accessWords(a)} is a constant`
            : 'a line carries a value, not a variable';
        r.error(
          'LD-E23',
          `the in-out ${pin.name} of ${name} must name a variable: it is passed by reference (the block reads and writes it), and ${why}`,
          el,
        );
        continue;
      }
      if (a.kind === 'pin' && a.dir === 'out') {
        r.error('LD-E23', `the in-out ${pin.name} of ${name} cannot be ${accessWords(a)}, an output of another block`, el);
        continue;
      }
      if ((a.kind === 'var' || a.kind === 'bit') && a.v.constant) {
        r.error('LD-E23', `the in-out ${pin.name} of ${name} cannot be "${a.v.name}", which is CONSTANT`, el);
        continue;
      }
      if (isElementaryType(pinType) && a.type !== pinType) {
        r.error('LD-R11', `the in-out ${pin.name} of ${name} is ${pinType}; ${accessWords(a)} is ${a.type}`, el);
        continue;
      }
      refs.set(pin.name, a);
      continue;
    }
    if (!info.src) {
      if (!isFb) open.push(pin.name);
      continue;
    }
    let src = info.src;
    if (info.literal !== undefined && isElementaryType(pinType)) {
      // an untyped literal takes the pin's type
    } else if (info.type && isElementaryType(pinType) && !canWiden(info.type, pinType) && src.from !== 'power') {
      r.error('LD-R11', `input ${pin.name} of ${name} needs ${pinType}; ${describeSource(src)} is ${info.type}`, el);
      continue;
    }
    if (src.from === 'access' && src.access.kind === 'const' && isElementaryType(pinType) && src.access.type !== pinType) {
      src = { from: 'access', access: { ...src.access, type: pinType } };
    }
    given.push({ pin: pin.name, src, type: pinType });
  }

  // A function's open inputs start at their declared initial value.
  for (const pin of open) {
    const decl = pou.variables.find((v) => v.name.toUpperCase() === pin.toUpperCase());
    const type = decl?.type.toUpperCase() ?? 'BOOL';
    const initial = decl?.initial?.trim() || (isElementaryType(type) ? initialText(type) : `the initial value of ${decl?.type}`);
    r.warning(
      'LD-R10',
      `input ${pin} of ${name} is not connected: it takes its initial value (${initial}); wire it or write a variable or a literal beside it`,
      el,
    );
  }
  if (r.errors > c.before) return undefined;

  // The callee's variables: the instance's, or a function call site's own.
  let scope: SymbolTable | undefined;
  let body: { first: number; end: number } | undefined;
  if (isFb) {
    if (!c.instance) return undefined;
    scope = c.instance.scope;
    body = ctx.calls ? ctx.calls.fbBody(c.instance, refs) : { first: -1, end: -1 };
  } else if (ctx.calls) {
    const site = ctx.calls.functionCall(pou, `${ctx.instance ? `${ctx.instance}.` : ''}${ctx.pouName}@${el.id}`);
    scope = site.scope;
    body = site.body(refs);
  }

  const outs: { out: OutIR; src: Access }[] = [];
  let eno: OutIR | undefined;
  const site = { symbols: ctx.symbols, nets: c.nets, el, name, r };
  for (const o of c.outputs) {
    if (o.pin.name === 'ENO') {
      eno = lowerOutput(ctx, c.nets, el, name, o, 'BOOL', undefined, r);
      continue;
    }
    const member = o.pin.name === 'OUT' && !isFb ? pou.name : o.pin.name;
    const aggShape = aggregatePinShape(ctx.symbols.storage.types, o.pin);
    if (aggShape) {
      const ref = isInOutPin(o.pin) ? refs.get(o.pin.name) : scope?.own(member);
      const node = ref?.kind === 'agg' ? ref.node : undefined;
      for (const copy of lowerAggregateOutput(site, o, aggShape, node, isFb || isInOutPin(o.pin)))
        outs.push({ out: { pin: o.pin.name, type: copy.dst.type, dst: copy.dst }, src: copy.src });
      continue;
    }
    const type = o.pin.type as ElementaryType;
    const ref = isInOutPin(o.pin) ? refs.get(o.pin.name) : undefined;
    const src = isInOutPin(o.pin)
      ? ref?.kind === 'agg' ? undefined : ref
      : scope
        ? memberAccess(scope, member)
        : undefined;
    const out = lowerOutput(ctx, c.nets, el, name, o, type, src, r);
    if (out && src) outs.push({ out, src });
  }
  if (r.errors > c.before || !scope || !body) return undefined;

  const assigns: { dst: Access; src: Source }[] = [];
  for (const g of given) {
    const dst = memberAccess(scope, g.pin);
    if (dst) assigns.push({ dst, src: g.src });
  }
  for (const g of aggGiven) {
    const dst = scope.own(g.pin);
    if (dst?.kind === 'agg' && g.value.node)
      for (const copy of leafCopies(dst.node, g.value.node)) assigns.push({ dst: copy.dst, src: { from: 'access', access: copy.src } });
  }
  // Temporaries (an FB's VAR_TEMP; every variable of a function) start at their initial values
  // (every leaf of a struct/array one).
  const assigned = new Set([...given, ...aggGiven].map((g) => g.pin.toUpperCase()));
  const inits = initialLeaves(scope, (v, key) => (isFb ? v.temp === true : !assigned.has(key)));

  return {
    op: 'call',
    node: c.node.index,
    kind: isFb ? 'fb' : 'function',
    pou: pou.name,
    ...(en ? { en } : {}),
    inits,
    assigns,
    first: body.first,
    end: body.end,
    outs,
    ...(eno ? { eno } : {}),
    ...(isFb && c.enMemory ? { enMemory: c.enMemory } : {}),
  };
}
