// The status line's debugger position: where execution stands while stepping or at a breakpoint,
// `Main / network 4 → Motor1 (Motor) / network 2`.
import type { SimState } from '../../store/simState';
import { positionWords } from './position';
import { useSim } from './simContext';

const selectWords = (s: SimState): string | undefined => {
  if (s.mode !== 'paused' && s.mode !== 'faulted') return undefined;
  const frames = s.position.length > 0 ? s.position : s.breakpointAt ? [s.breakpointAt] : [];
  return frames.length > 0 ? positionWords(frames) : undefined;
};

export function SimPosition() {
  const words = useSim(selectWords);
  return words ? (
    <span className="rs-sim-position" data-testid="sim-position" title="Where execution stands: the next network to run, inside the calls it stands in">
      ▶ {words}
    </span>
  ) : null;
}
