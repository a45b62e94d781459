// What the library manager does to the document: add a library read from a file, update one from a
// newer file, remove one. Each change is one undo step (a 'project.update' of the libraries); a
// refused change leaves the project as it was and says why.
import { addLibrary, removeLibrary, updateLibrary } from '../../model/libraries';
import type { ProjectLibrary } from '../../model/project';
import { readLibraryFile, renameLibrary } from '../../plcopen/libraryFile';
import type { DocumentStore } from '../../store/documentStore';
import { openFilePicker } from '../files/fileActions';
import { libraryUi } from './libraryUi';

/** Asks for a file to add as a library (`update`: a newer file for that library). */
export function chooseLibraryFile(update?: string): void {
  libraryUi.getState().setUpdateTarget(update);
  openFilePicker(libraryUi.getState().openPicker);
}

/** Reads the chosen file; the manager then shows what it holds (or why it cannot be used). */
export async function readChosenLibrary(file: File): Promise<void> {
  const text = await file.text();
  const updating = libraryUi.getState().updateTarget;
  const read = await readLibraryFile(file.name, text);
  libraryUi.getState().setPending({ fileName: file.name, read, ...(updating ? { updating } : {}) });
}

/** Adds the library under `name`; returns the reasons when refused. */
export function commitAdd(store: DocumentStore, library: ProjectLibrary, name: string): readonly string[] {
  const lib = name.trim() === library.name ? library : renameLibrary(library, name.trim());
  const r = addLibrary(store.getState().project, lib);
  if (!r.ok) return r.errors;
  store.getState().updateProject({ libraries: r.project.libraries ?? [] });
  libraryUi.getState().setPending(undefined);
  return [];
}

/** Replaces the library `name` by `next`; returns the reasons when refused. */
export function commitUpdate(store: DocumentStore, name: string, next: ProjectLibrary): readonly string[] {
  const r = updateLibrary(store.getState().project, name, next);
  if (!r.ok) return r.errors;
  store.getState().updateProject({ libraries: r.project.libraries ?? [] });
  libraryUi.getState().setPending(undefined);
  return [];
}

/** Removes the library, or shows where it is still used. */
export function commitRemove(store: DocumentStore, name: string): void {
  const r = removeLibrary(store.getState().project, name);
  if (!r.ok) {
    libraryUi.getState().setRefused({ library: name, uses: r.uses });
    return;
  }
  libraryUi.getState().setRefused(undefined);
  store.getState().updateProject({ libraries: r.project.libraries ?? [] });
}
