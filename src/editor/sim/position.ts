// Where execution stands, in the words of the status line: `Main / network 4 → Motor1 (Motor) / network 2`,
// `Main / network 3 → PID1 (Pid) / line 12` (1-based network numbers; an ST/IL body by the line of
// its statement; a body named by its instance and its POU).
import type { Fault, StepFrame } from '../../engine/api';
import { describePosition } from '../../engine/runtime/breakpoints';

export const frameWords = (f: StepFrame): string => describePosition([f]);

export const positionWords = (frames: readonly StepFrame[]): string => describePosition(frames);

/** A fault in words; inside a body it names the instance and the POU: `Watchdog fault in Motor1 (Motor) network 2 (LOOP): …`. */
export const faultWords = (f: Fault): string =>
  `${f.kind === 'watchdog' ? 'Watchdog fault' : 'Runtime fault'} in ${f.instance ? `${f.instance} (${f.pou})` : f.pou} ${
    f.network < 0 ? 'variables' : f.line !== undefined ? `line ${f.line}` : `network ${f.network + 1}${f.networkLabel ? ` (${f.networkLabel})` : ''}`
  }: ${f.message.replace(/^watchdog:\s*/, '')}`;
