// One network grid → PLCopen LD objects with real coordinates, relPosition on every pin and wire
// points on every connection (first point at the consumer, last at the producer).
import type { CoilElement, ContactElement, LdElement } from '../model/elements';
import type { BlockLibrary } from '../model/library';
import type { Network } from '../model/project';
import {
  BOX_MARGIN_X,
  CELL_W,
  COMMENT_H,
  ELEMENT_H,
  ELEMENT_W,
  LEFT_X,
  RAIL_W,
  ROW_H,
  boundaryX,
  rowY,
  type Point,
} from './geometry';
import { elementPins, gridGraph, type Source } from './gridGraph';
import { boxPins, rel, writeBox } from './exportBlock';
import type { Connect, IdAllocator, Placed } from './exportPlaced';
import { RS_CONTACT, RS_COIL, RS_NETWORK, preserved, type PreservedNetwork } from './types';
import { escapeAttr, type XmlWriter } from './xml/write';

const pt = (x: number, y: number): Point => ({ x, y });

function contactAttrs(el: ContactElement): Record<string, string | undefined> {
  return {
    negated: el.contact === 'NC' ? 'true' : 'false',
    edge: el.contact === 'P' ? 'rising' : el.contact === 'N' ? 'falling' : undefined,
  };
}

function coilAttrs(el: CoilElement): Record<string, string | undefined> {
  const c = el.coil;
  return {
    negated: c === 'NEG' ? 'true' : 'false',
    storage: c === 'SET' || c === 'SM' ? 'set' : c === 'RESET' || c === 'RM' ? 'reset' : undefined,
    edge: c === 'P' ? 'rising' : c === 'N' ? 'falling' : undefined,
  };
}

/** Writes the LD objects of one network starting at y = top; returns the y below it. */
export function writeNetwork(
  w: XmlWriter,
  net: Network,
  top: number,
  ids: IdAllocator,
  library: BlockLibrary,
): number {
  const g = gridGraph(net, library);
  const keep = preserved<PreservedNetwork>(net.extensions);
  if (net.comment || net.title) {
    const id = ids.next();
    w.open('comment', { localId: id, height: COMMENT_H - 10, width: Math.max(net.cols, 4) * CELL_W }, () => {
      w.empty('position', { x: LEFT_X, y: top });
      w.formatted('content', net.comment);
      if (net.title) {
        w.open('addData', undefined, () =>
          w.raw(
            `<data name="${RS_NETWORK}" handleUnknown="discard"><network xmlns="" title="${escapeAttr(net.title)}"/></data>`,
          ),
        );
      }
    });
    top += COMMENT_H;
  }
  if (net.label !== undefined && net.label !== '') {
    const id = ids.next();
    w.open(
      'label',
      { localId: id, height: 20, width: Math.max(40, net.label.length * 8), label: net.label },
      () => w.empty('position', { x: LEFT_X, y: top }),
    );
    top += 30;
  }
  for (const raw of keep?.objects ?? []) w.raw(raw.replace(/localId="\d+"/, `localId="${ids.next()}"`));

  const railId = ids.next();
  const placed: Placed[] = net.elements.map((el) => placeElement(el, top, ids, library));
  const railRows = new Set<number>();
  g.sources.forEach((pins, ei) =>
    pins.forEach((srcs, pin) => {
      if (srcs.some((s) => s.kind === 'rail'))
        railRows.add(Math.round((placed[ei]!.pins.get(pin)!.y - top - ROW_H / 2) / ROW_H));
    }),
  );
  if (!railRows.size) railRows.add(0);
  const railX = LEFT_X - RAIL_W;
  const height = net.rows * ROW_H;
  w.open('leftPowerRail', { localId: railId, height, width: RAIL_W }, () => {
    w.empty('position', { x: railX, y: top });
    for (const r of [...railRows].sort((a, b) => a - b)) {
      w.line(() =>
        w.open('connectionPointOut', { formalParameter: '' }, () =>
          w.empty('relPosition', { x: RAIL_W, y: rowY(0, r) }),
        ),
      );
    }
  });

  const sourcePoint = (s: Source, consumer: Point): { ref: number; formal?: string; at: Point } => {
    if (s.kind === 'rail') return { ref: railId, at: pt(LEFT_X, consumer.y) };
    const p = placed[s.el]!;
    return { ref: p.id, formal: p.formal?.(s.pin), at: (p.outs ?? p.pins).get(s.pin)! };
  };
  // The hottest path of an export: one line per input pin, built as a string.
  const writeConnections = (
    consumer: Point,
    origin: Point,
    srcs: readonly Source[] | undefined,
    barX: number | undefined,
  ) => {
    let line = `<connectionPointIn><relPosition x="${consumer.x - origin.x}" y="${consumer.y - origin.y}"/>`;
    for (const s of srcs ?? []) {
      const { ref, formal, at } = sourcePoint(s, consumer);
      line += `<connection refLocalId="${ref}"${formal !== undefined ? ` formalParameter="${escapeAttr(formal)}"` : ''}>`;
      line += `<position x="${consumer.x}" y="${consumer.y}"/>`;
      if (at.y !== consumer.y) {
        const xm =
          barX !== undefined && barX <= consumer.x && barX >= at.x
            ? barX
            : Math.round((consumer.x + at.x) / 2);
        line += `<position x="${xm}" y="${consumer.y}"/><position x="${xm}" y="${at.y}"/>`;
      }
      line += `<position x="${at.x}" y="${at.y}"/></connection>`;
    }
    w.text(`${line}</connectionPointIn>`);
  };
  const barOf = (row: number, boundary: number): number | undefined => {
    const b = g.barBoundary.get(g.netOf(row, boundary));
    return b === undefined ? undefined : boundaryX(b);
  };

  net.elements.forEach((el, ei) => {
    const p = placed[ei]!;
    const srcOf = (pin: string) => g.sources.get(ei)?.get(pin);
    const pins = elementPins(el, library);
    const inBar = (pin: string) => {
      const pp = pins.inputs.find((x) => x.pin === pin);
      return pp ? barOf(pp.row, pp.boundary) : undefined;
    };
    writeElement(w, el, p, ids, srcOf, inBar, writeConnections, keep?.elementData?.[el.id], library);
  });

  const rightRows = [...g.rightRail.keys()].sort((a, b) => a - b);
  w.open('rightPowerRail', { localId: ids.next(), height, width: RAIL_W }, () => {
    const origin = pt(boundaryX(net.cols), top);
    w.empty('position', { x: origin.x, y: origin.y });
    for (const r of rightRows)
      writeConnections(pt(origin.x, rowY(top, r)), origin, g.rightRail.get(r), barOf(r, net.cols));
    if (!rightRows.length)
      w.line(() =>
        w.open('connectionPointIn', undefined, () => w.empty('relPosition', { x: 0, y: ROW_H / 2 })),
      );
  });
  return top + height;
}

function placeElement(el: LdElement, top: number, ids: IdAllocator, library: BlockLibrary): Placed {
  const x0 = boundaryX(el.col);
  const y = rowY(top, el.row);
  switch (el.kind) {
    case 'contact':
    case 'coil': {
      const left = x0 + Math.floor((CELL_W - ELEMENT_W) / 2);
      const pins = new Map([
        ['in', pt(left, y)],
        ['out', pt(left + ELEMENT_W, y)],
      ]);
      const notContact = el.kind === 'contact' && el.contact === 'NOT';
      if (notContact) {
        return {
          id: ids.next(),
          pins: new Map([
            ['in', pt(x0 + 10, y)],
            ['out', pt(x0 + CELL_W - 10, y)],
          ]),
          formal: () => 'OUT',
        };
      }
      return { id: ids.next(), pins };
    }
    case 'jump':
    case 'return':
      return { id: ids.next(), pins: new Map([['in', pt(x0 + 8, y)]]) };
    case 'link':
      return { id: -1, pins: new Map() };
    case 'connector':
      return { id: ids.next(), pins: new Map([['in', pt(x0 + 8, y)]]) };
    case 'continuation':
      return { id: ids.next(), pins: new Map([['out', pt(x0 + CELL_W - 8, y)]]) };
    case 'box': {
      const bp = boxPins(el, library);
      const left = x0 + BOX_MARGIN_X;
      const right = x0 + 2 * CELL_W - BOX_MARGIN_X;
      const pins = new Map<string, Point>();
      const outs = new Map<string, Point>();
      for (const i of bp.inputs) pins.set(i.name, pt(left, rowY(top, el.row + i.off)));
      for (const o of bp.outputs) outs.set(o.name, pt(right, rowY(top, el.row + o.off)));
      return { id: ids.next(), pins, outs, formal: (pin) => pin };
    }
  }
}

function writeElement(
  w: XmlWriter,
  el: LdElement,
  p: Placed,
  ids: IdAllocator,
  srcOf: (pin: string) => readonly Source[] | undefined,
  inBar: (pin: string) => number | undefined,
  connect: Connect,
  data: readonly string[] | undefined,
  library: BlockLibrary,
): void {
  // The object's last children: its addData, then its own comment as `<documentation>` (TC6 puts
  // documentation after addData in contact, coil, block, jump, return, connector and continuation).
  const addData = (extra?: string) => {
    const all = [...(extra ? [extra] : []), ...(data ?? [])];
    if (all.length) w.open('addData', undefined, () => all.forEach((d) => w.raw(d)));
    if (el.comment) w.formatted('documentation', el.comment);
  };
  switch (el.kind) {
    case 'link':
      return;
    case 'contact':
    case 'coil': {
      if (el.kind === 'contact' && el.contact === 'NOT') {
        const inP = p.pins.get('in')!;
        const origin = pt(inP.x, inP.y - 15);
        w.open('block', { localId: p.id, width: CELL_W - 20, height: 30, typeName: 'NOT' }, () => {
          w.empty('position', { x: origin.x, y: origin.y });
          w.open('inputVariables', undefined, () =>
            w.line(() =>
              w.open('variable', { formalParameter: 'IN' }, () =>
                connect(inP, origin, srcOf('in'), inBar('in')),
              ),
            ),
          );
          w.empty('inOutVariables');
          w.open('outputVariables', undefined, () =>
            w.line(() =>
              w.open('variable', { formalParameter: 'OUT' }, () =>
                w.open('connectionPointOut', undefined, () => rel(w, p.pins.get('out')!, origin)),
              ),
            ),
          );
          addData(`<data name="${RS_CONTACT}" handleUnknown="discard"><contact xmlns="" type="NOT"/></data>`);
        });
        return;
      }
      const inP = p.pins.get('in')!;
      const origin = pt(inP.x, inP.y - ELEMENT_H / 2);
      const attrs = el.kind === 'contact' ? contactAttrs(el) : coilAttrs(el);
      const retentive = el.kind === 'coil' && (el.coil === 'M' || el.coil === 'SM' || el.coil === 'RM');
      w.open(el.kind, { localId: p.id, height: ELEMENT_H, width: ELEMENT_W, ...attrs }, () => {
        w.text(`<position x="${origin.x}" y="${origin.y}"/>`);
        connect(inP, origin, srcOf('in'), inBar('in'));
        const out = p.pins.get('out')!;
        w.text(
          `<connectionPointOut><relPosition x="${out.x - origin.x}" y="${out.y - origin.y}"/></connectionPointOut>`,
        );
        w.leaf('variable', el.variable);
        addData(
          retentive
            ? `<data name="${RS_COIL}" handleUnknown="discard"><coil xmlns="" type="${el.coil}"/></data>`
            : undefined,
        );
      });
      return;
    }
    case 'jump':
    case 'return': {
      const inP = p.pins.get('in')!;
      const origin = pt(inP.x, inP.y - ELEMENT_H / 2);
      w.open(
        el.kind,
        {
          localId: p.id,
          height: ELEMENT_H,
          width: CELL_W - 16,
          label: el.kind === 'jump' ? el.target : undefined,
        },
        () => {
          w.empty('position', { x: origin.x, y: origin.y });
          connect(inP, origin, srcOf('in'), inBar('in'));
          addData();
        },
      );
      return;
    }
    case 'box':
      writeBox(w, el, p, ids, srcOf, inBar, connect, addData, library);
      return;
    case 'connector': {
      const inP = p.pins.get('in')!;
      const origin = pt(inP.x, inP.y - ELEMENT_H / 2);
      w.open('connector', { name: el.name, localId: p.id, height: ELEMENT_H, width: CELL_W - 16 }, () => {
        w.empty('position', { x: origin.x, y: origin.y });
        connect(inP, origin, srcOf('in'), inBar('in'));
        addData();
      });
      return;
    }
    case 'continuation': {
      const out = p.pins.get('out')!;
      const origin = pt(out.x - (CELL_W - 16), out.y - ELEMENT_H / 2);
      w.open('continuation', { name: el.name, localId: p.id, height: ELEMENT_H, width: CELL_W - 16 }, () => {
        w.empty('position', { x: origin.x, y: origin.y });
        w.open('connectionPointOut', undefined, () => rel(w, out, origin));
        addData();
      });
      return;
    }
  }
}
