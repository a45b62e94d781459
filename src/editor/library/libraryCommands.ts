// The library manager's entry in the File menu (same shape as the other File commands).
import type { FileMenuCommand } from '../files/fileMenuCommand';
import { openLibraryManager } from './libraryUi';

export const LIBRARY_COMMANDS: readonly FileMenuCommand[] = [
  {
    id: 'file.libraries',
    label: 'Libraries…',
    group: 'File',
    inMenu: true,
    description: 'The library manager: add the blocks of a PLCopen file or another project as a library, update or remove it',
    run: () => openLibraryManager(),
  },
];
