// Values beside a box's pins while simulating and on a recorded scan (issue 24): every input and
// output operand and every function pin on a data line, as CODESYS shows them online.
// - An input or output given a variable shows that variable's value (read in the monitored body);
//   a function block's pins show its instance's (`T1.PT`: what the block saw).
// - An input given a literal shows the literal, as the pin's type writes it (`5` on a REAL: 5.0).
// - An input on a data line from another block's output shows the value that flowed on the line in
//   the scan (the engine's data line, SimState.pins); the output feeding it shows it once, there.
// - An output nothing is attached to (a TON's ET) shows its instance's value; BOOL lines carry
//   power flow, drawn by the wire's colour.
import { useMemo } from 'react';
import { boxLayout, type PlacedPin } from '../../model/boxLayout';
import type { ElementId } from '../../model/ids';
import type { BoxElement, LdElement } from '../../model/elements';
import { isElementaryType, type ElementaryType, type Value } from '../../model/iecTypes';
import type { BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import { parseLiteral } from '../../engine/values/literals';
import type { SimPinLine } from '../../sim/protocol';
import type { SimState } from '../../store/simState';
import { selectLibrary, useDocument } from '../../store/documentStore';
import { useSim } from './simContext';
import { pinSlots } from '../canvas/pinOperands';
import { canvasName, formatLive, liveText } from './liveValues';

/** Text beside each pin of one box, by pin name. */
export interface BoxPinTexts {
  readonly inputs: Readonly<Record<string, string>>;
  readonly outputs: Readonly<Record<string, string>>;
}

/** A data line into a box input, with its value in the shown scan. */
interface LineValue {
  readonly pin: string;
  readonly type: string;
  readonly value: Value;
}

const byLayout = new WeakMap<readonly SimPinLine[], Map<string, number[]>>();

/** The data lines into the inputs of box `element` (layout.pins grouped by box once per layout), with the frame's values. */
function linesOf(s: SimState, element: string): readonly LineValue[] {
  const lines = s.layout?.pins;
  if (!lines || s.pins.length !== lines.length) return [];
  let map = byLayout.get(lines);
  if (!map) {
    map = new Map();
    lines.forEach((p, i) => {
      const list = map!.get(p.element);
      if (list) list.push(i);
      else map!.set(p.element, [i]);
    });
    byLayout.set(lines, map);
  }
  return (map.get(element) ?? []).map((i) => ({ pin: lines[i]!.pin, type: lines[i]!.type, value: s.pins[i]! }));
}

const same = (a: string, b: string) => a.toUpperCase() === b.toUpperCase();

/** The value of a named operand of the shown body, or of a literal written on an input. */
function operandValue(s: SimState, operand: string, pin: PlacedPin): string | undefined {
  const name = canvasName(s, operand);
  const text = name === undefined ? undefined : liveText(s, name);
  if (text !== undefined) return text;
  if (!isElementaryType(pin.type) && pin.type !== 'ANY' && !pin.type.startsWith('ANY')) return undefined;
  const expected = isElementaryType(pin.type) ? (pin.type as ElementaryType) : undefined;
  const lit = parseLiteral(operand, expected);
  return lit.ok ? formatLive(lit.type, lit.value) : undefined;
}

/** The pin texts of a box in the shown body; undefined when it shows none. */
export function boxPinTexts(s: SimState, n: Network, el: BoxElement, library: BlockLibrary): BoxPinTexts | undefined {
  const layout = boxLayout(el, library);
  if (!layout) return undefined;
  const fb = layout.signature.kind === 'fb' && el.instance?.trim() ? el.instance.trim() : undefined;
  const lines = linesOf(s, el.id);
  const inputs: Record<string, string> = {};
  const outputs: Record<string, string> = {};
  const pins = new Map<string, PlacedPin>();
  for (const p of [...layout.inputs, ...layout.outputs]) pins.set(`${p.name}`, p);
  const instanceText = (pin: string) => (fb ? (canvasName(s, `${fb}.${pin}`) ?? '') : '');
  for (const slot of pinSlots(n, el, library)) {
    const pin = pins.get(slot.pin);
    if (!pin) continue;
    let text: string | undefined;
    if (slot.operand) {
      // A function block's pin: the instance's value (what the call saw or gave), else the operand's.
      const ofInstance = fb ? liveText(s, instanceText(slot.pin)) : undefined;
      text = ofInstance ?? operandValue(s, slot.operand, pin);
    } else if (slot.side === 'input') {
      if (!slot.wired) continue;
      const line = lines.find((l) => same(l.pin, slot.pin));
      text = line ? formatLive(line.type, line.value) : undefined;
    } else if (!slot.wired && fb) {
      text = liveText(s, instanceText(slot.pin));
    }
    if (text === undefined || (pin.type === 'BOOL' && !slot.operand && slot.wired)) continue;
    (slot.side === 'input' ? inputs : outputs)[slot.pin] = text;
  }
  return Object.keys(inputs).length + Object.keys(outputs).length > 0 ? { inputs, outputs } : undefined;
}

/** The pin texts of a network's boxes, as one string (a selector's result: equal strings, no redraw). */
export function networkPinKey(s: SimState, n: Network, library: BlockLibrary): string {
  if (!s.live) return '';
  const entries: [string, BoxPinTexts][] = [];
  for (const el of n.elements as readonly LdElement[]) {
    if (el.kind !== 'box') continue;
    const texts = boxPinTexts(s, n, el, library);
    if (texts) entries.push([el.id, texts]);
  }
  return entries.length > 0 ? JSON.stringify(entries) : '';
}

/** Pin texts by box id for one network, or undefined when not simulating (or no box shows one). */
export function useNetworkPinValues(network: Network): ReadonlyMap<ElementId, BoxPinTexts> | undefined {
  const library = useDocument(selectLibrary);
  const key = useSim((s) => networkPinKey(s, network, library));
  return useMemo(() => (key ? new Map(JSON.parse(key) as [ElementId, BoxPinTexts][]) : undefined), [key]);
}
