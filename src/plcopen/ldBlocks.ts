// A PLCopen <block> as a Rungsmith box: standard signature, extensible input count, pins wired or
// given operands (from in/outVariables), EN wired to the rail when a function has none.
import { blockSignature } from '../model/blocks';
import { boxLayoutFor } from '../model/boxLayout';
import type { Finding, GNode, GSource } from './ldGraph';
import type { RawObject, RawPin } from './ldObjects';

const RAIL: GSource = { kind: 'rail' };

export function buildBox(
  n: GNode,
  o: RawObject,
  sourcesOf: (pin: RawPin, consumer: RawObject, operandTarget?: (text: string) => void) => GSource[],
  warn: (f: Finding) => void,
): void {
  const typeName = o.text;
  const sig = blockSignature(typeName);
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
      message: `block type ${typeName} is not a standard block Rungsmith can simulate; kept with its operands`,
      obj: o,
    });
    return;
  }
  n.blockType = sig.name;
  if (sig.kind === 'fb' && !instance)
    warn({ message: `function block ${sig.name} has no instance name`, obj: o });
  if (sig.kind === 'function' && instance) n.instance = undefined;
  if (sig.extensible) {
    const { prefix } = sig.extensible;
    const count = o.inputs.filter(
      (p) => p.pin.toUpperCase().startsWith(prefix) && /^\d+$/.test(p.pin.slice(prefix.length)),
    ).length;
    if (count > 0 && count !== sig.extensible.min) n.inputCount = count;
  }
  const layout = boxLayoutFor(sig.name, n.inputCount);
  const known = new Set(layout?.inputs.map((p) => p.name) ?? []);
  let hasEn = false;
  for (const pin of o.inputs) {
    const name = pin.pin.toUpperCase();
    if (name === 'EN') hasEn = true;
    if (!known.has(name)) {
      if (pin.connections.length)
        warn({
          message: `block ${instance ?? sig.name}: pin ${pin.pin} is not a pin of ${sig.name}; its wire is dropped`,
          obj: o,
        });
      continue;
    }
    if (pin.negated)
      warn({ message: `block ${instance ?? sig.name}: negation of input ${name} is dropped`, obj: o });
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
    if (operand !== undefined) n.operandsIn[name] = operand;
    else if (src.length) n.inputs.set(name, src);
  }
  if (sig.kind === 'function' && !hasEn) n.inputs.set('EN', [RAIL]);
  for (const pin of o.outputs) {
    if (pin.negated)
      warn({ message: `block ${instance ?? sig.name}: negation of output ${pin.pin} is dropped`, obj: o });
    if (pin.expression) n.operandsOut[pin.pin.toUpperCase()] = pin.expression;
  }
}
