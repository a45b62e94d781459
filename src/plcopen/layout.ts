// Graph → grid: lays out one network from its wiring, not from coordinates (CODESYS files have none).
// Columns: longest path from the left rail (each net gets one vertical bar at the boundary where its
// last producer ends); coils, jumps and returns are pushed to the right rail. Rows: depth-first along
// the branches — a series element continues its source's row, parallel branches and fan-out go to the
// first row below where their cells, links and bars cross nothing of another net.
import type { GNode } from './ldGraph';
import { placeRows } from './layoutRows';
import { shapeOf, type LaidOut, type Net, type PinSpec, type Shape } from './layoutShapes';

export interface Prepared {
  readonly nodes: readonly number[];
  readonly needCols: number;
  readonly run: (cols: number) => LaidOut;
}

/** Prepares the layout of the nodes of one network: columns now, rows when the width is known. */
export function prepareLayout(all: readonly GNode[], members: readonly number[]): Prepared {
  const shapes = new Map<number, Shape>();
  for (const i of members) shapes.set(i, shapeOf(all[i]!));
  // Nets: union of each wired input pin with its sources. Ports are numbered: 0 is the left rail,
  // then each member's input pins and output pins in shape order.
  const local = new Map<number, number>();
  members.forEach((i, li) => local.set(i, li));
  // Plain arrays: a network has a few dozen ports, and typed arrays cost far more to create.
  const inBase: number[] = new Array<number>(members.length).fill(0);
  const outBase: number[] = new Array<number>(members.length).fill(0);
  let ports = 1;
  members.forEach((i, li) => {
    const sh = shapes.get(i)!;
    inBase[li] = ports;
    ports += sh.inputs.length;
    outBase[li] = ports;
    ports += sh.outputs.length;
  });
  const pinIndex = (list: readonly PinSpec[], pin: string) => {
    for (let k = 0; k < list.length; k++) if (list[k]!.pin === pin) return k;
    return -1;
  };
  const inPort = (node: number, pin: string): number => {
    const li = local.get(node);
    if (li === undefined) return -1;
    const k = pinIndex(shapes.get(node)!.inputs, pin);
    return k < 0 ? -1 : inBase[li]! + k;
  };
  const outPort = (node: number, pin: string): number => {
    const li = local.get(node);
    if (li === undefined) return -1;
    const k = pinIndex(shapes.get(node)!.outputs, pin);
    return k < 0 ? -1 : outBase[li]! + k;
  };
  const parent: number[] = new Array<number>(ports).fill(0);
  for (let k = 0; k < ports; k++) parent[k] = k;
  const touched: number[] = new Array<number>(ports).fill(0);
  const find = (a: number): number => {
    while (parent[a]! !== a) {
      parent[a] = parent[parent[a]!]!;
      a = parent[a]!;
    }
    return a;
  };
  const union = (a: number, b: number) => {
    touched[a] = 1;
    touched[b] = 1;
    const ra = find(a);
    const rb = find(b);
    if (ra !== rb) parent[ra] = rb;
  };
  for (const i of members) {
    // forEach, not for-of: no [pin, sources] entry arrays for every pin of the file.
    all[i]!.inputs.forEach((srcs, pin) => {
      const k = inPort(i, pin);
      if (k < 0) return;
      touched[k] = 1;
      for (const s of srcs) {
        const o = s.kind === 'rail' ? 0 : outPort(s.node, s.pin);
        if (o >= 0) union(k, o);
      }
    });
  }
  const netOfRoot = new Map<number, Net>();
  const netOfPort: (Net | undefined)[] = new Array(ports);
  /** Nets by id (ids are given in order). */
  const nets: Net[] = [];
  const netFor = (k: number): Net | undefined => {
    if (k < 0 || !touched[k]) return undefined;
    const root = find(k);
    let net = netOfRoot.get(root);
    if (!net) {
      net = {
        id: netOfRoot.size,
        producers: [],
        consumers: [],
        rail: false,
        rightRail: false,
        b: 0,
        min: Infinity,
        max: -Infinity,
      };
      netOfRoot.set(root, net);
      nets.push(net);
    }
    netOfPort[k] = net;
    return net;
  };
  if (touched[0]) netFor(0)!.rail = true;
  for (const i of members) {
    const sh = shapes.get(i)!;
    for (const p of sh.inputs) netFor(inPort(i, p.pin))?.consumers.push({ node: i, pin: p.pin });
    for (const p of sh.outputs) netFor(outPort(i, p.pin))?.producers.push({ node: i, pin: p.pin });
    if (all[i]!.feedsRightRail) {
      const o = sh.outputs[0];
      if (o) {
        const k = outPort(i, o.pin);
        touched[k] = 1;
        netFor(k)!.rightRail = true;
      }
    }
  }
  const inNet = (node: number, pin: string) => {
    const k = inPort(node, pin);
    return k < 0 ? undefined : netOfPort[k];
  };
  const outNet = (node: number, pin: string) => {
    const k = outPort(node, pin);
    return k < 0 ? undefined : netOfPort[k];
  };

  // Columns: longest path (Kahn over "producers of my input nets").
  // Dependencies as short arrays (a node has a handful): a Set per node costs far more.
  const deps = new Map<number, number[]>();
  const users = new Map<number, number[]>();
  for (const i of members) {
    const d: number[] = [];
    for (const p of shapes.get(i)!.inputs)
      for (const pr of inNet(i, p.pin)?.producers ?? [])
        if (pr.node !== i && !d.includes(pr.node)) d.push(pr.node);
    deps.set(i, d);
    for (const x of d) {
      let u = users.get(x);
      if (!u) users.set(x, (u = []));
      u.push(i);
    }
  }
  const col = new Map<number, number>();
  const indeg = new Map<number, number>();
  for (const i of members) indeg.set(i, deps.get(i)!.length);
  const queue = members.filter((i) => indeg.get(i) === 0);
  const topo: number[] = [];
  // A bar (or a direct join) right at the edge of a multi-row box would touch its other pins:
  // such nets get their bar one boundary further right, with a link from the box.
  const tall = (node: number) => shapes.get(node)!.h > 1;
  const gap = new Map<Net, number>();
  for (const net of nets) {
    const tallProducer = net.producers.some((p) => tall(p.node));
    const tallConsumer = net.consumers.some((c) => tall(c.node));
    const many = net.producers.length + (net.rail ? 1 : 0) > 1;
    gap.set(net, tallProducer && (net.consumers.length > 1 || many || tallConsumer) ? 1 : 0);
  }
  const barOf = (net: Net): number => {
    let b = 0;
    for (const p of net.producers)
      if (col.has(p.node)) b = Math.max(b, col.get(p.node)! + shapes.get(p.node)!.w);
    return net.producers.length ? b + gap.get(net)! : 0;
  };
  const settle = (i: number) => {
    let c = 0;
    for (const p of shapes.get(i)!.inputs) {
      const net = inNet(i, p.pin);
      // Boundary 0 is the left rail on every row: an input that is not wired stays off it. A box
      // keeps one link between its pins and the bar feeding them, so the bar never runs down its edge.
      c = Math.max(c, net ? barOf(net) + (tall(i) && net.producers.length ? 1 : 0) : 1);
    }
    col.set(i, c);
    topo.push(i);
  };
  for (let qi = 0; qi < queue.length; qi++) {
    const i = queue[qi]!;
    settle(i);
    for (const u of users.get(i) ?? []) {
      const left = indeg.get(u)! - 1;
      indeg.set(u, left);
      if (left === 0) queue.push(u);
    }
  }
  for (const i of members) if (!col.has(i)) settle(i); // feedback loops: best effort
  // Right-aligned tails: coils (and chains of coils), jumps, returns with nothing after them.
  const tail = new Map<number, number>();
  for (let k = topo.length - 1; k >= 0; k--) {
    const i = topo[k]!;
    const n = all[i]!;
    if (n.kind === 'jump' || n.kind === 'return') tail.set(i, 1);
    else if (n.kind === 'coil') {
      const net = outNet(i, 'out');
      const cons = net?.consumers ?? [];
      if (
        cons.every((c) => tail.has(c.node) && all[c.node]!.kind === 'coil') &&
        (net?.producers.length ?? 1) <= 1
      ) {
        tail.set(i, 1 + Math.max(0, ...cons.map((c) => tail.get(c.node)!)));
      }
    }
  }
  let needCols = 1;
  for (const i of members) needCols = Math.max(needCols, col.get(i)! + shapes.get(i)!.w);
  for (const net of nets) if (net.consumers.length) needCols = Math.max(needCols, barOf(net) + 1);

  const run = (cols: number): LaidOut => {
    for (const [i, t] of tail) col.set(i, Math.max(col.get(i)!, cols - t));
    for (const net of nets) net.b = barOf(net);
    return placeRows(all, members, shapes, col, nets, inNet, outNet, cols);
  };
  return { nodes: members, needCols, run };
}
