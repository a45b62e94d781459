// File > Export PLCopen XML (a download) and File > Import PLCopen XML… (read, report, then open).
import type { PouId } from '../../model/ids';
import { exportPlcopen } from '../../plcopen/exportPlcopen';
import { importPlcopen } from '../../plcopen/importPlcopen';
import type { DocumentStore } from '../../store/documentStore';
import { replaceDocument } from '../files/fileActions';
import { filesUi } from '../files/filesUi';
import { projectFileName } from '../files/projectFile';
import { plcopenUi, type PendingImport } from './plcopenUi';

/** Offers the open project as a PLCopen TC6 XML v2.01 download; returns the file name. */
export function exportPlcopenFile(store: DocumentStore): string {
  const project = store.getState().project;
  const name = projectFileName(project).replace(/\.json$/, '.xml');
  const url = URL.createObjectURL(new Blob([exportPlcopen(project)], { type: 'application/xml' }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.style.display = 'none';
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
  filesUi.getState().setNotice(`Exported ${name} (PLCopen XML, in your downloads folder).`);
  return name;
}

export function chooseImportFile(): void {
  const open = plcopenUi.getState().openPicker;
  if (open) open();
  else filesUi.getState().setNotice('The file picker is not available in this view.');
}

/** Reads a chosen file; a bad file shows its located errors and leaves the open project untouched. */
export async function readImportFile(file: File): Promise<void> {
  let text: string;
  try {
    text = await file.text();
  } catch (e) {
    plcopenUi.getState().setFailure({
      fileName: file.name,
      errors: [{ message: `could not read the file: ${(e as Error).message}` }],
    });
    return;
  }
  const r = importPlcopen(text);
  if (!r.ok) plcopenUi.getState().setFailure({ fileName: file.name, errors: r.errors });
  else plcopenUi.getState().setPending({ fileName: file.name, project: r.project, report: r.report });
}

/** Opens the imported project (asking first if there are unsaved changes) on the chosen POU. */
export function openImported(store: DocumentStore, pending: PendingImport, pouId: PouId | undefined): void {
  plcopenUi.getState().setPending(undefined);
  replaceDocument(store, `Importing ${pending.fileName}`, 'Discard and import', () => {
    store.getState().loadProject(pending.project);
    if (pouId) store.getState().setActivePou(pouId);
    const n = pending.report.warnings.length;
    filesUi
      .getState()
      .setNotice(
        `Imported ${pending.fileName}${n ? ` (${n} note${n === 1 ? '' : 's'} in the import report)` : ''}.`,
      );
  });
}
