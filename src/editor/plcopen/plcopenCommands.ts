// The PLCopen entries of the File menu (same shape as the other File commands).
import type { FileMenuCommand } from '../files/fileMenuCommand';
import { chooseImportFile, exportPlcopenFile } from './plcopenActions';

export const PLCOPEN_COMMANDS: readonly FileMenuCommand[] = [
  {
    id: 'file.exportPlcopen',
    label: 'Export PLCopen XML',
    group: 'File',
    inMenu: true,
    description: 'Download the project as PLCopen TC6 XML v2.01 (opens in CODESYS, Beremiz, OpenPLC)',
    run: ({ doc }) => void exportPlcopenFile(doc),
  },
  {
    id: 'file.importPlcopen',
    label: 'Import PLCopen XML…',
    group: 'File',
    inMenu: true,
    description: 'Open a PLCopen XML file written by CODESYS, TwinCAT, Beremiz or OpenPLC',
    run: () => chooseImportFile(),
  },
];
