// "Start is not declared — declare it?": the declarations offered for an undeclared name, with a
// sensible type for where it was typed and, on request, the next free input/output/memory address.
// Inside a function block or a function the choices are its interface instead (VAR_INPUT,
// VAR_OUTPUT, VAR_IN_OUT, VAR): a block's variables have no addresses, its inputs and outputs are
// what its callers wire.
// A name can also be declared global (VAR_GLOBAL, with an input/output address in a program, as
// CODESYS's I/O lists are): where the POU names its globals with VAR_EXTERNAL (an OpenPLC project,
// whose MATIEC build requires it, or a POU that already declares externals), the VAR_EXTERNAL is
// added to the POU too, in the same undo step.
import { blockSignature } from '../../model/blocks';
import { variable } from '../../model/factory';
import type { PinType } from '../../model/iecTypes';
import type { Pou, PouKind, Project, VarClass, Variable } from '../../model/project';
import type { VariableScope } from '../../store/changes';
import { machinePoints, nextFreeAddress, type AddressArea } from '../variables/addresses';
import { addressOwners } from '../variables/validation';
import { locationText, parseLocation } from '../../model/iecTypes';
import { identifierProblem, isKnownVariableType } from '../variables/validation';
import { blockLibrary } from '../../model/library';
import { resolveType } from '../../model/dataTypes';
import { importType } from '../../store/symbolPaste';
import type { BindingRole } from './operands';

export interface DeclareChoice {
  /** Short words for the list: "BOOL", "BOOL input at %IX0.2". */
  readonly label: string;
  readonly variable: Variable;
  /** Declared in the project's globals instead of the POU. */
  readonly global?: boolean;
  /** With `global`: the POU gets a VAR_EXTERNAL of it too. */
  readonly external?: boolean;
}

/**
 * Whether a global used in `pou` is also declared VAR_EXTERNAL there: in a program or function block
 * of an OpenPLC project (MATIEC refuses a global without it) or of a POU that already names its
 * globals that way. Rungsmith itself lets every POU see the globals.
 */
export function needsExternal(project: Pick<Project, 'profile'>, pou: Pick<Pou, 'kind' | 'variables'>): boolean {
  if (pou.kind === 'FUNCTION') return false;
  return project.profile === 'openplc' || pou.variables.some((v) => v.varClass === 'external');
}

/** The store commands a declaration uses. */
export interface DeclareTarget {
  batch<T>(name: string, fn: () => T): T;
  addVariable(v: Variable, scope?: VariableScope): boolean;
}

/** Declares a chosen offer as one undo step (in a caller's batch, with its own edit): false when the name is taken. */
export function declareChoice(target: DeclareTarget, choice: DeclareChoice, pou: VariableScope): boolean {
  return target.batch('declareVariable', () => {
    if (!choice.global) return target.addVariable(choice.variable, pou);
    if (!target.addVariable(choice.variable, 'globals')) return false;
    if (choice.external) {
      const { location: _l, initial: _i, retain: _r, constant: _c, ...rest } = choice.variable;
      target.addVariable({ ...rest, varClass: 'external', retain: false }, pou);
    }
    return true;
  });
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
 * Declarations to offer for `name`, typed in `pou` (or a POU of that kind; a program when not
 * given): the POU's own first, then global; empty when the name cannot be a variable name.
 * `typed`: the type the user wrote (`Speed : INT`, typedDeclaration) instead of the suggested one.
 */
export function declareChoices(
  project: Project,
  name: string,
  role: BindingRole,
  pouOrKind?: PouKind | Pick<Pou, 'kind' | 'name' | 'variables'>,
  typed?: string,
): DeclareChoice[] {
  const pou = typeof pouOrKind === 'string' ? { kind: pouOrKind, name: '', variables: [] } : pouOrKind;
  const trimmed = name.trim();
  if (identifierProblem(trimmed)) return [];
  const type = typed ?? suggestedType(role);
  const kind = pou?.kind ?? 'PROGRAM';
  const external = pou ? needsExternal(project, pou) : false;
  const globalWords = external ? `global + VAR_EXTERNAL in ${pou?.name ?? ''}` : 'global (VAR_GLOBAL)';
  if (kind === 'FUNCTION_BLOCK' || kind === 'FUNCTION') {
    const choices: DeclareChoice[] = classesFor(role, kind).map((varClass) => ({
      label: `${type} ${CLASS_WORDS[varClass]}`,
      variable: variable(trimmed, type, { varClass }),
    }));
    // A block's own variables come first; a global is for a flag the whole program shares.
    if (role.kind !== 'instance')
      choices.push({ label: `${type} ${globalWords}`, variable: variable(trimmed, type), global: true, external });
    return choices;
  }
  const choices: DeclareChoice[] = [{ label: type, variable: variable(trimmed, type) }];
  // A point of the project's machine (LowLevel with the tank chosen): at the machine's address first,
  // so Enter wires it (the next free input, %IX0.0, is the tank's Start button).
  const machine = machineOffer(project, trimmed, type, role);
  if (machine) choices.unshift(machine);
  const areas = areasFor(role);
  for (const area of areas) {
    const location = nextFreeAddress(project, area, type);
    if (location)
      choices.push({
        label: `${type} ${AREA_WORDS[area]} at ${location}`,
        variable: variable(trimmed, type, { location }),
      });
  }
  // An FB instance belongs to the POU that calls it: no global offer for it.
  if (role.kind === 'instance') return choices;
  choices.push({ label: `${type} ${globalWords}`, variable: variable(trimmed, type), global: true, external });
  // I/O is where globals matter most: the input or output address as a global too (worded apart
  // from the local "input at %IX0.2" offer).
  const io = areas.find((a) => a !== 'M');
  const location = io ? nextFreeAddress(project, io, type) : undefined;
  if (io && location)
    choices.push({
      label: `${type} ${globalWords.replace(/^global/, `global at ${location}`)}`,
      variable: variable(trimmed, type, { location }),
      global: true,
      external,
    });
  return choices;
}

/**
 * In a program of a project with a machine: the machine's points not declared yet whose names start
 * with what was typed (`Hi` -> HighLevel), each offered at the machine's address, so a newcomer sees
 * the machine's names while typing. The name typed whole is offered by declareChoices itself.
 */
export function machinePointOffers(
  project: Project,
  typed: string,
  role: BindingRole,
  pou: Pick<Pou, 'kind' | 'variables'>,
): DeclareChoice[] {
  const q = typed.trim().toUpperCase();
  if (q === '' || pou.kind !== 'PROGRAM' || role.kind === 'instance') return [];
  const declared = new Set([...pou.variables, ...project.globals].map((v) => v.name.toUpperCase()));
  const type = suggestedType(role).toUpperCase();
  return machinePoints(project)
    .filter((p) => p.name.toUpperCase().startsWith(q) && p.name.toUpperCase() !== q && !declared.has(p.name.toUpperCase()))
    .flatMap((p) => machineOffer(project, p.name, type, role) ?? []);
}

/**
 * The declaration of a point of the project's machine named `name` (any case), at the address the
 * machine is wired to, with the point's comment: undefined when there is no such point, its type is
 * not `type`, or a variable of the project has its address already.
 */
function machineOffer(project: Project, name: string, type: string, role: BindingRole): DeclareChoice | undefined {
  if (role.kind === 'instance') return undefined;
  const point = machinePoints(project).find((p) => p.name.toUpperCase() === name.toUpperCase());
  const loc = point ? parseLocation(point.address) : undefined;
  if (!point || !loc || point.type !== type.toUpperCase()) return undefined;
  const address = locationText(loc);
  if ([...addressOwners(project).keys()].some((k) => k === address)) return undefined;
  const words = point.kind === 'actuator' ? 'output' : 'input';
  return {
    label: `${point.type} ${words} at ${address}, the machine's ${point.name}`,
    variable: variable(name, point.type, { location: address, comment: point.comment }),
  };
}

/**
 * `Speed : INT` typed in a name field: the name and the type (in the project's spelling) to declare
 * it with, as in a declaration; undefined when the text is not of that form or the type is unknown.
 */
export function typedDeclaration(project: Project, text: string): { name: string; type: string } | undefined {
  const m = /^\s*([A-Za-z_][A-Za-z0-9_]*)\s*:\s*(\S.*?)\s*;?\s*$/.exec(text);
  if (!m) return undefined;
  const type = importType(project, m[2]!);
  const lib = blockLibrary(project);
  const known =
    isKnownVariableType(type, lib) || project.dataTypes?.some((d) => d.name === type) || resolveType(project, type).ok;
  return known ? { name: m[1]!, type } : undefined;
}
