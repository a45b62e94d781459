// Field edits of one element kind, sent through the store's updateElement command.
import type { BoxElement, CoilElement, ContactElement, JumpElement } from '../../model/elements';
import type { ElementId } from '../../model/ids';
import type { DocumentStore, ElementPatch } from '../../store/documentStore';

type Own<T> = Partial<Omit<T, 'id' | 'kind' | 'row' | 'col'>>;
export type KindPatch = Own<ContactElement> | Own<CoilElement> | Own<JumpElement> | Own<BoxElement>;

export function patchElement(store: DocumentStore, id: ElementId, patch: KindPatch): void {
  store.getState().updateElement(id, patch as ElementPatch);
}
