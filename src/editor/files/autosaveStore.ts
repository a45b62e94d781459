// The autosave snapshots in the browser's IndexedDB (via idb-keyval), one pair per browser profile
// (two slots, see autosaveJournal.ts), and the journal in localStorage.
import { createStore, del, get, set, type UseStore } from 'idb-keyval';
import type { AutosaveRecord } from './autosaveRecord';
import { JOURNAL_KEY, SLOT_KEYS, type Slot, type StoredAutosave } from './autosaveJournal';

let db: UseStore | undefined;
const store = (): UseStore => (db ??= createStore('rungsmith', 'autosave'));

export async function readAutosave(): Promise<StoredAutosave> {
  const [a, b] = await Promise.all([get(SLOT_KEYS.a, store()), get(SLOT_KEYS.b, store())]);
  return { slots: { a, b }, journal: readJournal() };
}
export const writeAutosave = (slot: Slot, record: AutosaveRecord): Promise<void> =>
  set(SLOT_KEYS[slot], record, store());
export async function clearAutosave(): Promise<void> {
  removeJournal();
  await Promise.all([del(SLOT_KEYS.a, store()), del(SLOT_KEYS.b, store())]);
}

function readJournal(): string | null {
  try {
    return localStorage.getItem(JOURNAL_KEY);
  } catch {
    return null;
  }
}
/** Writes the journal text at once (synchronously); throws when the browser refuses (quota). */
export const writeJournal = (text: string): void => localStorage.setItem(JOURNAL_KEY, text);
export function removeJournal(): void {
  try {
    localStorage.removeItem(JOURNAL_KEY);
  } catch {
    // No storage: nothing to remove.
  }
}
