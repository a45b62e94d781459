// The CodeMirror extensions of the ST editor, in one list. Language services and debugging add
// theirs here with one line each (`...stLanguageServices(ctx)`, `...stDebug(ctx)`); the editor
// component (StEditor.tsx) adds its own link to the document (model sync, project undo, read-only).
import { closeBrackets, closeBracketsKeymap } from '@codemirror/autocomplete';
import { defaultKeymap, indentWithTab } from '@codemirror/commands';
import {
  bracketMatching,
  codeFolding,
  foldGutter,
  foldKeymap,
  indentOnInput,
  indentUnit,
} from '@codemirror/language';
import { highlightSelectionMatches, search, searchKeymap } from '@codemirror/search';
import { EditorState, type Extension } from '@codemirror/state';
import {
  crosshairCursor,
  drawSelection,
  dropCursor,
  EditorView,
  highlightActiveLine,
  highlightActiveLineGutter,
  highlightSpecialChars,
  keymap,
  lineNumbers,
  rectangularSelection,
} from '@codemirror/view';
import type { StEditorContext } from './context';
import { stLanguage } from './stLanguage';
import { stLanguageServices } from './services';
import { stDebugExtensions } from './debug/stDebug';
import './st.css';

/** Colours and fonts from the app's theme variables (light and dark follow data-theme). */
const stTheme = EditorView.theme({
  '&': {
    height: '100%',
    backgroundColor: 'var(--canvas-bg, var(--bg))',
    color: 'var(--text)',
    fontSize: '13px',
  },
  '.cm-scroller': {
    fontFamily: "var(--rs-font-mono, ui-monospace, 'SF Mono', Menlo, Consolas, monospace)",
    lineHeight: '1.5',
  },
  '.cm-content': { caretColor: 'var(--text)' },
  '&.cm-focused': { outline: 'none', boxShadow: 'inset var(--focus-ring)' },
  '.cm-cursor, .cm-dropCursor': { borderLeftColor: 'var(--text)' },
  '&.cm-focused .cm-selectionBackground, .cm-selectionBackground, .cm-content ::selection': {
    backgroundColor: 'var(--canvas-selection-fill) !important',
  },
  '.cm-gutters': {
    backgroundColor: 'var(--surface-2)',
    color: 'var(--text-muted)',
    borderRight: '1px solid var(--border)',
  },
  '.cm-activeLine': { backgroundColor: 'var(--canvas-hover)' },
  '.cm-activeLineGutter': { backgroundColor: 'var(--canvas-hover)', color: 'var(--text)' },
  '.cm-foldPlaceholder': {
    backgroundColor: 'var(--surface-2)',
    border: '1px solid var(--border)',
    color: 'var(--text-muted)',
  },
  '.cm-panels': { backgroundColor: 'var(--surface)', color: 'var(--text)' },
  '.cm-panels.cm-panels-top': { borderBottom: '1px solid var(--border)' },
  '.cm-searchMatch': { backgroundColor: 'color-mix(in srgb, var(--warning) 30%, transparent)' },
  '.cm-searchMatch.cm-searchMatch-selected': {
    backgroundColor: 'color-mix(in srgb, var(--accent) 35%, transparent)',
  },
  '.cm-selectionMatch': { backgroundColor: 'color-mix(in srgb, var(--accent) 14%, transparent)' },
  '&.cm-focused .cm-matchingBracket': {
    backgroundColor: 'color-mix(in srgb, var(--canvas-energised) 30%, transparent)',
    outline: '1px solid var(--canvas-energised)',
  },
  '&.cm-focused .cm-nonmatchingBracket': {
    backgroundColor: 'color-mix(in srgb, var(--danger) 30%, transparent)',
  },
  '.cm-tooltip': {
    backgroundColor: 'var(--surface)',
    color: 'var(--text)',
    border: '1px solid var(--border)',
  },
});

/** Editing basics: gutters, selection, indentation, brackets, folding, search, keys. */
function stEditing(): Extension {
  return [
    lineNumbers(),
    highlightActiveLineGutter(),
    highlightSpecialChars(),
    foldGutter(),
    codeFolding(),
    drawSelection(),
    dropCursor(),
    EditorState.allowMultipleSelections.of(true),
    EditorState.tabSize.of(4),
    indentUnit.of('    '),
    indentOnInput(),
    bracketMatching(),
    closeBrackets(),
    rectangularSelection(),
    crosshairCursor(),
    highlightActiveLine(),
    highlightSelectionMatches(),
    search({ top: true }),
    // Tab indents; Escape then Tab (or Ctrl+M, which toggles it) moves the focus out of the editor.
    keymap.of([...closeBracketsKeymap, ...defaultKeymap, ...searchKeymap, ...foldKeymap, indentWithTab]),
    stTheme,
  ];
}

/** Every extension of the ST editor of one POU (see the file comment). */
export function stExtensions(ctx: StEditorContext): Extension[] {
  return [stLanguage(), stEditing(), ...stLanguageServices(ctx), ...stDebugExtensions(ctx)];
}
