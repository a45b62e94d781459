// Mount once inside the DocumentStoreProvider: the hidden .xml file picker of File > Import PLCopen
// XML…, the import report (what was dropped or changed, which POU to open), import errors, and the
// export review (what Beremiz/OpenPLC would run differently, before the download).
import { useEffect, useState } from 'react';
import { useStore } from 'zustand';
import type { PouId } from '../../model/ids';
import type { ImportIssue } from '../../plcopen/types';
import { useDocumentStore } from '../../store/documentStore';
import { HiddenFilePicker } from '../files/HiddenFilePicker';
import { ModalDialog, OkButton } from '../files/ModalDialog';
import { CancelOr } from './CancelOrButtons';
import { ExportReviewDialog } from './ExportReviewDialog';
import { openImported, readImportFile } from './plcopenActions';
import { plcopenUi } from './plcopenUi';
import { extrasText, pouCountText, pouToOpen } from '../../plcopen/importSummary';
import { bodyLanguage, libraryInfo } from '../../model/codesysUtil';
import './plcopen.css';

export function PlcopenHost() {
  return (
    <>
      <HiddenFilePicker
        accept=".xml,application/xml,text/xml"
        label="Import PLCopen XML file"
        testId="plcopen-file-input"
        register={plcopenUi.getState().setOpenPicker}
        onFile={(file) => void readImportFile(file)}
      />
      <ImportReportDialog />
      <ImportFailureDialog />
      <ExportReviewDialog />
    </>
  );
}

/** "line 12 <contact localId="7"> (POU Main): message" */
function where(i: ImportIssue): string {
  return [
    i.line !== undefined ? `line ${i.line}` : '',
    i.element ? `<${i.element}${i.localId ? ` localId="${i.localId}"` : ''}>` : '',
    i.pou ? `(POU ${i.pou})` : '',
  ]
    .filter(Boolean)
    .join(' ');
}

function IssueList({ issues, testId }: { readonly issues: readonly ImportIssue[]; readonly testId: string }) {
  return (
    <ul className="rs-load-errors rs-plcopen-issues" data-testid={testId}>
      {issues.map((i, k) => (
        <li key={k}>
          {where(i) ? <code>{where(i)}</code> : null}
          {where(i) ? ': ' : ''}
          {i.message}
        </li>
      ))}
    </ul>
  );
}

function ImportReportDialog() {
  const store = useDocumentStore();
  const pending = useStore(plcopenUi, (s) => s.pending);
  const [pou, setPou] = useState<string>('');
  // Open the program the configuration's resource runs, not the file's first POU (often a function).
  useEffect(() => setPou((pending && pouToOpen(pending.project)) ?? ''), [pending]);
  if (!pending) return null;
  const { project, report, fileName } = pending;
  const close = () => plcopenUi.getState().setPending(undefined);
  const networks = project.pous.reduce((n, p) => n + p.networks.length, 0);
  return (
    <ModalDialog
      role="dialog"
      titleId="rs-plcopen-title"
      title={`Import ${fileName}`}
      className="rs-plcopen-report"
      testId="plcopen-report"
      onClose={close}
      buttons={
        <CancelOr
          label="Open"
          disabled={project.pous.length === 0}
          onCancel={close}
          onConfirm={() => openImported(store, pending, (pou || undefined) as PouId | undefined)}
        />
      }
    >
      <p>
        PLCopen XML{report.producer ? ` written by ${report.producer}` : ''}:{' '}
        <span data-testid="plcopen-pou-count">{pouCountText(project)}</span>, {networks} LD network
        {networks === 1 ? '' : 's'},{' '}
        {project.tasks.length} task
        {project.tasks.length === 1 ? '' : 's'}.
      </p>
      {extrasText(project) && <p data-testid="plcopen-extras">{extrasText(project)}</p>}
      <p data-testid="plcopen-profile">
        Runs under the {report.profileReason}. Change it in the project inspector (Semantics).
      </p>
      {project.pous.length > 1 ? (
        <label className="rs-plcopen-pou">
          Open on POU{' '}
          <select value={pou} onChange={(e) => setPou(e.target.value)} data-testid="plcopen-pou-choice">
            {project.pous.map((p) => (
              <option key={p.id} value={p.id}>
                {`${p.name} (${p.kind.toLowerCase().replace('_', ' ')}, ${
                  p.language === 'LD' ? `${p.networks.length} network${p.networks.length === 1 ? '' : 's'}` : bodyLanguage(p)
                }${libraryInfo(p) ? `, ${libraryInfo(p)!.vendor} ${libraryInfo(p)!.library} library` : ''})`}
              </option>
            ))}
          </select>
          <span className="rs-plcopen-hint">All POUs are kept in the project.</span>
        </label>
      ) : null}
      {project.pous.length === 0 ? (
        <p className="rs-error-text">The file has no POU that Rungsmith can open.</p>
      ) : null}
      {report.warnings.length ? (
        <>
          <h3>
            {report.warnings.length} thing{report.warnings.length === 1 ? '' : 's'} dropped or changed
          </h3>
          <IssueList issues={report.warnings} testId="plcopen-warnings" />
        </>
      ) : (
        <p data-testid="plcopen-warnings">Nothing was dropped or changed.</p>
      )}
      {report.notes.length ? (
        <>
          <h3>Notes (nothing lost)</h3>
          <IssueList issues={report.notes} testId="plcopen-notes" />
        </>
      ) : null}
    </ModalDialog>
  );
}

function ImportFailureDialog() {
  const failure = useStore(plcopenUi, (s) => s.failure);
  if (!failure) return null;
  const close = () => plcopenUi.getState().setFailure(undefined);
  return (
    <ModalDialog
      role="alertdialog"
      titleId="rs-plcopen-failed"
      title={`Could not import ${failure.fileName}`}
      testId="plcopen-failure"
      onClose={close}
      buttons={<OkButton onClick={close} />}
    >
      <p>The file is not PLCopen XML Rungsmith can read. The open project is unchanged.</p>
      <IssueList issues={failure.errors} testId="plcopen-errors" />
    </ModalDialog>
  );
}
