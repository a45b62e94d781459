// Saving the project as a .json download (or any text as a download) and reading an uploaded one.
import { loadProject, saveProject, type LoadResult } from '../../model/load';
import type { Project } from '../../model/project';

/** A file name from the project name: "Motor start/stop" -> "Motor_start_stop.json" (or another extension). */
export function projectFileName(project: Project, extension = '.json'): string {
  const base = project.name
    .trim()
    .replace(/[^A-Za-z0-9._-]+/g, '_')
    .replace(/^_+|_+$/g, '');
  return `${base || 'project'}${extension}`;
}

/** Offers `text` as a file download through the browser. */
export function downloadText(fileName: string, text: string, mimeType: string): void {
  const url = URL.createObjectURL(new Blob([text], { type: mimeType }));
  const a = document.createElement('a');
  a.href = url;
  a.download = fileName;
  a.style.display = 'none';
  document.body.appendChild(a);
  a.click();
  a.remove();
  // Revoke after the click has been handled; the download keeps its own reference.
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** Offers the project as a download through the browser; returns the file name. */
export function downloadProject(project: Project): string {
  const name = projectFileName(project);
  downloadText(name, saveProject(project), 'application/json');
  return name;
}

/** Reads and validates an uploaded project file. Never throws. */
export async function readProjectFile(file: File): Promise<LoadResult> {
  try {
    return loadProject(await file.text());
  } catch (e) {
    return {
      ok: false,
      errors: [{ path: '(file)', message: `could not read ${file.name}: ${(e as Error).message}` }],
    };
  }
}
