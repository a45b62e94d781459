// Autosave: on start, restore the project the browser kept (after a reload or a crash); then, on
// every change, write a small journal of it to localStorage at once (synchronously, so a reload or a
// closed tab a moment later keeps it), and a full snapshot to IndexedDB shortly after; the journal
// is a patch against the last confirmed snapshot (autosaveJournal.ts).
import { useEffect, useState } from 'react';
import type { DocumentStore } from '../../store/documentStore';
import type { Project } from '../../model/project';
import { makeAutosaveRecord, recoveryNotice } from './autosaveRecord';
import {
  decideRecoveryFrom,
  JOURNAL_MAX_NETWORKS,
  makeJournal,
  otherSlot,
  projectPatch,
  type Slot,
} from './autosaveJournal';
import { readAutosave, removeJournal, writeAutosave, writeJournal } from './autosaveStore';
import { filesUi } from './filesUi';
import { showPlantTab } from '../plant/showPlantTab';
import { whenIdle } from './projectJson';

/** Quiet time after the last change before writing the snapshot, ms. */
export const AUTOSAVE_DELAY_MS = 400;
/** Longest wait for an idle moment after the quiet time, ms. */
export const IDLE_TIMEOUT_MS = 2000;

const clock = (ms: number) => new Date(ms).toLocaleTimeString();

let lastStamp = 0;
/** Milliseconds since the epoch, but always later than the last stamp: orders states of the project. */
const nextStamp = () => (lastStamp = Math.max(Date.now(), lastStamp + 1));
const newId = () => `${Date.now().toString(36)}-${Math.random().toString(36).slice(2, 10)}`;

interface Ready {
  /** The slot holding what was restored (or the journal's base): not overwritten first. */
  readonly keepSlot: Slot | undefined;
}

function useRecovery(store: DocumentStore): Ready | undefined {
  const [ready, setReady] = useState<Ready | undefined>(undefined);
  useEffect(() => {
    let cancelled = false;
    const startRevision = store.getState().revision;
    readAutosave().then(
      (stored) => {
        if (cancelled) return;
        const { decision, keepSlot } = decideRecoveryFrom(stored);
        // Never replace work the user started while the browser was still reading.
        if (decision.action === 'restore' && store.getState().revision === startRevision) {
          lastStamp = Math.max(lastStamp, decision.savedAt);
          store.getState().loadProject(decision.project);
          if (decision.unsavedChanges) store.setState({ dirty: true });
          filesUi.getState().setNotice(recoveryNotice(decision, clock) ?? '');
          // Work on a machine comes back with the machine in view, as the project opened.
          if (decision.project.plant) showPlantTab();
        } else if (decision.action === 'discard') {
          filesUi.getState().setNotice(recoveryNotice(decision, clock) ?? '');
        }
        setReady({ keepSlot });
      },
      (e: unknown) => {
        if (cancelled) return;
        filesUi
          .getState()
          .setAutosaved(undefined, `Autosave is not available in this browser (${(e as Error).message}).`);
      },
    );
    return () => {
      cancelled = true;
    };
  }, [store]);
  return ready;
}

export function useAutosave(store: DocumentStore): void {
  const ready = useRecovery(store);
  useEffect(() => {
    if (!ready) return undefined;
    // The last snapshot IndexedDB confirmed: the journal is a patch against it.
    let base: { slot: Slot; id: string; project: Project; dirty: boolean } | undefined;
    let keep = ready.keepSlot;
    let stateStamp = nextStamp();
    // The journal in localStorage is older than the project (a change too large to journal at once).
    let journalBehind = false;
    // A change starts the quiet-time timer; then the snapshot waits for an idle moment of the page
    // (never in the middle of a drag or a scroll), at the latest IDLE_TIMEOUT_MS later.
    let timer: ReturnType<typeof setTimeout> | undefined;
    let cancelIdle: (() => void) | undefined;
    let inFlight = false;
    let again = false;
    const settle = () =>
      filesUi.getState().setAutosavePending(timer !== undefined || cancelIdle !== undefined || inFlight);

    /** Brings the journal up to the project; `force`: whatever its size (the page is going away). */
    const journal = (force: boolean) => {
      const { project, dirty } = store.getState();
      if (base && base.project === project && base.dirty === dirty) {
        removeJournal();
        journalBehind = false;
        return;
      }
      const { patch, inlineNetworks } = projectPatch(base?.project, project);
      if (!force && inlineNetworks > JOURNAL_MAX_NETWORKS) {
        journalBehind = true;
        return;
      }
      try {
        writeJournal(JSON.stringify(makeJournal(base && { slot: base.slot, id: base.id }, patch, dirty, stateStamp)));
        journalBehind = false;
      } catch (e) {
        journalBehind = true;
        if (force)
          filesUi
            .getState()
            .setAutosaved(undefined, `Autosave could not keep the last change: ${(e as Error).message}`);
      }
    };

    const write = () => {
      timer = undefined;
      cancelIdle = undefined;
      if (inFlight) {
        // One snapshot at a time: the slot being written is never the journal's base.
        again = true;
        return settle();
      }
      const { project, dirty } = store.getState();
      if (base && base.project === project && base.dirty === dirty) return settle();
      const slot: Slot = base ? otherSlot(base.slot) : keep ? otherSlot(keep) : 'a';
      const id = newId();
      inFlight = true;
      settle();
      writeAutosave(slot, makeAutosaveRecord(project, dirty, stateStamp, id))
        .then(
          () => {
            base = { slot, id, project, dirty };
            keep = slot;
            journal(false);
            filesUi.getState().setAutosaved(Date.now());
          },
          (e: unknown) =>
            filesUi.getState().setAutosaved(undefined, `Autosave failed: ${(e as Error).message}`),
        )
        .finally(() => {
          inFlight = false;
          settle();
          if (again) {
            again = false;
            write();
          }
        });
    };
    const cancel = () => {
      if (timer) clearTimeout(timer);
      cancelIdle?.();
      timer = undefined;
      cancelIdle = undefined;
    };
    const unsubscribe = store.subscribe((s, prev) => {
      if (s.project === prev.project && s.dirty === prev.dirty) return;
      stateStamp = nextStamp();
      journal(false);
      cancel();
      timer = setTimeout(() => {
        timer = undefined;
        cancelIdle = whenIdle(write, IDLE_TIMEOUT_MS);
      }, AUTOSAVE_DELAY_MS);
      settle();
    });
    const flush = () => {
      if (journalBehind) journal(true);
      if (timer || cancelIdle) {
        cancel();
        write();
      }
    };
    const onVisibility = () => document.visibilityState === 'hidden' && flush();
    window.addEventListener('pagehide', flush);
    document.addEventListener('visibilitychange', onVisibility);
    write();
    return () => {
      flush();
      unsubscribe();
      window.removeEventListener('pagehide', flush);
      document.removeEventListener('visibilitychange', onVisibility);
    };
  }, [ready, store]);
}
