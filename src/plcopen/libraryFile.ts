// Reading a file as a library (docs/libraries.md): a PLCopen XML file (through importPlcopen) or a
// Rungsmith project file (through loadProject). The library takes the file's FUNCTION_BLOCK and
// FUNCTION POUs and its data types; its PROGRAMs, tasks and globals stay behind (said in `notes`).
// Pure: no DOM (the editor reads the file and hands over its text).
import { libraryHash, libraryPou } from '../model/libraries';
import { loadProject } from '../model/load';
import type { DataType, Pou, Project, ProjectLibrary } from '../model/project';
import { importPlcopen } from './importPlcopen';
import { asLibraryPou } from './rungsmithData';

export type LibraryRead =
  | {
      readonly ok: true;
      /** The library as it would be added (its name: the file's project name, else the file name). */
      readonly library: ProjectLibrary;
      /** What the library leaves out or cannot do (programs skipped, blocks it calls that nobody defines). */
      readonly notes: readonly string[];
    }
  | { readonly ok: false; readonly errors: readonly string[] };

/** A library name from a file name: `conveyors-v2.xml` -> `conveyors-v2`. */
export const nameFromFile = (fileName: string): string =>
  fileName
    .replace(/^.*[\\/]/, '')
    .replace(/\.(xml|json|rungsmith|rsproj)$/i, '')
    .replace(/[^A-Za-z0-9_ .-]/g, '_')
    .replace(/^[^A-Za-z_]+/, '') || 'Library';

/** The blocks of a project read from the file, and what is left behind. */
function blocksOf(project: Project, what: string): { pous: Pou[]; dataTypes: DataType[]; notes: string[] } {
  const notes: string[] = [];
  const programs = project.pous.filter((p) => p.kind === 'PROGRAM');
  if (programs.length)
    notes.push(`${what} has ${programs.length} PROGRAM${programs.length === 1 ? '' : 's'} (${programs.map((p) => p.name).join(', ')}): a library holds only function blocks, functions and data types, so they are left out`);
  for (const b of project.externalBlocks ?? [])
    notes.push(`${what} calls ${b.name}, which it does not define: a POU of this project or another library must provide it, else its calls are LD-E01 errors`);
  if (project.libraries?.length)
    notes.push(`${what} uses the libraries ${project.libraries.map((l) => l.name).join(', ')}: add them too (their blocks are not copied into this library)`);
  const externals = project.pous.filter((p) => p.kind !== 'PROGRAM').flatMap((p) => p.variables.filter((v) => v.varClass === 'external').map((v) => `${p.name}.${v.name}`));
  if (externals.length)
    notes.push(`blocks of the library read globals (VAR_EXTERNAL ${externals.join(', ')}): the project must declare them`);
  return { pous: project.pous.filter((p) => p.kind !== 'PROGRAM'), dataTypes: [...(project.dataTypes ?? [])], notes };
}

/**
 * Reads `text` (the content of `fileName`) as a library. A PLCopen file is recognised by its
 * `<`, a Rungsmith project by its `{`. `now`: the date it is added (default: now).
 */
export async function readLibraryFile(fileName: string, text: string, now: Date = new Date(), name?: string): Promise<LibraryRead> {
  const trimmed = text.trimStart();
  let project: Project;
  let origin: ProjectLibrary['origin'];
  if (trimmed.startsWith('{')) {
    const loaded = loadProject(text);
    if (!loaded.ok) return { ok: false, errors: loaded.errors.map((e) => `${fileName}: ${e.path}: ${e.message}`) };
    project = loaded.project;
    origin = 'rungsmith';
  } else if (trimmed.startsWith('<')) {
    const imported = importPlcopen(text);
    if (!imported.ok)
      return { ok: false, errors: imported.errors.map((e) => `${fileName}${e.line !== undefined ? `, line ${e.line}` : ''}: ${e.message}`) };
    project = imported.project;
    origin = 'plcopen';
  } else return { ok: false, errors: [`${fileName} is neither a PLCopen XML file nor a Rungsmith project file`] };
  const libName = (name ?? (project.name && project.name !== 'Imported' && project.name !== 'Untitled' ? project.name : nameFromFile(fileName))).trim();
  const { pous, dataTypes, notes } = blocksOf(project, fileName);
  const library: ProjectLibrary = {
    name: libName,
    hash: await libraryHash(text),
    sourceFile: fileName.replace(/^.*[\\/]/, ''),
    addedAt: now.toISOString(),
    origin,
    pous: pous.map((p) => asLibraryPou(libName, p)),
    ...(dataTypes.length ? { dataTypes } : {}),
  };
  return { ok: true, library, notes };
}

/** The library with another name (its POUs' ids follow). */
export function renameLibrary(library: ProjectLibrary, name: string): ProjectLibrary {
  return { ...library, name, pous: library.pous.map((p) => libraryPou(name, p)) };
}
