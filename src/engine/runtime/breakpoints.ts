// Breakpoints by POU and network: a breakpoint in a program's network, or in an FB's or function's
// body (in any instance, or in the one named). The simulator checks `breakpointAt(plc, list)`
// before each step; with breakpoints inside bodies it steps with `stepNetwork({ into: true })`.
import type { Plc, StepFrame } from '../api';

export interface Breakpoint {
  readonly pou: string;
  /** 0-based network index in the POU. */
  readonly network: number;
  /** An FB instance path (`Motor1`, `Line.Motor1`): only there; absent: in every instance. */
  readonly instance?: string;
}

const same = (a: string | undefined, b: string | undefined): boolean =>
  (a ?? '').toUpperCase() === (b ?? '').toUpperCase();

/** Where the next step starts: the innermost frame, or (at a scan boundary) the program's network 0. */
export function nextStop(plc: Plc): StepFrame {
  const frames = plc.position();
  return frames[frames.length - 1] ?? { pou: plc.pou, network: 0 };
}

/** The breakpoint execution stands at, if any. */
export function breakpointAt(plc: Plc, breakpoints: readonly Breakpoint[]): Breakpoint | undefined {
  const at = nextStop(plc);
  return breakpoints.find(
    (b) => same(b.pou, at.pou) && b.network === at.network && (b.instance === undefined || same(b.instance, at.instance)),
  );
}

/** True when a breakpoint lies inside a body (stepping must go into calls to reach it). */
export const needsStepInto = (plc: Plc, breakpoints: readonly Breakpoint[]): boolean =>
  breakpoints.some((b) => !same(b.pou, plc.pou) || b.instance !== undefined);
