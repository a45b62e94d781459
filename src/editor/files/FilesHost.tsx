// Mount once inside the DocumentStoreProvider: autosave + recovery, the hidden file picker used by
// File > Open, the "discard unsaved changes?" dialog, open errors and short notices.
import { useEffect, useRef } from 'react';
import { useStore } from 'zustand';
import { useDocumentStore } from '../../store/documentStore';
import { openChosenFile } from './fileActions';
import { filesUi } from './filesUi';
import { useAutosave } from './useAutosave';
import './files.css';

export function FilesHost() {
  const store = useDocumentStore();
  const input = useRef<HTMLInputElement>(null);
  useAutosave(store);
  useEffect(() => {
    filesUi.getState().setOpenPicker(() => input.current?.click());
    return () => filesUi.getState().setOpenPicker(undefined);
  }, []);
  return (
    <>
      <input
        ref={input}
        type="file"
        accept=".json,application/json"
        hidden
        data-testid="open-file-input"
        aria-label="Open project file"
        onChange={(e) => {
          const file = e.target.files?.[0];
          e.target.value = ''; // choosing the same file again still fires
          if (file) void openChosenFile(store, file);
        }}
      />
      <Notice />
      <ConfirmDialog />
      <OpenFailureDialog />
      <AutosaveStatus />
    </>
  );
}

function Notice() {
  const notice = useStore(filesUi, (s) => s.notice);
  useEffect(() => {
    if (!notice) return undefined;
    const timer = setTimeout(() => filesUi.getState().setNotice(''), 12_000);
    return () => clearTimeout(timer);
  }, [notice]);
  if (!notice) return null;
  return (
    <div className="rs-notice" role="status" data-testid="file-notice">
      <span>{notice}</span>
      <button type="button" className="rs-icon-button" aria-label="Dismiss" onClick={() => filesUi.getState().setNotice('')}>
        ×
      </button>
    </div>
  );
}

function ConfirmDialog() {
  const c = useStore(filesUi, (s) => s.confirmation);
  if (!c) return null;
  const close = () => filesUi.getState().closeConfirmation();
  return (
    <div className="rs-modal-backdrop" onKeyDown={(e) => e.key === 'Escape' && close()}>
      <div className="rs-modal" role="alertdialog" aria-modal="true" aria-labelledby="rs-confirm-title" aria-describedby="rs-confirm-message">
        <h2 id="rs-confirm-title">{c.title}</h2>
        <p id="rs-confirm-message">{c.message}</p>
        <div className="rs-modal-buttons">
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
        </div>
      </div>
    </div>
  );
}

function OpenFailureDialog() {
  const failure = useStore(filesUi, (s) => s.openFailure);
  if (!failure) return null;
  const close = () => filesUi.getState().showOpenFailure(undefined);
  return (
    <div className="rs-modal-backdrop" onKeyDown={(e) => e.key === 'Escape' && close()}>
      <div className="rs-modal" role="alertdialog" aria-modal="true" aria-labelledby="rs-open-failed" data-testid="open-failure">
        <h2 id="rs-open-failed">Could not open {failure.fileName}</h2>
        <p>The file is not a valid Rungsmith project. The open project is unchanged.</p>
        <ul className="rs-load-errors">
          {failure.errors.map((e, i) => (
            <li key={i}>
              <code>{e.path}</code>: {e.message}
            </li>
          ))}
        </ul>
        <div className="rs-modal-buttons">
          <button type="button" className="rs-button rs-primary" autoFocus onClick={close}>
            OK
          </button>
        </div>
      </div>
    </div>
  );
}

function AutosaveStatus() {
  const at = useStore(filesUi, (s) => s.autosavedAt);
  const error = useStore(filesUi, (s) => s.autosaveError);
  const dirty = useStore(useDocumentStore(), (s) => s.dirty);
  const text = error || (at ? `Autosaved in this browser at ${new Date(at).toLocaleTimeString()}${dirty ? ' · not saved to a file' : ''}` : '');
  if (!text) return null;
  return (
    <div className={error ? 'rs-autosave rs-error-text' : 'rs-autosave'} data-testid="autosave-status" data-saved-at={at ?? ''} role="status">
      {text}
    </div>
  );
}
