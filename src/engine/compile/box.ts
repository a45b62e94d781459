// Function and function block boxes: instance (LD-R10), pin wiring and operands (LD-R10), types
// (LD-R11, with the implicit widenings of values/types.canWiden), and the operation to generate.
// Pin descriptions and outputs shared with user POU calls: boxPins.ts; user POU calls: userCall.ts.
import {
  GENERIC_MEMBERS,
  isElementaryType,
  type ElementaryType,
  type GenericType,
} from '../../model/iecTypes';
import type { BoxElement } from '../../model/elements';
import { resolveFunction } from '../library/functions';
import { isUntypedLiteral, parseLiteral } from '../values/literals';
import { canWiden, defaultValue, normalize, typeRange, type SizedType } from '../values/types';
import type { PouContext } from './context';
import { upstream, type GraphNode } from './graph';
import type { ArgIR, Op, OutIR, Source } from './ir';
import type { NetMap } from './netMap';
import { describeElement, type Reporter } from './report';
import type { Access, FbSymbol, UfbSymbol } from './symbols';
import { boxLayoutFor, type BoxLayout, type PlacedPin } from '../../model/boxLayout';
import { isInOutPin } from '../../model/library';
import { lowerUserCall } from './userCall';
import { describeSource, initialText, lowerOutput, type InputInfo } from './boxPins';
import { aggregatePinShape, lowerAggregateInput } from './aggregatePins';

const admitsType = (pinType: string, t: ElementaryType): boolean =>
  isElementaryType(pinType) ? pinType === t : (GENERIC_MEMBERS[pinType as GenericType] ?? []).includes(t);

export function lowerBox(
  ctx: PouContext,
  node: GraphNode,
  nets: NetMap,
  network: number,
  r: Reporter,
): Op | undefined {
  const el = node.el as BoxElement;
  const name = describeElement(el);
  const layout = node.layout && calledAs(ctx, node, nets, name, r);
  if (!node.layout) {
    const program = ctx.project.pous.find(
      (p) => p.kind === 'PROGRAM' && p.name.toUpperCase() === el.blockType.trim().toUpperCase(),
    );
    if (program)
      r.error(
        'LD-E24',
        `${name} calls the PROGRAM ${program.name}; a program is not called from a network, a task runs it (add it to the task's programs)`,
        el,
      );
    else
      r.error(
        'LD-E01',
        `${name} uses "${el.blockType}", which is not a standard function or function block${ctx.symbols.library.userBlocks.length ? ' nor a FUNCTION or FUNCTION_BLOCK of the project' : ''}${ctx.project.libraries?.length ? ` nor a block of its libraries (${ctx.project.libraries.map((l) => l.name).join(', ')})` : ''}`,
        el,
      );
    return undefined;
  }
  if (!layout) return undefined; // LD-R10: the box's type does not fit its instance's (calledAs)
  const sig = layout.signature;
  const isFb = sig.kind === 'fb';
  const lib = ctx.symbols.library;
  const userPou = sig.category === 'user' || lib.isExternal(sig.name) ? lib.userPou(sig.name) : undefined;
  if (userPou && lib.isExternal(sig.name))
    r.warning(
      'LD-W10',
      `${name} is the external block ${sig.name} (a vendor library's); the simulator does not run its body, so its outputs keep their values`,
      el,
    );
  const changed = userPou ? ` (the interface of ${sig.name} has no such pin; it may have changed: redraw the block or add the pin back)` : '';
  const before = r.errors;
  const pinKey = (pins: readonly PlacedPin[], key: string) =>
    pins.some((p) => p.name.toUpperCase() === key.toUpperCase());
  for (const key of Object.keys(el.inputs)) {
    if (!pinKey(layout.inputs, key))
      r.error(
        'LD-E04',
        `${name} has no input "${key}"${changed} (inputs: ${layout.inputs.map((p) => p.name).join(', ')})`,
        el,
      );
  }
  for (const key of Object.keys(el.outputs)) {
    if (!pinKey(layout.outputs, key))
      r.error(
        'LD-E04',
        `${name} has no output "${key}"${changed} (outputs: ${layout.outputs.map((p) => p.name).join(', ')})`,
        el,
      );
  }
  const operandOf = (rec: Readonly<Record<string, string>>, pin: string): string => {
    const key = Object.keys(rec).find((k) => k.toUpperCase() === pin.toUpperCase());
    return key === undefined ? '' : (rec[key] ?? '').trim();
  };

  // LD-R10: the FB instance.
  let fbIndex = -1;
  let userInstance: UfbSymbol | undefined;
  if (isFb) {
    const inst = (el.instance ?? '').trim();
    const sym = inst ? ctx.symbols.lookup(inst) : undefined;
    if (!inst)
      r.error(
        'LD-R10',
        `${name} has no instance name; declare a ${sig.name} variable and name it on the block`,
        el,
      );
    else if (!sym)
      r.error(
        'LD-R10',
        `${name}: the instance "${inst}" is not declared; add a variable "${inst}" of type ${sig.name}`,
        el,
      );
    else if (sym.kind !== 'fb' && sym.kind !== 'ufb')
      r.error(
        'LD-R10',
        `${name}: "${inst}" is declared as ${sym.kind === 'ref' ? sym.access.type : sym.type}, not ${sig.name}`,
        el,
      );
    else {
      // IEC and MATIEC run every call of an instance, in order, each with the state the previous
      // call left (Beremiz emits one `T1(...)` per box); some editors refuse a second call (000/002).
      const first = ctx.fbCalls.get(sym);
      if (first)
        r.warning(
          'LD-R10',
          `${name} is a second call of its instance (first at network ${first.network + 1}); both calls run, in order, on the same instance`,
          el,
        );
      else ctx.fbCalls.set(sym, { network, row: el.row, col: el.col });
      if (sym.kind === 'fb') fbIndex = sym.index;
      else userInstance = sym;
    }
  }

  // Inputs: wire, operand, or (EN of a function only) nothing.
  const powerPin = layout.inputs.find((p) => p.type === 'BOOL')?.name;
  const infos: InputInfo[] = [];
  for (const pin of layout.inputs) {
    const t = node.inputs.find((x) => x.pin === pin.name)!;
    // LD-R03: a line that starts nowhere leaves the input unconnected (Beremiz leaves an input with
    // no connection out of the call).
    const wired = nets.isWired(t.net) && nets.isFed(t.net);
    const operand = operandOf(el.inputs, pin.name);
    const info: InputInfo = { pin };
    infos.push(info);
    if (wired && operand) {
      r.error('LD-R10', `input ${pin.name} of ${name} is both wired and given "${operand}"; keep one`, el);
      continue;
    }
    const aggShape = userPou ? aggregatePinShape(ctx.symbols.storage.types, pin) : undefined;
    if (aggShape) {
      const agg = lowerAggregateInput({ symbols: ctx.symbols, nets, el, name, r }, pin, aggShape, { net: t.net, wired, operand });
      if (agg) info.agg = agg;
      else if (isFb && !wired && !operand && !isInOutPin(pin))
        r.warning('LD-R10', `input ${pin.name} of ${name} is not connected: it keeps the instance's value (the initial value of ${aggShape.name} at first); wire it or write a variable beside it`, el);
      continue;
    }
    if (wired) {
      const data = nets.data.get(t.net);
      if (data) {
        info.src = data;
        info.type = data.from === 'data' ? data.type : data.from === 'access' ? data.access.type : 'BOOL';
      } else if (nets.dataPending.has(t.net)) continue;
      else {
        info.src = { from: 'power', net: nets.powerNet(t.net) };
        info.type = 'BOOL';
      }
      if (!admitsType(pin.type, info.type)) {
        r.error(
          'LD-R11',
          `input ${pin.name} of ${name} needs ${pin.type} but its line carries ${info.type}`,
          el,
        );
      }
      continue;
    }
    if (operand) {
      const expected = isElementaryType(pin.type) ? pin.type : undefined;
      const res = ctx.symbols.resolve(operand, {
        ...(expected ? { expected } : {}),
        literals: true,
        implicitLocations: true,
      });
      const loose = !res.ok && expected ? foreignIntLiteral(operand, expected) : undefined;
      if (loose) {
        r.warning(
          'LD-W03',
          `input ${pin.name} of ${name}: ${operand} is typed ${loose.from} but the input is ${expected}; its value ${loose.text} fits, so the simulator passes it, but Beremiz and OpenPLC refuse this; write ${loose.text} or ${expected}#${loose.text}`,
          el,
        );
        info.src = { from: 'access', access: loose.access };
        info.type = expected;
        continue;
      }
      if (!res.ok) {
        r.error(res.unknown ? 'LD-E02' : 'LD-E03', `input ${pin.name} of ${name}: ${res.message}`, el);
        continue;
      }
      info.src = { from: 'access', access: res.access };
      // An untyped literal (42, 16#FF, 1.5) adopts the block's resolved type; typed ones (INT#5, T#1s) keep theirs.
      if (res.access.kind === 'const' && isUntypedLiteral(operand) && !isElementaryType(pin.type))
        info.literal = operand;
      else info.type = res.access.type;
      if (res.access.kind === 'const' && isElementaryType(pin.type)) info.type = pin.type;
      continue;
    }
    if (pin.name === 'EN') continue; // a function whose EN is not connected always runs
    if (isInOutPin(pin)) continue; // LD-E23 (userCall.ts)
    if (isFb) {
      // IEC / MATIEC: an FB input left out of the call keeps the instance's value (its initial value,
      // or what the previous call or an `Instance.Pin` coil left); Beremiz passes only connected
      // inputs. Warned where that is likely a mistake: the power-flow input and value inputs (PT, PV).
      if (pin.name === powerPin || pin.type !== 'BOOL')
        r.warning('LD-R10', unconnectedFbInput(name, pin), el);
      continue;
    }
    // A function input left unconnected takes its type's initial value (IEC; MATIEC passes the
    // parameter's default, else its type's initial value). Warned once the type is known.
    info.open = true;
  }

  // EN that the file left open (drawn from the rail): not connected, while the rail alone feeds it.
  const enInfo = infos.find((i) => i.pin.name === 'EN');
  if (el.enOpen && enInfo?.src?.from === 'power') {
    const t = node.inputs.find((x) => x.pin === 'EN')!;
    const up = upstream(nets.g, t.net);
    if (up.leftRail && up.sources.length === 0) delete enInfo.src;
  }
  // An FB instance keeps EN like any input (IEC: VAR_INPUT EN : BOOL := TRUE; MATIEC alike).
  const fbSym = userInstance ?? (fbIndex >= 0 ? ctx.symbols.fbs[fbIndex] : undefined);
  const enMemory = fbSym && el.instance ? enMemoryOf(ctx, fbSym, el.instance) : undefined;

  // Outputs.
  const outputs = layout.outputs.map((pin) => {
    const t = node.outputs.find((x) => x.pin === pin.name)!;
    return { pin, net: t.net, wired: nets.isWired(t.net), operand: operandOf(el.outputs, pin.name) };
  });

  if (userPou)
    return lowerUserCall(ctx, { el, name, node, nets, infos, outputs, pou: userPou, instance: userInstance, network, r, before, enMemory });

  if (isFb) {
    const args: ArgIR[] = [];
    let en: Source | undefined;
    for (const info of infos) {
      if (info.pin.name === 'EN') {
        if (info.src) en = info.src;
        continue;
      }
      const pinType = info.pin.type as ElementaryType;
      if (!info.src) continue;
      if (info.type && !canWiden(info.type, pinType) && info.src.from !== 'power') {
        r.error(
          'LD-R11',
          `input ${info.pin.name} of ${name} needs ${pinType}; ${describeSource(info.src)} is ${info.type}`,
          el,
        );
      }
      args.push({ pin: info.pin.name, type: pinType, src: info.src });
    }
    const outs: OutIR[] = [];
    let eno: OutIR | undefined;
    for (const o of outputs) {
      const type = o.pin.type as ElementaryType;
      if (o.pin.name === 'ENO') {
        eno = lowerOutput(ctx, nets, el, name, o, 'BOOL', undefined, r);
        continue;
      }
      const out = lowerOutput(
        ctx,
        nets,
        el,
        name,
        o,
        type,
        fbIndex >= 0
          ? { kind: 'pin', fb: ctx.symbols.fbs[fbIndex]!, pin: o.pin.name, type, dir: 'out' }
          : undefined,
        r,
      );
      if (out) outs.push(out);
    }
    if (r.errors > before || fbIndex < 0) return undefined;
    return {
      op: 'fb',
      node: node.index,
      fb: fbIndex,
      ...(en ? { en } : {}),
      args,
      outs,
      ...(eno ? { eno } : {}),
      ...(enMemory ? { enMemory } : {}),
    };
  }

  // Function: resolve generic pins from the argument types.
  const argInfos = infos.filter((i) => i.pin.name !== 'EN');
  const outPin = outputs.find((o) => o.pin.name !== 'ENO')!;
  let hint: ElementaryType | undefined;
  if (outPin.operand) {
    const res = ctx.symbols.resolve(outPin.operand, { literals: false, implicitLocations: true });
    if (res.ok) hint = res.access.type;
  } else if (outPin.wired) hint = sinkTypeHint(ctx, nets, outPin.net);
  if (r.errors > before) return undefined;
  const resolved = resolveFunction(
    sig.name,
    argInfos.map((i) => i.type),
    ctx.profile,
    hint,
  );
  if (!resolved.ok) {
    r.error('LD-R11', `${name}: ${resolved.message}`, el);
    return undefined;
  }
  const fn = resolved.fn;
  const args: ArgIR[] = [];
  // No input, variable or output operand gives the generic type: the type an untyped literal takes.
  const guessed = !hint && argInfos.every((i) => !i.type);
  argInfos.forEach((info, i) => {
    const type = fn.argTypes[i]!;
    if (info.open) {
      const value = defaultValue(type);
      const text = initialText(type);
      r.warning(
        'LD-R10',
        `input ${info.pin.name} of ${name} is not connected: it takes the initial value of ${type} (${text})${guessed && !isElementaryType(info.pin.type) ? `; no other input gives the block a type, so ${type} is assumed` : ''}; wire it or write a variable or a literal beside it`,
        el,
      );
      args.push({
        pin: info.pin.name,
        type,
        src: { from: 'access', access: { kind: 'const', type, value, text } },
      });
      return;
    }
    let src = info.src!;
    if (info.literal !== undefined) {
      const lit = parseLiteral(info.literal, type);
      if (!lit.ok) return void r.error('LD-E03', `input ${info.pin.name} of ${name}: ${lit.message}`, el);
      src = { from: 'access', access: { kind: 'const', type, value: lit.value, text: info.literal } };
    } else if (info.type && !canWiden(info.type, type)) {
      return void r.error(
        'LD-R11',
        `input ${info.pin.name} of ${name} needs ${type}; ${describeSource(src)} is ${info.type}`,
        el,
      );
    }
    args.push({ pin: info.pin.name, type, src });
  });
  const outType = fn.outType;
  const out = lowerOutput(ctx, nets, el, name, outPin, outType, undefined, r);
  const enoPin = outputs.find((o) => o.pin.name === 'ENO')!;
  const eno = lowerOutput(ctx, nets, el, name, enoPin, 'BOOL', undefined, r);
  if (r.errors > before || !out || !eno) return undefined;
  const fnIndex = ctx.functions.length;
  ctx.functions.push(fn);
  return {
    op: 'function',
    node: node.index,
    name: fn.name,
    fn: fnIndex,
    ...(enInfo?.src ? { en: enInfo.src } : {}),
    args,
    out,
    eno,
    ...(ctx.profile === 'openplc' ? { matiecOutputs: true as const } : {}),
  };
}

const enCalls = new WeakMap<PouContext, ReadonlySet<string>>();

/** Instances (upper case) that a box of the POU being lowered calls with an EN pin it does not leave open. */
function instancesCalledWithEn(ctx: PouContext): ReadonlySet<string> {
  let set = enCalls.get(ctx);
  if (set) return set;
  const names = new Set<string>();
  const pou = ctx.project.pous.find((p) => p.name === ctx.pouName);
  for (const network of pou?.networks ?? [])
    for (const el of network.elements)
      if (el.kind === 'box' && el.executionControl && !el.enOpen && el.instance) names.add(el.instance.trim().toUpperCase());
  set = names;
  enCalls.set(ctx, set);
  return set;
}

/**
 * The EN an FB instance kept from its last call, where a call with EN and one without meet (IEC
 * declares EN as the instance's `VAR_INPUT EN : BOOL := TRUE`; MATIEC keeps it in the instance):
 * a hidden BOOL, "EN was OFF at the last call given EN", FALSE at a cold restart. Only for instances
 * the POU calls with an EN pin; an instance never given EN always runs.
 */
function enMemoryOf(ctx: PouContext, sym: FbSymbol | UfbSymbol, instance: string): Access | undefined {
  if (!instancesCalledWithEn(ctx).has(instance.trim().toUpperCase())) return undefined;
  let a = ctx.enMemories.get(sym);
  if (!a) {
    const slot = ctx.symbols.counts.b++;
    ctx.dataSlots.push({ store: 'b', slot, type: 'BOOL' });
    const v = { kind: 'var', name: `${instance.trim()}.EN`, type: 'BOOL', store: 'b', slot, initial: false, retain: false, constant: false, global: false, implicit: false, hidden: true } as const;
    a = { kind: 'var', v, type: 'BOOL' };
    ctx.enMemories.set(sym, a);
  }
  return a;
}

function unconnectedFbInput(name: string, pin: PlacedPin): string {
  const initial = initialText(pin.type);
  return `input ${pin.name} of ${name} is not connected: it keeps the instance's value (${initial} at first); wire it or write a variable or a literal beside it`;
}

/**
 * The layout a box is called with. An FB box whose type differs from its instance's declared type
 * (a box typed TP on a TOF instance t1): Beremiz and OpenPLC call an FB by its instance name only
 * (`t1(IN := ..., PT := ...)`, outputs read as `t1.Q`), so MATIEC compiles the call against the
 * declared type. It runs as the declared type (LD-R10 warning) when every pin the box wires or
 * names exists on the declared type with a compatible type; otherwise LD-R10 error, undefined. The
 * canvas keeps the file's box (its type and pins), which is what the file shows in Beremiz.
 */
function calledAs(ctx: PouContext, node: GraphNode, nets: NetMap, name: string, r: Reporter): BoxLayout | undefined {
  const el = node.el as BoxElement;
  const layout = node.layout!;
  const sig = layout.signature;
  const inst = (el.instance ?? '').trim();
  if (sig.kind !== 'fb' || !inst) return layout;
  const sym = ctx.symbols.lookup(inst);
  if (!sym || (sym.kind !== 'fb' && sym.kind !== 'ufb') || sym.type.toUpperCase() === sig.name.toUpperCase()) return layout;
  const declared = ctx.symbols.library.signature(sym.type);
  const declaredLayout = declared?.kind === 'fb' ? boxLayoutFor(declared.name, undefined, ctx.symbols.library, el.executionControl) : undefined;
  const used = (pins: readonly PlacedPin[], side: 'inputs' | 'outputs', rec: Readonly<Record<string, string>>) =>
    pins.filter((pin) => {
      const t = node[side].find((x) => x.pin === pin.name);
      return (t !== undefined && nets.isWired(t.net)) || Object.keys(rec).some((k) => k.toUpperCase() === pin.name.toUpperCase() && rec[k]!.trim());
    });
  const missing: string[] = [];
  const fit = (pins: readonly PlacedPin[], theirs: readonly PlacedPin[] | undefined, input: boolean): PlacedPin[] => {
    const out: PlacedPin[] = [];
    for (const pin of pins) {
      const other = theirs?.find((p) => p.name.toUpperCase() === pin.name.toUpperCase());
      const ok =
        other &&
        (other.type === pin.type ||
          (isElementaryType(pin.type) &&
            isElementaryType(other.type) &&
            (input ? canWiden(pin.type, other.type) : canWiden(other.type, pin.type))));
      if (!ok) missing.push(`${pin.name}${other ? ` (${other.type} there)` : ''}`);
      else out.push({ ...other, rowOffset: pin.rowOffset });
    }
    return out;
  };
  const usedIn = used(layout.inputs, 'inputs', el.inputs);
  const usedOut = used(layout.outputs, 'outputs', el.outputs);
  const inputs = fit(usedIn, declaredLayout?.inputs, true);
  const outputs = fit(usedOut, declaredLayout?.outputs, false);
  if (!declaredLayout || missing.length) {
    r.error(
      'LD-R10',
      `${name}: "${inst}" is declared as ${sym.type}, not ${sig.name}${declaredLayout ? `, and ${sym.type} has no ${missing.join(', ')} as the box wires` : ''}; make the box a ${sym.type} or declare "${inst}" as ${sig.name}`,
      el,
    );
    return undefined;
  }
  r.warning(
    'LD-R10',
    `the box says ${sig.name} but ${inst} is declared ${declared!.name}; Beremiz/OpenPLC call ${inst} as a ${declared!.name} and so does the simulator`,
    el,
  );
  // The box's own pins (where its lines attach), typed as the declared type's; pins the box does not
  // use are left out of the call (an FB input left out keeps the instance's value).
  return { ...layout, signature: declared!, inputs, outputs };
}

/**
 * The type a block's generic output takes from where its line goes, as MATIEC types a call from its
 * use: LEN or FIND into INT_TO_DINT's IN gives INT, into SUB beside an INT variable gives INT. The
 * first block input on the line that says a type: an elementary pin, or a poly pin whose block has
 * another poly input given a typed variable.
 */
function sinkTypeHint(ctx: PouContext, nets: NetMap, net: number): ElementaryType | undefined {
  for (const s of nets.g.nets[net]?.sinks ?? []) {
    const node = nets.g.nodes[s.node];
    if (!node || node.el.kind !== 'box' || !node.layout) continue;
    const box = node.el;
    const pin = node.layout.inputs.find((p) => p.name.toUpperCase() === s.pin.toUpperCase());
    if (!pin) continue;
    if (isElementaryType(pin.type)) return pin.type;
    if (!pin.poly) continue;
    for (const other of node.layout.inputs) {
      if (!other.poly || other === pin) continue;
      const key = Object.keys(box.inputs).find((k) => k.toUpperCase() === other.name.toUpperCase());
      const operand = key === undefined ? '' : (box.inputs[key] ?? '').trim();
      if (!operand) continue;
      const res = ctx.symbols.resolve(operand, { literals: false, implicitLocations: true });
      if (res.ok && isElementaryType(res.access.type) && admitsType(pin.type, res.access.type)) return res.access.type;
    }
  }
  return undefined;
}

/**
 * LD-W03: a typed literal of another integer type whose value fits the input's type (UINT#3 on a
 * USINT input). IEC and MATIEC refuse it, CODESYS-era tools accepted it; the value is passed.
 */
function foreignIntLiteral(
  text: string,
  expected: ElementaryType,
): { from: ElementaryType; text: string; access: Access } | undefined {
  const ints = GENERIC_MEMBERS.ANY_INT;
  if (!ints.includes(expected) || !/^[A-Za-z_][A-Za-z0-9_]*#/.test(text.trim())) return undefined;
  const lit = parseLiteral(text);
  if (!lit.ok || !ints.includes(lit.type) || lit.type === expected) return undefined;
  const v = BigInt(lit.value as number | bigint);
  const { min, max } = typeRange(expected as SizedType);
  if (v < min || v > max) return undefined; // does not fit: LD-E03
  const plain = String(v);
  return { from: lit.type, text: plain, access: { kind: 'const', type: expected, value: normalize(expected, lit.value), text: plain } };
}
