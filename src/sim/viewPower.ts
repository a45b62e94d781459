// The power flow of the body a user monitors (a program, an FB instance, a function's call), packed
// by the layout's network fields.
import type { NetworkPower, Plc } from '../engine/api';
import type { CompiledProgram } from '../engine/plc';
import { programOf } from '../engine/compile/taskSchedule';
import { shownBody } from '../engine/explain/flatPou';
import { packNetworks, type PackedPower } from './frames';
import type { SimLayout } from './protocol';

type BodyInfo = CompiledProgram['bodies'][number];

const same = (a: string | undefined, b: string | undefined) => (a ?? '').toUpperCase() === (b ?? '').toUpperCase();

/**
 * The body of a function (no instance): of its calls, the one that ran last (`ranIn`: scan in which
 * each network last ran), as the engine's snapshot picks an instance's call.
 */
export function functionBody(program: CompiledProgram, pou: string, ranIn: Int32Array): BodyInfo | undefined {
  let best: BodyInfo | undefined;
  for (const b of program.bodies) {
    if (b.kind !== 'function' || !same(b.pou, pou)) continue;
    if (!best || (b.end > b.first && (ranIn[b.first] ?? -1) > (ranIn[best.first] ?? -1))) best = b;
  }
  return best;
}

const EMPTY: readonly NetworkPower[] = [];

/**
 * The networks of the shown body in a recorded scan (`networks`: the whole program's, as decoded
 * from the history): an FB or program instance's call, or a function's, that ran last in the scan
 * (the later of the calls that ran: calls run in body order), else its first call, as the live
 * view picks it. Nothing when the view is the program or names no body.
 */
export function recordedBody(program: CompiledProgram, layout: SimLayout, networks: readonly NetworkPower[]): readonly NetworkPower[] {
  const view = layout.view;
  if (!view) return networks;
  const body = shownBody(program, view, (n) => networks[n]?.executed === true);
  return body ? networks.slice(body.first, body.end) : EMPTY;
}

/** Power of the layout's view in the PLC's last (or current) scan; nothing when the view is not called. */
export function viewNetworks(plc: Plc, layout: SimLayout, program: CompiledProgram | undefined): readonly NetworkPower[] {
  const view = layout.view;
  if (!view || (same(view.pou, layout.pou) && view.instance === undefined)) return plc.snapshot().networks;
  if (view.instance !== undefined) {
    // An instance declared but never called has no body to show.
    if (!plc.instances().some((i) => same(i.path, view.instance)) && !layout.programs?.some((p) => same(p.instance, view.instance))) return EMPTY;
    try {
      return plc.snapshot({ instance: view.instance }).networks;
    } catch {
      return EMPTY;
    }
  }
  const probe = plc.probe?.();
  if (!probe || !program) return EMPTY;
  const body = functionBody(program, view.pou, probe.ranIn);
  if (!body) return EMPTY;
  // At a boundary, a function called by a program whose task did not run in this tick shows that
  // program's last run (as the engine's snapshot shows a program or FB instance).
  const root = programOf(program.bodies, body);
  const shown = plc.schedule?.multiRate && plc.nextNetwork === -1 && root.end > root.first ? probe.ranIn[root.first]! : plc.scanCount;
  const executed = Uint8Array.from(probe.ranIn, (scan) => (scan === shown && scan > 0 ? 1 : 0));
  return probe.decode(probe.power, executed).slice(body.first, body.end);
}

export function packView(plc: Plc, layout: SimLayout, program: CompiledProgram | undefined): PackedPower {
  return packNetworks(viewNetworks(plc, layout, program), layout);
}
