// Whole networks as units: copy (with their title, comment, label, collapsed state and the
// declarations they use), paste into any POU of any project (JSON text through the system
// clipboard, marker `rungsmith-networks`), delete and move a set of networks.
//
// Paste, as TIA does for FB calls: `keep` keeps the instances (a second call of one instance is
// legal IEC; the checks warn, LD-R10); `new` gives every instance that the target already
// declares the next free name (`Timer1` -> `Timer2`), declared with the copied declaration.
// Labels stay unique in the target POU (renamed the same way), and a pasted jump to a label that
// came along follows the rename; a jump to a label that did not come along keeps its text.
import { withoutExecutionOrder, type LdElement } from '../model/elements';
import { newNetwork, newProject } from '../model/factory';
import { newId, type ElementId, type NetworkId } from '../model/ids';
import { validateProject } from '../model/load';
import type { Network, Pou, Project, Variable } from '../model/project';
import type { Change } from './changes';
import { jsonObject } from './clipboard';
import { renameInElement } from './variableEdits';

export const NETWORK_CLIP_FORMAT = 'rungsmith-networks';
export const NETWORK_CLIP_VERSION = 1;

export interface NetworkClip {
  readonly format: typeof NETWORK_CLIP_FORMAT;
  readonly version: typeof NETWORK_CLIP_VERSION;
  readonly networks: readonly Network[];
  /** Declarations (from the source POU) of the variables and instances the networks use. */
  readonly variables: readonly Variable[];
}

export type InstanceMode = 'keep' | 'new';

const upper = (s: string) => s.toUpperCase();

/** The variable names an element refers to (the part before a `.`), as written. */
export function elementNames(el: LdElement): string[] {
  const heads = (ops: readonly string[]) =>
    ops.map((o) => o.trim().split('.')[0] ?? '').filter((h) => /^[A-Za-z_][A-Za-z0-9_]*$/.test(h));
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return heads([el.variable]);
    case 'box':
      return heads([
        ...(el.instance !== undefined ? [el.instance] : []),
        ...Object.values(el.inputs),
        ...Object.values(el.outputs),
      ]);
    default:
      return [];
  }
}

/** The networks `ids` of the POU (in the POU's order) and the POU's declarations they use. */
export function copyNetworks(pou: Pou, ids: readonly NetworkId[]): NetworkClip | undefined {
  const set = new Set(ids);
  const networks = pou.networks.filter((n) => set.has(n.id));
  if (networks.length === 0) return undefined;
  const names = new Set<string>();
  for (const n of networks) for (const el of n.elements) for (const h of elementNames(el)) names.add(upper(h));
  const variables = pou.variables.filter((v) => names.has(upper(v.name)));
  return { format: NETWORK_CLIP_FORMAT, version: NETWORK_CLIP_VERSION, networks, variables };
}

export const networkClipText = (clip: NetworkClip): string => JSON.stringify(clip);

/** The network clip in `text`, or undefined when it is not one (validated like a project file). */
export function parseNetworkClip(text: string): NetworkClip | undefined {
  const d = jsonObject(text);
  if (!d) return undefined;
  if (d.format !== NETWORK_CLIP_FORMAT || d.version !== NETWORK_CLIP_VERSION || !Array.isArray(d.networks))
    return undefined;
  if (d.networks.length === 0) return undefined;
  const probe = newProject('clip');
  const pou = probe.pous[0]!;
  const variables = Array.isArray(d.variables) ? d.variables : [];
  const result = validateProject({ ...probe, pous: [{ ...pou, variables, networks: d.networks }] });
  if (!result.ok) return undefined;
  const loaded = result.project.pous[0]!;
  return {
    format: NETWORK_CLIP_FORMAT,
    version: NETWORK_CLIP_VERSION,
    networks: loaded.networks,
    variables: loaded.variables,
  };
}

/** FB instance names the clip's boxes call, as first written. */
export function clipInstances(clip: NetworkClip): string[] {
  const seen = new Map<string, string>();
  for (const n of clip.networks)
    for (const el of n.elements)
      if (el.kind === 'box' && el.instance && !seen.has(upper(el.instance))) seen.set(upper(el.instance), el.instance);
  return [...seen.values()];
}

/** `Timer1` -> `Timer2`, `Loop` -> `Loop2`, `10` -> `11`: the first name past `name` not in `taken` (upper-cased). */
export function nextFreeName(name: string, taken: ReadonlySet<string>): string {
  const m = /^(.*?)(\d*)$/.exec(name)!;
  const base = m[1]!;
  let i = m[2] ? Number(m[2]) + 1 : 2;
  while (taken.has(upper(`${base}${i}`))) i++;
  return `${base}${i}`;
}

export interface PreparedPaste {
  readonly networks: readonly Network[];
  /** Declarations to add to the target POU (missing ones, and new instances). */
  readonly variables: readonly Variable[];
  /** Instances given a new name: old -> new. */
  readonly instances: ReadonlyMap<string, string>;
  /** Labels given a new name: old -> new. */
  readonly labels: ReadonlyMap<string, string>;
}

/** The clip's networks ready to go into `pou`: new ids, labels unique, instances per `mode`. */
export function preparePaste(project: Project, pou: Pou, clip: NetworkClip, mode: InstanceMode): PreparedPaste {
  const declared = new Set([...pou.variables, ...project.globals].map((v) => upper(v.name)));
  const clipVar = new Map(clip.variables.map((v) => [upper(v.name), v]));
  const instances = new Map<string, string>();
  const variables: Variable[] = [];
  const taken = new Set([...declared, ...project.pous.map((p) => upper(p.name)), ...clipVar.keys()]);
  if (mode === 'new') {
    for (const name of clipInstances(clip)) {
      if (!declared.has(upper(name))) continue;
      const to = nextFreeName(name, taken);
      taken.add(upper(to));
      instances.set(name, to);
      const decl =
        clipVar.get(upper(name)) ?? pou.variables.find((v) => upper(v.name) === upper(name)) ??
        project.globals.find((v) => upper(v.name) === upper(name));
      if (decl) variables.push({ ...decl, name: to, varClass: decl.varClass === 'external' ? 'local' : decl.varClass });
    }
  }
  for (const v of clip.variables) if (!declared.has(upper(v.name))) variables.push(v);

  const labelsTaken = new Set(pou.networks.flatMap((n) => (n.label ? [upper(n.label)] : [])));
  const labels = new Map<string, string>();
  for (const n of clip.networks) {
    if (!n.label) continue;
    if (!labelsTaken.has(upper(n.label))) {
      labelsTaken.add(upper(n.label));
      continue;
    }
    const to = nextFreeName(n.label, labelsTaken);
    labelsTaken.add(upper(to));
    labels.set(upper(n.label), to);
  }

  const networks = clip.networks.map((n): Network => {
    const elements = n.elements.map((el) => {
      // A pasted copy keeps no PLCopen execution order: it must not jump the openplc queue.
      let out: LdElement = { ...withoutExecutionOrder(el), id: newId<'ElementId'>('e') as ElementId };
      for (const [from, to] of instances) out = renameInElement(out, from, to);
      if (out.kind === 'jump') {
        const to = labels.get(upper(out.target));
        if (to) out = { ...out, target: to };
      }
      return out;
    });
    const label = n.label ? (labels.get(upper(n.label)) ?? n.label) : undefined;
    // Nor the imported generator turns (Network.turns): its elements have new ids.
    const { id: _id, label: _label, turns: _turns, ...rest } = n;
    return newNetwork({ ...rest, ...(label ? { label } : {}), elements, vlinks: [...n.vlinks] });
  });
  return { networks, variables, instances, labels };
}

/** Changes that paste the prepared networks into `pou` at `index` and declare what they need. */
export function pasteChanges(pou: Pou, index: number, p: PreparedPaste): Change[] {
  const at = Math.max(0, Math.min(index, pou.networks.length));
  return [
    ...p.variables.map(
      (variable, i): Change => ({ type: 'variable.add', scope: pou.id, index: pou.variables.length + i, variable }),
    ),
    ...p.networks.map((network, i): Change => ({ type: 'network.add', pou: pou.id, index: at + i, network })),
  ];
}

/** Changes that remove the networks `ids` from the POU (highest index first, so undo restores them in place). */
export function deleteChanges(pou: Pou, ids: readonly NetworkId[]): Change[] {
  const set = new Set(ids);
  const out: Change[] = [];
  for (let i = pou.networks.length - 1; i >= 0; i--) {
    const network = pou.networks[i]!;
    if (set.has(network.id)) out.push({ type: 'network.remove', pou: pou.id, index: i, network });
  }
  return out;
}

/**
 * Changes that move the networks `ids` (any set) by `delta` places (-1 up, +1 down) as a block
 * each keeps its order; undefined when one is already at the edge.
 */
export function moveChanges(pou: Pou, ids: readonly NetworkId[], delta: number): Change[] | undefined {
  const set = new Set(ids);
  const indices = pou.networks.flatMap((n, i) => (set.has(n.id) ? [i] : []));
  if (indices.length === 0 || delta === 0) return undefined;
  if (indices[0]! + delta < 0 || indices[indices.length - 1]! + delta >= pou.networks.length) return undefined;
  const order = delta < 0 ? indices : [...indices].reverse();
  return order.map((from): Change => ({ type: 'network.move', pou: pou.id, from, to: from + delta }));
}

/**
 * Changes that move the networks `ids` so they sit, in order, before the network now at `before`
 * (a drag ending over a header; `before` = the count puts them at the end).
 */
export function moveToChanges(pou: Pou, ids: readonly NetworkId[], before: number): Change[] | undefined {
  const set = new Set(ids);
  const moving = pou.networks.filter((n) => set.has(n.id));
  if (moving.length === 0) return undefined;
  const rest = pou.networks.filter((n) => !set.has(n.id));
  const insertAt = pou.networks.slice(0, before).filter((n) => !set.has(n.id)).length;
  const target = [...rest.slice(0, insertAt), ...moving, ...rest.slice(insertAt)];
  const current = pou.networks.map((n) => n.id);
  const changes: Change[] = [];
  for (let i = 0; i < target.length; i++) {
    const from = current.indexOf(target[i]!.id);
    if (from === i) continue;
    changes.push({ type: 'network.move', pou: pou.id, from, to: i });
    current.splice(i, 0, ...current.splice(from, 1));
  }
  return changes.length ? changes : undefined;
}

