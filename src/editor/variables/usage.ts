// Where variables are used on the canvas: contacts, coils, FB instances and box pin operands
// (`Name`, `Name.Pin`, `Name.3`, `Name[2].X` all count as a use of Name).
import type { LdElement } from '../../model/elements';
import type { ElementId, NetworkId, PouId } from '../../model/ids';
import type { Network, Pou, Project } from '../../model/project';

export interface VariableUse {
  readonly pou: PouId;
  readonly network: NetworkId;
  readonly element: ElementId;
  readonly row: number;
  readonly col: number;
}

/** The variable an operand refers to, upper-cased (IEC names ignore case); undefined for none. */
function operandHead(operand: string): string | undefined {
  const head = operand.trim().split(/[.[]/)[0] ?? '';
  return /^[A-Za-z_][A-Za-z0-9_]*$/.test(head) ? head.toUpperCase() : undefined;
}

function operandsOf(el: LdElement): string[] {
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return [el.variable];
    case 'box':
      return [
        ...(el.instance !== undefined ? [el.instance] : []),
        ...Object.values(el.inputs),
        ...Object.values(el.outputs),
      ];
    case 'link':
    case 'jump':
    case 'return':
    case 'connector':
    case 'continuation':
      return [];
  }
}

interface NetworkRef {
  readonly head: string;
  readonly element: ElementId;
  readonly row: number;
  readonly col: number;
}

/** Per network, computed once per network version: an edit re-reads only the network it touched. */
const refsCache = new WeakMap<Network, readonly NetworkRef[]>();

function networkRefs(network: Network): readonly NetworkRef[] {
  const hit = refsCache.get(network);
  if (hit) return hit;
  const refs: NetworkRef[] = [];
  for (const el of network.elements) {
    const seen = new Set<string>();
    for (const operand of operandsOf(el)) {
      const head = operandHead(operand);
      if (!head || seen.has(head)) continue;
      seen.add(head);
      refs.push({ head, element: el.id, row: el.row, col: el.col });
    }
  }
  refsCache.set(network, refs);
  return refs;
}

function collect(
  pous: readonly Pou[],
  skip: (pou: Pou, name: string) => boolean,
): Map<string, VariableUse[]> {
  const uses = new Map<string, VariableUse[]>();
  for (const pou of pous) {
    for (const network of pou.networks) {
      for (const ref of networkRefs(network)) {
        if (skip(pou, ref.head)) continue;
        const use = { pou: pou.id, network: network.id, element: ref.element, row: ref.row, col: ref.col };
        const list = uses.get(ref.head);
        if (list) list.push(use);
        else uses.set(ref.head, [use]);
      }
    }
  }
  return uses;
}

/** Uses of the POU's own variables, by upper-cased name, in network order. */
export const pouVariableUses = (pou: Pou): Map<string, VariableUse[]> => collect([pou], () => false);

/** Uses of global variables in every POU that does not declare the same name itself. */
export function globalVariableUses(project: Project): Map<string, VariableUse[]> {
  const local = new Map(
    project.pous.map((p) => [p.id, new Set(p.variables.map((v) => v.name.toUpperCase()))]),
  );
  return collect(project.pous, (pou, name) => local.get(pou.id)?.has(name) === true);
}
