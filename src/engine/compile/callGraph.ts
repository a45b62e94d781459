// Which POUs a POU uses (calls from its networks, FB instances in its variables), the POUs a
// program reaches, and recursion (LD-E21): a POU that uses itself, directly or through others,
// would have no end (an FB instance inside itself, a call that never returns), so it is refused.
import type { BoxElement } from '../../model/elements';
import { blockLibrary } from '../../model/library';
import type { Pou, Project } from '../../model/project';
import type { Diagnostic } from '../api';
import { Reporter } from './report';
import { calledNames } from '../st/index';
import { yieldPoint } from '../yieldPoint';

interface Use {
  readonly callee: Pou;
  /** The box that calls it (network index), or the variable that instantiates it. */
  readonly network: number;
  readonly box?: BoxElement;
  readonly variable?: string;
}

/** The user POUs a POU uses, in document order: its FB instance variables, then its boxes. */
export function usesOf(project: Project, pou: Pou): Use[] {
  const lib = blockLibrary(project);
  const out: Use[] = [];
  for (const v of pou.variables) {
    const callee = lib.userPou(v.type);
    if (callee && callee.kind === 'FUNCTION_BLOCK' && v.varClass !== 'external')
      out.push({ callee, network: -1, variable: v.name });
  }
  // ST and IL bodies: the functions (and instances) their text calls.
  if (pou.language === 'ST' || pou.language === 'IL')
    for (const name of calledNames(pou)) {
      const callee = lib.userPou(name);
      if (callee && callee.kind === 'FUNCTION' && !out.some((u) => u.callee === callee)) out.push({ callee, network: -1 });
    }
  pou.networks.forEach((net, i) => {
    for (const el of net.elements) {
      if (el.kind !== 'box') continue;
      const callee = lib.userPou(el.blockType);
      if (callee) out.push({ callee, network: i, box: el });
    }
    // Between pieces of 64 networks, the simulator runs the scans that fell due (yieldPoint.ts).
    if ((i & 63) === 63) yieldPoint();
  });
  return out;
}

/** The user FBs and functions reachable from `roots` (not the roots), in discovery order. */
export function reachablePous(project: Project, roots: readonly Pou[]): Pou[] {
  const seen = new Set<Pou>(roots);
  const out: Pou[] = [];
  const queue = [...roots];
  while (queue.length) {
    const p = queue.shift()!;
    for (const u of usesOf(project, p))
      if (!seen.has(u.callee)) {
        seen.add(u.callee);
        out.push(u.callee);
        queue.push(u.callee);
      }
  }
  return out;
}

/** LD-E21 for every use that closes a cycle, among `pous` (default: every POU). */
export function checkRecursion(project: Project, out: Diagnostic[], pous: readonly Pou[] = project.pous): boolean {
  const uses = new Map<Pou, Use[]>();
  for (const p of project.pous) uses.set(p, usesOf(project, p));
  const only = new Set(pous);
  let found = false;
  for (const p of project.pous) {
    if (!only.has(p)) continue;
    for (const u of uses.get(p)!) {
      const back = pathTo(uses, u.callee, p);
      if (!back) continue;
      found = true;
      const cycle = [p, ...back].map((x) => x.name).join(' → ');
      const r = new Reporter(out, p.name, u.network, u.network >= 0 ? p.networks[u.network]!.label?.trim() : undefined);
      const what = u.box
        ? `the ${u.box.blockType} block${u.box.instance ? ` "${u.box.instance}"` : ''}`
        : u.variable !== undefined
          ? `the variable "${u.variable}" (a ${u.callee.name} instance)`
          : `the call of ${u.callee.name} in its ${p.language} body`;
      r.error(
        'LD-E21',
        `${what} makes ${p.name} use itself (${cycle}); a POU cannot call itself, directly or through others`,
        u.box,
      );
    }
  }
  return found;
}

/** A path of uses from `from` to `to` (the POUs after `from`, ending with `to`), if any. */
function pathTo(uses: ReadonlyMap<Pou, Use[]>, from: Pou, to: Pou): Pou[] | undefined {
  const prev = new Map<Pou, Pou | undefined>([[from, undefined]]);
  const queue = [from];
  while (queue.length) {
    const p = queue.shift()!;
    if (p === to) {
      const path: Pou[] = [];
      for (let x: Pou | undefined = p; x; x = prev.get(x)) path.unshift(x);
      return path;
    }
    for (const u of uses.get(p) ?? [])
      if (!prev.has(u.callee)) {
        prev.set(u.callee, p);
        queue.push(u.callee);
      }
  }
  return undefined;
}
