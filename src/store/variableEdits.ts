// Renaming a variable rewrites the places that refer to it.
import type { LdElement } from '../model/elements';
import type { Pou } from '../model/project';

/** `Name`, `Name.Pin` or `Name.3` referring to `from` (case-insensitive, as IEC names are), renamed to `to`. */
export function renameOperand(operand: string, from: string, to: string): string {
  const trimmed = operand.trim();
  const dot = trimmed.indexOf('.');
  const head = dot < 0 ? trimmed : trimmed.slice(0, dot);
  if (head.toUpperCase() !== from.toUpperCase()) return operand;
  return dot < 0 ? to : `${to}${trimmed.slice(dot)}`;
}

function renameInRecord(
  rec: Readonly<Record<string, string>>,
  from: string,
  to: string,
): Readonly<Record<string, string>> {
  let changed = false;
  const out: Record<string, string> = {};
  for (const [pin, operand] of Object.entries(rec)) {
    const next = renameOperand(operand, from, to);
    if (next !== operand) changed = true;
    out[pin] = next;
  }
  return changed ? out : rec;
}

/** The element with references to variable `from` renamed to `to`; the same object when none. */
export function renameInElement(el: LdElement, from: string, to: string): LdElement {
  switch (el.kind) {
    case 'contact':
    case 'coil': {
      const variable = renameOperand(el.variable, from, to);
      return variable === el.variable ? el : { ...el, variable };
    }
    case 'box': {
      const instance = el.instance !== undefined ? renameOperand(el.instance, from, to) : undefined;
      const inputs = renameInRecord(el.inputs, from, to);
      const outputs = renameInRecord(el.outputs, from, to);
      if (instance === el.instance && inputs === el.inputs && outputs === el.outputs) return el;
      return { ...el, ...(instance !== undefined ? { instance } : {}), inputs, outputs };
    }
    case 'link':
    case 'jump':
    case 'return':
    case 'connector':
    case 'continuation':
      return el;
  }
}

/** Does the POU declare a variable of this name itself (so a global of that name is hidden)? */
export const declaresLocally = (pou: Pou, name: string): boolean =>
  pou.variables.some((v) => v.name.toUpperCase() === name.toUpperCase());
