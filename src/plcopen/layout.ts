// Graph → grid: lays out one network from its wiring, not from coordinates (CODESYS files have none).
// Columns: longest path from the left rail (each net gets one vertical bar at the boundary where its
// last producer ends); coils, jumps and returns are pushed to the right rail. Rows: depth-first along
// the branches — a series element continues its source's row, parallel branches and fan-out go to the
// first row below where their cells, links and bars cross nothing of another net.
import { boxLayoutFor } from '../model/boxLayout';
import type { LdElement, VLink } from '../model/elements';
import { newId, type ElementId } from '../model/ids';
import type { GNode } from './ldGraph';

interface PinSpec {
  readonly pin: string;
  readonly off: number;
}

interface Shape {
  readonly w: number;
  readonly h: number;
  readonly inputs: readonly PinSpec[];
  readonly outputs: readonly PinSpec[];
}

function shapeOf(n: GNode): Shape {
  switch (n.kind) {
    case 'contact':
    case 'coil':
      return { w: 1, h: 1, inputs: [{ pin: 'in', off: 0 }], outputs: [{ pin: 'out', off: 0 }] };
    case 'jump':
    case 'return':
      return { w: 1, h: 1, inputs: [{ pin: 'in', off: 0 }], outputs: [] };
    case 'box': {
      const l = boxLayoutFor(n.blockType ?? '', n.inputCount);
      if (!l) return { w: 1, h: 1, inputs: [], outputs: [] };
      return {
        w: l.cols,
        h: l.rows,
        inputs: l.inputs.map((p) => ({ pin: p.name, off: p.rowOffset })),
        outputs: l.outputs.map((p) => ({ pin: p.name, off: p.rowOffset })),
      };
    }
  }
}

interface Net {
  readonly id: number;
  readonly producers: { node: number; pin: string }[];
  readonly consumers: { node: number; pin: string }[];
  rail: boolean;
  rightRail: boolean;
  /** Boundary of the vertical bar. */
  b: number;
  min: number;
  max: number;
}

export interface LaidOut {
  readonly rows: number;
  readonly cols: number;
  readonly elements: LdElement[];
  readonly vlinks: VLink[];
  /** Element id per node index (for verification and preserved data). */
  readonly elementOf: Map<number, ElementId>;
  /** Nodes that could not be placed without touching another net (their wiring may differ). */
  readonly forced: number[];
}

export interface Prepared {
  readonly nodes: readonly number[];
  readonly needCols: number;
  readonly run: (cols: number) => LaidOut;
}

const KEY = 4096;

/** Prepares the layout of the nodes of one network: columns now, rows when the width is known. */
export function prepareLayout(all: readonly GNode[], members: readonly number[]): Prepared {
  const shapes = new Map<number, Shape>();
  for (const i of members) shapes.set(i, shapeOf(all[i]!));
  // Nets: union of each wired input pin with its sources. Ports are numbered: 0 is the left rail,
  // then each member's input pins and output pins in shape order.
  const local = new Map<number, number>();
  members.forEach((i, li) => local.set(i, li));
  const inBase = new Int32Array(members.length);
  const outBase = new Int32Array(members.length);
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
  const parent = new Int32Array(ports);
  for (let k = 0; k < ports; k++) parent[k] = k;
  const touched = new Uint8Array(ports);
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
    for (const [pin, srcs] of all[i]!.inputs) {
      const k = inPort(i, pin);
      if (k < 0) continue;
      touched[k] = 1;
      for (const s of srcs) {
        const o = s.kind === 'rail' ? 0 : outPort(s.node, s.pin);
        if (o >= 0) union(k, o);
      }
    }
  }
  const netOfRoot = new Map<number, Net>();
  const netOfPort: (Net | undefined)[] = new Array(ports);
  const nets = new Map<number, Net>();
  const netFor = (k: number): Net | undefined => {
    if (k < 0 || !touched[k]) return undefined;
    const root = find(k);
    let net = netOfRoot.get(root);
    if (!net) {
      net = { id: netOfRoot.size, producers: [], consumers: [], rail: false, rightRail: false, b: 0, min: Infinity, max: -Infinity };
      netOfRoot.set(root, net);
      nets.set(net.id, net);
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
  const deps = new Map<number, Set<number>>();
  const users = new Map<number, number[]>();
  for (const i of members) {
    const d = new Set<number>();
    for (const p of shapes.get(i)!.inputs) for (const pr of inNet(i, p.pin)?.producers ?? []) if (pr.node !== i) d.add(pr.node);
    deps.set(i, d);
    for (const x of d) {
      let u = users.get(x);
      if (!u) users.set(x, (u = []));
      u.push(i);
    }
  }
  const col = new Map<number, number>();
  const indeg = new Map<number, number>();
  for (const i of members) indeg.set(i, deps.get(i)!.size);
  const queue = members.filter((i) => indeg.get(i) === 0);
  const topo: number[] = [];
  // A bar (or a direct join) right at the edge of a multi-row box would touch its other pins:
  // such nets get their bar one boundary further right, with a link from the box.
  const tall = (node: number) => shapes.get(node)!.h > 1;
  const gap = new Map<Net, number>();
  for (const net of nets.values()) {
    const tallProducer = net.producers.some((p) => tall(p.node));
    const tallConsumer = net.consumers.some((c) => tall(c.node));
    const many = net.producers.length + (net.rail ? 1 : 0) > 1;
    gap.set(net, (tallProducer && (net.consumers.length > 1 || many || tallConsumer)) || (tallConsumer && many) ? 1 : 0);
  }
  const barOf = (net: Net): number => {
    let b = 0;
    for (const p of net.producers) if (col.has(p.node)) b = Math.max(b, col.get(p.node)! + shapes.get(p.node)!.w);
    return net.producers.length ? b + gap.get(net)! : 0;
  };
  const settle = (i: number) => {
    let c = 0;
    for (const p of shapes.get(i)!.inputs) {
      const net = inNet(i, p.pin);
      // Boundary 0 is the left rail on every row: an input that is not wired stays off it.
      c = Math.max(c, net ? barOf(net) : 1);
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
      if (cons.every((c) => tail.has(c.node) && all[c.node]!.kind === 'coil') && (net?.producers.length ?? 1) <= 1) {
        tail.set(i, 1 + Math.max(0, ...cons.map((c) => tail.get(c.node)!)));
      }
    }
  }
  let needCols = 1;
  for (const i of members) needCols = Math.max(needCols, col.get(i)! + shapes.get(i)!.w);
  for (const net of nets.values()) if (net.consumers.length) needCols = Math.max(needCols, barOf(net) + 1);

  const run = (cols: number): LaidOut => {
    for (const [i, t] of tail) col.set(i, Math.max(col.get(i)!, cols - t));
    for (const net of nets.values()) net.b = barOf(net);
    return placeRows(all, members, shapes, col, nets, inNet, outNet, cols);
  };
  return { nodes: members, needCols, run };
}

function placeRows(
  all: readonly GNode[],
  members: readonly number[],
  shapes: Map<number, Shape>,
  col: Map<number, number>,
  nets: Map<number, Net>,
  inNet: (node: number, pin: string) => Net | undefined,
  outNet: (node: number, pin: string) => Net | undefined,
  cols: number,
): LaidOut {
  const cellOwner = new Map<number, number>(); // cell -> node index (>=0) or -(net id + 1) for links
  const pointNet = new Map<number, number>(); // point -> net id, or a unique negative id when blocked
  let blockedId = -1;
  const row = new Map<number, number>();
  const elements: LdElement[] = [];
  const elementOf = new Map<number, ElementId>();
  const vlinks = new Map<number, VLink>();
  const forced: number[] = [];
  let maxRow = -1;
  // Element ids: one fresh prefix per network and a counter (as unique as newId, far cheaper).
  const prefix = newId<'ElementId'>('e');
  let counter = 0;
  const nextId = () => `${prefix}_${(counter++).toString(36)}` as ElementId;

  const pointOk = (r: number, b: number, net: Net) => {
    if (b === cols) return true;
    if (b === 0) return net.rail;
    const v = pointNet.get(r * KEY + b);
    return v === undefined || v === net.id;
  };
  const cellOk = (r: number, c: number, net: Net | undefined) => {
    const v = cellOwner.get(r * KEY + c);
    return v === undefined || (net !== undefined && v === -(net.id + 1));
  };
  /** Horizontal run of net on row r from boundary a to boundary z (a <= z), plus the bar reaching r. */
  const runOk = (r: number, a: number, z: number, net: Net): boolean => {
    for (let c = a; c < z; c++) if (!cellOk(r, c, net)) return false;
    for (let b = a; b <= z; b++) if (!pointOk(r, b, net)) return false;
    if (net.b > 0 && net.min !== Infinity) {
      for (let rr = Math.min(r, net.min); rr <= Math.max(r, net.max); rr++) if (!pointOk(rr, net.b, net)) return false;
    }
    return true;
  };
  const claimRun = (r: number, a: number, z: number, net: Net) => {
    for (let c = a; c < z; c++) {
      const k = r * KEY + c;
      if (cellOwner.get(k) === undefined) {
        cellOwner.set(k, -(net.id + 1));
        elements.push({ id: nextId(), kind: 'link', row: r, col: c });
      }
    }
    for (let b = a; b <= z; b++) if (b !== 0 && b !== cols) pointNet.set(r * KEY + b, net.id);
    if (net.b > 0) {
      const lo = Math.min(r, net.min === Infinity ? r : net.min);
      const hi = Math.max(r, net.max === -Infinity ? r : net.max);
      for (let rr = lo; rr < hi; rr++) vlinks.set(rr * KEY + net.b, { row: rr, boundary: net.b });
      for (let rr = lo; rr <= hi; rr++) pointNet.set(rr * KEY + net.b, net.id);
    }
    net.min = Math.min(net.min, r);
    net.max = Math.max(net.max, r);
  };

  const fits = (i: number, r: number): boolean => {
    const sh = shapes.get(i)!;
    const c = col.get(i)!;
    for (let y = 0; y < sh.h; y++) for (let x = 0; x < sh.w; x++) if (cellOwner.has((r + y) * KEY + c + x)) return false;
    for (let y = 0; y < sh.h; y++) for (let x = 1; x < sh.w; x++) if (pointNet.has((r + y) * KEY + c + x)) return false;
    for (const p of sh.inputs) {
      const net = inNet(i, p.pin);
      if (net) {
        if (!runOk(r + p.off, Math.min(net.b, c), c, net)) return false;
      } else if (c !== 0 && pointNet.has((r + p.off) * KEY + c)) return false;
    }
    for (const p of sh.outputs) {
      const net = outNet(i, p.pin);
      const end = c + sh.w;
      if (net && (net.consumers.length || net.producers.length > 1)) {
        if (!runOk(r + p.off, end, Math.max(net.b, end), net)) return false;
      } else if (end !== cols && pointNet.has((r + p.off) * KEY + end)) return false;
    }
    return true;
  };

  const commit = (i: number, r: number) => {
    const n = all[i]!;
    const sh = shapes.get(i)!;
    const c = col.get(i)!;
    row.set(i, r);
    maxRow = Math.max(maxRow, r + sh.h - 1);
    for (let y = 0; y < sh.h; y++) for (let x = 0; x < sh.w; x++) cellOwner.set((r + y) * KEY + c + x, i);
    for (let y = 0; y < sh.h; y++) for (let x = 1; x < sh.w; x++) pointNet.set((r + y) * KEY + c + x, blockedId--);
    for (const p of sh.inputs) {
      const net = inNet(i, p.pin);
      if (net) claimRun(r + p.off, Math.min(net.b, c), c, net);
      else if (c !== 0) pointNet.set((r + p.off) * KEY + c, blockedId--);
    }
    for (const p of sh.outputs) {
      const net = outNet(i, p.pin);
      const end = c + sh.w;
      if (net && (net.consumers.length || net.producers.length > 1)) claimRun(r + p.off, end, Math.max(net.b, end), net);
      else if (end !== cols) pointNet.set((r + p.off) * KEY + end, blockedId--);
    }
    const id = nextId();
    elementOf.set(i, id);
    const base = { id, row: r, col: c };
    switch (n.kind) {
      case 'contact':
        elements.push({ ...base, kind: 'contact', contact: n.contact ?? 'NO', variable: n.variable ?? '' });
        break;
      case 'coil':
        elements.push({ ...base, kind: 'coil', coil: n.coil ?? 'COIL', variable: n.variable ?? '' });
        break;
      case 'jump':
        elements.push({ ...base, kind: 'jump', target: n.target ?? '' });
        break;
      case 'return':
        elements.push({ ...base, kind: 'return' });
        break;
      case 'box':
        elements.push({
          ...base,
          kind: 'box',
          blockType: n.blockType ?? '',
          ...(n.instance ? { instance: n.instance } : {}),
          ...(n.inputCount !== undefined ? { inputCount: n.inputCount } : {}),
          inputs: { ...n.operandsIn },
          outputs: { ...n.operandsOut },
        });
        break;
    }
  };

  const preferredRow = (i: number): number => {
    const sh = shapes.get(i)!;
    let best = Infinity;
    for (const p of sh.inputs) {
      const net = inNet(i, p.pin);
      if (!net) continue;
      for (const pr of net.producers) {
        const pr_r = row.get(pr.node);
        if (pr_r === undefined) continue;
        const off = shapes.get(pr.node)!.outputs.find((o) => o.pin === pr.pin)?.off ?? 0;
        best = Math.min(best, pr_r + off - p.off);
      }
    }
    return best === Infinity ? 0 : Math.max(0, best);
  };

  const byPosition = (a: number, b: number) => all[a]!.y - all[b]!.y || all[a]!.x - all[b]!.x || all[a]!.order - all[b]!.order;
  const placing = new Set<number>();
  const place = (i: number) => {
    if (row.has(i) || placing.has(i)) return;
    placing.add(i);
    const sh = shapes.get(i)!;
    // Everything feeding my input bars first, top to bottom.
    for (const p of sh.inputs) {
      const net = inNet(i, p.pin);
      if (net) [...net.producers].sort((a, b) => byPosition(a.node, b.node)).forEach((pr) => place(pr.node));
    }
    let r = preferredRow(i);
    while (r <= maxRow + 1 && !fits(i, r)) r++;
    if (r > maxRow + 1) {
      r = maxRow + 1;
      forced.push(i);
    }
    commit(i, r);
    placing.delete(i);
    // Then what I feed: siblings in the same bars, then consumers, depth-first.
    for (const p of sh.outputs) {
      const net = outNet(i, p.pin);
      if (!net) continue;
      [...net.producers].sort((a, b) => byPosition(a.node, b.node)).forEach((pr) => place(pr.node));
      [...net.consumers].sort((a, b) => byPosition(a.node, b.node)).forEach((cn) => place(cn.node));
    }
  };

  const railNet = [...nets.values()].find((n) => n.rail);
  const starts = railNet ? [...railNet.consumers.map((c) => c.node)].sort(byPosition) : [];
  for (const i of starts) place(i);
  for (const i of [...members].sort(byPosition)) place(i);

  // Cosmetic: wires to the right rail where the row is free.
  for (const net of nets.values()) {
    if (!net.rightRail || net.consumers.length) continue;
    for (const pr of net.producers) {
      const r = row.get(pr.node)! + (shapes.get(pr.node)!.outputs.find((o) => o.pin === pr.pin)?.off ?? 0);
      const end = col.get(pr.node)! + shapes.get(pr.node)!.w;
      if (end >= cols) continue;
      let ok = true;
      for (let c = end; c < cols && ok; c++) ok = !cellOwner.has(r * KEY + c);
      for (let b = end + 1; b < cols && ok; b++) ok = !pointNet.has(r * KEY + b) || pointNet.get(r * KEY + b) === net.id;
      if (ok) {
        const save = net.b;
        net.b = 0;
        claimRun(r, end, cols, net);
        net.b = save;
      }
    }
  }
  return { rows: Math.max(1, maxRow + 1), cols, elements, vlinks: [...vlinks.values()], elementOf, forced };
}
