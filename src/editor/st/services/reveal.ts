// "Show this line of that ST body": the Problems list (or a Run refusal) asks, the ST editor of that
// POU answers when it is (or comes) on screen by putting the cursor there.
import { createStore } from 'zustand/vanilla';
import type { PouId } from '../../../model/ids';

export interface StRevealRequest {
  readonly pouId: PouId;
  /** 1-based. */
  readonly line: number;
  readonly col: number;
  readonly seq: number;
}

export const stReveal = createStore<{ request: StRevealRequest | undefined }>()(() => ({
  request: undefined,
}));

let seq = 0;
export function revealStLine(pouId: PouId, line: number, col = 1): void {
  seq += 1;
  stReveal.setState({ request: { pouId, line, col, seq } });
}

/** Takes the request for this POU (once). */
export function takeReveal(pouId: PouId): StRevealRequest | undefined {
  const r = stReveal.getState().request;
  if (!r || r.pouId !== pouId) return undefined;
  stReveal.setState({ request: undefined });
  return r;
}
