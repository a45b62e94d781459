// File > Export PLCopen XML (a download, after a review of what Beremiz/OpenPLC run differently) and File > Import PLCopen XML… (read, report, then open).
import type { PouId } from '../../model/ids';
import { pouToOpen } from '../../plcopen/importSummary';
import { exportBehaviour, type ExportFix } from '../../plcopen/exportBehaviour';
import { exportPlcopen } from '../../plcopen/exportPlcopen';
import { importPlcopen } from '../../plcopen/importPlcopen';
import type { DocumentStore } from '../../store/documentStore';
import { openFilePicker, replaceDocument } from '../files/fileActions';
import { filesUi } from '../files/filesUi';
import { downloadText, projectFileName } from '../files/projectFile';
import { plcopenUi, type PendingImport } from './plcopenUi';

/**
 * File > Export PLCopen XML: when Beremiz/OpenPLC would run something differently (LD-X rules), the
 * review dialog lists it first (fixes, "Export anyway"); otherwise the download starts at once.
 */
export function exportPlcopenFile(store: DocumentStore): void {
  if (exportBehaviour(store.getState().project).length) plcopenUi.getState().setReviewingExport(true);
  else downloadPlcopenFile(store);
}

/** Applies an export fix as one undo step: the network rewritten, the new variables declared. */
export function applyExportFixTo(store: DocumentStore, fix: ExportFix): void {
  const doc = store.getState();
  const pou = doc.project.pous.find((p) => p.id === fix.pouId);
  const current = pou?.networks.find((n) => n.id === fix.before.id);
  if (!pou || current !== fix.before) return; // the project changed since the fix was computed
  doc.batch(fix.label, () => {
    store.getState().replaceNetworks(fix.label, [{ pou: pou.id, before: current, after: fix.after }]);
    for (const v of fix.variables) store.getState().addVariable(v, pou.id);
  });
}

/** Offers the open project as a PLCopen TC6 XML v2.01 download; returns the file name. */
export function downloadPlcopenFile(store: DocumentStore): string {
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
    const open = pouId ?? pouToOpen(pending.project);
    if (open) store.getState().setActivePou(open);
    const n = pending.report.warnings.length;
    filesUi
      .getState()
      .setNotice(
        `Imported ${pending.fileName}${n ? ` (${n} note${n === 1 ? '' : 's'} in the import report)` : ''}.`,
      );
  });
}
