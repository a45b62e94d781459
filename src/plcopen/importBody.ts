// An LD body → the networks of a POU: connected components ordered top to bottom (or, for a
// profile other than openplc, by their smallest executionOrderId first), labels and comments
// attached to the network below. Under openplc, networks whose coils Beremiz's generator runs in
// another order than network by network (drawn side by side) record that order (generatorTurns).
import { uniqueConnectorNames } from './connectorNames';
import type { LdElement } from '../model/elements';
import type { BlockLibrary } from '../model/library';
import { newNetwork } from '../model/factory';
import type { Network } from '../model/project';
import { LAYOUT_STRATEGIES, prepareLayout } from './layout';
import { addCuts, allNodeWires, CUT_ROUNDS, cutView, type CutPin, type CutView, type StackRoom } from './layoutCut';
import { instantiate, LayoutCache, shapeKey } from './layoutCache';
import { shapeOf, type LaidOut } from './layoutShapes';
import { sortInstances } from './generatorOrder';
import type { ElementId } from '../model/ids';
import { buildLdGraph, LdGraphError } from './ldGraph';
import type { Finding, GNode } from './ldNodes';
import { splitSharedSources } from './ldNormalize';
import { planBody, type BodyPlan } from './ldBatches';
import { readLdObjects, type RawObject } from './ldObjects';
import { RS_NETWORK, type PreservedNetwork } from './types';
import { mismatchFinding, verify, type Mismatch } from './verifyLayout';
import { child, childrenNamed, type XmlDoc, type XmlElement } from './xml/parse';

export interface BodyResult {
  readonly networks: Network[];
  /** One line per network the grid draws with connector pairs (see pairNotes). */
  readonly notes: string[];
}

/** How a body is read (the defaults are right; tests use these to check that results do not depend on them). */
export interface BodyTuning {
  /** Objects per batch (see ldBatches.ts). */
  readonly batchObjects?: number;
  /** Whether networks of one shape share a layout (see layoutCache.ts). */
  readonly shareLayouts?: boolean;
  /**
   * Whether a network's smallest executionOrderId places it before the networks without one
   * (default). False under the openplc profile: Beremiz's generator orders instances by their
   * ids (the engine does too, BoxElement.executionOrder), coils by position, never networks.
   */
  readonly orderByIds?: boolean;
  /**
   * Which wires are drawn through connector pairs: those the grid cannot route ('needed', the
   * default), none ('none': a network the grid cannot draw exactly refuses the body), or every
   * wire between elements ('all': the last layout tried, which must draw any graph exactly).
   */
  readonly cuts?: 'needed' | 'none' | 'all';
  /**
   * Profile openplc: record the generator's order of coils and output variables where it is not
   * network by network, row by row (Network.turns; see generatorTurns).
   */
  readonly turns?: boolean;
  /**
   * The profile to import for, whatever the file says (`rungsmith simulate --profile`): the import
   * orders networks and records Beremiz's order for the profile that will run them.
   */
  readonly profile?: 'iec' | 'openplc';
}

const MIN_COLS = 3;

/** One network of a batch: its node indices and its place in the POU. */
interface Group {
  readonly nodes: number[];
  readonly key: readonly number[];
}

/** What one batch leaves for the assembly of the POU: networks laid out, labels, comments, vendor data. */
type BatchItem = { readonly key: readonly number[]; readonly rank: number } & (
  | { kind: 'network'; laid: LaidNetwork; findings: Finding[] }
  | { kind: 'label'; text: string }
  | { kind: 'comment'; text: string; title: string }
  | { kind: 'vendor'; raw: string }
);
/** Items of all batches, numbered in the order they were made (ties in `key` keep that order). */
type Item = BatchItem & { readonly seq: number };

interface LaidNetwork {
  readonly rows: number;
  readonly cols: number;
  readonly elements: LdElement[];
  readonly vlinks: Network['vlinks'];
  readonly elementData?: PreservedNetwork['elementData'];
  /** Profile openplc: the network's coils and output variables, where the file draws them (see generatorTurns). */
  readonly anchors?: Anchor[];
}

/**
 * A statement of Beremiz's generator: a coil, or a variable written beside a block output (an
 * outVariable), where the file draws it; `key` is its Network.turns key, `row`/`col` its place on
 * the grid (the engine's order without turns). A network lists its anchors in that order.
 */
interface Anchor {
  readonly x: number;
  readonly y: number;
  readonly order: number;
  readonly key: string;
  readonly row: number;
  readonly col: number;
}

const RANK = { network: 0, label: 1, comment: 2, vendor: 3 } as const;

function compareItems(a: Item, b: Item): number {
  const k = a.key;
  const l = b.key;
  for (let i = 0; i < Math.max(k.length, l.length); i++) {
    const d = (k[i] ?? 0) - (l[i] ?? 0);
    if (d) return d;
  }
  return a.rank - b.rank || a.seq - b.seq;
}

/**
 * Imports one LD body into networks. Throws LdGraphError for broken references, and for a network
 * the grid cannot draw exactly (never drawn with other wiring).
 *
 * Large bodies are read in batches of whole networks (see ldBatches.ts); networks are ordered
 * top to bottom (executionOrderId first unless `tuning.orderByIds` is false) once all are laid out.
 * Each network is as wide as its own elements need (at least MIN_COLS), its coils at its own
 * right rail; the editor draws every network at its own width.
 */
export function importLdBody(
  body: XmlElement,
  raw: (el: XmlElement) => string,
  warn: (f: Finding) => void,
  library: BlockLibrary,
  tuning: BodyTuning = {},
  /** Whether a variable the body names is BOOL (negated inputs of generic blocks, FBD). */
  isBool?: (name: string) => boolean,
): BodyResult {
  const plan = planBody(body, tuning.batchObjects);
  const cache = new LayoutCache(tuning.shareLayouts ?? true);
  const items: Item[] = [];
  let seq = 0;
  for (const positions of plan.batches)
    for (const it of readBatch(body.doc, plan, positions, cache, raw, warn, library, isBool, tuning.orderByIds !== false, tuning.cuts ?? 'needed', tuning.turns === true))
      items.push({ ...it, seq: seq++ });
  items.sort(compareItems);
  // A network with nothing but a label or a comment: as narrow as a network gets.
  const cols = MIN_COLS;

  const networks: Network[] = [];
  /** Per network: its generator statements (profile openplc). */
  const anchors: (readonly Anchor[])[] = [];
  let pendingLabel: string | undefined;
  let pendingComments: { text: string; title: string }[] = [];
  let pendingVendor: string[] = [];
  const flushEmpty = () => {
    if (pendingLabel === undefined) return;
    networks.push(newNetwork({ rows: 1, cols, label: pendingLabel, ...commentsOf(pendingComments) }));
    anchors.push([]);
    pendingLabel = undefined;
    pendingComments = [];
  };
  for (const it of items) {
    if (it.kind === 'label') {
      flushEmpty();
      pendingLabel = it.text;
      continue;
    }
    if (it.kind === 'comment') {
      pendingComments.push(it);
      continue;
    }
    if (it.kind === 'vendor') {
      pendingVendor.push(it.raw);
      continue;
    }
    // A network that no layout draws exactly (verifyLayout.ts) is never drawn with other wiring:
    // a grid that joins or drops a wire runs another program than the file's. The body is refused
    // at the first pin that differs (the last layout, every wire cut, draws any graph exactly).
    const undrawn = it.findings[0];
    if (undrawn) throw new LdGraphError(`network ${networks.length + 1}: ${undrawn.message}`, undrawn.obj);
    const { laid } = it;
    const keep: PreservedNetwork = {
      ...(pendingVendor.length ? { objects: pendingVendor } : {}),
      ...(laid.elementData ? { elementData: laid.elementData } : {}),
    };
    networks.push(
      newNetwork({
        rows: laid.rows,
        cols: laid.cols,
        elements: laid.elements,
        vlinks: laid.vlinks,
        ...(pendingLabel !== undefined ? { label: pendingLabel } : {}),
        ...commentsOf(pendingComments),
        ...(keep.objects || keep.elementData ? { extensions: { plcopen: keep } } : {}),
      }),
    );
    anchors.push(laid.anchors ?? []);
    pendingLabel = undefined;
    pendingComments = [];
    pendingVendor = [];
  }
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
    } else {
      networks.push(
        newNetwork({
          rows: 1,
          cols,
          ...extra,
          ...(pendingVendor.length ? { extensions: { plcopen: keep } } : {}),
        }),
      );
      anchors.push([]);
    }
  }
  // The layout names its pairs C1, C2, … per network; PLCopen names are the body's.
  const named = [...uniqueConnectorNames(networks)];
  const turned = tuning.turns ? generatorTurns(named, anchors) : { networks: named, notes: [] };
  return { networks: turned.networks, notes: [...pairNotes(turned.networks), ...turned.notes] };
}

/**
 * Profile openplc: Beremiz's generator writes one statement per coil and per output variable of
 * the whole body (ComputeProgram), sorted by SortInstances from file order, across networks. The
 * engine runs a network's statements by row and column, network after network; where that differs,
 * the networks get turns (Network.turns, each statement's rank in the generator's order):
 * - networks whose statements interleave (one's runs between two of another's, as when networks
 *   are drawn side by side) form a group: every network between the group's first and last gets
 *   turns, and the group runs its statements together in turn order;
 * - a network alone whose own rows do not follow the drawing gets turns too.
 * Everything else keeps network order (no turns: nothing to store).
 */
export function generatorTurns(
  networks: readonly Network[],
  anchors: readonly (readonly Anchor[])[],
): { networks: Network[]; notes: string[] } {
  // Usually the engine's order (network by network, each network's anchors by row and column, as
  // anchorsOf lists them) is already sorted: nothing to record, and nothing more to compute.
  let prev: Anchor | undefined;
  let sorted = true;
  const all: Anchor[] = [];
  for (const list of anchors)
    for (const a of list) {
      all.push(a);
      if (!sorted || !prev) {
        prev = a;
        continue;
      }
      const c = sortInstances(prev, a);
      if (c > 0 || (c === 0 && prev.order > a.order)) sorted = false;
      prev = a;
    }
  if (sorted) return { networks: [...networks], notes: [] };
  // The generator sorts the instances as the file lists them (a stable sort, like Python's).
  all.sort((p, q) => p.order - q.order);
  all.sort(sortInstances);
  const rank = new Map<Anchor, number>();
  all.forEach((a, k) => rank.set(a, k));
  // Each network's ranks in the engine's order without turns (row, then column).
  const ranks = anchors.map((list) => list.map((a) => rank.get(a)!));
  const n = networks.length;
  const suffixMin: number[] = new Array<number>(n + 1).fill(Infinity);
  for (let i = n - 1; i >= 0; i--) {
    let m = suffixMin[i + 1]!;
    for (const r of ranks[i]!) if (r < m) m = r;
    suffixMin[i] = m;
  }
  const out = [...networks];
  const notes: string[] = [];
  const give = (i: number) => {
    const turns: Record<string, number> = {};
    for (const a of anchors[i]!) turns[a.key] = rank.get(a)!;
    out[i] = { ...out[i]!, turns };
  };
  let start = 0;
  let max = -Infinity;
  for (let i = 0; i < n; i++) {
    for (const r of ranks[i]!) max = Math.max(max, r);
    // A cut after network i: everything up to it runs before everything after it.
    if (max >= suffixMin[i + 1]! && i + 1 < n) continue;
    const members: number[] = [];
    for (let k = start; k <= i; k++) if (ranks[k]!.length) members.push(k);
    if (members.length > 1) {
      const first = members[0]!;
      const last = members[members.length - 1]!;
      for (let k = first; k <= last; k++) give(k);
      notes.push(
        `networks ${first + 1} to ${last + 1} are drawn so that Beremiz and OpenPLC run their coils and output variables interleaved, in the order of their drawn height across the networks (not network by network): the openplc profile runs them in that order`,
      );
    } else if (members.length === 1) {
      const own = ranks[members[0]!]!;
      if (own.some((r, k) => k > 0 && r < own[k - 1]!)) give(members[0]!);
    }
    start = i + 1;
  }
  return { networks: out, notes };
}

/**
 * What the import report says of the connector pairs the layout drew: every pair on an imported
 * network was drawn where the grid cannot route a wire (a file's own pairs are followed, then drawn
 * again only where needed). One line per network: the wires (one continuation each) and the pairs.
 */
export function pairNotes(networks: readonly Network[]): string[] {
  const out: string[] = [];
  networks.forEach((net, k) => {
    const names: string[] = [];
    let wires = 0;
    for (const el of net.elements) {
      if (el.kind === 'connector' && !names.includes(el.name)) names.push(el.name);
      if (el.kind === 'continuation') wires++;
    }
    if (!names.length) return;
    const many = wires !== 1;
    const pairs = names
      .sort((a, b) => a.localeCompare(b, 'en', { numeric: true }))
      .map((n) => `>${n}>`)
      .join(', ');
    out.push(
      `network ${k + 1}: ${wires} wire${many ? 's' : ''} drawn through ${names.length > 1 ? `connector pairs ${pairs}` : `the connector pair ${pairs}`} because the grid cannot route ${many ? 'them' : 'it'}`,
    );
  });
  return out;
}

/** Reads, interprets and lays out one batch of whole networks, each as wide as it needs. */
function readBatch(
  doc: XmlDoc,
  plan: BodyPlan,
  positions: readonly number[],
  cache: LayoutCache,
  raw: (el: XmlElement) => string,
  warn: (f: Finding) => void,
  library: BlockLibrary,
  isBool?: (name: string) => boolean,
  orderByIds = true,
  cutWires: NonNullable<BodyTuning['cuts']> = 'needed',
  turns = false,
): BatchItem[] {
  const inBatch = new Set(positions);
  const keepRef = (ref: string) => {
    const p = plan.positionOf(ref);
    return p === undefined || inBatch.has(p);
  };
  const objects = readLdObjects(doc, plan.children, positions, keepRef);
  const graph = buildLdGraph(objects, raw, warn, library, isBool);
  splitSharedSources(graph.nodes, warn);
  const { nodes } = graph;
  const { hasGeometry } = plan;

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
  const keyOf = (objs: readonly RawObject[]): number[] => {
    let eo = Infinity;
    let y = Infinity;
    let x = Infinity;
    let order = Infinity;
    for (const o of objs) {
      if (o.executionOrderId > 0 && o.executionOrderId < eo) eo = o.executionOrderId;
      if (o.pos.y < y) y = o.pos.y;
      if (o.pos.x < x) x = o.pos.x;
      if (o.order < order) order = o.order;
    }
    if (eo !== Infinity && orderByIds) return [0, eo];
    return hasGeometry ? [1, y, x] : [1, order];
  };
  const groups: Group[] = [];
  for (const list of comps.values()) groups.push({ nodes: list, key: keyOf(list.map((i) => nodes[i]!.obj)) });

  const room: StackRoom = (n, pin) => {
    const ins = shapeOf(n, library).inputs;
    let off = -1;
    for (const p of ins) if (p.pin === pin) off = p.off;
    let free = Infinity;
    for (const p of ins) if (p.off > off) free = Math.min(free, p.off - off);
    return free;
  };
  const laidOut: { group: Group; laid: LaidNetwork; findings: Finding[] }[] = [];
  const layOut = (g: Group, findings: Finding[]): LaidNetwork => {
    const key = cache.enabled ? shapeKey(nodes, g.nodes) : '';
    const known = cache.needCols(key);
    const template = known === undefined ? undefined : cache.template(key, Math.max(MIN_COLS, known));
    let laid: LaidOut;
    let mismatches: Mismatch[] = [];
    if (template) {
      laid = instantiate(template, nodes, g.nodes);
    } else {
      // Every layout is checked against the file; the first strategy that draws it exactly wins.
      // `base` is the file's graph as drawn: the nodes, or a copy with implicit ENs left open.
      let base: readonly GNode[] = nodes;
      let best: { laid: LaidOut; mismatches: Mismatch[]; needCols: number } | undefined;
      const tryAll = (view: CutView = { nodes: base, members: g.nodes }) => {
        for (let s = 0; s < LAYOUT_STRATEGIES; s++) {
          const prepared = prepareLayout(view.nodes, view.members, library, s);
          const tryLaid = prepared.run(Math.max(MIN_COLS, prepared.needCols));
          const m = verify(base, g.nodes, tryLaid, library);
          if (!best || m.length < best.mismatches.length)
            best = { laid: tryLaid, mismatches: m, needCols: prepared.needCols };
          if (!m.length) return;
        }
      };
      const first = () =>
        cutWires === 'all' ? tryAll(cutView(base, g.nodes, allNodeWires(base, g.nodes), room)) : tryAll();
      first();
      // A block whose EN the file leaves out runs unconditionally (MATIEC, and the engine, run a
      // block with an open EN): drawn with EN wired to the rail where the rail reaches it, open
      // where it cannot (a function fed by another block's output, FBD style). The file's nodes
      // stay as read (a network read again, or of the same shape, starts from them).
      const implicit = best!.mismatches.length ? g.nodes.filter((i) => nodes[i]!.implicitEn) : [];
      if (implicit.length) {
        const before = best!;
        const open = nodes.slice();
        for (const i of implicit) {
          const n = { ...nodes[i]!, inputs: new Map(nodes[i]!.inputs) };
          n.inputs.delete('EN');
          open[i] = n;
        }
        base = open;
        best = undefined;
        first();
        if (best!.mismatches.length >= before.mismatches.length) {
          base = nodes;
          best = before;
        }
      }
      // Wires the grid cannot route are drawn through connector/continuation pairs (layoutCut.ts).
      if (best!.mismatches.length && cutWires === 'needed') {
        const cuts: CutPin[] = [];
        for (let round = 0; round < CUT_ROUNDS && best!.mismatches.length; round++) {
          addCuts(base, g.nodes, best!.mismatches, cuts);
          tryAll(cutView(base, g.nodes, cuts, room));
        }
        if (best!.mismatches.length) tryAll(cutView(base, g.nodes, allNodeWires(base, g.nodes), room));
      }
      ({ laid, mismatches } = best!);
      cache.remember(key, best!.needCols, g.nodes, laid, mismatches);
    }
    findings.length = 0;
    for (const m of mismatches) findings.push(mismatchFinding(nodes, m));
    const data = elementData(nodes, g.nodes, laid);
    const anchors = turns ? anchorsOf(nodes, g.nodes, laid, library) : undefined;
    return {
      rows: laid.rows,
      cols: laid.cols,
      elements: laid.elements,
      vlinks: laid.vlinks,
      ...(data ? { elementData: data } : {}),
      ...(anchors?.length ? { anchors } : {}),
    };
  };
  for (const g of groups) {
    const findings: Finding[] = [];
    laidOut.push({ group: g, laid: layOut(g, findings), findings });
  }

  const items: BatchItem[] = laidOut.map((l) => ({
    kind: 'network',
    key: l.group.key,
    rank: RANK.network,
    laid: l.laid,
    findings: l.findings,
  }));
  // A label or comment drawn beside the first row of its network still belongs to it.
  const keyOfSingle = (o: RawObject): number[] => {
    const k = keyOf([o]);
    if (hasGeometry && k[0] === 1) k[1] = k[1]! - 20;
    return k;
  };
  for (const o of graph.labels)
    items.push({ kind: 'label', key: keyOfSingle(o), rank: RANK.label, text: o.text });
  for (const o of graph.comments)
    items.push({ kind: 'comment', key: keyOfSingle(o), rank: RANK.comment, ...commentOf(o) });
  for (const o of graph.vendor)
    items.push({ kind: 'vendor', key: keyOfSingle(o), rank: RANK.vendor, raw: raw(o.xml) });
  return items;
}

function commentsOf(list: readonly { text: string; title: string }[]): { comment: string; title: string } {
  let title = '';
  const texts: string[] = [];
  for (const c of list) {
    if (c.title) title = c.title;
    if (c.text) texts.push(c.text);
  }
  return { comment: texts.join('\n'), title };
}

/** A comment's text, and the network title Rungsmith keeps in its addData. */
function commentOf(o: RawObject): { text: string; title: string } {
  const add = o.hasAddData ? child(o.xml, 'addData') : undefined;
  const mine = add ? childrenNamed(add, 'data').find((d) => d.attrs.name === RS_NETWORK) : undefined;
  return { text: o.text, title: mine?.children[0]?.attrs.title ?? '' };
}

/**
 * The generator's statements of one network: its coils and the variables written beside its block
 * outputs (outVariables; one drawn as a MOVE), without executionOrderId (those run first anyway).
 */
function anchorsOf(nodes: readonly GNode[], members: readonly number[], laid: LaidOut, library: BlockLibrary): Anchor[] {
  const out: Anchor[] = [];
  // A network holds a few coils and boxes: found by a scan, no map per network (10,000 networks).
  const placed: LdElement[] = [];
  for (const el of laid.elements) if (el.kind === 'coil' || el.kind === 'box') placed.push(el);
  const find = (id: ElementId | undefined) => {
    if (id !== undefined) for (const el of placed) if (el.id === id) return el;
    return undefined;
  };
  for (const i of members) {
    const n = nodes[i]!;
    if ((n.kind !== 'coil' && n.kind !== 'box') || n.obj.executionOrderId > 0) continue;
    const el = find(laid.elementOf.get(i));
    if (!el) continue;
    const { obj } = n;
    if (n.kind === 'coil') out.push({ x: obj.pos.x, y: obj.pos.y, order: obj.order, key: el.id, row: el.row, col: el.col });
    if (n.kind !== 'box') continue;
    const variable = obj.kind === 'outVariable' || obj.kind === 'inOutVariable';
    if (!variable && !n.outputAt) continue;
    const shape = shapeOf(n, library);
    const pinAt = (pin: string, o: RawObject) => {
      const off = shape.outputs.find((p) => p.pin === pin)?.off ?? 0;
      out.push({ x: o.pos.x, y: o.pos.y, order: o.order, key: `${el.id}.${pin.toUpperCase()}`, row: el.row + off, col: el.col + shape.w });
    };
    if (variable) pinAt('OUT', obj);
    for (const [pin, o] of Object.entries(n.outputAt ?? {})) pinAt(pin, o);
  }
  // In the engine's order without turns (generated.ts): row, then column.
  return out.length > 1 ? out.sort((p, q) => p.row - q.row || p.col - q.col) : out;
}

function elementData(
  nodes: readonly GNode[],
  members: readonly number[],
  laid: LaidOut,
): PreservedNetwork['elementData'] | undefined {
  let out: Record<string, readonly string[]> | undefined;
  for (const i of members) {
    const d = nodes[i]!.data;
    const id = laid.elementOf.get(i);
    if (d && id) (out ??= {})[id] = d;
  }
  return out;
}
