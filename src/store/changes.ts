// Serialisable document changes: the unit of undo/redo. A command produces a list of changes;
// history keeps them (not project snapshots) and undoes them by applying their inverses in
// reverse order. Every change names its POU and, where relevant, its network by id.
import type { LdElement, VLink } from '../model/elements';
import type { NetworkId, PouId } from '../model/ids';
import type { Network, Pou, Project, Task, Variable } from '../model/project';

/** Network fields that are not its elements or vertical links. */
export type NetworkProps = Omit<Network, 'id' | 'elements' | 'vlinks'>;
export type ProjectProps = Pick<Project, 'name' | 'description' | 'profile' | 'scenarios' | 'dataTypes' | 'libraries' | 'onlineChange' | 'plant'>;
/** POU fields a command may change in place (an `undefined` value removes an optional field). */
export type PouProps = Pick<Pou, 'name' | 'comment' | 'kind' | 'returnType' | 'source'>;
/** 'globals' addresses the project's global variables instead of a POU's. */
export type VariableScope = PouId | 'globals';

export type Change =
  | {
      readonly type: 'element.add';
      readonly pou: PouId;
      readonly network: NetworkId;
      readonly index: number;
      readonly element: LdElement;
    }
  | {
      readonly type: 'element.remove';
      readonly pou: PouId;
      readonly network: NetworkId;
      readonly index: number;
      readonly element: LdElement;
    }
  | {
      readonly type: 'element.update';
      readonly pou: PouId;
      readonly network: NetworkId;
      readonly before: LdElement;
      readonly after: LdElement;
    }
  | {
      readonly type: 'vlink.add';
      readonly pou: PouId;
      readonly network: NetworkId;
      readonly index: number;
      readonly vlink: VLink;
    }
  | {
      readonly type: 'vlink.remove';
      readonly pou: PouId;
      readonly network: NetworkId;
      readonly index: number;
      readonly vlink: VLink;
    }
  | {
      readonly type: 'network.update';
      readonly pou: PouId;
      readonly network: NetworkId;
      readonly before: Partial<NetworkProps>;
      readonly after: Partial<NetworkProps>;
    }
  | { readonly type: 'network.add'; readonly pou: PouId; readonly index: number; readonly network: Network }
  | {
      readonly type: 'network.remove';
      readonly pou: PouId;
      readonly index: number;
      readonly network: Network;
    }
  | { readonly type: 'network.move'; readonly pou: PouId; readonly from: number; readonly to: number }
  | {
      readonly type: 'variable.add';
      readonly scope: VariableScope;
      readonly index: number;
      readonly variable: Variable;
    }
  | {
      readonly type: 'variable.remove';
      readonly scope: VariableScope;
      readonly index: number;
      readonly variable: Variable;
    }
  | {
      readonly type: 'variable.update';
      readonly scope: VariableScope;
      readonly index: number;
      readonly before: Variable;
      readonly after: Variable;
    }
  | {
      readonly type: 'project.update';
      readonly before: Partial<ProjectProps>;
      readonly after: Partial<ProjectProps>;
    }
  | {
      readonly type: 'pou.update';
      readonly pou: PouId;
      readonly before: Partial<PouProps>;
      readonly after: Partial<PouProps>;
    }
  | { readonly type: 'pou.add'; readonly index: number; readonly pou: Pou }
  | { readonly type: 'pou.remove'; readonly index: number; readonly pou: Pou }
  | { readonly type: 'tasks.update'; readonly before: readonly Task[]; readonly after: readonly Task[] };

export function invertChange(c: Change): Change {
  switch (c.type) {
    case 'element.add':
      return { ...c, type: 'element.remove' };
    case 'element.remove':
      return { ...c, type: 'element.add' };
    case 'element.update':
      return { ...c, before: c.after, after: c.before };
    case 'vlink.add':
      return { ...c, type: 'vlink.remove' };
    case 'vlink.remove':
      return { ...c, type: 'vlink.add' };
    case 'network.update':
      return { ...c, before: c.after, after: c.before };
    case 'network.add':
      return { ...c, type: 'network.remove' };
    case 'network.remove':
      return { ...c, type: 'network.add' };
    case 'network.move':
      return { ...c, from: c.to, to: c.from };
    case 'variable.add':
      return { ...c, type: 'variable.remove' };
    case 'variable.remove':
      return { ...c, type: 'variable.add' };
    case 'variable.update':
      return { ...c, before: c.after, after: c.before };
    case 'project.update':
      return { ...c, before: c.after, after: c.before };
    case 'pou.update':
      return { ...c, before: c.after, after: c.before };
    case 'pou.add':
      return { ...c, type: 'pou.remove' };
    case 'pou.remove':
      return { ...c, type: 'pou.add' };
    case 'tasks.update':
      return { ...c, before: c.after, after: c.before };
  }
}

/** The inverse of a list of changes: each inverted, in reverse order. */
export const invertChanges = (changes: readonly Change[]): Change[] => changes.map(invertChange).reverse();

const insertAt = <T>(list: readonly T[], index: number, item: T): T[] => {
  const out = list.slice();
  out.splice(Math.min(index, out.length), 0, item);
  return out;
};
const removeAt = <T>(list: readonly T[], index: number): T[] => {
  const out = list.slice();
  if (index >= 0 && index < out.length) out.splice(index, 1);
  return out;
};

function updateNetwork(
  project: Project,
  pouId: PouId,
  networkId: NetworkId,
  fn: (n: Network) => Network,
): Project {
  return updatePou(project, pouId, (pou) => ({
    ...pou,
    networks: pou.networks.map((n) => (n.id === networkId ? fn(n) : n)),
  }));
}

function updatePou(project: Project, pouId: PouId, fn: (p: Pou) => Pou): Project {
  const pous = project.pous.map((p) => (p.id === pouId ? fn(p) : p));
  return { ...project, pous };
}

function updateVariables(
  project: Project,
  scope: VariableScope,
  fn: (vars: readonly Variable[]) => Variable[],
): Project {
  if (scope === 'globals') return { ...project, globals: fn(project.globals) };
  return updatePou(project, scope, (pou) => ({ ...pou, variables: fn(pou.variables) }));
}

const sameVLink = (a: VLink, b: VLink) => a.row === b.row && a.boundary === b.boundary;

/** Applies one change; a change that does not fit the project (stale id) is an internal error. */
export function applyChange(project: Project, c: Change): Project {
  switch (c.type) {
    case 'element.add':
      return updateNetwork(project, c.pou, c.network, (n) => ({
        ...n,
        elements: insertAt(n.elements, c.index, c.element),
      }));
    case 'element.remove':
      return updateNetwork(project, c.pou, c.network, (n) => ({
        ...n,
        elements: n.elements.filter((e) => e.id !== c.element.id),
      }));
    case 'element.update':
      return updateNetwork(project, c.pou, c.network, (n) => ({
        ...n,
        elements: n.elements.map((e) => (e.id === c.before.id ? c.after : e)),
      }));
    case 'vlink.add':
      return updateNetwork(project, c.pou, c.network, (n) => ({
        ...n,
        vlinks: insertAt(n.vlinks, c.index, c.vlink),
      }));
    case 'vlink.remove':
      return updateNetwork(project, c.pou, c.network, (n) => ({
        ...n,
        vlinks: n.vlinks.filter((v) => !sameVLink(v, c.vlink)),
      }));
    case 'network.update':
      return updateNetwork(project, c.pou, c.network, (n) => withProps(n, c.after));
    case 'network.add':
      return updatePou(project, c.pou, (p) => ({ ...p, networks: insertAt(p.networks, c.index, c.network) }));
    case 'network.remove':
      return updatePou(project, c.pou, (p) => ({
        ...p,
        networks: p.networks.filter((n) => n.id !== c.network.id),
      }));
    case 'network.move':
      return updatePou(project, c.pou, (p) => {
        const moved = p.networks[c.from];
        if (!moved) return p;
        return { ...p, networks: insertAt(removeAt(p.networks, c.from), c.to, moved) };
      });
    case 'variable.add':
      return updateVariables(project, c.scope, (vars) => insertAt(vars, c.index, c.variable));
    case 'variable.remove':
      return updateVariables(project, c.scope, (vars) => removeAt(vars, c.index));
    case 'variable.update':
      return updateVariables(project, c.scope, (vars) => vars.map((v, i) => (i === c.index ? c.after : v)));
    case 'project.update': {
      // An undefined value removes an optional field (a project without a machine has no `plant`).
      const next: Record<string, unknown> = { ...project, ...c.after };
      for (const [k, v] of Object.entries(c.after)) if (v === undefined) delete next[k];
      return next as unknown as Project;
    }
    case 'pou.update':
      return updatePou(project, c.pou, (p) => withFields(p, c.after));
    case 'pou.add':
      return { ...project, pous: insertAt(project.pous, c.index, c.pou) };
    case 'pou.remove':
      return { ...project, pous: project.pous.filter((p) => p.id !== c.pou.id) };
    case 'tasks.update':
      return { ...project, tasks: c.after };
  }
}

/** Sets fields; an `undefined` value removes the optional field (label, collapsed, returnType...). */
function withFields<T extends object>(target: T, props: object): T {
  const out: Record<string, unknown> = { ...(target as Record<string, unknown>) };
  for (const [k, v] of Object.entries(props)) {
    if (v === undefined) delete out[k];
    else out[k] = v;
  }
  return out as T;
}
const withProps = (n: Network, props: Partial<NetworkProps>): Network => withFields(n, props);

export const applyChanges = (project: Project, changes: readonly Change[]): Project =>
  changes.reduce(applyChange, project);

/**
 * The changes that turn network `before` into `after` (same id). Elements are matched by id and
 * vertical links by position; survivors must keep their relative order (edits filter, map and
 * append, they never reorder), so removing, updating and then inserting reproduces `after`.
 */
export function diffNetwork(pou: PouId, before: Network, after: Network): Change[] {
  const network = before.id;
  const changes: Change[] = [];
  const afterIds = new Map(after.elements.map((e) => [e.id, e]));
  const beforeIds = new Map(before.elements.map((e) => [e.id, e]));
  for (let i = before.elements.length - 1; i >= 0; i--) {
    const el = before.elements[i]!;
    if (!afterIds.has(el.id)) changes.push({ type: 'element.remove', pou, network, index: i, element: el });
  }
  for (const el of after.elements) {
    const old = beforeIds.get(el.id);
    if (old && old !== el) changes.push({ type: 'element.update', pou, network, before: old, after: el });
  }
  after.elements.forEach((el, i) => {
    if (!beforeIds.has(el.id)) changes.push({ type: 'element.add', pou, network, index: i, element: el });
  });
  const has = (list: readonly VLink[], v: VLink) => list.some((w) => sameVLink(w, v));
  for (let i = before.vlinks.length - 1; i >= 0; i--) {
    const v = before.vlinks[i]!;
    if (!has(after.vlinks, v)) changes.push({ type: 'vlink.remove', pou, network, index: i, vlink: v });
  }
  after.vlinks.forEach((v, i) => {
    if (!has(before.vlinks, v)) changes.push({ type: 'vlink.add', pou, network, index: i, vlink: v });
  });
  const keys: (keyof NetworkProps)[] = [
    'label',
    'title',
    'comment',
    'rows',
    'cols',
    'collapsed',
    'extensions',
  ];
  const b: Record<string, unknown> = {};
  const a: Record<string, unknown> = {};
  for (const k of keys) {
    if (before[k] !== after[k]) {
      b[k] = before[k];
      a[k] = after[k];
    }
  }
  if (Object.keys(a).length > 0) {
    changes.push({
      type: 'network.update',
      pou,
      network,
      before: b as Partial<NetworkProps>,
      after: a as Partial<NetworkProps>,
    });
  }
  return changes;
}
