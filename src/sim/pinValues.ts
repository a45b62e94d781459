// Values on the box pins of the monitored body that no name reads (issue 24): the data lines between
// blocks (a function's result wired into another block's input), as the engine keeps them
// (PlcProbe.pinLines). Read at frame rate and for a recorded scan, never per scan.
import type { PlcProbe } from '../engine/api';
import type { CompiledProgram } from '../engine/plc';
import type { BodyInfo } from '../engine/compile/flatten';
import { shownBody } from '../engine/explain/flatPou';
import type { Value } from '../model/iecTypes';
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

/** The values on the data lines of `body`, by element id (the layout's view's networks). */
export function readPinValues(probe: PlcProbe, layout: SimLayout, body: BodyInfo | undefined): SimPinValue[] {
  if (!body || body.end <= body.first) return [];
  // The layout describes another body than the program's networks (a view change in flight): nothing.
  if (layout.networkIds.length !== body.end - body.first) return [];
  const { lines, read } = probe.pinLines(body.first, body.end);
  if (lines.length === 0) return [];
  const values = new Array<Value>(lines.length);
  read(values);
  const out: SimPinValue[] = [];
  for (let i = 0; i < lines.length; i++) {
    const l = lines[i]!;
    const start = layout.elementOffsets[l.network];
    const element = start === undefined ? undefined : layout.elementIds[start + l.element];
    if (element === undefined || start + l.element >= layout.elementOffsets[l.network + 1]!) continue;
    out.push({ element, pin: l.pin, side: l.side, type: l.type, value: values[i]! });
  }
  return out;
}
