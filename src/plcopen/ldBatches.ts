// Splitting a large LD body into batches of whole networks, read straight from the XML document
// (no objects per element). Each batch is then read, interpreted and laid out on its own, so the
// objects of one batch are garbage before the next is read: a 10,000-network body never has all
// its objects and graph nodes alive at once. Wires are followed as written (continuations join
// their connectors); rails do not join networks, they are added to every batch that uses them.
import type { XmlElement } from './xml/parse';

export interface BodyPlan {
  /** Element index (in the document) of each child of the body, in file order. */
  readonly children: Int32Array;
  /** Whether any object of the body has a position other than 0,0. */
  readonly hasGeometry: boolean;
  /** Child positions (indices into `children`) of each batch, ascending. */
  readonly batches: readonly (readonly number[])[];
  /** Child position of a localId, if the body has it. */
  readonly positionOf: (localId: string) => number | undefined;
}

/**
 * Objects per batch. Small enough that a batch is read and laid out between two collections of
 * the young generation, so its objects die there instead of being copied to the old one (with
 * 2,048 the 10,000-network benchmark promoted three times as much and ran 25% slower); large
 * enough that the work per batch stays negligible.
 */
export const BATCH_OBJECTS = 256;

export function planBody(body: XmlElement, batchObjects = BATCH_OBJECTS): BodyPlan {
  const d = body.doc;
  const ids = {
    localId: d.id('localId'),
    refLocalId: d.id('refLocalId'),
    connection: d.id('connection'),
    position: d.id('position'),
    x: d.id('x'),
    y: d.id('y'),
    name: d.id('name'),
    leftPowerRail: d.id('leftPowerRail'),
    rightPowerRail: d.id('rightPowerRail'),
    connector: d.id('connector'),
    continuation: d.id('continuation'),
  };
  const list: number[] = [];
  for (let c = d.firstChild[body.index]!; c !== -1; c = d.nextSibling[c]!) list.push(c);
  const children = Int32Array.from(list);
  const n = children.length;

  // localIds as numbers when all are plain integers (nearly every file), else as strings.
  const numeric = new Int32Array(n);
  let allNumeric = true;
  let maxId = 0;
  let hasGeometry = false;
  const isRail = new Uint8Array(n);
  for (let p = 0; p < n; p++) {
    const el = children[p]!;
    const v = d.attrIndexNumber(el, ids.localId);
    numeric[p] = v;
    if (v === -1 && d.attrIndex(el, ids.localId) !== -1) allNumeric = false;
    if (v > maxId) maxId = v;
    const lid = d.lid[el]!;
    if (lid === ids.leftPowerRail || lid === ids.rightPowerRail) isRail[p] = 1;
    if (!hasGeometry) {
      const pos = d.childById(el, ids.position);
      if (pos !== -1 && (d.attrNumber(pos, ids.x) !== 0 || d.attrNumber(pos, ids.y) !== 0))
        hasGeometry = true;
    }
  }
  // Position of each localId (the first object with it: a repeated one is reported when its batch is read).
  const byNumber = allNumeric ? new Int32Array(maxId + 1).fill(-1) : undefined;
  const byString = allNumeric ? undefined : new Map<string, number>();
  /** Position of the object an attribute (localId, refLocalId) of element `el` names, or -1. */
  const named = (el: number, attr: number): number => {
    if (byNumber) {
      const v = d.attrIndexNumber(el, attr);
      return v === -1 || v >= byNumber.length ? -1 : byNumber[v]!;
    }
    const s = d.attr(el, attr);
    return s === undefined ? -1 : (byString!.get(s) ?? -1);
  };
  for (let p = 0; p < n; p++) {
    if (byNumber) {
      const v = numeric[p]!;
      if (v !== -1 && byNumber[v] === -1) byNumber[v] = p;
    } else {
      const s = d.attr(children[p]!, ids.localId);
      if (s !== undefined && s !== '' && !byString!.has(s)) byString!.set(s, p);
    }
  }
  const positionOf = (ref: string): number | undefined => {
    if (byString) return byString.get(ref);
    if (!/^(0|[1-9][0-9]{0,8})$/.test(ref)) return undefined;
    const p = byNumber![+ref];
    return p === undefined || p === -1 ? undefined : p;
  };

  const parent = new Int32Array(n);
  for (let p = 0; p < n; p++) parent[p] = p;
  const find = (a: number): number => {
    while (parent[a] !== a) {
      parent[a] = parent[parent[a]!]!;
      a = parent[a]!;
    }
    return a;
  };
  const union = (a: number, b: number): void => {
    const ra = find(a);
    const rb = find(b);
    if (ra !== rb) parent[Math.max(ra, rb)] = Math.min(ra, rb);
  };
  // Rails used by an object: [object position, rail position] pairs, resolved after the unions.
  const railUse: number[] = [];
  // A repeated localId joins its objects: the batch that reads them reports it.
  for (let p = 0; p < n; p++) {
    const first = byNumber
      ? numeric[p] === -1
        ? -1
        : byNumber[numeric[p]!]!
      : named(children[p]!, ids.localId);
    if (first === -1 || first === p) continue;
    if (isRail[first] || isRail[p]) railUse.push(isRail[p] ? first : p, isRail[p] ? p : first);
    else union(first, p);
  }
  const connectors = new Map<string, number[]>();
  const continuations: number[] = [];
  // Elements are numbered in document order, so the descendants of a child of the body are the
  // elements numbered from it to the next child (to the end of the body for the last one).
  let bodyEnd = body.index;
  for (let last = bodyEnd; last !== -1;) {
    bodyEnd = last;
    last = -1;
    for (let c = d.firstChild[bodyEnd]!; c !== -1; c = d.nextSibling[c]!) last = c;
  }
  bodyEnd++;
  for (let p = 0; p < n; p++) {
    const el = children[p]!;
    const lid = d.lid[el]!;
    if (lid === ids.connector || lid === ids.continuation) {
      const name = (d.attr(el, ids.name) ?? '').toUpperCase();
      if (lid === ids.connector) {
        let same = connectors.get(name);
        if (!same) connectors.set(name, (same = []));
        same.push(p);
      } else continuations.push(p);
    }
    // Every <connection> inside the object, at any depth (block pins nest them).
    const to = p + 1 < n ? children[p + 1]! : bodyEnd;
    for (let e = el + 1; e < to; e++) {
      if (d.lid[e] !== ids.connection) continue;
      const t = named(e, ids.refLocalId);
      if (t === -1 || t === p) continue;
      if (isRail[p]) railUse.push(t, p);
      else if (isRail[t]) railUse.push(p, t);
      else union(p, t);
    }
  }
  for (const p of continuations) {
    const name = (d.attr(children[p]!, ids.name) ?? '').toUpperCase();
    for (const c of connectors.get(name) ?? []) union(p, c);
  }

  // Components in file order of their first object, then batches of whole components.
  const rails = new Map<number, number[]>();
  for (let k = 0; k < railUse.length; k += 2) {
    const root = find(railUse[k]!);
    let r = rails.get(root);
    if (!r) rails.set(root, (r = []));
    r.push(railUse[k + 1]!);
  }
  const members = new Map<number, number[]>();
  for (let p = 0; p < n; p++) {
    const root = find(p);
    let m = members.get(root);
    if (!m) members.set(root, (m = []));
    m.push(p);
  }
  const batches: number[][] = [];
  let current: number[] = [];
  let extra = new Set<number>();
  const close = () => {
    if (!current.length) return;
    for (const r of extra) current.push(r);
    batches.push([...new Set(current)].sort((a, b) => a - b));
    current = [];
    extra = new Set<number>();
  };
  for (const [root, m] of members) {
    for (const p of m) current.push(p);
    for (const r of rails.get(root) ?? []) extra.add(r);
    if (current.length >= batchObjects) close();
  }
  close();
  return { children, hasGeometry, batches, positionOf };
}
