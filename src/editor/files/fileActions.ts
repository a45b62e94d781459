// What New, Open, Save and the examples do. Anything that would discard unsaved work asks first.
import type { Project } from '../../model/project';
import type { DocumentStore } from '../../store/documentStore';
import { filesUi } from './filesUi';
import { downloadProject, readProjectFile } from './projectFile';
import { showPlantTab } from '../plant/showPlantTab';

/** Runs `replace` now, or after the user agreed to lose the unsaved changes. */
export function replaceDocument(
  store: DocumentStore,
  what: string,
  confirmLabel: string,
  replace: () => void,
): void {
  if (!store.getState().dirty) return replace();
  filesUi.getState().confirm({
    title: 'Discard unsaved changes?',
    message: `"${store.getState().project.name}" has changes that are not saved to a file. ${what} replaces it; the changes will be lost.`,
    confirmLabel,
    onConfirm: replace,
  });
}

export function newProject(store: DocumentStore): void {
  replaceDocument(store, 'A new project', 'Discard and start new', () => {
    store.getState().newProject();
    filesUi.getState().setNotice('Started a new project.');
  });
}

export function saveProjectFile(store: DocumentStore): void {
  const name = downloadProject(store.getState().project);
  store.getState().markSaved();
  filesUi.getState().setNotice(`Saved as ${name} (in your downloads folder).`);
}

export function openProjectFile(): void {
  openFilePicker(filesUi.getState().openPicker);
}

/** Opens a browser file picker a host component registered, or says why it cannot. */
export function openFilePicker(open: (() => void) | undefined): void {
  if (open) open();
  else filesUi.getState().setNotice('The file picker is not available in this view.');
}

/** Validates a chosen file; a bad file shows its located errors and leaves the open project untouched. */
export async function openChosenFile(store: DocumentStore, file: File): Promise<void> {
  const result = await readProjectFile(file);
  if (!result.ok) {
    filesUi.getState().showOpenFailure({ fileName: file.name, errors: result.errors });
    return;
  }
  loadWithConsent(store, result.project, `Opening ${file.name}`, `Opened ${file.name}.`);
}

export function loadWithConsent(store: DocumentStore, project: Project, what: string, notice: string): void {
  replaceDocument(store, what, 'Discard and open', () => {
    store.getState().loadProject(project);
    filesUi.getState().setNotice(notice);
    // A project that names a machine (an exercise) opens with the machine in view.
    if (project.plant) showPlantTab();
  });
}
