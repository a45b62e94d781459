// Typing a box's pin operands from the keyboard: Enter on a box opens the field of its first open
// pin (or its unnamed instance), Tab / Shift+Tab go to the next / previous field (see
// src/editor/canvas/pinOperands.ts for the order).
import type { BoxElement } from '../../model/elements';
import type { ElementId, NetworkId } from '../../model/ids';
import type { Network } from '../../model/project';
import { firstField, INSTANCE_FIELD, nextField } from '../canvas/pinOperands';
import { libraryOf, networkById, type EditorContext } from './editorActions';

function editField(ctx: EditorContext, box: BoxElement, field: string | undefined) {
  const ui = ctx.ui.getState();
  if (field === undefined) {
    ui.stopEditing();
    return ui.setStatus(`Every pin of this ${box.blockType} is wired: nothing to type.`);
  }
  ui.startEditing(box.id, field === INSTANCE_FIELD ? {} : { pin: field });
}

/** Enter on a box. */
export function editBox(ctx: EditorContext, n: Network, box: BoxElement) {
  editField(ctx, box, firstField(n, box, libraryOf(ctx)));
}

/** Tab (or Shift+Tab, `back`) from `field` of the box: the next field, as the document is now. */
export function tabToField(ctx: EditorContext, network: NetworkId, boxId: ElementId, field: string, back: boolean) {
  const n = networkById(ctx, network);
  const box = n?.elements.find((e): e is BoxElement => e.id === boxId && e.kind === 'box');
  if (!n || !box) return ctx.ui.getState().stopEditing();
  editField(ctx, box, nextField(n, box, field, back, libraryOf(ctx)));
}
