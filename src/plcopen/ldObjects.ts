// Reading the objects of a PLCopen LD body: positions, pins and the connections recorded on the
// consumer side. No interpretation yet (see ldGraph.ts).
import type { Point } from './geometry';
import { child, childrenNamed, deepText, type XmlElement } from './xml/parse';

export interface RawConnection {
  readonly ref: string;
  readonly formal?: string;
  /** Route points: first at the consumer, last at the producer. */
  readonly points: readonly Point[];
}

export interface RawPin {
  readonly pin: string;
  readonly connections: readonly RawConnection[];
  /** Absolute pin position when relPosition is given. */
  readonly at?: Point;
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
}

const num = (s: string | undefined): number => {
  const n = Number(s);
  return Number.isFinite(n) ? n : 0;
};

function readPoint(el: XmlElement | undefined): Point | undefined {
  return el ? { x: num(el.attrs.x), y: num(el.attrs.y) } : undefined;
}

function readPointIn(cp: XmlElement | undefined, origin: Point, pin: string, attrs: Readonly<Record<string, string>> = {}): RawPin {
  const relPos = cp ? readPoint(child(cp, 'relPosition')) : undefined;
  const connections: RawConnection[] = cp
    ? childrenNamed(cp, 'connection').map((c) => ({
        ref: c.attrs.refLocalId ?? '',
        ...(c.attrs.formalParameter !== undefined && c.attrs.formalParameter !== '' ? { formal: c.attrs.formalParameter } : {}),
        points: childrenNamed(c, 'position').map((p) => readPoint(p)!),
      }))
    : [];
  return {
    pin,
    connections,
    ...(relPos ? { at: { x: origin.x + relPos.x, y: origin.y + relPos.y } } : {}),
    negated: attrs.negated === 'true' || attrs.negated === '1',
    ...(attrs.edge && attrs.edge !== 'none' ? { edge: attrs.edge } : {}),
  };
}

function readPointOut(cp: XmlElement | undefined, origin: Point, pin: string, attrs: Readonly<Record<string, string>> = {}): RawPin {
  const relPos = cp ? readPoint(child(cp, 'relPosition')) : undefined;
  const expr = cp ? child(cp, 'expression') : undefined;
  const expression = expr ? expr.text.trim() : '';
  return {
    pin,
    connections: [],
    ...(relPos ? { at: { x: origin.x + relPos.x, y: origin.y + relPos.y } } : {}),
    negated: attrs.negated === 'true' || attrs.negated === '1',
    ...(attrs.edge && attrs.edge !== 'none' ? { edge: attrs.edge } : {}),
    ...(expression ? { expression } : {}),
  };
}

/** Reads every direct child of an LD body. */
export function readLdObjects(body: XmlElement): RawObject[] {
  return body.children.map((el) => {
    const pos = readPoint(child(el, 'position')) ?? { x: 0, y: 0 };
    const base = {
      kind: el.name,
      localId: el.attrs.localId ?? '',
      xml: el,
      pos,
      width: num(el.attrs.width),
      height: num(el.attrs.height),
      executionOrderId: num(el.attrs.executionOrderId),
      attrs: el.attrs,
    };
    const inputs: RawPin[] = [];
    const outputs: RawPin[] = [];
    let text = '';
    switch (el.name) {
      case 'leftPowerRail':
        childrenNamed(el, 'connectionPointOut').forEach((cp, i) => outputs.push(readPointOut(cp, pos, String(i))));
        break;
      case 'rightPowerRail':
        childrenNamed(el, 'connectionPointIn').forEach((cp, i) => inputs.push(readPointIn(cp, pos, String(i))));
        break;
      case 'contact':
      case 'coil':
      case 'inVariable':
      case 'outVariable':
      case 'inOutVariable':
        if (child(el, 'connectionPointIn') || el.name !== 'inVariable') inputs.push(readPointIn(child(el, 'connectionPointIn'), pos, 'in'));
        if (child(el, 'connectionPointOut') || el.name !== 'outVariable') outputs.push(readPointOut(child(el, 'connectionPointOut'), pos, 'out'));
        text = (child(el, 'variable') ?? child(el, 'expression'))?.text.trim() ?? '';
        break;
      case 'jump':
      case 'return':
      case 'connector':
        inputs.push(readPointIn(child(el, 'connectionPointIn'), pos, 'in'));
        text = el.attrs.label ?? el.attrs.name ?? '';
        break;
      case 'continuation':
        outputs.push(readPointOut(child(el, 'connectionPointOut'), pos, 'out'));
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
          inputs.push(readPointIn(child(v, 'connectionPointIn'), pos, v.attrs.formalParameter ?? '', v.attrs));
        for (const v of childrenNamed(child(el, 'inOutVariables') ?? el, 'variable')) {
          inputs.push(readPointIn(child(v, 'connectionPointIn'), pos, v.attrs.formalParameter ?? '', v.attrs));
          outputs.push(readPointOut(child(v, 'connectionPointOut'), pos, v.attrs.formalParameter ?? '', v.attrs));
        }
        for (const v of childrenNamed(child(el, 'outputVariables') ?? el, 'variable'))
          outputs.push(readPointOut(child(v, 'connectionPointOut'), pos, v.attrs.formalParameter ?? '', v.attrs));
        text = el.attrs.typeName ?? '';
        break;
      }
      default:
        break;
    }
    return { ...base, inputs, outputs, text };
  });
}
