// "Start is not declared — declare it?": the declarations offered for an undeclared name, with a
// sensible type for where it was typed and, on request, the next free input/output/memory address.
// Inside a function block or a function the choices are its interface instead (VAR_INPUT,
// VAR_OUTPUT, VAR_IN_OUT, VAR): a block's variables have no addresses, its inputs and outputs are
// what its callers wire.
import { blockSignature } from '../../model/blocks';
import { variable } from '../../model/factory';
import type { PinType } from '../../model/iecTypes';
import type { PouKind, Project, VarClass, Variable } from '../../model/project';
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

const CLASS_WORDS: Partial<Record<VarClass, string>> = {
  input: 'input (VAR_INPUT)',
  output: 'output (VAR_OUTPUT)',
  inOut: 'in-out (VAR_IN_OUT)',
  local: 'local (VAR)',
};

/**
 * The interface sections a name typed in a block's body may go to, the likeliest first: a contact
 * or an input pin reads (VAR_INPUT), a coil or an output pin writes (VAR_OUTPUT). A function has no
 * VAR_IN_OUT here (its callers pass values); an FB instance is a local of the block.
 */
function classesFor(role: BindingRole, kind: 'FUNCTION_BLOCK' | 'FUNCTION'): VarClass[] {
  if (role.kind === 'instance') return ['local'];
  const writes = role.kind === 'coil' || (role.kind === 'pin' && role.direction !== 'input');
  const order: VarClass[] = writes ? ['output', 'inOut', 'input', 'local'] : ['input', 'inOut', 'output', 'local'];
  return kind === 'FUNCTION' ? order.filter((c) => c !== 'inOut') : order;
}

/**
 * Declarations to offer for `name`, typed in a POU of kind `pouKind` (a program when not given);
 * empty when the name cannot be a variable name.
 */
export function declareChoices(project: Project, name: string, role: BindingRole, pouKind?: PouKind): DeclareChoice[] {
  const trimmed = name.trim();
  if (identifierProblem(trimmed)) return [];
  const type = suggestedType(role);
  if (pouKind === 'FUNCTION_BLOCK' || pouKind === 'FUNCTION')
    return classesFor(role, pouKind).map((varClass) => ({
      label: `${type} ${CLASS_WORDS[varClass]}`,
      variable: variable(trimmed, type, { varClass }),
    }));
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
