// Where execution stands, in the words of the status line: `Main / network 4 → Motor1 (Motor) / network 2`
// (1-based network numbers; a body named by its instance and its POU).
import type { Fault, StepFrame } from '../../engine/api';

export const frameWords = (f: StepFrame): string => `${f.instance ? `${f.instance} (${f.pou})` : f.pou} / network ${f.network + 1}`;

export const positionWords = (frames: readonly StepFrame[]): string => frames.map(frameWords).join(' → ');

/** A fault in words; inside a body it names the instance and the POU: `Watchdog fault in Motor1 (Motor) network 2 (LOOP): …`. */
export const faultWords = (f: Fault): string =>
  `${f.kind === 'watchdog' ? 'Watchdog fault' : 'Runtime fault'} in ${f.instance ? `${f.instance} (${f.pou})` : f.pou} ${
    f.network < 0 ? 'variables' : `network ${f.network + 1}${f.networkLabel ? ` (${f.networkLabel})` : ''}`
  }: ${f.message.replace(/^watchdog:\s*/, '')}`;
