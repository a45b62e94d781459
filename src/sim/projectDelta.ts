// The document sent to the simulation worker as a difference from the one sent before it: an edit
// of one network of a 1,000-network program sends that network, not the whole project (whose
// copy into the worker, before any of its code runs, would hold up the scans). Documents are
// immutable, so what an edit did not touch is the same object in both: unchanged POUs and networks
// travel as their index in the base. The worker rebuilds the document from its copy of the base;
// the rebuilt one has the same program id (what runs is still checked against what is shown).
import type { Network, Pou, Project } from '../model/project';

/** A POU: unchanged (its index in the base), new or replaced whole, or its fields with networks by index where unchanged. */
export type PouDelta = number | { readonly pou: Pou } | { readonly fields: Omit<Pou, 'networks'>; readonly networks: readonly (number | Network)[] };

export interface ProjectDelta {
  /** Sequence number of the base document (the worker refuses a delta on another base). */
  readonly base: number;
  readonly fields: Omit<Project, 'pous'>;
  readonly pous: readonly PouDelta[];
}

/** `next` as a difference from `base`. */
export function diffProject(base: Project, baseSeq: number, next: Project): ProjectDelta {
  const { pous: _pous, ...fields } = next;
  const index = new Map(base.pous.map((p, i) => [p, i]));
  const byId = new Map(base.pous.map((p, i) => [p.id, { p, i }]));
  const pous = next.pous.map((pou): PouDelta => {
    const same = index.get(pou);
    if (same !== undefined) return same;
    const before = byId.get(pou.id);
    if (!before) return { pou };
    const networkIndex = new Map(before.p.networks.map((n, i) => [n, i]));
    const { networks, ...pouFields } = pou;
    return { fields: pouFields, networks: networks.map((n) => networkIndex.get(n) ?? n) };
  });
  return { base: baseSeq, fields, pous };
}

/** The document `delta` describes, from the base it was made against. */
export function applyDelta(base: Project, delta: ProjectDelta): Project {
  const pous = delta.pous.map((d): Pou => {
    if (typeof d === 'number') return at(base.pous, d);
    if ('pou' in d) return d.pou;
    const before = base.pous.find((p) => p.id === d.fields.id);
    if (!before) throw new Error(`the simulator's copy of the project has no POU ${d.fields.name}`);
    return { ...d.fields, networks: d.networks.map((n) => (typeof n === 'number' ? at(before.networks, n) : n)) };
  });
  return { ...delta.fields, pous };
}

function at<T>(list: readonly T[], i: number): T {
  const x = list[i];
  if (x === undefined) throw new Error(`the simulator's copy of the project has no item ${i}`);
  return x;
}
