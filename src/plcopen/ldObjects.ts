// Reading the objects of a PLCopen LD body: positions, pins and the connections recorded on the
// consumer side. No interpretation yet (see ldGraph.ts).
import { inputAliases } from '../model/vendorPins';
import type { Point } from './geometry';
import { deepText, type XmlDoc, type XmlElement } from './xml/parse';

/** A wire as recorded on its consumer. Route points and pin offsets are not read: the grid is built
 * from the wiring (topology), and these files run to hundreds of thousands of wires. */
export interface RawConnection {
  readonly ref: string;
  readonly formal?: string;
}

export interface RawPin {
  readonly pin: string;
  readonly connections: readonly RawConnection[];
  readonly negated: boolean;
  readonly edge?: string;
  /** CODESYS writes a variable assigned to a block output as `<connectionPointOut><expression>`. */
  readonly expression?: string;
}

export interface RawObject {
  readonly kind: string;
  readonly localId: string;
  /** The element in the file (made on demand: most objects never need it). */
  readonly xml: XmlElement;
  /** Whether the element has an `<addData>` child (markers and preserved vendor data). */
  readonly hasAddData: boolean;
  readonly pos: Point;
  readonly width: number;
  readonly height: number;
  readonly executionOrderId: number;
  readonly inputs: readonly RawPin[];
  readonly outputs: readonly RawPin[];
  /** contact/coil variable, in/outVariable expression, label/jump label, connector name, comment text. */
  readonly text: string;
  /** An attribute of the element (read from the document, without building the element). */
  attr(name: string): string | undefined;
  /** The text of the element's `<documentation>` (an element's own comment), '' when none. Read on demand. */
  documentation(): string;
  /** Position among the children of the body (file order). */
  readonly order: number;
}

/** Output pins never hold connections (PLCopen records wires on the consumer side). */
const NO_CONNECTIONS: readonly RawConnection[] = Object.freeze([]);

type MutablePin = { -readonly [K in keyof RawPin]: RawPin[K] };

/** The ids of the names a reader of LD objects looks for (an object literal: its fields stay in the object). */
const namesOf = (d: XmlDoc) => ({
  position: d.id('position'),
  x: d.id('x'),
  y: d.id('y'),
  connectionPointIn: d.id('connectionPointIn'),
  connectionPointOut: d.id('connectionPointOut'),
  connection: d.id('connection'),
  refLocalId: d.id('refLocalId'),
  formalParameter: d.id('formalParameter'),
  expression: d.id('expression'),
  variable: d.id('variable'),
  negated: d.id('negated'),
  edge: d.id('edge'),
  label: d.id('label'),
  name: d.id('name'),
  typeName: d.id('typeName'),
  inputVariables: d.id('inputVariables'),
  inOutVariables: d.id('inOutVariables'),
  outputVariables: d.id('outputVariables'),
  content: d.id('content'),
  addData: d.id('addData'),
  localId: d.id('localId'),
  width: d.id('width'),
  height: d.id('height'),
  executionOrderId: d.id('executionOrderId'),
});

class LdObject implements RawObject {
  constructor(
    private readonly doc: XmlDoc,
    private readonly index: number,
    readonly kind: string,
    readonly localId: string,
    readonly pos: Point,
    readonly width: number,
    readonly height: number,
    readonly executionOrderId: number,
    readonly inputs: readonly RawPin[],
    readonly outputs: readonly RawPin[],
    readonly text: string,
    readonly order: number,
    readonly hasAddData: boolean,
  ) {}
  get xml(): XmlElement {
    return this.doc.element(this.index);
  }
  attr(name: string): string | undefined {
    const id = this.doc.id(name);
    return id === -1 ? undefined : this.doc.attr(this.index, id);
  }
  documentation(): string {
    const id = this.doc.id('documentation');
    const c = id === -1 ? -1 : this.doc.childById(this.index, id);
    return c === -1 ? '' : deepText(this.doc.element(c)).trim();
  }
}

/** Reads the LD objects of one body from its document. */
class Reader {
  private readonly n: ReturnType<typeof namesOf>;
  constructor(private readonly d: XmlDoc) {
    this.n = namesOf(d);
  }

  /** Negation and edge of a block pin (`<variable negated="true" edge="rising">`). */
  private pinFlags(pin: MutablePin, el: number): void {
    const neg = this.d.attr(el, this.n.negated);
    pin.negated = neg === 'true' || neg === '1';
    const edge = this.d.attr(el, this.n.edge);
    if (edge && edge !== 'none') pin.edge = edge;
  }

  /** An input pin and the connections on its `connectionPointIn` (cp; -1 if absent). `flagsOf` is a block pin variable. */
  pointIn(cp: number, pin: string, flagsOf = -1): RawPin {
    const d = this.d;
    const connections: RawConnection[] = [];
    const out: MutablePin = { pin, connections, negated: false };
    if (cp !== -1) {
      const connection = this.n.connection;
      for (let c = d.firstChild[cp]!; c !== -1; c = d.nextSibling[c]!) {
        if (d.lid[c] !== connection) continue;
        const ref = d.attr(c, this.n.refLocalId) ?? '';
        const formal = d.attr(c, this.n.formalParameter);
        connections.push(formal !== undefined && formal !== '' ? { ref, formal } : { ref });
      }
    }
    if (flagsOf !== -1) this.pinFlags(out, flagsOf);
    return out;
  }

  /** An output pin; CODESYS may name the assigned variable in `<connectionPointOut><expression>`. */
  pointOut(cp: number, pin: string, flagsOf = -1): RawPin {
    const d = this.d;
    const out: MutablePin = { pin, connections: NO_CONNECTIONS, negated: false };
    if (cp !== -1) {
      const expression = this.n.expression;
      for (let c = d.firstChild[cp]!; c !== -1; c = d.nextSibling[c]!) {
        if (d.lid[c] !== expression) continue;
        const e = d.text(c).trim();
        if (e) out.expression = e;
      }
    }
    if (flagsOf !== -1) this.pinFlags(out, flagsOf);
    return out;
  }

  /** The pins of the `<variable>` children of a block's pin list (list: -1 if absent). */
  private blockPins(list: number, inputs: RawPin[] | undefined, outputs: RawPin[] | undefined): void {
    const d = this.d;
    const n = this.n;
    if (list === -1) return;
    for (let v = d.firstChild[list]!; v !== -1; v = d.nextSibling[v]!) {
      if (d.lid[v] !== n.variable) continue;
      const formal = d.attr(v, n.formalParameter) ?? '';
      if (inputs) inputs.push(this.pointIn(d.childById(v, n.connectionPointIn), formal, v));
      if (outputs) outputs.push(this.pointOut(d.childById(v, n.connectionPointOut), formal, v));
    }
  }

  object(el: number, order: number): RawObject {
    const d = this.d;
    const n = this.n;
    const p = d.childById(el, n.position);
    const pos: Point = p === -1 ? { x: 0, y: 0 } : { x: d.attrNumber(p, n.x), y: d.attrNumber(p, n.y) };
    const inputs: RawPin[] = [];
    const outputs: RawPin[] = [];
    let text = '';
    const kind = d.name(el);
    switch (kind) {
      case 'leftPowerRail': {
        let k = 0;
        for (let c = d.firstChild[el]!; c !== -1; c = d.nextSibling[c]!)
          if (d.lid[c] === n.connectionPointOut) outputs.push(this.pointOut(c, String(k++)));
        break;
      }
      case 'rightPowerRail': {
        let k = 0;
        for (let c = d.firstChild[el]!; c !== -1; c = d.nextSibling[c]!)
          if (d.lid[c] === n.connectionPointIn) inputs.push(this.pointIn(c, String(k++)));
        break;
      }
      case 'contact':
      case 'coil':
      case 'inVariable':
      case 'outVariable':
      case 'inOutVariable': {
        const cpIn = d.childById(el, n.connectionPointIn);
        const cpOut = d.childById(el, n.connectionPointOut);
        if (cpIn !== -1 || kind !== 'inVariable') inputs.push(this.pointIn(cpIn, 'in'));
        if (cpOut !== -1 || kind !== 'outVariable') outputs.push(this.pointOut(cpOut, 'out'));
        let t = d.childById(el, n.variable);
        if (t === -1) t = d.childById(el, n.expression);
        text = t === -1 ? '' : d.text(t).trim();
        break;
      }
      case 'jump':
      case 'return':
      case 'connector':
        inputs.push(this.pointIn(d.childById(el, n.connectionPointIn), 'in'));
        text = d.attr(el, n.label) ?? d.attr(el, n.name) ?? '';
        break;
      case 'continuation':
        outputs.push(this.pointOut(d.childById(el, n.connectionPointOut), 'out'));
        text = d.attr(el, n.name) ?? '';
        break;
      case 'label':
        text = d.attr(el, n.label) ?? '';
        break;
      case 'comment': {
        const content = d.childById(el, n.content);
        text = content === -1 ? '' : deepText(d.element(content)).trim();
        break;
      }
      case 'block': {
        this.blockPins(d.childById(el, n.inputVariables), inputs, undefined);
        this.blockPins(d.childById(el, n.inOutVariables), inputs, outputs);
        this.blockPins(d.childById(el, n.outputVariables), undefined, outputs);
        text = d.attr(el, n.typeName) ?? '';
        // CODESYS's names of the IEC inputs (SR.SET1 is S1, CTU.RESET is R: model/vendorPins.ts).
        const aliases = inputAliases(text);
        if (aliases)
          for (let i = 0; i < inputs.length; i++) {
            const iec = aliases[inputs[i]!.pin.trim().toUpperCase()];
            if (iec) inputs[i] = { ...inputs[i]!, pin: iec };
          }
        break;
      }
      default:
        break;
    }
    return new LdObject(
      d,
      el,
      kind,
      d.attr(el, n.localId) ?? '',
      pos,
      d.attrNumber(el, n.width),
      d.attrNumber(el, n.height),
      d.attrNumber(el, n.executionOrderId),
      inputs,
      outputs,
      text,
      order,
      d.childById(el, n.addData) !== -1,
    );
  }
}

/**
 * Reads some children of an LD body: `children` are the element indices of all of them (file
 * order), `positions` the ones wanted (ascending). A right rail collects wires from many networks:
 * `keepRef` says which of its wires belong to the objects read.
 */
export function readLdObjects(
  doc: XmlDoc,
  children: Int32Array,
  positions: readonly number[],
  keepRef: (ref: string) => boolean,
): RawObject[] {
  const reader = new Reader(doc);
  const rightRail = doc.id('rightPowerRail');
  return positions.map((p) => {
    const el = children[p]!;
    const o = reader.object(el, p);
    if (doc.lid[el] !== rightRail) return o;
    return new LdObject(
      doc,
      el,
      o.kind,
      o.localId,
      o.pos,
      o.width,
      o.height,
      o.executionOrderId,
      o.inputs.map((pin) => ({ ...pin, connections: pin.connections.filter((c) => keepRef(c.ref)) })),
      o.outputs,
      o.text,
      o.order,
      o.hasAddData,
    );
  });
}
