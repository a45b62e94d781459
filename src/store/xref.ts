// Cross-reference: every use of a variable or FB instance in the networks, with its POU, network,
// element kind and access (read, write, call, read/write for a VAR_IN_OUT pin); the variables no
// network uses; and the variables written in more than one place. Pure over the Project.
import type { ElementKind, LdElement } from '../model/elements';
import { blockLibrary, isInOutPin, type BlockLibrary } from '../model/library';
import type { ElementId, NetworkId, PouId } from '../model/ids';
import type { Network, Pou, Project, Variable } from '../model/project';
import type { VariableScope } from './changes';
import { isLiteral } from './find';

export type Access = 'read' | 'write' | 'read/write' | 'call';

export interface XrefUse {
  readonly pou: PouId;
  readonly pouName: string;
  readonly network: NetworkId;
  readonly networkIndex: number;
  readonly element: ElementId;
  readonly elementKind: ElementKind;
  /** Contact/coil type, or the box's block type. */
  readonly detail: string;
  readonly row: number;
  readonly col: number;
  /** Box pin, `instance` for the call itself. */
  readonly pin?: string;
  readonly operand: string;
  readonly access: Access;
}

const head = (operand: string) => operand.trim().split('.')[0]!.toUpperCase();

/** Each variable reference of an element: operand text, pin, access. */
function elementRefs(el: LdElement, lib: BlockLibrary): { operand: string; pin?: string; access: Access }[] {
  switch (el.kind) {
    case 'contact':
      return el.variable ? [{ operand: el.variable, access: 'read' }] : [];
    case 'coil':
      return [{ operand: el.variable, access: 'write' }];
    case 'box': {
      const out: { operand: string; pin?: string; access: Access }[] = [];
      if (el.instance) out.push({ operand: el.instance, pin: 'instance', access: 'call' });
      const sig = lib.signature(el.blockType);
      const inOut = new Set((sig?.inputs ?? []).filter(isInOutPin).map((p) => p.name.toUpperCase()));
      for (const [pin, operand] of Object.entries(el.inputs))
        if (operand.trim() && !isLiteral(operand))
          out.push({ operand, pin, access: inOut.has(pin.toUpperCase()) ? 'read/write' : 'read' });
      for (const [pin, operand] of Object.entries(el.outputs))
        if (operand.trim() && !isLiteral(operand) && !inOut.has(pin.toUpperCase()))
          out.push({ operand, pin, access: 'write' });
      return out;
    }
    default:
      return [];
  }
}

function toUse(
  pou: Pou,
  network: Network,
  networkIndex: number,
  el: LdElement,
  ref: { operand: string; pin?: string; access: Access },
): XrefUse {
  return {
    pou: pou.id,
    pouName: pou.name,
    network: network.id,
    networkIndex,
    element: el.id,
    elementKind: el.kind,
    detail: el.kind === 'contact' ? el.contact : el.kind === 'coil' ? el.coil : el.kind === 'box' ? el.blockType : el.kind,
    row: el.row,
    col: el.col,
    ...(ref.pin ? { pin: ref.pin } : {}),
    operand: ref.operand,
    access: ref.access,
  };
}

/** POUs whose names refer to a variable of `scope`: the POU itself, or for a global every POU that does not shadow it. */
function pousSeeing(project: Project, scope: VariableScope, name: string): Pou[] {
  const key = name.toUpperCase();
  if (scope !== 'globals') return project.pous.filter((p) => p.id === scope);
  return project.pous.filter((p) => !p.variables.some((v) => v.name.toUpperCase() === key));
}

/** Every use of variable (or instance) `name` declared in `scope`, POU by POU, in network order. */
export function crossReference(project: Project, scope: VariableScope, name: string): XrefUse[] {
  const key = name.toUpperCase();
  const lib = blockLibrary(project);
  const out: XrefUse[] = [];
  for (const pou of pousSeeing(project, scope, name))
    pou.networks.forEach((network, networkIndex) => {
      const els = [...network.elements].sort((a, b) => a.row - b.row || a.col - b.col);
      for (const el of els)
        for (const ref of elementRefs(el, lib)) {
          if (head(ref.operand) !== key) continue;
          out.push(toUse(pou, network, networkIndex, el, ref));
        }
    });
  return out;
}

export interface VariableSummary {
  readonly scope: VariableScope;
  readonly variable: Variable;
  readonly uses: number;
  /** Distinct elements that write it (coils, box outputs, in-out pins). */
  readonly writers: number;
}

/** Every declared variable (globals, then each POU's) with its use and writer counts, in one pass. */
export function variableSummary(project: Project): VariableSummary[] {
  const lib = blockLibrary(project);
  const count = (pou: Pou) => {
    const uses = new Map<string, number>();
    const writers = new Map<string, Set<ElementId>>();
    for (const network of pou.networks)
      for (const el of network.elements)
        for (const ref of elementRefs(el, lib)) {
          const h = head(ref.operand);
          uses.set(h, (uses.get(h) ?? 0) + 1);
          if (ref.access === 'write' || ref.access === 'read/write') {
            const set = writers.get(h) ?? new Set<ElementId>();
            set.add(el.id);
            writers.set(h, set);
          }
        }
    return { uses, writers };
  };
  const perPou = new Map(project.pous.map((p) => [p.id, count(p)]));
  const out: VariableSummary[] = [];
  for (const variable of project.globals) {
    const key = variable.name.toUpperCase();
    let uses = 0;
    let writers = 0;
    for (const pou of project.pous) {
      if (pou.variables.some((v) => v.name.toUpperCase() === key)) continue;
      const c = perPou.get(pou.id)!;
      uses += c.uses.get(key) ?? 0;
      writers += c.writers.get(key)?.size ?? 0;
    }
    out.push({ scope: 'globals', variable, uses, writers });
  }
  for (const pou of project.pous) {
    const c = perPou.get(pou.id)!;
    for (const variable of pou.variables) {
      const key = variable.name.toUpperCase();
      out.push({ scope: pou.id, variable, uses: c.uses.get(key) ?? 0, writers: c.writers.get(key)?.size ?? 0 });
    }
  }
  return out;
}

/**
 * Declared variables no network uses. Inputs and outputs of a FUNCTION_BLOCK or FUNCTION are its
 * interface (callers use them), so only locals, temps and a PROGRAM's variables count; POUs kept
 * in another language (ST, IL...) are skipped, as their bodies are not searched.
 */
export function unusedVariables(project: Project): VariableSummary[] {
  const lang = new Map(project.pous.map((p) => [p.id, p]));
  return variableSummary(project).filter((s) => {
    if (s.uses > 0) return false;
    if (s.scope === 'globals') return project.pous.every((p) => p.language === 'LD');
    const pou = lang.get(s.scope)!;
    if (pou.language !== 'LD') return false;
    return pou.kind === 'PROGRAM' || s.variable.varClass === 'local' || s.variable.varClass === 'temp';
  });
}

/** Variables written by more than one element (coils, box outputs): legal, often a mistake. */
export const writtenInSeveralPlaces = (project: Project): VariableSummary[] =>
  variableSummary(project).filter((s) => s.writers > 1);

/**
 * Every use of every declared variable in one pass (the print's cross-reference): per scope
 * ('globals' or a POU id), per upper-case name, the uses in POU and network order. Names no scope
 * declares are left out.
 */
export function projectCrossReference(project: Project): Map<VariableScope, Map<string, XrefUse[]>> {
  const lib = blockLibrary(project);
  const globals = new Set(project.globals.map((v) => v.name.toUpperCase()));
  const out = new Map<VariableScope, Map<string, XrefUse[]>>();
  const add = (scope: VariableScope, key: string, use: XrefUse) => {
    let byName = out.get(scope);
    if (!byName) out.set(scope, (byName = new Map()));
    const list = byName.get(key);
    if (list) list.push(use);
    else byName.set(key, [use]);
  };
  for (const pou of project.pous) {
    const own = new Set(pou.variables.map((v) => v.name.toUpperCase()));
    pou.networks.forEach((network, networkIndex) => {
      const els = [...network.elements].sort((a, b) => a.row - b.row || a.col - b.col);
      for (const el of els)
        for (const ref of elementRefs(el, lib)) {
          const key = head(ref.operand);
          const scope: VariableScope | undefined = own.has(key) ? pou.id : globals.has(key) ? 'globals' : undefined;
          if (!scope) continue;
          add(scope, key, toUse(pou, network, networkIndex, el, ref));
        }
    });
  }
  return out;
}
