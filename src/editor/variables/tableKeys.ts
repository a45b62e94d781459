// Keyboard and clipboard habits of the variable table: Enter on the last row adds a row, Ctrl+V of
// rows copied from a spreadsheet opens the symbol table paste preview (SymbolPasteDialog), and the
// class of a variable is typed in its field (`in` VAR_INPUT, `o` VAR_OUTPUT, `in_` VAR_IN_OUT ...).
import type { KeyboardEvent } from 'react';
import type { VarClass } from '../../model/project';

/** A field the user types text into (a text input or text area), not a checkbox, select or button. */
export function isTextField(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  if (target.isContentEditable || target.tagName === 'TEXTAREA') return true;
  if (target.tagName !== 'INPUT') return false;
  return !['checkbox', 'radio', 'button', 'submit', 'reset', 'file', 'range', 'color'].includes(
    (target as HTMLInputElement).type,
  );
}

/**
 * A paste into the table that is a symbol table: any text pasted outside a text field, or text of
 * several cells (a tab or a line break) pasted into a one-line field: a single word pasted into a
 * field stays the field's, and so does anything pasted into a text area (the text view).
 */
export function isTablePaste(target: EventTarget | null, text: string): boolean {
  if (text.trim() === '') return false;
  if (!isTextField(target)) return true;
  // A field of several lines (the declarations' text view) takes text of several lines as text.
  if (target instanceof HTMLElement && (target.tagName === 'TEXTAREA' || target.isContentEditable)) return false;
  const t = text.replace(/[\r\n]+$/, '');
  return t.includes('\t') || t.includes('\n');
}

/** Enter (no modifier) in a field of the table's last row (`lastName`'s), except on its buttons. */
export function lastRowEnter(e: KeyboardEvent, lastName: string | undefined): boolean {
  if (e.key !== 'Enter' || e.shiftKey || e.ctrlKey || e.altKey || e.metaKey || lastName === undefined)
    return false;
  const target = e.target;
  if (!(target instanceof HTMLElement) || target.tagName === 'BUTTON' || target.tagName === 'TEXTAREA')
    return false;
  const row = target.closest('tr.rs-var-row');
  return row?.getAttribute('data-testid') === `variable-row-${lastName}`;
}

/** What each class is called when typed, the likeliest first: `in` is VAR_INPUT, `in_` VAR_IN_OUT. */
const CLASS_WORDS: readonly (readonly [string, VarClass])[] = [
  ['INPUT', 'input'],
  ['OUTPUT', 'output'],
  ['IN_OUT', 'inOut'],
  ['INOUT', 'inOut'],
  ['VAR', 'local'],
  ['LOCAL', 'local'],
  ['STATIC', 'local'],
  ['EXTERNAL', 'external'],
  ['TEMP', 'temp'],
  ['VAR_INPUT', 'input'],
  ['VAR_OUTPUT', 'output'],
  ['VAR_IN_OUT', 'inOut'],
  ['VAR_EXTERNAL', 'external'],
  ['VAR_TEMP', 'temp'],
];

/** The class whose name starts with the typed text (case ignored), or undefined when none does. */
export function classForTyped(typed: string): VarClass | undefined {
  const t = typed.trim().toUpperCase();
  if (!t) return undefined;
  return CLASS_WORDS.find(([word]) => word.startsWith(t))?.[1];
}
