// What the UI needs to know about a loaded program: its networks (to align power bytes with the
// document) and every readable name with its type (to format and parse values).
import { libraryOf } from '../model/libraries';
import type { InstanceInfo } from '../engine/api';
import { findVariable } from '../model/factory';
import { elementaryOf, leafPaths } from '../model/dataTypes';
import { parseLocation } from '../model/iecTypes';
import { blockLibrary } from '../model/library';
import type { Pou, Project, Variable } from '../model/project';
import { globalsWithOutside } from '../model/outsideGlobals';
import type { SimLayout, SimVariable, SimView, VariableRole } from './protocol';
import { programInstances, type ProgramInstance } from './runTarget';
import { yieldPoint } from '../engine/yieldPoint';

const roleOfLocation = (location: string | undefined): VariableRole => {
  const area = location ? parseLocation(location)?.area : undefined;
  if (area === 'I') return 'input';
  if (area === 'Q') return 'output';
  if (area === 'M') return 'memory';
  return 'local';
};

/** Type and role of a declared variable as a readable name. */
function declaredName(name: string, declared: Variable, inBody: boolean): SimVariable {
  return {
    name,
    type: declared.type.toUpperCase(),
    // A variable of an FB instance or of a configuration's program instance is the instance's own
    // memory (forceable, never bound to I/O by the instance's path).
    role: inBody && !declared.location ? 'local' : roleOfLocation(declared.location),
    ...(declared.location ? { location: declared.location } : {}),
  };
}

/**
 * Type and role of a readable name: a variable, `Instance.PIN` of a standard FB instance, a user FB
 * instance's variable by path (`Motor1.Run`, `Line.Motor1.T1.ET`), or in a configuration a program
 * instance's (`Prog1.Motor1.Run`). `pou` is the program the names are relative to.
 */
export function describeName(project: Project, pou: Pou, name: string): SimVariable | undefined {
  const library = blockLibrary(project);
  const parts = name.split('.');
  let scope: Pou = pou;
  let first = 0;
  // A configuration: the first part may be a program instance (globals keep their names).
  const program = parts.length > 1 ? programInstances(project).find((p) => sameName(p.instance, parts[0]!)) : undefined;
  if (program && !findVariable(project, pou, parts[0]!)) {
    const runs = findPou(project, program.pou);
    if (!runs) return undefined;
    scope = runs;
    first = 1;
  }
  for (let i = first; i < parts.length; i++) {
    const part = parts[i]!.replace(/\[.*$/s, ''); // `A[2]`: the variable A
    const declared = i === 0 || (i === first && scope === pou) ? findVariable(project, scope, part) : scope.variables.find((v) => sameName(v.name, part));
    if (!declared) return undefined;
    // A variable of a data type: one of its leaves (`P.X`, `A[2]`), or itself with its elementary type.
    const leaf = dataTypeLeaf(project, declared, parts.slice(i).join('.'));
    if (leaf) return { ...declaredName(name, declared, i > 0), type: leaf };
    if (i === parts.length - 1) return declaredName(name, declared, i > 0);
    const user = library.userPou(declared.type);
    if (user && user.kind === 'FUNCTION_BLOCK' && project.pous.includes(user)) {
      scope = user;
      continue;
    }
    // A standard (or external) FB instance: its pins, by the block's signature.
    const signature = library.signature(declared.type);
    if (!signature || signature.kind !== 'fb' || i !== parts.length - 2) return undefined;
    const pinName = parts[i + 1]!.toUpperCase();
    const pin = [...signature.inputs, ...signature.outputs].find((p) => p.name.toUpperCase() === pinName);
    return pin ? { name, type: pin.type, role: 'pin' } : undefined;
  }
  return undefined;
}

const sameName = (a: string, b: string) => a.toUpperCase() === b.toUpperCase();

/** The elementary type of `path` (`P.X`, `G[1, 2]`, `V`) in a variable of a user data type. */
function dataTypeLeaf(project: Project, declared: Variable, path: string): string | undefined {
  if (elementaryOf(declared.type)) return undefined;
  const r = leafPaths(project, declared);
  if (!r.ok) return undefined;
  const key = path.replace(/\s+/g, '').toUpperCase();
  return r.leaves.find((l) => l.path.toUpperCase() === key)?.type;
}

export function findPou(project: Project, name: string): Pou | undefined {
  const key = name.toUpperCase();
  return project.pous.find((p) => p.name.toUpperCase() === key);
}

/** Where each network of a POU starts in a frame's packed power, found by element id. */
function networkFields(pou: Pou | undefined): Pick<SimLayout, 'networkIds' | 'elementOffsets' | 'vlinkOffsets' | 'elementIds' | 'vlinkKeys'> {
  const elementOffsets = [0];
  const vlinkOffsets = [0];
  const elementIds: string[] = [];
  const vlinkKeys: string[] = [];
  const networks = pou?.networks ?? [];
  for (const network of networks) {
    yieldPoint();
    for (const el of network.elements) elementIds.push(el.id);
    for (const v of network.vlinks) vlinkKeys.push(`${v.row}|${v.boundary}`);
    elementOffsets.push(elementOffsets[elementOffsets.length - 1]! + network.elements.length);
    vlinkOffsets.push(vlinkOffsets[vlinkOffsets.length - 1]! + network.vlinks.length);
  }
  return { networkIds: networks.map((n) => n.id), elementOffsets, vlinkOffsets, elementIds, vlinkKeys };
}

/** What a loaded program offers to monitor besides its own networks. */
export interface LayoutExtras {
  /** User FB instances (plc.instances()). */
  readonly instances?: readonly InstanceInfo[];
  /** A configuration's program instances, in task order. */
  readonly programs?: readonly ProgramInstance[];
}

/** Layout of a compiled program; `names` is the engine's list of readable names in declaration order. */
export function buildLayout(project: Project, pouName: string, names: readonly string[], cycleMs: number, extras: LayoutExtras = {}): SimLayout {
  const pou = findPou(project, pouName);
  if (!pou) throw new Error(`the program "${pouName}" is not in the project`);
  const variables: SimVariable[] = [];
  for (let i = 0; i < names.length; i++) {
    const name = names[i]!;
    if ((i & 63) === 63) yieldPoint();
    const described = describeName(project, pou, name);
    // Names the engine can read but whose type the document cannot tell are not shown (none expected).
    if (described && described.type !== 'ANY') variables.push(described);
  }
  const programs = extras.programs ?? [];
  const first = programs[0];
  return {
    pou: pou.name,
    view: { pou: pou.name, ...(first ? { instance: first.instance } : {}) },
    ...(extras.instances ? { instances: extras.instances } : {}),
    ...(programs.length > 0 ? { programs } : {}),
    ...networkFields(pou),
    variables,
    cycleMs,
  };
}

/** The layout with its network fields describing another body (the view): an FB instance's, a function's, another program instance's. */
export function withView(project: Project, layout: SimLayout, view: SimView): SimLayout {
  const pou = findPou(project, view.pou);
  // The data lines are the view's (pinValues.ts withPinLines): those of the body left are dropped.
  const { pins: _pins, ...rest } = layout;
  return { ...rest, view: { pou: pou?.name ?? view.pou, ...(view.instance ? { instance: view.instance } : {}) }, ...networkFields(pou) };
}

/** True when a view is the program's own (first) body: the one the scan history and "Why?" describe. */
export function isProgramView(layout: SimLayout, view: SimView | undefined = layout.view): boolean {
  if (!view) return true;
  const first = layout.programs?.[0]?.instance;
  return sameName(view.pou, layout.pou) && sameName(view.instance ?? '', first ?? '');
}

/** Keys that change nothing the program does (left out of fingerprints). */
const NOT_BEHAVIOUR = new Set(['title', 'comment', 'collapsed', 'description', 'scenarios', 'watch', 'onlineChange', 'plant']);
const behaviourOnly = (key: string, value: unknown) => (NOT_BEHAVIOUR.has(key) ? undefined : value);

/** A part of a document (a network, a variable) as JSON without what changes nothing the program does. */
export function behaviourPrint(part: unknown): string {
  return JSON.stringify(part, behaviourOnly) ?? '';
}

/** Networks' prints, kept per network object: documents are immutable, so an edit prints only the networks it replaced. */
const networkPrints = new WeakMap<object, string>();
function networkPrint(network: object): string {
  let p = networkPrints.get(network);
  if (p === undefined) {
    p = behaviourPrint(network);
    networkPrints.set(network, p);
  }
  return p;
}

/**
 * The document with everything that does not change what the program does (titles, comments,
 * collapsed state, descriptions, test scenarios, the watch list, the online change mode) left out: equal fingerprints mean no online change is needed.
 */
export function programFingerprint(project: Project): string {
  // A yield point every 64 networks: an online change's fingerprint (~0.5 MB at 1,000 networks)
  // is made in pieces, between which the simulator runs the scans that fell due (yieldPoint.ts).
  const print = (n: object, i: number) => {
    if ((i & 63) === 63) yieldPoint();
    return networkPrint(n);
  };
  const pous = project.pous.map((p) => `${behaviourPrint({ ...p, networks: undefined })}[${p.networks.map(print).join(',')}]`);
  return `${behaviourPrint({ ...project, pous: undefined })}{${pous.join(',')}}`;
}

/** Deepest nesting of user FB instances listed by readableNames (recursion is refused by the compiler anyway). */
const MAX_NESTING = 8;

/**
 * Every name a user can watch in a POU, from the document alone: variables, `Instance.PIN` of
 * standard FB instances, and the variables of user FB instances by path (`Motor1.Run`, `Motor1.T1.ET`).
 */
export function readableNames(project: Project, pou: Pou): SimVariable[] {
  const library = blockLibrary(project);
  const out: SimVariable[] = [];
  const add = (prefix: string, variables: readonly Variable[], depth: number) => {
    for (const v of variables) {
      const name = `${prefix}${v.name}`;
      const user = library.userPou(v.type);
      // A POU of the project or of one of its libraries (not an external block's synthesized POU).
      if (user && user.kind === 'FUNCTION_BLOCK' && (project.pous.includes(user) || libraryOf(project, user.name)?.pous.includes(user))) {
        if (depth < MAX_NESTING) add(`${name}.`, user.variables.filter((x) => x.varClass !== 'external' && x.varClass !== 'temp'), depth + 1);
        continue;
      }
      const signature = library.signature(v.type);
      if (signature?.kind === 'fb') {
        for (const pin of [...signature.inputs, ...signature.outputs]) out.push({ name: `${name}.${pin.name}`, type: pin.type, role: 'pin' });
      } else if (depth > 0) {
        out.push(declaredName(name, v, true));
      } else {
        out.push(declaredName(name, v, false));
      }
    }
  };
  // A VAR_EXTERNAL names a global, listed once with the globals (also one declared outside the project).
  add('', [...pou.variables.filter((x) => x.varClass !== 'external'), ...globalsWithOutside(project)], 0);
  return out;
}
