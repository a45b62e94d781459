// Reading the objects of a PLCopen LD body: positions, pins and the connections recorded on the
// consumer side. No interpretation yet (see ldGraph.ts).
import type { Point } from './geometry';
import { child, childrenNamed, deepText, type XmlElement } from './xml/parse';

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
  readonly xml: XmlElement;
  readonly pos: Point;
  readonly width: number;
  readonly height: number;
  readonly executionOrderId: number;
  readonly inputs: readonly RawPin[];
  readonly outputs: readonly RawPin[];
  /** contact/coil variable, in/outVariable expression, label/jump label, connector name, comment text. */
  readonly text: string;
  readonly attrs: Readonly<Record<string, string>>;
  /** Position among the children of the body (file order). */
  readonly order: number;
}

const num = (s: string | undefined): number => {
  if (s === undefined) return 0;
  const n = +s;
  return n === n && n !== Infinity && n !== -Infinity ? n : 0;
};

function readPoint(el: XmlElement | undefined): Point | undefined {
  return el ? { x: num(el.attrs.x), y: num(el.attrs.y) } : undefined;
}

const NO_ATTRS: Readonly<Record<string, string>> = {};
/** Output pins never hold connections (PLCopen records wires on the consumer side). */
const NO_CONNECTIONS: readonly RawConnection[] = Object.freeze([]);

function pinFlags(
  pin: RawPin & { negated: boolean; edge?: string },
  attrs: Readonly<Record<string, string>>,
): void {
  const neg = attrs.negated;
  pin.negated = neg === 'true' || neg === '1';
  const edge = attrs.edge;
  if (edge && edge !== 'none') pin.edge = edge;
}

type MutablePin = { -readonly [K in keyof RawPin]: RawPin[K] };

function readPointIn(
  cp: XmlElement | undefined,
  pin: string,
  attrs: Readonly<Record<string, string>> = NO_ATTRS,
): RawPin {
  const connections: RawConnection[] = [];
  const out: MutablePin = { pin, connections, negated: false };
  if (cp) {
    for (const c of cp.children) {
      if (c.name === 'connection') {
        const formal = c.attrs.formalParameter;
        connections.push(
          formal !== undefined && formal !== ''
            ? { ref: c.attrs.refLocalId ?? '', formal }
            : { ref: c.attrs.refLocalId ?? '' },
        );
      }
    }
  }
  if (attrs !== NO_ATTRS) pinFlags(out, attrs);
  return out;
}

function readPointOut(
  cp: XmlElement | undefined,
  pin: string,
  attrs: Readonly<Record<string, string>> = NO_ATTRS,
): RawPin {
  const out: MutablePin = { pin, connections: NO_CONNECTIONS, negated: false };
  if (cp) {
    for (const c of cp.children) {
      if (c.name === 'expression') {
        const e = c.text.trim();
        if (e) out.expression = e;
      }
    }
  }
  if (attrs !== NO_ATTRS) pinFlags(out, attrs);
  return out;
}

/** Reads every direct child of an LD body. */
export function readLdObjects(body: XmlElement): RawObject[] {
  return body.children.map((el, order) => {
    const pos = readPoint(child(el, 'position')) ?? { x: 0, y: 0 };
    const inputs: RawPin[] = [];
    const outputs: RawPin[] = [];
    let text = '';
    switch (el.name) {
      case 'leftPowerRail':
        childrenNamed(el, 'connectionPointOut').forEach((cp, i) => outputs.push(readPointOut(cp, String(i))));
        break;
      case 'rightPowerRail':
        childrenNamed(el, 'connectionPointIn').forEach((cp, i) => inputs.push(readPointIn(cp, String(i))));
        break;
      case 'contact':
      case 'coil':
      case 'inVariable':
      case 'outVariable':
      case 'inOutVariable':
        if (child(el, 'connectionPointIn') || el.name !== 'inVariable')
          inputs.push(readPointIn(child(el, 'connectionPointIn'), 'in'));
        if (child(el, 'connectionPointOut') || el.name !== 'outVariable')
          outputs.push(readPointOut(child(el, 'connectionPointOut'), 'out'));
        text = (child(el, 'variable') ?? child(el, 'expression'))?.text.trim() ?? '';
        break;
      case 'jump':
      case 'return':
      case 'connector':
        inputs.push(readPointIn(child(el, 'connectionPointIn'), 'in'));
        text = el.attrs.label ?? el.attrs.name ?? '';
        break;
      case 'continuation':
        outputs.push(readPointOut(child(el, 'connectionPointOut'), 'out'));
        text = el.attrs.name ?? '';
        break;
      case 'label':
        text = el.attrs.label ?? '';
        break;
      case 'comment': {
        const content = child(el, 'content');
        text = content ? deepText(content).trim() : '';
        break;
      }
      case 'block': {
        for (const v of childrenNamed(child(el, 'inputVariables') ?? el, 'variable'))
          inputs.push(readPointIn(child(v, 'connectionPointIn'), v.attrs.formalParameter ?? '', v.attrs));
        for (const v of childrenNamed(child(el, 'inOutVariables') ?? el, 'variable')) {
          inputs.push(readPointIn(child(v, 'connectionPointIn'), v.attrs.formalParameter ?? '', v.attrs));
          outputs.push(readPointOut(child(v, 'connectionPointOut'), v.attrs.formalParameter ?? '', v.attrs));
        }
        for (const v of childrenNamed(child(el, 'outputVariables') ?? el, 'variable'))
          outputs.push(readPointOut(child(v, 'connectionPointOut'), v.attrs.formalParameter ?? '', v.attrs));
        text = el.attrs.typeName ?? '';
        break;
      }
      default:
        break;
    }
    return {
      kind: el.name,
      localId: el.attrs.localId ?? '',
      xml: el,
      pos,
      width: num(el.attrs.width),
      height: num(el.attrs.height),
      executionOrderId: num(el.attrs.executionOrderId),
      attrs: el.attrs,
      order,
      inputs,
      outputs,
      text,
    };
  });
}
