// Where execution stands, in the words of the status line: `Main / network 4 → Motor1 (Motor) / network 2`
// (1-based network numbers; a body named by its instance and its POU).
import type { StepFrame } from '../../engine/api';

export const frameWords = (f: StepFrame): string => `${f.instance ? `${f.instance} (${f.pou})` : f.pou} / network ${f.network + 1}`;

export const positionWords = (frames: readonly StepFrame[]): string => frames.map(frameWords).join(' → ');
