// Values on the box pins of the monitored body that no name reads (issue 24): the data lines between
// blocks (a function's result wired into another block's input), as the engine keeps them
// (PlcProbe.pinLines). Read at frame rate and for a recorded scan, never per scan.
import type { PinLines, PlcProbe } from '../engine/api';
import type { CompiledProgram } from '../engine/plc';
import type { BodyInfo } from '../engine/compile/flatten';
import { shownBody } from '../engine/explain/flatPou';
import type { Value } from '../model/iecTypes';
import type { Pou, Project } from '../model/project';
import type { SimLayout, SimPinValue } from './protocol';

const same = (a: string | undefined, b: string | undefined) => (a ?? '').toUpperCase() === (b ?? '').toUpperCase();

/**
 * The body the layout's view shows: the program's (first) body, else the call of the instance or
 * function that `ran` says ran (the last of them), else its first call.
 */
export function viewBody(program: CompiledProgram, layout: SimLayout, ran: (network: number) => boolean): BodyInfo | undefined {
  const view = layout.view;
  if (!view || (view.instance === undefined && same(view.pou, layout.pou))) return program.bodies[0];
  return shownBody(program, view, ran);
}

/** The document's POU of the layout's view. */
export function viewPou(project: Project | undefined, layout: SimLayout): Pou | undefined {
  const name = (layout.view?.pou ?? layout.pou).toUpperCase();
  return project?.pous.find((p) => p.name.toUpperCase() === name);
}

/** Per engine list and document POU: the lines on pins without an operand (those are read by name). */
const unnamed = new WeakMap<PinLines, WeakMap<Pou, readonly number[]>>();

function linesToRead(pins: PinLines, pou: Pou | undefined): readonly number[] | undefined {
  if (!pou) return undefined;
  let byPou = unnamed.get(pins);
  if (!byPou) unnamed.set(pins, (byPou = new WeakMap()));
  let keep = byPou.get(pou);
  if (!keep) {
    const out: number[] = [];
    pins.lines.forEach((l, i) => {
      const el = pou.networks[l.network]?.elements[l.element];
      if (el?.kind !== 'box') return;
      const operands = l.side === 'in' ? el.inputs : el.outputs;
      const named = Object.entries(operands).some(([pin, text]) => pin.toUpperCase() === l.pin.toUpperCase() && text.trim() !== '');
      if (!named) out.push(i);
    });
    byPou.set(pou, (keep = out));
  }
  return keep;
}

/**
 * The values on the data lines of `body`, by element id (the layout's view's networks). With the
 * document's POU of the view, only pins without an operand (the canvas reads the others by name).
 */
export function readPinValues(probe: PlcProbe, layout: SimLayout, body: BodyInfo | undefined, pou?: Pou): SimPinValue[] {
  if (!body || body.end <= body.first) return [];
  // The layout describes another body than the program's networks (a view change in flight): nothing.
  if (layout.networkIds.length !== body.end - body.first) return [];
  const pins = probe.pinLines(body.first, body.end);
  const { lines, read } = pins;
  if (lines.length === 0) return [];
  const values = new Array<Value>(lines.length);
  read(values);
  const out: SimPinValue[] = [];
  const push = (i: number) => {
    const l = lines[i]!;
    const start = layout.elementOffsets[l.network];
    const element = start === undefined ? undefined : layout.elementIds[start + l.element];
    if (element === undefined || start! + l.element >= layout.elementOffsets[l.network + 1]!) return;
    out.push({ element, pin: l.pin, side: l.side, type: l.type, value: values[i]! });
  };
  const keep = linesToRead(pins, pou && pou.networks.length === layout.networkIds.length ? pou : undefined);
  if (keep) for (const i of keep) push(i);
  else for (let i = 0; i < lines.length; i++) push(i);
  return out;
}
