// Breakpoints and steps by POU and network (LD) or line (ST/IL): a breakpoint in a program's
// network or statement, or in an FB's or function's body (in any instance, or in the one named).
// The simulator checks `breakpointAt(plc, list)` before each step; with breakpoints inside bodies
// or on statements it steps with `stepNetwork({ into: true })` (the step code stops before each
// statement of an ST/IL body and before each network of an LD body). `step(plc, 'over' | 'into' |
// 'out')` is the debugger's step at either granularity, mixing both ways (an LD network calling
// an ST FB, an ST statement calling an LD FB).
import type { Plc, StepFrame, StepReport } from '../api';

export interface Breakpoint {
  readonly pou: string;
  /** 0-based network index in the POU (LD); ignored when `line` is given. */
  readonly network: number;
  /** ST/IL: the line of the statement (1-based, in the POU's text). */
  readonly line?: number;
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
    (b) =>
      same(b.pou, at.pou) &&
      (b.line !== undefined ? b.line === at.line : b.network === at.network && at.line === undefined) &&
      (b.instance === undefined || same(b.instance, at.instance)),
  );
}

/** True when a breakpoint lies inside a body or on a statement (stepping must go into calls to reach it). */
export const needsStepInto = (plc: Plc, breakpoints: readonly Breakpoint[]): boolean =>
  breakpoints.some((b) => !same(b.pou, plc.pou) || b.instance !== undefined || b.line !== undefined);

export type StepKind = 'over' | 'into' | 'out';

/**
 * One debugger step from where execution stands. Into: to the next stop at any depth (before the
 * first statement or network of a called body). Over: the statement or network runs whole, calls
 * included; the step ends at the next stop at this depth or above (after a body's last one, in its
 * caller). Out: the rest of the body runs; the step ends at the caller's next stop (at program
 * level: the end of the scan).
 */
export function step(plc: Plc, kind: StepKind): StepReport {
  const depth = plc.position().length;
  // Into, or over at program level (a network runs whole; an ST/IL program's statement: the PLC's own step over).
  if (kind === 'into' || depth === 0 || (kind === 'over' && depth === 1)) return plc.stepNetwork(kind === 'into' ? { into: true } : undefined);
  const goal = kind === 'out' ? depth - 1 : depth;
  let report = plc.stepNetwork({ into: true });
  while (!report.fault && !report.scanDone && plc.position().length > goal) report = plc.stepNetwork({ into: true });
  return report;
}

/** `Main / network 3 → PID1 (Pid) / line 12`: where execution stands, for the status line. */
export function describePosition(frames: readonly StepFrame[]): string {
  return frames
    .map((f) => `${f.instance ? `${f.instance} (${f.pou})` : f.pou} / ${f.line !== undefined ? `line ${f.line}` : `network ${f.network + 1}`}`)
    .join(' → ');
}
