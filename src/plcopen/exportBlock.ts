// A box (function or FB call) as a PLCopen <block> with every pin, and its operands as
// in/outVariables beside the pins. A user block's pins come from its POU's interface (the block
// library); a VAR_IN_OUT pin is written in inputVariables and in outputVariables under one
// formalParameter, as Beremiz writes it. EN/ENO pins (functions; FBs with executionControl) are
// written as pins: TC6 v2.01 has no executionControl attribute on <block>; an EN the imported file
// left open (enOpen) and that the rail alone still feeds is left out again.
import type { BoxElement } from '../model/elements';
import { BOX_MARGIN_X, BOX_MARGIN_Y, CELL_W, ROW_H, boundaryX, type Point } from './geometry';
import type { Source } from './gridGraph';
import { boxLayout } from '../model/boxLayout';
import type { BlockLibrary } from '../model/library';
import type { Connect, IdAllocator, Placed } from './exportPlaced';
import type { XmlWriter } from './xml/write';

const pt = (x: number, y: number): Point => ({ x, y });
/** `<relPosition>` of a pin from its owner's position. */
export const rel = (w: XmlWriter, p: Point, origin: Point) =>
  w.empty('relPosition', { x: p.x - origin.x, y: p.y - origin.y });

/** Pins of a box: from its standard layout, or from its operand names for blocks Rungsmith does not know. */
export function boxPins(
  el: BoxElement,
  library: BlockLibrary,
): {
  inputs: { name: string; off: number }[];
  outputs: { name: string; off: number }[];
  rows: number;
} {
  const layout = boxLayout(el, library);
  if (layout) {
    return {
      inputs: layout.inputs.map((p) => ({ name: p.name, off: p.rowOffset })),
      outputs: layout.outputs.map((p) => ({ name: p.name, off: p.rowOffset })),
      rows: layout.rows,
    };
  }
  const inputs = Object.keys(el.inputs).map((name, off) => ({ name, off }));
  const outputs = Object.keys(el.outputs).map((name, off) => ({ name, off }));
  return { inputs, outputs, rows: Math.max(1, inputs.length, outputs.length) };
}

export function writeBox(
  w: XmlWriter,
  el: BoxElement,
  p: Placed,
  ids: IdAllocator,
  srcOf: (pin: string) => readonly Source[] | undefined,
  inBar: (pin: string) => number | undefined,
  connect: Connect,
  addData: () => void,
  library: BlockLibrary,
): void {
  const bp = boxPins(el, library);
  const outs = p.outs ?? p.pins;
  const first = bp.inputs[0] ?? bp.outputs[0];
  const firstPin = bp.inputs[0]
    ? p.pins.get(bp.inputs[0].name)!
    : first
      ? outs.get(first.name)!
      : pt(boundaryX(el.col) + BOX_MARGIN_X, 0);
  const origin = pt(firstPin.x, firstPin.y - ROW_H / 2 - (first?.off ?? 0) * ROW_H + BOX_MARGIN_Y);
  const width = 2 * CELL_W - 2 * BOX_MARGIN_X;
  // Operands: literals and variables beside unwired pins become in/outVariables joined to the pin.
  const operandIn = new Map<string, number>();
  const operandOut: { pin: string; id: number; text: string; order?: number }[] = [];
  for (const i of bp.inputs) {
    const text = el.inputs[i.name];
    if (text !== undefined && text !== '' && !srcOf(i.name)) operandIn.set(i.name, ids.next());
  }
  for (const o of bp.outputs) {
    const text = el.outputs[o.name];
    if (text !== undefined && text !== '') operandOut.push({ pin: o.name, id: ids.next(), text, order: el.outputOrders?.[o.name] });
  }
  w.open(
    'block',
    {
      localId: p.id,
      width,
      height: bp.rows * ROW_H - 2 * BOX_MARGIN_Y,
      typeName: el.blockType,
      instanceName: el.instance || undefined,
      executionOrderId: el.executionOrder || undefined,
    },
    () => {
      w.empty('position', { x: origin.x, y: origin.y });
      w.open('inputVariables', undefined, () => {
        for (const i of bp.inputs) {
          // An EN the imported file left open (BoxElement.enOpen), still fed by the rail alone:
          // written without it again, so that Beremiz generates the call without EN.
          if (i.name === 'EN' && el.enOpen && srcOf('EN')?.every((s) => s.kind === 'rail')) continue;
          const at = p.pins.get(i.name)!;
          w.line(() =>
            w.open('variable', { formalParameter: i.name }, () => {
              const opId = operandIn.get(i.name);
              if (opId !== undefined) {
                w.open('connectionPointIn', undefined, () => {
                  rel(w, at, origin);
                  w.open('connection', { refLocalId: opId }, () => {
                    w.empty('position', { x: at.x, y: at.y });
                    w.empty('position', { x: at.x - 10, y: at.y });
                  });
                });
              } else connect(at, origin, srcOf(i.name), inBar(i.name));
            }),
          );
        }
      });
      w.empty('inOutVariables');
      w.open('outputVariables', undefined, () => {
        for (const o of bp.outputs) {
          w.line(() =>
            w.open('variable', { formalParameter: o.name }, () =>
              w.open('connectionPointOut', undefined, () => rel(w, outs.get(o.name)!, origin)),
            ),
          );
        }
      });
      addData();
    },
  );
  for (const i of bp.inputs) {
    const opId = operandIn.get(i.name);
    if (opId === undefined) continue;
    const at = p.pins.get(i.name)!;
    const vw = Math.max(30, el.inputs[i.name]!.length * 7);
    const vo = pt(at.x - 10 - vw, at.y - 10);
    w.open('inVariable', { localId: opId, height: 20, width: vw, negated: 'false' }, () => {
      w.empty('position', { x: vo.x, y: vo.y });
      w.line(() => w.open('connectionPointOut', undefined, () => w.empty('relPosition', { x: vw, y: 10 })));
      w.leaf('expression', el.inputs[i.name]!);
    });
  }
  for (const o of operandOut) {
    const at = outs.get(o.pin)!;
    const vw = Math.max(30, o.text.length * 7);
    const vo = pt(at.x + 10, at.y - 10);
    w.open('outVariable', { localId: o.id, height: 20, width: vw, negated: 'false', executionOrderId: o.order || undefined }, () => {
      w.empty('position', { x: vo.x, y: vo.y });
      w.line(() =>
        w.open('connectionPointIn', undefined, () => {
          w.empty('relPosition', { x: 0, y: 10 });
          w.open('connection', { refLocalId: p.id, formalParameter: o.pin }, () => {
            w.empty('position', { x: vo.x, y: at.y });
            w.empty('position', { x: at.x, y: at.y });
          });
        }),
      );
      w.leaf('expression', o.text);
    });
  }
}
