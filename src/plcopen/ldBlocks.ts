// A PLCopen <block> as a Rungsmith box: the signature of a standard block or of one of the file's
// own FUNCTION_BLOCKs and FUNCTIONs (from the block library), extensible input count, EN/ENO
// (functions always; FBs with executionControl), pins wired or given operands (from
// in/outVariables), EN wired to the rail when a function has none (it runs unconditionally, as
// MATIEC runs it).
import type { BlockSignature } from '../model/blocks';
import { boxLayoutFor } from '../model/boxLayout';
import type { BlockLibrary } from '../model/library';
import type { Finding, GNode, GSource } from './ldNodes';
import type { RawObject, RawPin } from './ldObjects';

const RAIL: GSource = { kind: 'rail' };

/**
 * The model's name of a pin of a block: pins are matched without regard to case (IEC names are
 * case-insensitive), and named as the callee declares them (`Counter`, not `COUNTER`).
 */
export function canonicalPin(sig: BlockSignature | undefined, pin: string): string {
  const upper = pin.toUpperCase();
  if (!sig || upper === 'EN' || upper === 'ENO') return upper;
  // TC6 v1.0 (Beremiz's legacy files) leaves a function's result pin unnamed: it is OUT.
  if (upper === '') return sig.outputs.find((p) => p.name.toUpperCase() !== 'ENO')?.name ?? upper;
  for (const p of sig.outputs) if (p.name.toUpperCase() === upper) return p.name;
  for (const p of sig.inputs) if (p.name.toUpperCase() === upper) return p.name;
  return upper;
}

export function buildBox(
  n: GNode,
  o: RawObject,
  sourcesOf: (pin: RawPin, consumer: RawObject, operandTarget?: (text: string) => void) => GSource[],
  warn: (f: Finding) => void,
  library: BlockLibrary,
  /**
   * The negation of a negated input as power flow (FBD): an inverting contact fed by the pin's
   * sources, or a normally-closed contact of its variable; undefined when the value is not BOOL
   * (a declared BOOL pin, or sources and variables known to be BOOL).
   */
  negate?: (what: GSource[] | string, boolPin: boolean) => GSource | undefined,
): void {
  const typeName = o.text;
  const sig = library.signature(typeName);
  const instance = o.attr('instanceName');
  n.instance = instance || undefined;
  if (!sig) {
    n.blockType = typeName;
    for (const pin of o.inputs) {
      const name = pin.pin;
      let operand: string | undefined;
      const src = sourcesOf(pin, o, (t) => (operand = t));
      if (operand !== undefined) n.operandsIn[name] = operand;
      else if (src.length)
        warn({
          message: `block ${instance ?? typeName}: the wire into pin ${name} is dropped (Rungsmith does not know block type ${typeName})`,
          obj: o,
        });
    }
    for (const pin of o.outputs) if (pin.expression) n.operandsOut[pin.pin] = pin.expression;
    warn({
      message: `block type ${typeName} is neither a standard block nor a POU of this file; kept with its operands`,
      obj: o,
    });
    return;
  }
  n.blockType = sig.name;
  if (sig.kind === 'fb' && !instance)
    warn({ message: `function block ${sig.name} has no instance name`, obj: o });
  if (sig.kind === 'function' && instance) n.instance = undefined;
  // An FB box shows EN/ENO when the file asks (executionControl) or wires them.
  if (
    sig.kind === 'fb' &&
    (o.attr('executionControl') === 'true' ||
      o.inputs.some((p) => p.pin.toUpperCase() === 'EN') ||
      o.outputs.some((p) => p.pin.toUpperCase() === 'ENO'))
  )
    n.executionControl = true;
  if (sig.extensible) {
    const { prefix } = sig.extensible;
    const count = o.inputs.filter(
      (p) => p.pin.toUpperCase().startsWith(prefix) && /^\d+$/.test(p.pin.slice(prefix.length)),
    ).length;
    if (count > 0 && count !== sig.extensible.min) n.inputCount = count;
  }
  const layout = boxLayoutFor(sig.name, n.inputCount, library, n.executionControl === true);
  const known = new Set(layout?.inputs.map((p) => p.name) ?? []);
  let hasEn = false;
  for (const pin of o.inputs) {
    const name = canonicalPin(sig, pin.pin);
    if (name === 'EN') hasEn = true;
    if (!known.has(name)) {
      if (pin.connections.length)
        warn({
          message: `block ${instance ?? sig.name}: pin ${pin.pin} is not a pin of ${sig.name}; its wire is dropped`,
          obj: o,
        });
      continue;
    }
    if (pin.edge) {
      const counterPin = sig.category === 'counter' && (name === 'CU' || name === 'CD');
      warn({
        message: counterPin
          ? `block ${instance ?? sig.name}: edge qualifier on ${name} dropped (the counter already counts rising edges)`
          : `block ${instance ?? sig.name}: ${pin.edge} edge qualifier on input ${name} is dropped`,
        obj: o,
      });
    }
    let operand: string | undefined;
    const src = sourcesOf(pin, o, (t) => (operand = t));
    // A negated BOOL input (FBD): drawn as an inverting or normally-closed contact before the pin.
    if (pin.negated && (operand !== undefined || src.length)) {
      const bool = layout?.inputs.find((p) => p.name === name)?.type === 'BOOL';
      const inverted = negate?.(operand ?? src, bool);
      if (inverted) {
        n.inputs.set(name, [inverted]);
        continue;
      }
      warn({ message: `block ${instance ?? sig.name}: negation of input ${name} is dropped`, obj: o });
    }
    if (operand !== undefined) n.operandsIn[name] = operand;
    else if (src.length) n.inputs.set(name, src);
  }
  if ((sig.kind === 'function' || n.executionControl) && !hasEn) {
    n.inputs.set('EN', [RAIL]);
    n.implicitEn = true;
  }
  for (const pin of o.outputs) {
    const name = canonicalPin(sig, pin.pin);
    if (pin.negated)
      warn({ message: `block ${instance ?? sig.name}: negation of output ${pin.pin} is dropped`, obj: o });
    if (pin.expression) n.operandsOut[name] = pin.expression;
  }
}
