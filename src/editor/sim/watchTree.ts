// The watch table's tree: a watched structure, array (or FB instance) is not a value itself; its
// members are the readable names under it (`P.X`, `A[2]`, `S.Pts[1].X`), shown as tree rows.
// Also: which struct/array variables the add-to-watch field offers, and the values of an
// enumeration leaf (shown and written by name). Pure functions.
import { leafPaths, resolveType, type Leaf } from '../../model/dataTypes';
import type { Project, Variable } from '../../model/project';
import type { SimVariable } from '../../sim/protocol';

export interface WatchNode {
  /** The whole path (`P.Pts[1]`). */
  readonly path: string;
  /** What the row shows: the last segment (`.X`, `[1]`). */
  readonly label: string;
  /** The readable leaf, when the node is one. */
  readonly leaf?: SimVariable;
  readonly children: readonly WatchNode[];
}

const SEGMENT = /^(\.[A-Za-z_][A-Za-z0-9_]*|\[[^\]]*\])/;

/** The members under `root` (a name that is not itself readable), as a tree; empty when none. */
export function watchTree(root: string, candidates: readonly SimVariable[]): WatchNode[] {
  const key = root.toUpperCase();
  const under = candidates.filter((c) => {
    const n = c.name.toUpperCase();
    return n.length > key.length && n.startsWith(key) && (n[key.length] === '.' || n[key.length] === '[');
  });
  return build(root, under);
}

function build(prefix: string, under: readonly SimVariable[]): WatchNode[] {
  const groups = new Map<string, { label: string; items: SimVariable[]; leaf?: SimVariable }>();
  for (const c of under) {
    const rest = c.name.slice(prefix.length);
    const seg = SEGMENT.exec(rest)?.[1];
    if (!seg) continue;
    const k = seg.toUpperCase();
    const g = groups.get(k) ?? { label: seg, items: [] };
    if (rest.length === seg.length) g.leaf = c;
    else g.items.push(c);
    groups.set(k, g);
  }
  return [...groups.values()].map((g) => {
    const path = `${prefix}${g.label}`;
    return { path, label: g.label, ...(g.leaf ? { leaf: g.leaf } : {}), children: g.leaf ? [] : build(path, g.items) };
  });
}

/** Every leaf under a tree (for counting). */
export const leafCount = (nodes: readonly WatchNode[]): number =>
  nodes.reduce((n, x) => n + (x.leaf ? 1 : leafCount(x.children)), 0);

/** Variables of the project (any POU, the globals) by upper-case name, first declaration wins. */
function declarations(project: Project): Map<string, Variable> {
  const out = new Map<string, Variable>();
  for (const v of [...project.globals, ...project.pous.flatMap((p) => p.variables)])
    if (!out.has(v.name.toUpperCase())) out.set(v.name.toUpperCase(), v);
  return out;
}

const rootOf = (name: string) => /^[A-Za-z_][A-Za-z0-9_]*/.exec(name)?.[0] ?? name;

/**
 * The struct and array variables among the readable names' roots (`P` for `P.X`), to offer in
 * the add-to-watch field: a variable of such a type is watched as a tree of its members.
 */
export function aggregateCandidates(project: Project, candidates: readonly SimVariable[]): SimVariable[] {
  const decls = declarations(project);
  const known = new Set(candidates.map((c) => c.name.toUpperCase()));
  const out = new Map<string, SimVariable>();
  for (const c of candidates) {
    const root = rootOf(c.name);
    const k = root.toUpperCase();
    if (root === c.name || known.has(k) || out.has(k)) continue;
    const v = decls.get(k);
    const r = v ? resolveType(project, v.type) : undefined;
    if (v && r?.ok && (r.shape.kind === 'struct' || r.shape.kind === 'array'))
      out.set(k, { name: v.name, type: v.type, role: 'local' });
  }
  return [...out.values()];
}

const leafCache = new WeakMap<Project, Map<string, Map<string, Leaf>>>();

/** The model's leaf (with enum values, declared type name) behind a readable path, or undefined. */
export function modelLeaf(project: Project, path: string): Leaf | undefined {
  const root = rootOf(path).toUpperCase();
  let byRoot = leafCache.get(project);
  if (!byRoot) leafCache.set(project, (byRoot = new Map()));
  let leaves = byRoot.get(root);
  if (!leaves) {
    const v = declarations(project).get(root);
    const r = v ? leafPaths(project, v) : undefined;
    leaves = new Map(r?.ok ? r.leaves.map((l) => [l.path.toUpperCase(), l]) : []);
    byRoot.set(root, leaves);
  }
  return leaves.get(path.replace(/\s+/g, '').toUpperCase());
}

/** An enumeration leaf's value (its index) as the value's name: `GREEN`. */
export function enumText(leaf: Leaf | undefined, text: string | undefined): string | undefined {
  if (!leaf?.enumValues || text === undefined || !/^\d+$/.test(text)) return text;
  return leaf.enumValues[Number(text)] ?? text;
}
