// What every part of the ST editor (language, language services, debugging) is given about the body
// it edits. Shared by the editor component and the extensions other modules add to it (issue 25).
import type { PouId } from '../../model/ids';

export interface StEditorContext {
  /** The POU whose ST body the editor shows (its id stays the same across renames). */
  readonly pouId: PouId;
}
