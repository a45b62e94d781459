// Second layout pass: rows. Depth-first along the branches — a series element continues its
// source's row; parallel branches and fan-out go to the first row below where their cells, links and
// vertical bars touch nothing of another net.
import type { LdElement, VLink } from '../model/elements';
import { newId, type ElementId } from '../model/ids';
import type { GNode } from './ldGraph';
import { KEY, type LaidOut, type Net, type Shape } from './layoutShapes';

export function placeRows(
  all: readonly GNode[],
  members: readonly number[],
  shapes: Map<number, Shape>,
  col: Map<number, number>,
  nets: readonly Net[],
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
  /** Whether net may run on row r from boundary a to z (and its bar reach r); `mine` holds the
   * points the same placement already uses, so two pins of one box cannot cross each other. */
  const runOk = (r: number, a: number, z: number, net: Net, mine: Map<number, number>): boolean => {
    const take = (row: number, b: number): boolean => {
      if (!pointOk(row, b, net)) return false;
      if (b === 0 || b === cols) return true;
      const k = row * KEY + b;
      const m = mine.get(k);
      if (m !== undefined && m !== net.id) return false;
      mine.set(k, net.id);
      return true;
    };
    for (let c = a; c < z; c++) if (!cellOk(r, c, net)) return false;
    for (let b = a; b <= z; b++) if (!take(r, b)) return false;
    if (net.b > 0) {
      const lo = net.min === Infinity ? r : Math.min(r, net.min);
      const hi = net.max === -Infinity ? r : Math.max(r, net.max);
      for (let rr = lo; rr <= hi; rr++) if (!take(rr, net.b)) return false;
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

  const mine = new Map<number, number>();
  const fits = (i: number, r: number): boolean => {
    const sh = shapes.get(i)!;
    const c = col.get(i)!;
    mine.clear();
    let own = -1;
    const block = (row: number, b: number): boolean => {
      const k = row * KEY + b;
      if (pointNet.has(k) || mine.has(k)) return false;
      mine.set(k, own--);
      return true;
    };
    for (let y = 0; y < sh.h; y++)
      for (let x = 0; x < sh.w; x++) if (cellOwner.has((r + y) * KEY + c + x)) return false;
    for (let y = 0; y < sh.h; y++) for (let x = 1; x < sh.w; x++) if (!block(r + y, c + x)) return false;
    for (const p of sh.inputs) {
      const net = inNet(i, p.pin);
      if (net) {
        if (!runOk(r + p.off, Math.min(net.b, c), c, net, mine)) return false;
      } else if (c !== 0 && !block(r + p.off, c)) return false;
    }
    for (const p of sh.outputs) {
      const net = outNet(i, p.pin);
      const end = c + sh.w;
      if (net && (net.consumers.length || net.producers.length > 1)) {
        if (!runOk(r + p.off, end, Math.max(net.b, end), net, mine)) return false;
      } else if (end !== cols && !block(r + p.off, end)) return false;
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
    for (let y = 0; y < sh.h; y++)
      for (let x = 1; x < sh.w; x++) pointNet.set((r + y) * KEY + c + x, blockedId--);
    for (const p of sh.inputs) {
      const net = inNet(i, p.pin);
      if (net) claimRun(r + p.off, Math.min(net.b, c), c, net);
      else if (c !== 0) pointNet.set((r + p.off) * KEY + c, blockedId--);
    }
    for (const p of sh.outputs) {
      const net = outNet(i, p.pin);
      const end = c + sh.w;
      if (net && (net.consumers.length || net.producers.length > 1))
        claimRun(r + p.off, end, Math.max(net.b, end), net);
      else if (end !== cols) pointNet.set((r + p.off) * KEY + end, blockedId--);
    }
    const id = nextId();
    elementOf.set(i, id);
    // Literal objects, not spreads of a shared base: this runs for every element of the file.
    switch (n.kind) {
      case 'contact':
        elements.push({
          id,
          row: r,
          col: c,
          kind: 'contact',
          contact: n.contact ?? 'NO',
          variable: n.variable ?? '',
        });
        break;
      case 'coil':
        elements.push({
          id,
          row: r,
          col: c,
          kind: 'coil',
          coil: n.coil ?? 'COIL',
          variable: n.variable ?? '',
        });
        break;
      case 'jump':
        elements.push({ id, row: r, col: c, kind: 'jump', target: n.target ?? '' });
        break;
      case 'return':
        elements.push({ id, row: r, col: c, kind: 'return' });
        break;
      case 'box':
        elements.push({
          id,
          row: r,
          col: c,
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

  const byPosition = (a: number, b: number) =>
    all[a]!.y - all[b]!.y || all[a]!.x - all[b]!.x || all[a]!.order - all[b]!.order;
  // A chain of contacts from the rail that only feeds a lower pin of a box (R of a counter, G of a
  // SEL) is drawn on that pin's row, after the box: placed first, at the top, its wire would have to
  // cross the pins of the boxes between.
  const chainOf = new Map<number, { box: number; off: number } | null>();
  const chainTarget = (n: number, depth = 0): { box: number; off: number } | null => {
    const known = chainOf.get(n);
    if (known !== undefined) return known;
    let result: { box: number; off: number } | null = null;
    const out = all[n]!.kind === 'contact' && depth < 64 ? outNet(n, 'out') : undefined;
    const inn = out ? inNet(n, 'in') : undefined;
    const fromRail = inn ? inn.rail && inn.producers.length === 0 : false;
    const fromChain = inn ? !inn.rail && inn.producers.length === 1 && inn.consumers.length === 1 : false;
    if (
      out &&
      inn &&
      (fromRail || fromChain) &&
      out.producers.length === 1 &&
      out.consumers.length === 1 &&
      !out.rail
    ) {
      const c = out.consumers[0]!;
      const sh = shapes.get(c.node)!;
      if (sh.h > 1) {
        const off = sh.inputs.find((p) => p.pin === c.pin)?.off ?? 0;
        result = off > 0 ? { box: c.node, off } : null;
      } else result = chainTarget(c.node, depth + 1);
    }
    chainOf.set(n, result);
    return result;
  };

  const placing = new Set<number>();
  /** Places the nodes of these pins top to bottom, then left to right (as drawn in the file). */
  const inOrder = (pins: readonly { node: number }[]) => {
    if (pins.length === 1) return place(pins[0]!.node);
    for (const n of sortSmall(
      pins.map((x) => x.node),
      byPosition,
    ))
      place(n);
  };
  const place = (i: number, prefer?: number): void => {
    if (row.has(i) || placing.has(i)) return;
    placing.add(i);
    const sh = shapes.get(i)!;
    const later: { node: number; row: number }[] = [];
    // Everything feeding my input bars first, top to bottom (chains drawn on a lower pin: after me).
    for (const p of sh.inputs) {
      const net = inNet(i, p.pin);
      if (!net) continue;
      const only = net.producers.length === 1 ? net.producers[0]!.node : undefined;
      if (only !== undefined && !row.has(only) && chainTarget(only)?.box === i) {
        later.push({ node: only, row: p.off });
        continue;
      }
      const chained = prefer !== undefined && only !== undefined && chainTarget(only) !== null;
      if (chained) place(only, prefer);
      else inOrder(net.producers);
    }
    let r = prefer ?? preferredRow(i);
    while (r <= maxRow + 1 && !fits(i, r)) r++;
    if (r > maxRow + 1) {
      r = maxRow + 1;
      forced.push(i);
    }
    commit(i, r);
    placing.delete(i);
    for (const l of later) place(l.node, r + l.row);
    // Then what I feed: siblings in the same bars, then consumers, depth-first.
    for (const p of sh.outputs) {
      const net = outNet(i, p.pin);
      if (!net) continue;
      inOrder(net.producers);
      inOrder(net.consumers);
    }
  };

  const railNet = nets.find((n) => n.rail);
  const starts = railNet
    ? sortSmall(
        railNet.consumers.map((c) => c.node),
        byPosition,
      )
    : [];
  for (const i of starts) if (!chainTarget(i)) place(i);
  const rest = sortSmall([...members], byPosition);
  for (const i of rest) if (!chainTarget(i)) place(i);
  for (const i of rest) place(i);

  // Cosmetic: wires to the right rail where the row is free.
  for (const net of nets) {
    if (!net.rightRail || net.consumers.length) continue;
    for (const pr of net.producers) {
      const r = row.get(pr.node)! + (shapes.get(pr.node)!.outputs.find((o) => o.pin === pr.pin)?.off ?? 0);
      const end = col.get(pr.node)! + shapes.get(pr.node)!.w;
      if (end >= cols) continue;
      let ok = true;
      for (let c = end; c < cols && ok; c++) ok = !cellOwner.has(r * KEY + c);
      for (let b = end + 1; b < cols && ok; b++)
        ok = !pointNet.has(r * KEY + b) || pointNet.get(r * KEY + b) === net.id;
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

/** Stable in-place sort; insertion sort for the short lists of one network (no work array). */
function sortSmall(a: number[], cmp: (x: number, y: number) => number): number[] {
  if (a.length > 24) return a.sort(cmp);
  for (let i = 1; i < a.length; i++) {
    const v = a[i]!;
    let j = i - 1;
    while (j >= 0 && cmp(a[j]!, v) > 0) {
      a[j + 1] = a[j]!;
      j--;
    }
    a[j + 1] = v;
  }
  return a;
}
