// The autosave journal: what changed since the last snapshot the browser confirmed writing.
//
// A full snapshot of the project goes to IndexedDB in the background (autosaveStore.ts), but an
// IndexedDB write started when the page unloads may never finish, and a large project takes a while
// to serialise. So every change also writes, synchronously, a small journal to localStorage: the
// project as a patch against the last confirmed snapshot. The patch names unchanged POUs and runs of
// unchanged networks by their index in the snapshot and carries only what differs (compared by
// reference: commands and undo share every untouched part of the project), so its cost follows
// the size of the change, not of the project (10,000 networks: a pass over the array, no
// serialising). Snapshots alternate between two slots, and a new one is never written to the slot
// the journal is based on, so the journal's base is always still there to apply it to.
//
// Pure (no storage here): useAutosave.ts does the I/O.
import type { Network, Pou, Project, Variable } from '../../model/project';
import { AUTOSAVE_FORMAT, AUTOSAVE_VERSION, decideRecovery, type RecoveryDecision } from './autosaveRecord';

export const JOURNAL_FORMAT = 'rungsmith-autosave-journal';
/** 2: a POU patch may give its variables as runs of the base POU's (`variables`); version 1 journals still read. */
export const JOURNAL_VERSION = 2;
/** localStorage key of the journal. */
export const JOURNAL_KEY = 'rungsmith.autosave.journal';
/** The two IndexedDB keys the snapshots alternate between ('a' is the key older versions used). */
export const SLOT_KEYS = { a: 'open-project', b: 'open-project-b' } as const;
export type Slot = keyof typeof SLOT_KEYS;
export const otherSlot = (s: Slot): Slot => (s === 'a' ? 'b' : 'a');

/**
 * More networks written out than this in one journal, and the journal waits for the page to hide
 * (a file opened, a thousand networks pasted): the per-change cost stays bounded; the snapshot
 * written shortly after covers the change, and the page-hide flush covers a reload before that.
 */
export const JOURNAL_MAX_NETWORKS = 300;

/** A run of networks unchanged since the base POU: [first index in the base, count]. */
type NetworkRun = readonly [number, number];

export interface PouPatch {
  /** Every field of the POU but its networks (and its variables when `variables` is there), as in the project file. */
  readonly fields: Readonly<Record<string, unknown>>;
  /**
   * The variables as runs of the base POU's and the new or changed ones, like `networks`: an edit
   * of a POU with thousands of variables does not write them all again (localStorage.setItem of
   * them cost ~10 ms a keystroke). Absent: the variables are in `fields`.
   */
  readonly variables?: readonly (NetworkRun | Variable)[];
  /** Index of the POU in the base the runs refer to (absent: no base, every network inline). */
  readonly base?: number;
  readonly networks: readonly (NetworkRun | Network)[];
}

export interface ProjectPatch {
  /** Top-level fields that differ from the base (all of them when there is no base). */
  readonly set: Readonly<Record<string, unknown>>;
  /** Top-level fields the base has and the project no longer has. */
  readonly unset: readonly string[];
  /** A number: the POU at that index of the base, unchanged. */
  readonly pous: readonly (number | PouPatch)[];
}

export interface JournalRecord {
  readonly format: typeof JOURNAL_FORMAT;
  readonly version: 1 | typeof JOURNAL_VERSION;
  /** The snapshot the patch applies to; absent: the patch holds the whole project. */
  readonly base?: { readonly slot: Slot; readonly id: string };
  /** When the project reached this state (a stamp: later states have larger ones). */
  readonly savedAt: number;
  readonly unsavedChanges: boolean;
  readonly patch: ProjectPatch;
}

const networkIndex = new WeakMap<Pou, Map<Network, number>>();
function indexOfNetworks(pou: Pou): Map<Network, number> {
  let m = networkIndex.get(pou);
  if (!m) {
    m = new Map(pou.networks.map((n, i) => [n, i]));
    networkIndex.set(pou, m);
  }
  return m;
}

const variableIndex = new WeakMap<Pou, Map<Variable, number>>();
function indexOfVariables(pou: Pou): Map<Variable, number> {
  let m = variableIndex.get(pou);
  if (!m) {
    m = new Map(pou.variables.map((v, i) => [v, i]));
    variableIndex.set(pou, m);
  }
  return m;
}

/** `items` as runs of the base's items ([first index, count]) and the items not in the base, and how many of those. */
function runsOf<T>(items: readonly T[], index: Map<T, number> | undefined): { list: (NetworkRun | T)[]; inline: number } {
  const list: (NetworkRun | T)[] = [];
  let inline = 0;
  let run: [number, number] | undefined;
  for (const item of items) {
    const at = index?.get(item);
    if (at === undefined) {
      run = undefined;
      list.push(item);
      inline += 1;
    } else if (run && run[0] + run[1] === at) run[1] += 1;
    else {
      run = [at, 1];
      list.push(run);
    }
  }
  return { list, inline };
}

/** The items of `runs` over the base's `from` (undefined when a run does not fit). */
function fromRuns(runs: readonly unknown[], from: readonly unknown[]): unknown[] | undefined {
  const out: unknown[] = [];
  for (const n of runs) {
    if (Array.isArray(n)) {
      const [start, count] = n as unknown as NetworkRun;
      if (start + count > from.length) return undefined;
      out.push(...from.slice(start, start + count));
    } else out.push(n);
  }
  return out;
}

const pouIndex = new WeakMap<Project, Map<string, number>>();
function indexOfPous(project: Project): Map<string, number> {
  let m = pouIndex.get(project);
  if (!m) {
    m = new Map(project.pous.map((p, i) => [p.id as string, i]));
    pouIndex.set(project, m);
  }
  return m;
}

function pouFields(pou: Pou): Record<string, unknown> {
  const { networks: _networks, ...fields } = pou;
  return fields;
}

/** The patch that turns `base` into `current`, and how many networks it writes out. */
export function projectPatch(
  base: Project | undefined,
  current: Project,
): { readonly patch: ProjectPatch; readonly inlineNetworks: number } {
  const set: Record<string, unknown> = {};
  const unset: string[] = [];
  const b = (base ?? {}) as unknown as Record<string, unknown>;
  const c = current as unknown as Record<string, unknown>;
  for (const key of Object.keys(c)) if (key !== 'pous' && c[key] !== b[key]) set[key] = c[key];
  if (base) for (const key of Object.keys(b)) if (key !== 'pous' && !(key in c)) unset.push(key);
  let inlineNetworks = 0;
  const byId = base ? indexOfPous(base) : undefined;
  const pous = current.pous.map((pou): number | PouPatch => {
    const bi = byId?.get(pou.id);
    const basePou = bi === undefined ? undefined : base!.pous[bi];
    if (basePou === pou) return bi!;
    const nets = runsOf(pou.networks, basePou ? indexOfNetworks(basePou) : undefined);
    inlineNetworks += nets.inline;
    const fields = pouFields(pou);
    if (!basePou) return { fields, networks: nets.list };
    delete fields.variables;
    return { fields, variables: runsOf(pou.variables, indexOfVariables(basePou)).list, base: bi!, networks: nets.list };
  });
  return { patch: { set, unset, pous }, inlineNetworks };
}

/**
 * The project data (as parsed from the base snapshot's text) with the patch applied. Returns
 * undefined when the patch does not fit the base (then the journal is not used).
 */
export function applyPatch(baseData: unknown, patch: ProjectPatch): unknown {
  const base = (baseData ?? {}) as Record<string, unknown>;
  const basePous = Array.isArray(base.pous) ? (base.pous as Record<string, unknown>[]) : [];
  const out: Record<string, unknown> = { ...base, ...patch.set };
  for (const key of patch.unset) delete out[key];
  const pous: unknown[] = [];
  for (const entry of patch.pous) {
    if (typeof entry === 'number') {
      if (!basePous[entry]) return undefined;
      pous.push(basePous[entry]);
      continue;
    }
    const from = entry.base === undefined ? undefined : basePous[entry.base];
    const fromNetworks = Array.isArray(from?.networks) ? (from.networks as unknown[]) : [];
    const networks = fromRuns(entry.networks, fromNetworks);
    if (!networks) return undefined;
    if (entry.variables) {
      const variables = fromRuns(entry.variables, Array.isArray(from?.variables) ? (from.variables as unknown[]) : []);
      if (!variables) return undefined;
      pous.push({ ...entry.fields, variables, networks });
    } else pous.push({ ...entry.fields, networks });
  }
  out.pous = pous;
  return out;
}

export function makeJournal(
  base: { readonly slot: Slot; readonly id: string } | undefined,
  patch: ProjectPatch,
  unsavedChanges: boolean,
  savedAt: number,
): JournalRecord {
  return {
    format: JOURNAL_FORMAT,
    version: JOURNAL_VERSION,
    ...(base ? { base } : {}),
    savedAt,
    unsavedChanges,
    patch,
  };
}

const recordOf = (v: unknown): Record<string, unknown> | undefined =>
  typeof v === 'object' && v !== null ? (v as Record<string, unknown>) : undefined;

function parseJournal(text: string | null | undefined): JournalRecord | undefined {
  if (!text) return undefined;
  try {
    const j = recordOf(JSON.parse(text));
    if (!j || j.format !== JOURNAL_FORMAT || (j.version !== JOURNAL_VERSION && j.version !== 1)) return undefined;
    if (typeof j.savedAt !== 'number' || !recordOf(j.patch)) return undefined;
    return j as unknown as JournalRecord;
  } catch {
    return undefined;
  }
}

export interface StoredAutosave {
  /** What each IndexedDB slot holds (undefined: nothing). */
  readonly slots: Readonly<Record<Slot, unknown>>;
  /** The localStorage journal's text (null: none). */
  readonly journal: string | null | undefined;
}

export interface Recovery {
  readonly decision: RecoveryDecision;
  /**
   * The slot that must not be overwritten before a newer snapshot is confirmed (the one the
   * journal or the restored state comes from); undefined: either may be written.
   */
  readonly keepSlot: Slot | undefined;
}

/**
 * On start: the newest state among the two snapshots and the journal (a journal only counts on top
 * of the very snapshot it was based on, or when it holds the whole project).
 */
export function decideRecoveryFrom(stored: StoredAutosave): Recovery {
  const slotOf = (s: Slot) => recordOf(stored.slots[s]);
  const stampOf = (s: Slot) => {
    const r = slotOf(s);
    return r && r.format === AUTOSAVE_FORMAT && typeof r.savedAt === 'number' ? r.savedAt : -Infinity;
  };
  const newestSlot: Slot | undefined =
    stampOf('a') === -Infinity && stampOf('b') === -Infinity ? undefined : stampOf('b') > stampOf('a') ? 'b' : 'a';

  const journal = parseJournal(stored.journal);
  if (journal && journal.savedAt >= (newestSlot ? stampOf(newestSlot) : -Infinity)) {
    const baseRecord = journal.base ? slotOf(journal.base.slot) : undefined;
    const fits = !journal.base || (baseRecord !== undefined && baseRecord.id === journal.base.id);
    if (fits) {
      let baseData: unknown;
      try {
        baseData = baseRecord ? JSON.parse(String(baseRecord.projectText)) : undefined;
      } catch {
        baseData = undefined;
      }
      const data = baseRecord && baseData === undefined ? undefined : applyPatch(baseData, journal.patch);
      if (data !== undefined) {
        const decision = decideRecovery({
          format: AUTOSAVE_FORMAT,
          version: AUTOSAVE_VERSION,
          savedAt: journal.savedAt,
          unsavedChanges: journal.unsavedChanges,
          projectText: JSON.stringify(data),
        });
        if (decision.action === 'restore') return { decision, keepSlot: journal.base?.slot ?? newestSlot };
      }
    }
  }
  if (!newestSlot) return { decision: decideRecovery(undefined), keepSlot: undefined };
  const decision = decideRecovery(stored.slots[newestSlot]);
  if (decision.action === 'restore' || stampOf(otherSlot(newestSlot)) === -Infinity)
    return { decision, keepSlot: newestSlot };
  // The newest snapshot is damaged: fall back to the other one.
  const older = decideRecovery(stored.slots[otherSlot(newestSlot)]);
  return older.action === 'restore'
    ? { decision: older, keepSlot: otherSlot(newestSlot) }
    : { decision, keepSlot: newestSlot };
}
