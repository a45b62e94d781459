// On a ladder grid every point of a wire joins everything drawn there, so two inputs that share
// some but not all of their sources (A feeds X and Y, B feeds only X) cannot be drawn as wired in
// the file. PLCopen graphs allow it. Rungsmith redraws such wiring by duplicating the shared
// contacts (a contact only reads its variable, so a copy behaves the same) — as a PLC programmer
// would draw it.
import type { Finding, GNode, GSource } from './ldNodes';

/** A source as a string key (the rail, or node and pin). */
export const srcKey = (s: GSource) => (s.kind === 'rail' ? 'R' : `${s.node}>${s.pin}`);

export function splitSharedSources(nodes: GNode[], warn: (f: Finding) => void): void {
  for (let round = 0; round < 4; round++) if (!splitOnce(nodes, warn)) return;
}

const sameSource = (a: GSource, b: GSource): boolean =>
  a.kind === 'rail' ? b.kind === 'rail' : b.kind !== 'rail' && a.node === b.node && a.pin === b.pin;

/** True when some source feeds two input pins whose source lists differ (the only case to redraw). */
function anyMismatch(nodes: readonly GNode[]): boolean {
  // Sources keyed by number (node and pin number), not by string: this looks at every wire of the file.
  const pinIds = new Map<string, number>();
  const firstUse = new Map<number, readonly GSource[]>();
  for (const n of nodes) {
    for (const srcs of n.inputs.values()) {
      for (const s of srcs) {
        if (s.kind === 'rail') continue;
        let pid = pinIds.get(s.pin);
        if (pid === undefined) pinIds.set(s.pin, (pid = pinIds.size));
        const k = s.node * 0x100000 + pid;
        const prev = firstUse.get(k);
        if (!prev) firstUse.set(k, srcs);
        else if (
          prev !== srcs &&
          (prev.length !== srcs.length || prev.some((p, i) => !sameSource(p, srcs[i]!)))
        )
          return true;
      }
    }
  }
  return false;
}

function splitOnce(nodes: GNode[], warn: (f: Finding) => void): boolean {
  if (!anyMismatch(nodes)) return false;
  const parent = new Map<string, string>();
  const find = (k: string): string => {
    let r = k;
    for (let p = parent.get(r); p !== undefined && p !== r; p = parent.get(r)) r = p;
    return r;
  };
  const union = (a: string, b: string) => {
    if (!parent.has(a)) parent.set(a, a);
    if (!parent.has(b)) parent.set(b, b);
    const ra = find(a);
    const rb = find(b);
    if (ra !== rb) parent.set(ra, rb);
  };
  for (const n of nodes)
    for (const [pin, srcs] of n.inputs) for (const s of srcs) union(`${n.index}<${pin}`, srcKey(s));
  // Consumers per net.
  const byNet = new Map<string, { node: GNode; pin: string; key: string; srcs: GSource[] }[]>();
  for (const n of nodes)
    for (const [pin, srcs] of n.inputs) {
      if (!srcs.length) continue;
      const root = find(`${n.index}<${pin}`);
      let list = byNet.get(root);
      if (!list) byNet.set(root, (list = []));
      list.push({ node: n, pin, key: srcs.map(srcKey).sort().join(' '), srcs });
    }
  let changed = false;
  for (const consumers of byNet.values()) {
    const groups = new Map<string, typeof consumers>();
    for (const c of consumers) {
      let g = groups.get(c.key);
      if (!g) groups.set(c.key, (g = []));
      g.push(c);
    }
    if (groups.size < 2) continue;
    const ordered = [...groups.values()].sort(
      (a, b) => b.length - a.length || b[0]!.srcs.length - a[0]!.srcs.length,
    );
    for (const group of ordered.slice(1)) {
      const outside = new Set(consumers.filter((c) => !group.includes(c)).flatMap((c) => c.srcs.map(srcKey)));
      const copies = new Map<string, GSource>();
      for (const s of group[0]!.srcs) {
        const k = srcKey(s);
        if (!outside.has(k) || s.kind === 'rail') continue;
        const orig = nodes[s.node]!;
        if (orig.kind !== 'contact') continue; // not copyable: verification reports it
        const copy: GNode = {
          ...orig,
          index: nodes.length,
          inputs: new Map([...orig.inputs].map(([p, v]) => [p, [...v]])),
          operandsIn: { ...orig.operandsIn },
          operandsOut: { ...orig.operandsOut },
          feedsRightRail: false,
          y: orig.y + 0.5,
        };
        nodes.push(copy);
        copies.set(k, { kind: 'node', node: copy.index, pin: s.pin });
        warn({
          message: `contact "${orig.variable}" drawn twice so that the ladder grid shows the file's wiring exactly`,
          obj: orig.obj,
        });
      }
      if (!copies.size) continue;
      changed = true;
      // The group reads the copies from now on: a later group that is the last to read a
      // source keeps the original (copying it too would leave the original feeding nothing).
      for (const c of group) {
        c.srcs = c.srcs.map((s) => copies.get(srcKey(s)) ?? s);
        c.node.inputs.set(c.pin, c.srcs);
      }
    }
  }
  return changed;
}
