// File > Export PLCopen XML (a download) and File > Import PLCopen XML… (read, report, then open).
import type { PouId } from '../../model/ids';
import { exportPlcopen } from '../../plcopen/exportPlcopen';
import { importPlcopen } from '../../plcopen/importPlcopen';
import type { DocumentStore } from '../../store/documentStore';
import { openFilePicker, replaceDocument } from '../files/fileActions';
import { filesUi } from '../files/filesUi';
import { downloadText, projectFileName } from '../files/projectFile';
import { plcopenUi, type PendingImport } from './plcopenUi';

/** Offers the open project as a PLCopen TC6 XML v2.01 download; returns the file name. */
export function exportPlcopenFile(store: DocumentStore): string {
  const project = store.getState().project;
  const name = projectFileName(project, '.xml');
  downloadText(name, exportPlcopen(project), 'application/xml');
  filesUi.getState().setNotice(`Exported ${name} (PLCopen XML, in your downloads folder).`);
  return name;
}

export function chooseImportFile(): void {
  openFilePicker(plcopenUi.getState().openPicker);
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
