// An LD body → the networks of a POU: connected components ordered like Beremiz runs them
// (executionOrderId first, then top to bottom), labels and comments attached to the network below.
import type { LdElement } from '../model/elements';
import { newNetwork } from '../model/factory';
import type { Network } from '../model/project';
import { gridGraph, type Source } from './gridGraph';
import { prepareLayout } from './layout';
import type { LaidOut } from './layoutShapes';
import { buildLdGraph, type Finding, type GNode, type GSource } from './ldGraph';
import { splitSharedSources } from './ldNormalize';
import { readLdObjects, type RawObject } from './ldObjects';
import { RS_NETWORK, type PreservedNetwork } from './types';
import { child, childrenNamed, type XmlElement } from './xml/parse';

export interface BodyResult {
  readonly networks: Network[];
}

const MIN_COLS = 3;

interface Group {
  readonly nodes: number[];
  readonly key: readonly number[];
  readonly kind: 'network' | 'label' | 'comment' | 'vendor';
  readonly obj?: RawObject;
}

function compareKeys(a: readonly number[], b: readonly number[]): number {
  for (let i = 0; i < Math.max(a.length, b.length); i++) {
    const d = (a[i] ?? 0) - (b[i] ?? 0);
    if (d) return d;
  }
  return 0;
}

/** Imports one LD body into networks. Throws LdGraphError for broken references. */
export function importLdBody(
  body: XmlElement,
  raw: (el: XmlElement) => string,
  warn: (f: Finding) => void,
): BodyResult {
  const objects = readLdObjects(body);
  const graph = buildLdGraph(objects, raw, warn);
  splitSharedSources(graph.nodes, warn);
  const { nodes } = graph;
  const hasGeometry = objects.some((o) => o.pos.x !== 0 || o.pos.y !== 0);

  // Connected components over wires between nodes (rails do not join networks).
  const parent = nodes.map((_, i) => i);
  const find = (a: number): number => {
    while (parent[a] !== a) {
      parent[a] = parent[parent[a]!]!;
      a = parent[a]!;
    }
    return a;
  };
  for (const n of nodes)
    n.inputs.forEach((srcs) => {
      for (const s of srcs) if (s.kind === 'node') parent[find(n.index)] = find(s.node);
    });
  const comps = new Map<number, number[]>();
  for (const n of nodes) {
    const r = find(n.index);
    let list = comps.get(r);
    if (!list) comps.set(r, (list = []));
    list.push(n.index);
  }
  const keyOf = (objs: readonly { obj: RawObject; order: number }[]): number[] => {
    let eo = Infinity;
    let y = Infinity;
    let x = Infinity;
    let order = Infinity;
    for (const o of objs) {
      if (o.obj.executionOrderId > 0 && o.obj.executionOrderId < eo) eo = o.obj.executionOrderId;
      if (o.obj.pos.y < y) y = o.obj.pos.y;
      if (o.obj.pos.x < x) x = o.obj.pos.x;
      if (o.order < order) order = o.order;
    }
    if (eo !== Infinity) return [0, eo];
    return hasGeometry ? [1, y, x] : [1, order];
  };
  const groups: Group[] = [];
  for (const list of comps.values())
    groups.push({
      nodes: list,
      kind: 'network',
      key: keyOf(list.map((i) => ({ obj: nodes[i]!.obj, order: nodes[i]!.obj.order }))),
    });
  const single = (o: RawObject, kind: Group['kind'], lift: number): Group => {
    const k = keyOf([{ obj: o, order: o.order }]);
    // A label or comment drawn beside the first row of its network still belongs to it.
    if (hasGeometry && k[0] === 1) k[1] = k[1]! - lift;
    return { nodes: [], kind, key: k, obj: o };
  };
  for (const o of graph.labels) groups.push(single(o, 'label', 20));
  for (const o of graph.comments) groups.push(single(o, 'comment', 20));
  for (const o of graph.vendor) groups.push(single(o, 'vendor', 20));
  groups.sort((a, b) => compareKeys(a.key, b.key));

  // Every network of the POU shares one width, coils on one right rail. Networks are laid out at
  // the widest width seen so far; the few laid out before a wider one came are laid out again at
  // the end (measuring every network first would lay each one out twice).
  let cols = MIN_COLS;
  const networks: Network[] = [];
  /** Laid-out networks: their group, position in `networks` and the wiring findings of their layout. */
  const laidOut: { group: Group; at: number; findings: Finding[] }[] = [];
  let pendingLabel: RawObject | undefined;
  let pendingComments: RawObject[] = [];
  let pendingVendor: string[] = [];
  const flushEmpty = () => {
    if (!pendingLabel) return;
    networks.push(newNetwork({ rows: 1, cols, label: pendingLabel.text, ...commentsOf(pendingComments) }));
    pendingLabel = undefined;
    pendingComments = [];
  };
  const layOut = (g: Group, width: number, base: Partial<Network>, findings: Finding[]): Network => {
    const prepared = prepareLayout(nodes, g.nodes);
    cols = Math.max(cols, prepared.needCols);
    const laid = prepared.run(Math.max(width, prepared.needCols));
    findings.length = 0;
    verify(nodes, g.nodes, laid, (f) => findings.push(f));
    const data = elementData(nodes, g.nodes, laid);
    const { extensions, ...rest } = base;
    const objects = (extensions?.plcopen as PreservedNetwork | undefined)?.objects;
    const keep: PreservedNetwork = { ...(objects ? { objects } : {}), ...data };
    return {
      ...rest,
      rows: laid.rows,
      cols: laid.cols,
      elements: laid.elements,
      vlinks: laid.vlinks,
      ...(keep.objects || keep.elementData ? { extensions: { plcopen: keep } } : {}),
    } as Network;
  };
  for (const g of groups) {
    if (g.kind === 'label') {
      flushEmpty();
      pendingLabel = g.obj;
      continue;
    }
    if (g.kind === 'comment') {
      pendingComments.push(g.obj!);
      continue;
    }
    if (g.kind === 'vendor') {
      pendingVendor.push(raw(g.obj!.xml));
      continue;
    }
    const base = newNetwork({
      ...(pendingLabel ? { label: pendingLabel.text } : {}),
      ...commentsOf(pendingComments),
      ...(pendingVendor.length ? { extensions: { plcopen: { objects: pendingVendor } } } : {}),
    });
    const findings: Finding[] = [];
    laidOut.push({ group: g, at: networks.length, findings });
    networks.push(layOut(g, cols, base, findings));
    pendingLabel = undefined;
    pendingComments = [];
    pendingVendor = [];
  }
  for (const l of laidOut) {
    const net = networks[l.at]!;
    if (net.cols < cols) networks[l.at] = layOut(l.group, cols, net, l.findings);
    for (const f of l.findings) warn(f);
  }
  for (let k = 0; k < networks.length; k++)
    if (networks[k]!.cols < cols) networks[k] = { ...networks[k]!, cols };
  flushEmpty();
  if (pendingComments.length || pendingVendor.length) {
    const last = networks.pop();
    const extra = commentsOf(pendingComments);
    const keep: PreservedNetwork = { objects: pendingVendor };
    if (last) {
      networks.push({
        ...last,
        comment: [last.comment, extra.comment].filter(Boolean).join('\n'),
        title: last.title || extra.title,
        ...(pendingVendor.length
          ? { extensions: { plcopen: { ...(last.extensions?.plcopen as object), objects: pendingVendor } } }
          : {}),
      });
    } else
      networks.push(
        newNetwork({
          rows: 1,
          cols,
          ...extra,
          ...(pendingVendor.length ? { extensions: { plcopen: keep } } : {}),
        }),
      );
  }
  return { networks };
}

function commentsOf(list: readonly RawObject[]): { comment: string; title: string } {
  let title = '';
  const texts: string[] = [];
  for (const o of list) {
    const add = o.hasAddData ? child(o.xml, 'addData') : undefined;
    const mine = add ? childrenNamed(add, 'data').find((d) => d.attrs.name === RS_NETWORK) : undefined;
    const t = mine?.children[0]?.attrs.title;
    if (t) title = t;
    if (o.text) texts.push(o.text);
  }
  return { comment: texts.join('\n'), title };
}

function elementData(
  nodes: readonly GNode[],
  members: readonly number[],
  laid: LaidOut,
): Pick<PreservedNetwork, 'elementData'> {
  const out: Record<string, readonly string[]> = {};
  for (const i of members) {
    const d = nodes[i]!.data;
    const id = laid.elementOf.get(i);
    if (d && id) out[id] = d;
  }
  return Object.keys(out).length ? { elementData: out } : {};
}

const describe = (n: GNode): string => {
  switch (n.kind) {
    case 'contact':
      return n.contact === 'NOT' ? 'NOT contact' : `contact "${n.variable}"`;
    case 'coil':
      return `coil "${n.variable}"`;
    case 'box':
      return `block ${n.instance ?? n.blockType}`;
    case 'jump':
      return `jump to ${n.target}`;
    case 'return':
      return 'return';
  }
};

/** Checks that the grid draws exactly the wiring of the file; reports elements whose inputs differ. */
function verify(
  nodes: readonly GNode[],
  members: readonly number[],
  laid: LaidOut,
  warn: (f: Finding) => void,
): void {
  const g = gridGraph(laid);
  const indexOfElement = new Map<string, number>();
  laid.elements.forEach((e: LdElement, i) => indexOfElement.set(e.id, i));
  const nodeOfElement = new Map<number, number>();
  for (const i of members) {
    const id = laid.elementOf.get(i);
    if (id) nodeOfElement.set(indexOfElement.get(id)!, i);
  }
  const memberSet = new Set(members);
  for (const i of members) {
    const n = nodes[i]!;
    const ei = indexOfElement.get(laid.elementOf.get(i)!);
    if (ei === undefined) continue;
    const drawn = g.sources.get(ei);
    // The pins wired in the file, then those only drawn; the first that differs is reported.
    let bad: string | undefined;
    for (const pin of n.inputs.keys())
      if (pinDiffers(n, pin, drawn, memberSet, nodeOfElement)) {
        bad = pin;
        break;
      }
    if (bad === undefined && drawn)
      for (const pin of drawn.keys())
        if (!n.inputs.has(pin) && pinDiffers(n, pin, drawn, memberSet, nodeOfElement)) {
          bad = pin;
          break;
        }
    if (bad !== undefined)
      warn({
        message: `${describe(n)}${bad === 'in' || bad === 'out' ? '' : ` pin ${bad}`}: this wiring cannot be drawn exactly on the ladder grid; check its connections`,
        obj: n.obj,
      });
  }
}

/** Whether the sources of a pin in the file (within the network) differ from those the grid draws. */
function pinDiffers(
  n: GNode,
  pin: string,
  drawn: Map<string, Source[]> | undefined,
  memberSet: ReadonlySet<number>,
  nodeOfElement: ReadonlyMap<number, number>,
): boolean {
  const wantList = (n.inputs.get(pin) ?? []).filter((s) => s.kind === 'rail' || memberSet.has(s.node));
  const gotList = drawn?.get(pin) ?? [];
  // One source each (most pins): compare directly, without building keys or sets.
  if (wantList.length === 1 && gotList.length === 1) {
    const want = wantList[0]!;
    const got = gotList[0]!;
    if (want.kind === 'rail' || got.kind === 'rail') return want.kind !== got.kind;
    return want.node !== nodeOfElement.get(got.el) || want.pin !== got.pin;
  }
  const key = (s: Source | GSource): string => {
    if (s.kind === 'rail') return 'rail';
    if (s.kind === 'pin') return `${nodeOfElement.get(s.el)}:${s.pin}`;
    return `${s.node}:${s.pin}`;
  };
  return !sameSet(new Set(wantList.map(key)), new Set(gotList.map(key)));
}

function sameSet(a: ReadonlySet<string>, b: ReadonlySet<string>): boolean {
  if (a.size !== b.size) return false;
  for (const k of a) if (!b.has(k)) return false;
  return true;
}
