// The File menu: New, Open, Save and the built-in examples, as commands shaped like the command
// registry's EditorCommand (src/editor/commands/registry.ts): { id, label, group, keys?, inMenu, run(ctx) }
// where ctx only needs { doc } (an EditorContext fits).
//
// The shell must also mount <FilesHost /> (src/editor/files/FilesHost.tsx) once, inside the
// DocumentStoreProvider: it restores the autosave on start, keeps autosaving, and renders the
// file picker, the "discard unsaved changes?" dialog, open errors and notices.
import { EXAMPLES } from '../../model/examples';
import { PLANT_EXAMPLES } from '../../plant/exercises';
import { PLCOPEN_COMMANDS } from '../plcopen/plcopenCommands';
import { LIBRARY_COMMANDS } from '../library/libraryCommands';
import { loadWithConsent, newProject, openProjectFile, saveProjectFile } from './fileActions';
import type { FileMenuCommand } from './fileMenuCommand';

export const FILE_COMMANDS: readonly FileMenuCommand[] = [
  {
    id: 'file.new',
    label: 'New project',
    group: 'File',
    keys: ['mod+alt+n'],
    inMenu: true,
    description: 'Start an empty project (asks before discarding unsaved changes)',
    run: ({ doc }) => newProject(doc),
  },
  {
    id: 'file.open',
    label: 'Open…',
    group: 'File',
    keys: ['mod+o'],
    inMenu: true,
    description: 'Open a Rungsmith project file (.json)',
    run: () => openProjectFile(),
  },
  {
    id: 'file.save',
    label: 'Save',
    group: 'File',
    keys: ['mod+s'],
    inMenu: true,
    description: 'Download the project as a .json file',
    run: ({ doc }) => saveProjectFile(doc),
  },
];

/** One command per built-in example; each builds a fresh copy (new ids) when chosen. */
export const EXAMPLE_COMMANDS: readonly FileMenuCommand[] = [...EXAMPLES, ...PLANT_EXAMPLES].map((example) => ({
  id: `example.${example.id}`,
  label: example.title,
  group: 'Examples',
  inMenu: true,
  description: example.description,
  run: ({ doc }) =>
    loadWithConsent(
      doc,
      example.build(),
      `Opening the example "${example.title}"`,
      `Opened the example "${example.title}".`,
    ),
}));

/** Everything for the File menu, New/Open/Save first, then PLCopen import/export, the library manager, then the examples. */
export const FILE_MENU_COMMANDS: readonly FileMenuCommand[] = [
  ...FILE_COMMANDS,
  ...PLCOPEN_COMMANDS,
  ...LIBRARY_COMMANDS,
  ...EXAMPLE_COMMANDS,
];
