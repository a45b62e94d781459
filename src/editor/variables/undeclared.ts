// Names used on the canvas that the variable table does not declare yet, each with the
// declaration the editor would offer for it (BOOL for contacts and coils, the block type for an
// FB instance, the pin's type for a box operand), so they can all be declared in one step.
import { boxLayout } from '../../model/boxLayout';
import { blockLibrary, type BlockLibrary } from '../../model/library';
import { variable } from '../../model/factory';
import type { Pou, Project, Variable } from '../../model/project';
import { suggestedType } from '../inspector/declareOffer';
import { pinRole, type BindingRole } from '../inspector/operands';
import { parseLiteral } from '../../engine/values/literals';
import { identifierProblem } from './validation';

function* namedOperands(pou: Pou, lib: BlockLibrary): Generator<{ name: string; role: BindingRole }> {
  for (const network of pou.networks) {
    for (const el of network.elements) {
      if (el.kind === 'contact' && el.contact !== 'NOT')
        yield { name: el.variable, role: { kind: 'contact' } };
      else if (el.kind === 'coil') yield { name: el.variable, role: { kind: 'coil' } };
      else if (el.kind === 'box') {
        const layout = boxLayout(el, lib);
        if (!layout) continue;
        if (el.instance !== undefined && layout.signature.kind === 'fb') {
          yield { name: el.instance, role: { kind: 'instance', blockType: layout.signature.name } };
        }
        for (const pin of layout.inputs) {
          const operand = el.inputs[pin.name];
          if (operand !== undefined && !parseLiteral(operand.trim()).ok) {
            yield { name: operand, role: pinRole(pin, 'input') };
          }
        }
        for (const pin of layout.outputs) {
          const operand = el.outputs[pin.name];
          if (operand !== undefined)
            yield { name: operand, role: pinRole(pin, 'output') };
        }
      }
    }
  }
}

/** Undeclared plain names used in the POU, in order of first use; the first use decides the type. */
export function undeclaredVariables(project: Project, pou: Pou): Variable[] {
  const out = new Map<string, Variable>();
  const declared = new Set([...pou.variables, ...project.globals].map((v) => v.name.toUpperCase()));
  for (const { name, role } of namedOperands(pou, blockLibrary(project))) {
    const trimmed = name.trim();
    const key = trimmed.toUpperCase();
    if (trimmed === '' || declared.has(key) || out.has(key) || identifierProblem(trimmed)) continue;
    out.set(key, variable(trimmed, suggestedType(role)));
  }
  return [...out.values()];
}
