// What the browser keeps of the open project between visits, and whether to restore it on start.
// Pure (no IndexedDB here) so the decision logic runs in Node tests; autosaveStore.ts does the I/O.
import { loadProject, type LoadError } from '../../model/load';
import type { Project } from '../../model/project';
import { projectJson } from './projectJson';

export const AUTOSAVE_FORMAT = 'rungsmith-autosave';
export const AUTOSAVE_VERSION = 1;

export interface AutosaveRecord {
  readonly format: typeof AUTOSAVE_FORMAT;
  readonly version: typeof AUTOSAVE_VERSION;
  /** When the browser wrote it (ms since epoch). */
  readonly savedAt: number;
  /** True when the project had changes not yet saved to a file, so "New" must still ask. */
  readonly unsavedChanges: boolean;
  /** The project as its file text: the same validation applies on the way back in. */
  readonly projectText: string;
  /** Names this snapshot for the journal that is based on it (autosaveJournal.ts). */
  readonly id?: string;
}

export function makeAutosaveRecord(
  project: Project,
  unsavedChanges: boolean,
  now: number,
  id?: string,
): AutosaveRecord {
  return {
    format: AUTOSAVE_FORMAT,
    version: AUTOSAVE_VERSION,
    savedAt: now,
    unsavedChanges,
    projectText: projectJson(project),
    ...(id !== undefined ? { id } : {}),
  };
}

export type RecoveryDecision =
  | { readonly action: 'start-fresh' }
  | {
      readonly action: 'restore';
      readonly project: Project;
      readonly unsavedChanges: boolean;
      readonly savedAt: number;
    }
  | { readonly action: 'discard'; readonly reason: string; readonly errors: readonly LoadError[] };

/**
 * On start: restore the last autosaved project when there is a readable one; an unreadable
 * record (older format, damaged data) is discarded with a reason instead of breaking the start.
 */
export function decideRecovery(stored: unknown): RecoveryDecision {
  if (stored === undefined || stored === null) return { action: 'start-fresh' };
  if (typeof stored !== 'object')
    return { action: 'discard', reason: 'the autosaved data is not a project', errors: [] };
  const r = stored as Partial<Record<keyof AutosaveRecord, unknown>>;
  if (r.format !== AUTOSAVE_FORMAT || r.version !== AUTOSAVE_VERSION) {
    return {
      action: 'discard',
      reason: 'the autosave was written by an incompatible version of Rungsmith',
      errors: [],
    };
  }
  if (typeof r.projectText !== 'string' || typeof r.savedAt !== 'number') {
    return { action: 'discard', reason: 'the autosave is incomplete', errors: [] };
  }
  const loaded = loadProject(r.projectText);
  if (!loaded.ok)
    return {
      action: 'discard',
      reason: 'the autosaved project did not pass validation',
      errors: loaded.errors,
    };
  return {
    action: 'restore',
    project: loaded.project,
    unsavedChanges: r.unsavedChanges === true,
    savedAt: r.savedAt,
  };
}

/** Nothing drawn or declared yet: restoring it is not worth a notice. */
export const isBlankProject = (p: Project): boolean =>
  p.globals.length === 0 &&
  p.pous.every((pou) => pou.variables.length === 0 && pou.networks.every((n) => n.elements.length === 0));

/** "Restored your work from 14:02:31 (not yet saved to a file)." */
export function recoveryNotice(
  decision: RecoveryDecision,
  formatTime: (ms: number) => string,
): string | undefined {
  switch (decision.action) {
    case 'start-fresh':
      return undefined;
    case 'restore':
      if (isBlankProject(decision.project)) return undefined;
      return `Restored "${decision.project.name}" from the browser's autosave of ${formatTime(decision.savedAt)}${
        decision.unsavedChanges ? ' (changes not yet saved to a file)' : ''
      }.`;
    case 'discard': {
      const first = decision.errors[0];
      return `The autosave could not be restored: ${decision.reason}${first ? ` (${first.path}: ${first.message})` : ''}. Starting with a new project.`;
    }
  }
}
