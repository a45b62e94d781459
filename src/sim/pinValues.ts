// Values on the box pins of the monitored body that no name reads (issue 24): the data lines between
// blocks (a function's result wired into another block's input), as the engine keeps them
// (PlcProbe.pinLines). Read at frame rate and for a recorded scan, never per scan.
import type { PinLines, Plc, PlcProbe } from '../engine/api';
import type { CompiledProgram } from '../engine/plc';
import type { BodyInfo } from '../engine/compile/flatten';
import { shownBody } from '../engine/explain/flatPou';
import type { Value } from '../model/iecTypes';
import type { Pou, Project } from '../model/project';
import type { SimLayout, SimPinLine } from './protocol';

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

/** Per engine list and document POU: the inputs on data lines without an operand (the others are read by name). */
const unnamed = new WeakMap<PinLines, WeakMap<Pou, readonly number[]>>();

function linesToRead(pins: PinLines, pou: Pou): readonly number[] {
  let byPou = unnamed.get(pins);
  if (!byPou) unnamed.set(pins, (byPou = new WeakMap()));
  let keep = byPou.get(pou);
  if (!keep) {
    const out: number[] = [];
    pins.lines.forEach((l, i) => {
      const el = pou.networks[l.network]?.elements[l.element];
      if (l.side !== 'in' || el?.kind !== 'box') return;
      const named = Object.entries(el.inputs).some(([pin, text]) => pin.toUpperCase() === l.pin.toUpperCase() && text.trim() !== '');
      if (!named) out.push(i);
    });
    byPou.set(pou, (keep = out));
  }
  return keep;
}

/** The lines of `body` to show, when the layout describes that body's POU. */
function shownLines(probe: PlcProbe, layout: SimLayout, body: BodyInfo | undefined, pou: Pou | undefined) {
  // The layout describes another body (a view change in flight): nothing.
  if (!body || !pou || body.end <= body.first || layout.networkIds.length !== body.end - body.first || pou.networks.length !== layout.networkIds.length) return undefined;
  const pins = probe.pinLines(body.first, body.end);
  return { pins, keep: linesToRead(pins, pou) };
}

/**
 * The layout with the inputs on data lines of its view's body (SimLayout.pins): every call of a POU
 * has the same lines, so frames and recorded scans send only their values (readPinValues).
 */
export function withPinLines(layout: SimLayout, plc: Plc, program: CompiledProgram, project: Project): SimLayout {
  const { pins: _old, ...rest } = layout;
  const probe = plc.probe?.();
  const found = probe ? shownLines(probe, rest, viewBody(program, rest, () => false), viewPou(project, rest)) : undefined;
  if (!found || found.keep.length === 0) return rest;
  const pins: SimPinLine[] = [];
  for (const i of found.keep) {
    const l = found.pins.lines[i]!;
    const start = rest.elementOffsets[l.network]!;
    pins.push({ element: rest.elementIds[start + l.element] ?? '', pin: l.pin, type: l.type });
  }
  return { ...rest, pins };
}

/** The values on the inputs of SimLayout.pins in `body` (aligned with them; empty when they do not fit). */
export function readPinValues(probe: PlcProbe, layout: SimLayout, body: BodyInfo | undefined, pou: Pou | undefined): Value[] {
  const want = layout.pins?.length ?? 0;
  if (want === 0) return [];
  const found = shownLines(probe, layout, body, pou);
  if (!found || found.keep.length !== want) return [];
  const all = new Array<Value>(found.pins.lines.length);
  found.pins.read(all);
  return found.keep.map((i) => all[i]!);
}
