// Undo/redo history of named change lists (diffs, never project snapshots).
import type { Change } from './changes';

export interface HistoryEntry {
  /** Command name shown in "Undo <name>": 'placeElement', 'moveElements', ... */
  readonly name: string;
  readonly changes: readonly Change[];
}

export interface History {
  readonly undo: readonly HistoryEntry[];
  readonly redo: readonly HistoryEntry[];
}

export const EMPTY_HISTORY: History = { undo: [], redo: [] };
/** Enough for a long session; the oldest steps are dropped first. */
export const HISTORY_LIMIT = 500;

export function record(h: History, entry: HistoryEntry): History {
  const undo = [...h.undo, entry];
  if (undo.length > HISTORY_LIMIT) undo.splice(0, undo.length - HISTORY_LIMIT);
  return { undo, redo: [] };
}

/** Merges every entry recorded after `mark` (an undo-stack length) into one named step. */
export function squash(h: History, mark: number, name: string): History {
  if (h.undo.length - mark <= 1) {
    if (h.undo.length - mark === 1) {
      const last = h.undo[h.undo.length - 1]!;
      return { ...h, undo: [...h.undo.slice(0, -1), { name, changes: last.changes }] };
    }
    return h;
  }
  const merged = h.undo.slice(mark).flatMap((e) => e.changes);
  return { ...h, undo: [...h.undo.slice(0, mark), { name, changes: merged }] };
}

/**
 * Merges `entry` (still on the undo stack) and every entry recorded after it into one step named
 * `name`: placing an element and naming it right away undo together. Found by identity, so the
 * oldest steps dropped at HISTORY_LIMIT do not shift it; unchanged when it is gone (undone).
 */
export function squashFrom(h: History, entry: HistoryEntry, name: string): History {
  const at = h.undo.lastIndexOf(entry);
  return at < 0 ? h : squash(h, at, name);
}
