// Interpreting an LD body: power-flow nodes (contacts, coils, blocks, jumps, returns) with the
// sources of every input pin resolved (continuations followed, block output pins named, data
// variables folded into block operands), then split into networks (connected components).
import type { CoilType, ContactType } from '../model/elements';
import type { BlockLibrary } from '../model/library';
import { buildBox, canonicalPin } from './ldBlocks';
import type { RawConnection, RawObject, RawPin } from './ldObjects';
import { RS_COIL, RS_CONTACT } from './types';
import { child, childrenNamed, type XmlElement } from './xml/parse';
import type { Finding, GNode, GSource } from './ldNodes';

export interface LdGraph {
  readonly nodes: GNode[];
  readonly labels: RawObject[];
  readonly comments: RawObject[];
  readonly vendor: RawObject[];
}

export class LdGraphError extends Error {
  constructor(
    message: string,
    readonly obj: RawObject | undefined,
  ) {
    super(message);
  }
}

const RAIL: GSource = { kind: 'rail' };
const isTrue = (s: string) => /^(TRUE|BOOL#TRUE|BOOL#1)$/i.test(s.trim());

/** The Rungsmith addData marker value (`type` attribute) on an object, if any. */
function rsMarker(obj: RawObject, name: string): string | undefined {
  if (!obj.hasAddData) return undefined;
  const add = child(obj.xml, 'addData');
  if (!add) return undefined;
  for (const d of childrenNamed(add, 'data')) if (d.attrs.name === name) return d.children[0]?.attrs.type;
  return undefined;
}

/**
 * Builds the node graph of one LD (or FBD) body. `raw` gives the source text of an element (for
 * preserved data); `library` knows the standard blocks and the file's own FBs and functions.
 */
export function buildLdGraph(
  objects: readonly RawObject[],
  raw: (el: XmlElement) => string,
  warn: (f: Finding) => void,
  library: BlockLibrary,
  /** Whether a variable of the POU is BOOL (for negated inputs of generic blocks). */
  isBool?: (name: string) => boolean,
): LdGraph {
  const byId = new Map<string, RawObject>();
  for (const o of objects) {
    if (!o.localId) {
      if (o.kind !== 'addData' && o.kind !== 'documentation')
        throw new LdGraphError(`<${o.kind}> has no localId`, o);
      continue;
    }
    if (byId.has(o.localId))
      throw new LdGraphError(
        `localId ${o.localId} is used twice (<${byId.get(o.localId)!.kind}> and <${o.kind}>)`,
        o,
      );
    byId.set(o.localId, o);
  }
  const connectors = new Map<string, RawObject>();
  for (const o of objects) if (o.kind === 'connector') connectors.set(o.text.toUpperCase(), o);

  const nodes: GNode[] = [];
  const nodeOf = new Map<RawObject, GNode>();
  const labels: RawObject[] = [];
  const comments: RawObject[] = [];
  const vendor: RawObject[] = [];
  const newNode = (obj: RawObject, kind: GNode['kind'], order: number): GNode => {
    const n: GNode = {
      index: nodes.length,
      obj,
      kind,
      inputs: new Map(),
      operandsIn: {},
      operandsOut: {},
      x: obj.pos.x,
      y: obj.pos.y,
      order,
      feedsRightRail: false,
    };
    // A block's (or, for a MOVE drawn for an outVariable, the variable's) execution order.
    if (kind === 'box' && obj.executionOrderId > 0) n.executionOrder = obj.executionOrderId;
    nodes.push(n);
    nodeOf.set(obj, n);
    return n;
  };

  objects.forEach((o, order) => {
    switch (o.kind) {
      case 'contact': {
        const edge = o.attr('edge');
        const negated = o.attr('negated') === 'true';
        const c: ContactType = edge === 'rising' ? 'P' : edge === 'falling' ? 'N' : negated ? 'NC' : 'NO';
        if ((edge === 'rising' || edge === 'falling') && negated)
          warn({
            message: `contact "${o.text}" is both negated and edge-triggered; Rungsmith keeps the edge (${c}) and drops the negation`,
            obj: o,
          });
        const n = newNode(o, 'contact', order);
        n.contact = c;
        n.variable = o.text;
        break;
      }
      case 'coil': {
        const marker = rsMarker(o, RS_COIL) as CoilType | undefined;
        const storage = o.attr('storage');
        const edge = o.attr('edge');
        let c: CoilType = 'COIL';
        if (storage === 'set') c = 'SET';
        else if (storage === 'reset') c = 'RESET';
        else if (edge === 'rising') c = 'P';
        else if (edge === 'falling') c = 'N';
        else if (o.attr('negated') === 'true') c = 'NEG';
        if (marker === 'M' || marker === 'SM' || marker === 'RM') c = marker;
        const n = newNode(o, 'coil', order);
        n.coil = c;
        n.variable = o.text;
        break;
      }
      case 'block':
        if (rsMarker(o, RS_CONTACT) === 'NOT') {
          const n = newNode(o, 'contact', order);
          n.contact = 'NOT';
          n.variable = '';
        } else newNode(o, 'box', order);
        break;
      case 'jump': {
        const n = newNode(o, 'jump', order);
        n.target = o.text;
        break;
      }
      case 'return':
        newNode(o, 'return', order);
        break;
      case 'label':
        labels.push(o);
        break;
      case 'comment':
        comments.push(o);
        break;
      case 'vendorElement':
      case 'error':
        vendor.push(o);
        warn({ message: `<${o.kind}> kept unchanged for export; Rungsmith does not interpret it`, obj: o });
        break;
      default:
        break;
    }
  });

  // Every reference, through continuations, to the objects producing it.
  const dangling = new Set<RawConnection>();
  const resolve = (
    c: RawConnection,
    consumer: RawObject,
    seen?: Set<string>,
  ): { obj: RawObject | 'rail'; pin?: string }[] => {
    const src = byId.get(c.ref);
    if (!src) {
      // One dangling reference (an editor that deleted an object but not the wire into it) drops
      // that wire only: the rest of the body imports, and the finding names where it was.
      if (!dangling.has(c)) {
        dangling.add(c);
        warn({
          message: `<${consumer.kind}> localId ${consumer.localId} is connected to localId ${c.ref}, which does not exist; that wire is dropped`,
          obj: consumer,
        });
      }
      return [];
    }
    switch (src.kind) {
      case 'leftPowerRail':
        return [{ obj: 'rail' }];
      case 'continuation': {
        const conn = connectors.get(src.text.toUpperCase());
        if (!conn) {
          warn({
            message: `continuation "${src.text}" has no connector of that name; its wire is dropped`,
            obj: src,
          });
          return [];
        }
        // Created only when following continuations (never for the common direct wire).
        seen ??= new Set<string>();
        if (seen.has(conn.localId)) throw new LdGraphError(`connector "${src.text}" feeds itself`, conn);
        seen.add(conn.localId);
        const chain = seen;
        return conn.inputs[0]!.connections.flatMap((cc) => resolve(cc, conn, chain));
      }
      case 'contact':
      case 'coil':
      case 'inVariable':
      case 'inOutVariable':
        return [{ obj: src }];
      case 'block': {
        if (c.formal) return [{ obj: src, pin: c.formal }];
        const first = src.outputs.find((p) => p.pin.toUpperCase() !== 'ENO') ?? src.outputs[0];
        return [{ obj: src, pin: first?.pin ?? 'OUT' }];
      }
      default:
        throw new LdGraphError(
          `<${consumer.kind}> localId ${consumer.localId} is connected to <${src.kind}> localId ${src.localId}, which has no output`,
          consumer,
        );
    }
  };

  // Variables standing for data: an inVariable read by a block pin is that pin's operand; elsewhere it
  // becomes a normally-open contact. An outVariable written by a block pin is that pin's operand;
  // fed by power flow it becomes a coil.
  const asContact = new Map<RawObject, GNode>();
  const dataContact = (o: RawObject): GSource => {
    if (isTrue(o.text)) return RAIL;
    let n = asContact.get(o);
    if (!n) {
      n = newNode(o, 'contact', o.executionOrderId);
      n.contact = 'NO';
      n.variable = o.text;
      n.inputs.set('in', [RAIL]);
      asContact.set(o, n);
      warn({ message: `variable "${o.text}" used as power flow became a normally-open contact`, obj: o });
    }
    return { kind: 'node', node: n.index, pin: 'out' };
  };

  /** The block output feeding an inOutVariable, when it is its only source. */
  const blockBehind = (o: RawObject): { node: GNode; pin: string } | undefined => {
    const conns = o.inputs[0]?.connections ?? [];
    if (conns.length !== 1) return undefined;
    const r = resolve(conns[0]!, o);
    const only = r.length === 1 ? r[0]! : undefined;
    if (!only || only.obj === 'rail' || only.obj.kind !== 'block' || !library.signature(only.obj.text))
      return undefined;
    const node = nodeOf.get(only.obj);
    return node && node.kind === 'box' ? { node, pin: boxPin(only.obj, only.pin ?? 'OUT') } : undefined;
  };
  const moveNode = (o: RawObject, input: GSource | string): GNode => {
    const n = newNode(o, 'box', o.executionOrderId);
    n.blockType = 'MOVE';
    n.inputs.set('EN', [RAIL]);
    n.implicitEn = true;
    if (typeof input === 'string') n.operandsIn.IN = input;
    else n.inputs.set('IN', [input]);
    n.operandsOut.OUT = o.text;
    return n;
  };

  /** Whether a wire carries BOOL: power flow, or a block output declared BOOL. */
  const boolSource = (s: GSource): boolean => {
    if (s.kind === 'rail') return true;
    const src = nodes[s.node]!;
    if (src.kind !== 'box') return true;
    return (
      library.signature(src.blockType ?? src.obj.text)?.outputs.find((p) => p.name === s.pin)?.type === 'BOOL'
    );
  };
  /** The model's name of a pin of a block object (see canonicalPin). */
  const boxPin = (o: RawObject, pin: string): string => canonicalPin(library.signature(o.text), pin);
  const pinName = (n: GNode, pin: string): string | undefined => {
    if (n.kind !== 'box')
      return n.kind === 'contact' && n.contact === 'NOT'
        ? pin.toUpperCase() === 'OUT'
          ? 'out'
          : 'in'
        : 'out';
    return boxPin(n.obj, pin);
  };
  const sourcesOf = (pin: RawPin, consumer: RawObject, operandTarget?: (text: string) => void): GSource[] => {
    // Most pins: one wire straight from the rail, a contact or a coil (no intermediate results).
    if (pin.connections.length === 1) {
      const src = byId.get(pin.connections[0]!.ref);
      if (src?.kind === 'leftPowerRail') return [RAIL];
      if (src?.kind === 'contact' || src?.kind === 'coil') {
        const n = nodeOf.get(src);
        return n ? [{ kind: 'node', node: n.index, pin: 'out' }] : [];
      }
    }
    const out: GSource[] = [];
    const all =
      pin.connections.length === 1
        ? resolve(pin.connections[0]!, consumer)
        : pin.connections.flatMap((c) => resolve(c, consumer));
    for (const r of all) {
      if (r.obj === 'rail') out.push(RAIL);
      else if (r.obj.kind === 'inVariable' || r.obj.kind === 'inOutVariable') {
        if (operandTarget && all.length === 1) operandTarget(r.obj.text);
        else out.push(dataContact(r.obj));
      } else {
        const n = nodeOf.get(r.obj);
        if (!n) continue;
        if (n.kind === 'box' && !library.signature(n.obj.text)) {
          warn({
            message: `the wire from block ${n.obj.text} (localId ${n.obj.localId}) cannot be kept: Rungsmith does not know its pins`,
            obj: consumer,
          });
          continue;
        }
        const pin = pinName(n, r.pin ?? 'out')!;
        if (n.kind === 'box' && !hasPin(n, pin)) {
          // A pin the block does not have (a vendor's block of the same name with other pins): its
          // wire is dropped and said, rather than drawn from a pin that does not exist.
          warn({
            message: `the wire from output ${r.pin} of block ${n.obj.text} (localId ${n.obj.localId}) cannot be kept: ${n.obj.text} has no pin ${r.pin}`,
            obj: consumer,
          });
          continue;
        }
        out.push({ kind: 'node', node: n.index, pin });
      }
    }
    return out;
  };
  const hasPin = (n: GNode, pin: string): boolean => {
    const sig = library.signature(n.blockType ?? n.obj.text);
    if (!sig || pin === 'ENO' || pin === 'EN') return true;
    return sig.outputs.some((p) => p.name === pin) || sig.inputs.some((p) => p.name === pin);
  };

  for (const n of [...nodes]) {
    const o = n.obj;
    if (n.kind === 'box')
      buildBox(n, o, sourcesOf, warn, library, (what, boolPin) => {
        const variable = typeof what === 'string' ? what : undefined;
        if (
          !boolPin &&
          (variable !== undefined ? !isBool?.(variable) : !(what as GSource[]).every(boolSource))
        )
          return undefined;
        const c = newNode(o, 'contact', n.order);
        c.contact = variable !== undefined ? 'NC' : 'NOT';
        c.variable = variable ?? '';
        c.inputs.set('in', variable !== undefined ? [RAIL] : (what as GSource[]));
        nodeOf.set(o, n); // the block's object still names the block
        return { kind: 'node', node: c.index, pin: 'out' };
      });
    else if (n.kind === 'contact' && n.contact === 'NOT' && o.kind === 'block') {
      const src = sourcesOf(o.inputs[0] ?? { pin: 'IN', connections: [], negated: false }, o);
      if (src.length) n.inputs.set('in', src);
    } else if (!asContact.has(o)) {
      const pin = o.inputs[0];
      if (pin) {
        const src = sourcesOf(pin, o);
        if (src.length) n.inputs.set('in', src);
      }
    }
  }

  // A contact after a continuation whose connector gathers an OR: Beremiz's generator pastes the
  // connector's expression without brackets (`I3 AND I1 OR I2`), so the PLC runs other logic than
  // the drawing, which Rungsmith runs (a connector pair is a wire). Said at import; an export from
  // Rungsmith writes the wire directly (or LD-X06 names a pair it keeps).
  if (connectors.size)
    for (const o of objects) {
      if (o.kind !== 'contact' || o.inputs[0]?.connections.length !== 1) continue;
      const cont = byId.get(o.inputs[0].connections[0]!.ref);
      const conn = cont?.kind === 'continuation' ? connectors.get(cont.text.toUpperCase()) : undefined;
      const feeds = conn?.inputs[0]?.connections.map((c) => byId.get(c.ref)) ?? [];
      if (feeds.length < 2 || feeds.some((f) => !f || f.kind === 'leftPowerRail')) continue;
      // Paths that end in the same element are factorized into one AND (`(A OR B) AND X`): no OR on top.
      const start = (f: RawObject): string => {
        let at = f;
        for (let k = 0; k < 64 && at.kind === 'contact' && at.inputs[0]?.connections.length === 1; k++) {
          const next = byId.get(at.inputs[0].connections[0]!.ref);
          if (!next || next.kind === 'leftPowerRail') return at.localId;
          at = next;
        }
        return `${at.localId}*`;
      };
      const starts = new Set(feeds.map((f) => start(f!)));
      if (starts.size === 1 && ![...starts][0]!.endsWith('*') && feeds.every((f) => start(f!) !== f!.localId))
        continue;
      const railFed = (f: RawObject) =>
        f.kind === 'contact' &&
        f.attr('negated') !== 'true' &&
        !f.attr('edge') &&
        f.inputs[0]?.connections.length === 1 &&
        byId.get(f.inputs[0].connections[0]!.ref)?.kind === 'leftPowerRail';
      const generated = feeds.every((f) => railFed(f!))
        ? ` (they write ${o.text} AND ${feeds.map((f) => f!.text).join(' OR ')})`
        : '';
      warn({
        message: `contact "${o.text}" follows continuation "${cont!.text}", whose connector gathers an OR: Beremiz and OpenPLC paste that OR without brackets after the contact${generated}, so AND binds before OR there; Rungsmith runs the drawing (the whole OR in series with "${o.text}"); an export from Rungsmith gives them the drawing (its review names any connector pair it keeps, LD-X06)`,
        obj: o,
      });
    }

  // Pins the file wires through one of its own connector pairs: drawn with that name where cut.
  if (connectors.size)
    for (const n of nodes) {
      const o = n.obj;
      if (nodeOf.get(o) !== n) continue;
      const pins = n.kind === 'box' ? o.inputs : o.inputs.slice(0, 1);
      for (const pin of pins) {
        const c = pin.connections.length === 1 ? byId.get(pin.connections[0]!.ref) : undefined;
        if (c?.kind !== 'continuation') continue;
        const name = n.kind === 'box' ? boxPin(o, pin.pin) : 'in';
        if (n.inputs.has(name)) (n.via ??= {})[name] = c.text;
      }
    }

  // Data variables written in the body.
  for (const o of objects) {
    if (o.kind !== 'outVariable' && o.kind !== 'inOutVariable') continue;
    const pin = o.inputs[0];
    if (!pin || !pin.connections.length) continue;
    const all = pin.connections.flatMap((c) => resolve(c, o));
    const single = all.length === 1 ? all[0]! : undefined;
    if (single && single.obj !== 'rail' && single.obj.kind === 'block') {
      const n = nodeOf.get(single.obj)!;
      const p = boxPin(single.obj, single.pin ?? 'OUT');
      if (n.operandsOut[p] === undefined) {
        n.operandsOut[p] = o.text;
        if (o.executionOrderId > 0) (n.outputOrders ??= {})[p] = o.executionOrderId;
        else (n.outputAt ??= {})[p] = o;
        continue;
      }
      if (library.signature(single.obj.text)) {
        // A second variable on the same output: copied by a MOVE wired to that output.
        moveNode(o, { kind: 'node', node: n.index, pin: p });
        warn({
          message: `block output ${single.obj.attr('instanceName') ?? single.obj.text}.${p} also goes to "${o.text}": drawn as a MOVE`,
          obj: o,
        });
        continue;
      }
    }
    if (
      single &&
      single.obj !== 'rail' &&
      (single.obj.kind === 'inVariable' || single.obj.kind === 'inOutVariable')
    ) {
      // Variable to variable (Out := Cnt): a MOVE, wired to the block behind Cnt when there is one.
      const behind = single.obj.kind === 'inOutVariable' ? blockBehind(single.obj) : undefined;
      moveNode(o, behind ? { kind: 'node', node: behind.node.index, pin: behind.pin } : single.obj.text);
      warn({
        message: `the assignment of "${single.obj.text}" to "${o.text}" is drawn as a MOVE block`,
        obj: o,
      });
      continue;
    }
    const coil = newNode(o, 'coil', o.executionOrderId);
    coil.coil = 'COIL';
    coil.variable = o.text;
    const src = sourcesOf(pin, o);
    if (src.length) coil.inputs.set('in', src);
    warn({ message: `variable "${o.text}" written by power flow became a coil`, obj: o });
  }

  // Right rails only collect wires; remember who reaches them (for drawing).
  for (const o of objects) {
    if (o.kind !== 'rightPowerRail') continue;
    for (const pin of o.inputs)
      for (const c of pin.connections)
        for (const r of resolve(c, o)) {
          if (r.obj === 'rail') continue;
          const n = nodeOf.get(r.obj) ?? asContact.get(r.obj);
          if (n) n.feedsRightRail = true;
        }
  }

  // Unknown addData on graphical objects is kept per object.
  for (const n of nodes) {
    if (!n.obj.hasAddData || nodeOf.get(n.obj) !== n) continue;
    const add = child(n.obj.xml, 'addData');
    if (!add) continue;
    const keep: string[] = [];
    for (const d of childrenNamed(add, 'data')) {
      if (d.attrs.name === RS_COIL || d.attrs.name === RS_CONTACT) continue;
      if (d.attrs.handleUnknown === 'discard')
        warn({ message: `addData "${d.attrs.name}" dropped (handleUnknown="discard")`, obj: n.obj });
      else keep.push(raw(d));
    }
    if (keep.length) n.data = keep;
  }
  return { nodes, labels, comments, vendor };
}
