// The operand fields beside a box's pins, typed from the keyboard: which pins take one (those not
// wired on the grid; EN/ENO never), in the order Tab visits them (the instance name of a function
// block first, then the inputs top to bottom, then the outputs), and the `???` drawn beside an
// unwired pin that has no operand yet (on the output side, not beside the BOOL output that carries
// the power flow on, nor beside an in-out pin, whose operand is its input's).
import { boxLayout, type PlacedPin } from '../../model/boxLayout';
import type { BoxElement, LdElement } from '../../model/elements';
import { elementSize } from '../../model/factory';
import { isInOutPin, type BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import { powerFlowOutput } from '../../store/networkEdits';

/** The instance name of a function block box, in the Tab order of its fields. */
export const INSTANCE_FIELD = '';

export interface PinSlot {
  readonly pin: string;
  readonly side: 'input' | 'output';
  readonly type: PlacedPin['type'];
  readonly rowOffset: number;
  /** Joined to something on the grid (the rail, an element, a vertical link): no operand. */
  readonly wired: boolean;
  readonly operand: string;
}

/** Does `el` have a terminal at its right (`side` 'out') or left ('in') edge on grid row `row`? */
function terminalOnRow(el: LdElement, row: number, side: 'in' | 'out', lib?: BlockLibrary): boolean {
  if (el.kind === 'box') {
    const layout = boxLayout(el, lib);
    const pins = layout ? (side === 'in' ? layout.inputs : layout.outputs) : [];
    return pins.some((p) => el.row + p.rowOffset === row);
  }
  if (el.row !== row) return false;
  if (side === 'out') return el.kind !== 'jump' && el.kind !== 'return' && el.kind !== 'connector';
  return el.kind !== 'continuation';
}

/** Is grid point (row, boundary) joined to anything but `self`: a rail, an element's side, a vertical link? */
export function pointWired(
  n: Network,
  self: LdElement,
  row: number,
  boundary: number,
  lib?: BlockLibrary,
): boolean {
  if (boundary === 0 || boundary === n.cols) return true;
  if (n.vlinks.some((v) => v.boundary === boundary && (v.row === row || v.row + 1 === row))) return true;
  return n.elements.some(
    (e) =>
      e !== self &&
      ((e.col + elementSize(e, lib).cols === boundary && terminalOnRow(e, row, 'out', lib)) ||
        (e.col === boundary && terminalOnRow(e, row, 'in', lib))),
  );
}

/** The box's pins that take operands (EN/ENO excluded), inputs then outputs, top to bottom. */
export function pinSlots(n: Network, box: BoxElement, lib?: BlockLibrary): PinSlot[] {
  const layout = boxLayout(box, lib);
  if (!layout) return [];
  const right = box.col + layout.cols;
  const slot = (side: PinSlot['side']) => (p: PlacedPin): PinSlot => ({
    pin: p.name,
    side,
    type: p.type,
    rowOffset: p.rowOffset,
    wired: pointWired(n, box, box.row + p.rowOffset, side === 'input' ? box.col : right, lib),
    operand: (side === 'input' ? box.inputs : box.outputs)[p.name] ?? '',
  });
  return [
    ...layout.inputs.filter((p) => p.name !== 'EN').map(slot('input')),
    ...layout.outputs.filter((p) => p.name !== 'ENO').map(slot('output')),
  ];
}

/** The fields Tab visits on a box: its instance name (function blocks), then its unwired pins. */
export function tabStops(n: Network, box: BoxElement, lib?: BlockLibrary): string[] {
  const pins = pinSlots(n, box, lib)
    .filter((s) => !s.wired)
    .map((s) => s.pin);
  return box.instance !== undefined ? [INSTANCE_FIELD, ...pins] : pins;
}

/** Enter on a box: its instance when unnamed, else the first unwired pin without an operand (else the first unwired pin). */
export function firstField(n: Network, box: BoxElement, lib?: BlockLibrary): string | undefined {
  if (box.instance !== undefined && box.instance.trim() === '') return INSTANCE_FIELD;
  const open = pinSlots(n, box, lib).filter((s) => !s.wired);
  return (open.find((s) => s.operand === '') ?? open[0])?.pin ?? (box.instance !== undefined ? INSTANCE_FIELD : undefined);
}

/** The field after (or before, `back`) `field` in the Tab order, wrapping around. */
export function nextField(
  n: Network,
  box: BoxElement,
  field: string,
  back: boolean,
  lib?: BlockLibrary,
): string | undefined {
  const stops = tabStops(n, box, lib);
  if (stops.length === 0) return undefined;
  const i = stops.indexOf(field);
  if (i < 0) return stops[0];
  return stops[(i + (back ? stops.length - 1 : 1)) % stops.length];
}

/** Operands with `pin` set to `text`, or removed when the text is empty. */
export function withOperand(
  rec: Readonly<Record<string, string>>,
  pin: string,
  text: string,
): Record<string, string> {
  const out = { ...rec };
  if (text.trim() === '') delete out[pin];
  else out[pin] = text.trim();
  return out;
}

/** Pins of a box drawn with a `???` operand, per side (an in-out pin is on both sides). */
export interface OpenPins {
  readonly inputs: ReadonlySet<string>;
  readonly outputs: ReadonlySet<string>;
}

/** The box's pins drawn with a `???` operand: unwired and without an operand yet (see the file comment). */
export function openPins(n: Network, box: BoxElement, lib?: BlockLibrary): OpenPins {
  const inputs = new Set<string>();
  const outputs = new Set<string>();
  const layout = boxLayout(box, lib);
  const flow = layout && powerFlowOutput(layout)?.name;
  const inOut = new Set(layout?.outputs.filter(isInOutPin).map((p) => p.name));
  for (const s of pinSlots(n, box, lib)) {
    if (s.wired || s.operand) continue;
    if (s.side === 'input') inputs.add(s.pin);
    else if (s.pin !== flow && !inOut.has(s.pin)) outputs.add(s.pin);
  }
  return { inputs, outputs };
}
