// The autosave slot in the browser's IndexedDB (via idb-keyval), one per browser profile.
import { createStore, del, get, set, type UseStore } from 'idb-keyval';
import type { AutosaveRecord } from './autosaveRecord';

const KEY = 'open-project';
let db: UseStore | undefined;
const store = (): UseStore => (db ??= createStore('rungsmith', 'autosave'));

export const readAutosave = (): Promise<unknown> => get(KEY, store());
export const writeAutosave = (record: AutosaveRecord): Promise<void> => set(KEY, record, store());
export const clearAutosave = (): Promise<void> => del(KEY, store());
