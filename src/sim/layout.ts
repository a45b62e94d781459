// What the UI needs to know about a loaded program: its networks (to align power bytes with the
// document) and every readable name with its type (to format and parse values).
import { blockSignature } from '../model/blocks';
import { findVariable } from '../model/factory';
import { parseLocation } from '../model/iecTypes';
import type { Pou, Project } from '../model/project';
import type { SimLayout, SimVariable, VariableRole } from './protocol';

const roleOfLocation = (location: string | undefined): VariableRole => {
  const area = location ? parseLocation(location)?.area : undefined;
  if (area === 'I') return 'input';
  if (area === 'Q') return 'output';
  if (area === 'M') return 'memory';
  return 'local';
};

/** Type and role of a readable name: a variable, or `Instance.PIN` of a function block instance. */
export function describeName(project: Project, pou: Pou, name: string): SimVariable | undefined {
  const declared = findVariable(project, pou, name);
  if (declared) {
    return {
      name,
      type: declared.type.toUpperCase(),
      role: roleOfLocation(declared.location),
      ...(declared.location ? { location: declared.location } : {}),
    };
  }
  const dot = name.indexOf('.');
  if (dot < 0) return undefined;
  const instance = findVariable(project, pou, name.slice(0, dot));
  const signature = instance ? blockSignature(instance.type) : undefined;
  if (!signature || signature.kind !== 'fb') return undefined;
  const pinName = name.slice(dot + 1).toUpperCase();
  const pin = [...signature.inputs, ...signature.outputs].find((p) => p.name === pinName);
  return pin ? { name, type: pin.type, role: 'pin' } : undefined;
}

export function findPou(project: Project, name: string): Pou | undefined {
  const key = name.toUpperCase();
  return project.pous.find((p) => p.name.toUpperCase() === key);
}

/** Layout of a compiled program; `names` is the engine's list of readable names in declaration order. */
export function buildLayout(project: Project, pouName: string, names: readonly string[], cycleMs: number): SimLayout {
  const pou = findPou(project, pouName);
  if (!pou) throw new Error(`the program "${pouName}" is not in the project`);
  const elementOffsets = [0];
  const vlinkOffsets = [0];
  const elementIds: string[] = [];
  const vlinkKeys: string[] = [];
  for (const network of pou.networks) {
    for (const el of network.elements) elementIds.push(el.id);
    for (const v of network.vlinks) vlinkKeys.push(`${v.row}|${v.boundary}`);
    elementOffsets.push(elementOffsets[elementOffsets.length - 1]! + network.elements.length);
    vlinkOffsets.push(vlinkOffsets[vlinkOffsets.length - 1]! + network.vlinks.length);
  }
  const variables: SimVariable[] = [];
  for (const name of names) {
    const described = describeName(project, pou, name);
    // Names the engine can read but whose type the document cannot tell are not shown (none expected).
    if (described && described.type !== 'ANY') variables.push(described);
  }
  return {
    pou: pou.name,
    networkIds: pou.networks.map((n) => n.id),
    elementOffsets,
    vlinkOffsets,
    elementIds,
    vlinkKeys,
    variables,
    cycleMs,
  };
}

/**
 * The document with everything that does not change what the program does (titles, comments,
 * collapsed state, descriptions, test scenarios) left out: equal fingerprints mean no online change is needed.
 */
export function programFingerprint(project: Project): string {
  return JSON.stringify(project, (key, value: unknown) =>
    key === 'title' || key === 'comment' || key === 'collapsed' || key === 'description' || key === 'scenarios' ? undefined : value,
  );
}

/** Every name a user can watch in a POU, from the document alone: variables, then `Instance.PIN` of FB instances. */
export function readableNames(project: Project, pou: Pou): SimVariable[] {
  const out: SimVariable[] = [];
  // A VAR_EXTERNAL names a global, listed once with the globals.
  for (const v of [...pou.variables.filter((x) => x.varClass !== 'external'), ...project.globals]) {
    const signature = blockSignature(v.type);
    if (signature?.kind === 'fb') {
      for (const pin of [...signature.inputs, ...signature.outputs]) out.push({ name: `${v.name}.${pin.name}`, type: pin.type, role: 'pin' });
    } else {
      out.push({ name: v.name, type: v.type.toUpperCase(), role: roleOfLocation(v.location), ...(v.location ? { location: v.location } : {}) });
    }
  }
  return out;
}
