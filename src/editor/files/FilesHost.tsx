// Mount once inside the DocumentStoreProvider: autosave + recovery, the hidden file picker used by
// File > Open, the "discard unsaved changes?" dialog, open errors and short notices.
import { useCallback, useEffect, useState } from 'react';
import { useStore } from 'zustand';
import { useDocumentStore } from '../../store/documentStore';
import { openChosenFile } from './fileActions';
import { filesUi } from './filesUi';
import { HiddenFilePicker } from './HiddenFilePicker';
import { Notice } from '../layout/Notice';
import { ModalDialog, OkButton } from './ModalDialog';
import { useAutosave } from './useAutosave';
import { OTHER_TAB_WARNING, otherTabs, watchOtherTabs } from './otherTabs';
import './files.css';

export function FilesHost() {
  const store = useDocumentStore();
  useAutosave(store);
  // Another tab with the app open shares this autosave: said (OtherTabNotice) while it is open.
  useEffect(() => watchOtherTabs(), []);
  const open = useCallback((file: File) => void openChosenFile(store, file), [store]);
  useFileDrop(open);
  return (
    <>
      <HiddenFilePicker
        accept=".json,application/json"
        label="Open project file"
        testId="open-file-input"
        register={filesUi.getState().setOpenPicker}
        onFile={open}
      />
      <ConfirmDialog />
      <OpenFailureDialog />
      <AutosaveStatus />
    </>
  );
}

/** A project file dropped anywhere on the page opens like File > Open (other drags pass through). */
function useFileDrop(open: (file: File) => void) {
  useEffect(() => {
    const carriesFiles = (e: DragEvent) => e.dataTransfer?.types.includes('Files') === true;
    const onDragOver = (e: DragEvent) => {
      if (!carriesFiles(e)) return;
      e.preventDefault();
      if (e.dataTransfer) e.dataTransfer.dropEffect = 'copy';
    };
    const onDrop = (e: DragEvent) => {
      if (!carriesFiles(e)) return;
      e.preventDefault();
      const file = e.dataTransfer?.files[0];
      if (file) open(file);
    };
    window.addEventListener('dragover', onDragOver);
    window.addEventListener('drop', onDrop);
    return () => {
      window.removeEventListener('dragover', onDragOver);
      window.removeEventListener('drop', onDrop);
    };
  }, [open]);
}

/** What a file command did ("Saved as …", "Opened …", an import), in the notice area (NoticeArea.tsx). */
export function FileNotice() {
  const notice = useStore(filesUi, (s) => s.notice);
  const serial = useStore(filesUi, (s) => s.noticeSerial);
  if (!notice) return null;
  return <Notice testId="file-notice" tone="info" text={notice} token={serial} onDismiss={() => filesUi.getState().setNotice('')} />;
}

/** While Rungsmith is open in another tab of this browser: the tabs overwrite each other's autosave. */
export function OtherTabNotice() {
  const others = useStore(otherTabs, (s) => s.others);
  if (others.length === 0) return null;
  return <Notice testId="other-tab-notice" tone="info" text={OTHER_TAB_WARNING} token={others} />;
}

function ConfirmDialog() {
  const c = useStore(filesUi, (s) => s.confirmation);
  if (!c) return null;
  const close = () => filesUi.getState().closeConfirmation();
  return (
    <ModalDialog
      role="alertdialog"
      titleId="rs-confirm-title"
      title={c.title}
      describedBy="rs-confirm-message"
      onClose={close}
      buttons={
        <>
          <button type="button" className="rs-button" autoFocus onClick={close}>
            Cancel
          </button>
          <button
            type="button"
            className="rs-button rs-danger"
            onClick={() => {
              close();
              c.onConfirm();
            }}
          >
            {c.confirmLabel}
          </button>
        </>
      }
    >
      <p id="rs-confirm-message">{c.message}</p>
    </ModalDialog>
  );
}

function OpenFailureDialog() {
  const failure = useStore(filesUi, (s) => s.openFailure);
  if (!failure) return null;
  const close = () => filesUi.getState().showOpenFailure(undefined);
  return (
    <ModalDialog
      role="alertdialog"
      titleId="rs-open-failed"
      title={`Could not open ${failure.fileName}`}
      testId="open-failure"
      onClose={close}
      buttons={<OkButton onClick={close} />}
    >
      <p>The file is not a valid Rungsmith project. The open project is unchanged.</p>
      <ul className="rs-load-errors">
        {failure.errors.map((e, i) => (
          <li key={i}>
            <code>{e.path}</code>: {e.message}
          </li>
        ))}
      </ul>
    </ModalDialog>
  );
}

/** "Autosaved at 14:02:31": shown for a moment after each write (errors stay), just above the status bar. */
function AutosaveStatus() {
  const at = useStore(filesUi, (s) => s.autosavedAt);
  const error = useStore(filesUi, (s) => s.autosaveError);
  const pending = useStore(filesUi, (s) => s.autosavePending);
  const dirty = useStore(useDocumentStore(), (s) => s.dirty);
  const [fresh, setFresh] = useState(false);
  useEffect(() => {
    if (!at) return undefined;
    setFresh(true);
    const timer = setTimeout(() => setFresh(false), 2500);
    return () => clearTimeout(timer);
  }, [at]);
  const text =
    error ||
    (at
      ? `Autosaved in this browser at ${new Date(at).toLocaleTimeString()}${dirty ? ' · not saved to a file' : ''}`
      : '');
  if (!text) return null;
  return (
    <div
      className={`rs-autosave${error ? ' rs-error-text' : ''}${error || fresh ? ' rs-shown' : ''}`}
      data-testid="autosave-status"
      data-saved-at={at ?? ''}
      data-pending={pending}
      role="status"
    >
      {text}
    </div>
  );
}
