// "Start is not declared — declare it?": the declarations offered for an undeclared name, with a
// sensible type for where it was typed and, on request, the next free input/output/memory address.
import { blockSignature } from '../../model/blocks';
import { variable } from '../../model/factory';
import type { PinType } from '../../model/iecTypes';
import type { Project, Variable } from '../../model/project';
import { nextFreeAddress, type AddressArea } from '../variables/addresses';
import { identifierProblem } from '../variables/validation';
import type { BindingRole } from './operands';

export interface DeclareChoice {
  /** Short words for the list: "BOOL", "BOOL input at %IX0.2". */
  readonly label: string;
  readonly variable: Variable;
}

/** The type a new variable gets when first typed in this role. */
export function suggestedType(role: BindingRole): string {
  switch (role.kind) {
    case 'contact':
    case 'coil':
      return 'BOOL';
    case 'instance':
      // A standard block's name (TON), or a user FB as the project spells it (Motor).
      return blockSignature(role.blockType)?.name ?? role.blockType;
    case 'pin':
      return role.declaredType ?? concreteType(role.pinType);
  }
}

/** A generic pin gets the type a PLC programmer most often means there. */
function concreteType(type: PinType): string {
  switch (type) {
    case 'ANY':
    case 'ANY_ELEMENTARY':
    case 'ANY_MAGNITUDE':
    case 'ANY_NUM':
    case 'ANY_INT':
      return 'INT';
    case 'ANY_REAL':
      return 'REAL';
    case 'ANY_BIT':
      return 'WORD';
    default:
      return type;
  }
}

const AREA_WORDS: Record<AddressArea, string> = { I: 'input', Q: 'output', M: 'memory' };

/** Areas worth offering: contacts read inputs, coils write outputs; both may use memory. */
function areasFor(role: BindingRole): AddressArea[] {
  switch (role.kind) {
    case 'contact':
      return ['I', 'M'];
    case 'coil':
      return ['Q', 'M'];
    case 'instance':
      return [];
    case 'pin':
      return role.direction === 'input' ? ['I', 'M'] : ['Q', 'M'];
  }
}

/** Declarations to offer for `name`; empty when the name cannot be a variable name. */
export function declareChoices(project: Project, name: string, role: BindingRole): DeclareChoice[] {
  const trimmed = name.trim();
  if (identifierProblem(trimmed)) return [];
  const type = suggestedType(role);
  const choices: DeclareChoice[] = [{ label: type, variable: variable(trimmed, type) }];
  for (const area of areasFor(role)) {
    const location = nextFreeAddress(project, area, type);
    if (location)
      choices.push({
        label: `${type} ${AREA_WORDS[area]} at ${location}`,
        variable: variable(trimmed, type, { location }),
      });
  }
  return choices;
}
