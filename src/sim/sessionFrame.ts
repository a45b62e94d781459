// The frame a simulation session posts to the page: mode, scan, timing, power flow, values,
// forces, trend samples and the recorded history range, built from the session's current state.
import type { Plc, TextTarget } from '../engine/api';
import type { CompiledProgram } from '../engine/plc';
import type { ShownScan } from './carryOver';
import { readValues } from './frames';
import type { SimFrame, SimLayout, SimMode, SimTextTrace } from './protocol';
import type { ScanRunner } from './scanRunner';
import type { TrendRecorder } from './trendRecorder';
import { packView } from './viewPower';
import { readPinValues, viewBody, viewPou } from './pinValues';
import type { Project } from '../model/project';

/** What a frame is built from (SimSession.frame). */
export interface FrameParts {
  readonly mode: SimMode;
  readonly plc: Plc | undefined;
  readonly layout: SimLayout | undefined;
  readonly runner: ScanRunner;
  /** What the replaced program's last scan showed, while the new one has not run (SimSession.carriedShown). */
  readonly carried: ShownScan | undefined;
  readonly program: CompiledProgram | undefined;
  readonly trend: TrendRecorder;
  readonly scanBase: number;
  readonly programId: string | null;
  readonly epoch: number;
  readonly history: SimFrame['history'];
  /** The document the program was compiled from: pins with an operand are read by name, not sent as lines. */
  readonly project?: Project;
  /** The shown body when it is ST/IL (its trace goes in the frame). */
  readonly text?: TextTarget | undefined;
}

export function buildFrame(parts: FrameParts): SimFrame {
  const { plc, layout, runner, carried } = parts;
  // Fresh arrays: a frame's buffers are transferred to the page.
  const power = carried
    ? { elements: carried.power.elements.slice(), vlinks: carried.power.vlinks.slice(), executed: carried.power.executed.slice() }
    : plc && layout
      ? packView(plc, layout, parts.program)
      : undefined;
  const values = plc && layout ? readValues(plc, layout) : [];
  // Inputs are read into the new program at its first scan: until then they show the last scan's
  // (the other values were carried into the new program itself: carryValues).
  if (carried && layout)
    layout.variables.forEach((v, i) => {
      if (v.location?.toUpperCase().startsWith('%I')) values[i] = carried.values[i]!;
    });
  // The data lines of the shown body (the carried scan of a replaced program has none to show).
  // Nothing to read when the view has no box input on a line (no probe, no body search).
  const probe = !carried && plc && layout?.pins?.length && parts.program ? plc.probe?.() : undefined;
  const pins =
    probe && layout && parts.program
      ? readPinValues(probe, layout, viewBody(parts.program, layout, lastRun(probe.ranIn)), viewPou(parts.project, layout))
      : [];
  const trend = parts.trend.take();
  const trendTrigger = parts.trend.triggerState;
  const trendCapture = parts.trend.takeCapture();
  const fault = plc?.fault;
  // At a scan boundary a configuration stands before its first program instance's network 1.
  const first = layout?.programs?.[0]?.instance;
  const hit = runner.breakpointHit && first !== undefined && runner.breakpointHit.instance === undefined && plc?.position().length === 0
    ? { ...runner.breakpointHit, instance: first }
    : runner.breakpointHit;
  return {
    mode: parts.mode,
    scan: parts.scanBase + (plc?.scanCount ?? 0),
    timeMs: runner.timeMs(plc),
    cycleMs: runner.cycleMs,
    exec: runner.exec(),
    ...(fault ? { fault } : {}),
    nextNetwork: plc?.nextNetwork ?? -1,
    ...(hit !== undefined ? { breakpointHit: hit.network, breakpointAt: hit } : {}),
    position: plc ? plc.position() : [],
    overruns: runner.overruns,
    elements: power?.elements ?? new Uint8Array(0),
    vlinks: power?.vlinks ?? new Uint8Array(0),
    executed: power?.executed ?? new Uint8Array(0),
    values,
    pins,
    forced: plc ? [...plc.forced()] : [],
    ...(trend ? { trend } : {}),
    ...(trendTrigger ? { trendTrigger } : {}),
    ...(trendCapture ? { trendCapture } : {}),
    program: plc ? parts.programId : null,
    epoch: parts.epoch,
    ...(parts.history ? { history: parts.history } : {}),
    ...textOf(plc, parts.text, parts.scanBase),
  };
}

/** The shown ST/IL body's trace, numbered like the frame's scans; stale when it did not run in the last (or current) scan. */
export function textOf(plc: Plc | undefined, target: TextTarget | undefined, scanBase: number): { text?: SimTextTrace } {
  const t = target && plc?.textTrace(target);
  return t ? { text: { ...t, scan: scanBase + t.scan, stale: t.scan !== plc!.scanCount } } : {};
}

/** A test for "this body's call ran last": the networks that ran in the latest scan any network ran in. */
function lastRun(ranIn: Int32Array): (network: number) => boolean {
  let latest = 0;
  for (let i = 0; i < ranIn.length; i++) if (ranIn[i]! > latest) latest = ranIn[i]!;
  return (n) => latest > 0 && ranIn[n] === latest;
}
