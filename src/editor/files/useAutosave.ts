// Autosave: on start, restore the project the browser kept (after a reload or a crash); then
// write the open project to IndexedDB shortly after every change, and at once when the page hides.
import { useEffect, useState } from 'react';
import type { DocumentStore } from '../../store/documentStore';
import { decideRecovery, makeAutosaveRecord, recoveryNotice } from './autosaveRecord';
import { readAutosave, writeAutosave } from './autosaveStore';
import { filesUi } from './filesUi';
import { whenIdle } from './projectJson';

/** Quiet time after the last change before writing, ms. */
export const AUTOSAVE_DELAY_MS = 400;
/** Longest wait for an idle moment after the quiet time, ms. */
export const IDLE_TIMEOUT_MS = 2000;

const clock = (ms: number) => new Date(ms).toLocaleTimeString();

function useRecovery(store: DocumentStore): boolean {
  const [ready, setReady] = useState(false);
  useEffect(() => {
    let cancelled = false;
    const startRevision = store.getState().revision;
    readAutosave().then(
      (stored) => {
        if (cancelled) return;
        const decision = decideRecovery(stored);
        // Never replace work the user started while the browser was still reading.
        if (decision.action === 'restore' && store.getState().revision === startRevision) {
          store.getState().loadProject(decision.project);
          if (decision.unsavedChanges) store.setState({ dirty: true });
          filesUi.getState().setNotice(recoveryNotice(decision, clock) ?? '');
        } else if (decision.action === 'discard') {
          filesUi.getState().setNotice(recoveryNotice(decision, clock) ?? '');
        }
        setReady(true);
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
    // A change starts the quiet-time timer; then the write waits for an idle moment of the page
    // (never in the middle of a drag or a scroll), at the latest IDLE_TIMEOUT_MS later.
    let timer: ReturnType<typeof setTimeout> | undefined;
    let cancelIdle: (() => void) | undefined;
    let inFlight = 0;
    let written: { project: unknown; dirty: boolean } | undefined;
    const settle = () =>
      filesUi.getState().setAutosavePending(timer !== undefined || cancelIdle !== undefined || inFlight > 0);
    const write = () => {
      timer = undefined;
      cancelIdle = undefined;
      const { project, dirty } = store.getState();
      if (written && written.project === project && written.dirty === dirty) return settle();
      written = { project, dirty };
      inFlight += 1;
      settle();
      writeAutosave(makeAutosaveRecord(project, dirty, Date.now()))
        .then(
          () => filesUi.getState().setAutosaved(Date.now()),
          (e: unknown) =>
            filesUi.getState().setAutosaved(undefined, `Autosave failed: ${(e as Error).message}`),
        )
        .finally(() => {
          inFlight -= 1;
          settle();
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
      cancel();
      timer = setTimeout(() => {
        timer = undefined;
        cancelIdle = whenIdle(write, IDLE_TIMEOUT_MS);
      }, AUTOSAVE_DELAY_MS);
      settle();
    });
    const flush = () => {
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
