// The Structured Text editor of one POU's body: a CodeMirror 6 view created once per mounted
// component (the parent keys it by POU), linked to the document (stModelSync.ts: typing bursts
// are named undo steps, the project's undo/redo come back into the editor as transactions).
// `extensions` are added after the editor's own (stExtensions.ts), e.g. by tests or embedders;
// language services and debugging add theirs in stExtensions.ts.
import { useEffect, useRef } from 'react';
import { Compartment, EditorState, type Extension } from '@codemirror/state';
import { EditorView } from '@codemirror/view';
import { useDocument, useDocumentStore } from '../../store/documentStore';
import type { StEditorContext } from './context';
import { stExtensions } from './stExtensions';
import { modelSync } from './stModelSync';

export interface StEditorProps {
  readonly ctx: StEditorContext;
  /** More CodeMirror extensions (reconfigured when the array changes). */
  readonly extensions?: readonly Extension[];
  /** Shown and navigable but not editable (a library block's body). */
  readonly readOnly?: boolean;
}

const NONE: readonly Extension[] = [];

const readOnlyExtension = (readOnly: boolean): Extension =>
  readOnly ? [EditorState.readOnly.of(true), EditorView.contentAttributes.of({ 'aria-readonly': 'true' })] : [];

const labelExtension = (name: string, readOnly: boolean): Extension =>
  EditorView.contentAttributes.of({
    'aria-label': `ST body of ${name}${readOnly ? ' (read-only)' : ''}`,
    'data-testid': 'st-editor-content',
  });

export function StEditor({ ctx, extensions = NONE, readOnly = false }: StEditorProps) {
  const store = useDocumentStore();
  const host = useRef<HTMLDivElement>(null);
  const view = useRef<EditorView | undefined>(undefined);
  const compartments = useRef({ extra: new Compartment(), readOnly: new Compartment(), label: new Compartment() });
  // The first values, for the view created once (later changes reconfigure it below).
  const initial = useRef({ ctx, extensions, readOnly });
  const pouName = useDocument((s) => s.project.pous.find((p) => p.id === ctx.pouId)?.name ?? '');

  useEffect(() => {
    const { ctx: c, extensions: ext, readOnly: ro } = initial.current;
    const c0 = compartments.current;
    const pou = store.getState().project.pous.find((p) => p.id === c.pouId);
    const v = new EditorView({
      parent: host.current!,
      state: EditorState.create({
        doc: pou?.source ?? '',
        extensions: [
          stExtensions(c),
          modelSync(store, c.pouId),
          c0.readOnly.of(readOnlyExtension(ro)),
          c0.label.of(labelExtension(pou?.name ?? '', ro)),
          c0.extra.of(ext),
        ],
      }),
    });
    view.current = v;
    return () => {
      view.current = undefined;
      v.destroy();
    };
  }, [store]);

  useEffect(() => {
    const v = view.current;
    if (!v) return;
    const c0 = compartments.current;
    v.dispatch({
      effects: [
        c0.extra.reconfigure(extensions),
        c0.readOnly.reconfigure(readOnlyExtension(readOnly)),
        c0.label.reconfigure(labelExtension(pouName, readOnly)),
      ],
    });
  }, [extensions, readOnly, pouName]);

  return <div ref={host} className="rs-st-editor" data-testid="st-editor" data-pou={pouName} />;
}
