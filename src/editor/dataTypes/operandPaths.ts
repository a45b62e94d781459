// Operands that name a member of a structure or an element of an array (`P.X`, `A[3]`,
// `G[1,2]`, `L.Pts[2].X`): what they resolve to, and the members offered by completion (after
// `P.` the list shows P's members). Over the model's leaves (src/model/dataTypes.ts leafPaths).
import { leafPaths, resolveType, type Leaf } from '../../model/dataTypes';
import { findVariable } from '../../model/factory';
import type { Pou, Project, Variable } from '../../model/project';

/** Leaves offered per variable at most (a huge array would flood the completion list). */
const MAX_OFFERED = 1000;

const rootOf = (text: string) => /^\s*([A-Za-z_][A-Za-z0-9_]*)/.exec(text)?.[1];

/** True when the variable's type is a structure or an array (its operands are member paths). */
export function isAggregateVariable(project: Project, v: Variable): boolean {
  const r = resolveType(project, v.type);
  return r.ok && (r.shape.kind === 'struct' || r.shape.kind === 'array');
}

/** Normalised path text: no spaces, as leafPaths writes it (`G[1,2]`). */
const normal = (text: string) => text.replace(/\s+/g, '');

export type MemberResolution =
  | { readonly status: 'declared'; readonly type: string }
  | { readonly status: 'other'; readonly message: string };

/**
 * What `P.X` / `A[3]` names when its root is a struct/array variable (the leaf's type: an enum
 * leaf answers its type name); undefined when the text is not such a path (plain names, FB pins).
 */
export function resolveMemberPath(project: Project, pou: Pou, text: string): MemberResolution | undefined {
  const root = rootOf(text);
  const path = normal(text);
  if (!root || path === root) return undefined;
  const v = findVariable(project, pou, root);
  if (!v || !isAggregateVariable(project, v)) return undefined;
  const r = leafPaths(project, v);
  if (!r.ok) return { status: 'other', message: r.message };
  const key = path.toUpperCase();
  const hit = r.leaves.find((l) => l.path.toUpperCase() === key);
  if (hit) return { status: 'declared', type: leafType(hit) };
  if (r.leaves.some((l) => l.path.toUpperCase().startsWith(key) && /^[.[]/.test(l.path.slice(key.length))))
    return { status: 'other', message: `"${path}" is a structure or array; name one of its values, e.g. ${firstUnder(r.leaves, key)}` };
  return { status: 'other', message: `${v.type} "${v.name}" has no value ${path.slice(root.length)} (e.g. ${r.leaves[0]?.path ?? v.name})` };
}

const leafType = (l: Leaf) => (l.enumValues ? l.typeName : l.type);
const firstUnder = (leaves: readonly Leaf[], key: string) => leaves.find((l) => l.path.toUpperCase().startsWith(key))?.path ?? '';

/** The members of struct/array variables whose type is one of `accepted` (enum values are not numbers). */
export function memberCandidates(
  project: Project,
  variables: readonly Variable[],
  accepted: ReadonlySet<string>,
): { text: string; type: string; detail: string }[] {
  const out: { text: string; type: string; detail: string }[] = [];
  for (const v of variables) {
    if (!isAggregateVariable(project, v)) continue;
    const r = leafPaths(project, v);
    if (!r.ok) continue;
    let offered = 0;
    for (const l of r.leaves) {
      if (l.enumValues || !accepted.has(l.type)) continue;
      out.push({ text: l.path, type: l.type, detail: `member of ${v.type}` });
      if (++offered >= MAX_OFFERED) break;
    }
  }
  return out;
}
