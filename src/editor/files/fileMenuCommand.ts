// The shape of a File menu command (src/editor/files/FileMenu.ts, src/editor/plcopen/plcopenCommands.ts)
// and the context it runs with.
import type { DocumentStore } from '../../store/documentStore';

export interface FileCommandContext {
  readonly doc: DocumentStore;
}

export interface FileMenuCommand {
  readonly id: string;
  readonly label: string;
  /** 'File' for New/Open/Save, 'Examples' for the example projects (a submenu or a second menu). */
  readonly group: 'File' | 'Examples';
  /** Shortcut specs as in commands/keys.ts; the first is the one shown. */
  readonly keys?: readonly string[];
  readonly inMenu: true;
  /** Tooltip / menu hint. */
  readonly description: string;
  run(ctx: FileCommandContext): void;
}
