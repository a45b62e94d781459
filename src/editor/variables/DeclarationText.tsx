// The text view of the variables panel: the POU's (or the globals') declarations as IEC 61131-3
// text, edited like code. Parsed as you type: syntax errors are marked at their line in the gutter
// and listed under the text (and in the Problems list, LD-E18). The text applies to the document
// when the editor loses focus or on Ctrl+Enter, as ONE undo step ('editDeclarations'); it is then
// printed again from the model. Text that does not parse is never applied: the variables stay as
// they were and the text stays here (even when switching away) until it is fixed or reverted.
// Keys: Tab / Shift+Tab indent and unindent (Escape first lets Tab leave the editor), Ctrl+Enter
// applies, Ctrl+Z / Ctrl+Y undo and redo in the text while it has changes not applied, else the
// document's undo and redo (so Ctrl+Z right after applying takes the whole edit back).
import { useDeferredValue, useEffect, useMemo, useRef, useState, type KeyboardEvent } from 'react';
import { useStore } from 'zustand';
import {
  DECLARATION_SYNTAX_RULE,
  parseDeclarations,
  printDeclarations,
  type DeclarationProblem,
  type DeclarationSection,
} from '../../engine/st/declarations';
import type { VariableScope } from '../../store/changes';
import { applyDeclarationText, scopeVariables } from '../../store/declarationText';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import type { Variable } from '../../model/project';
import { declarationView, draftOf, handled, keepDraft, setPending } from './declarationView';
import { validateVariables } from './validation';
import { variableFocus } from './variableFocus';
import './declarationText.css';

interface Props {
  readonly scope: VariableScope;
  /** The POU's name, or undefined for the globals. */
  readonly pouName: string | undefined;
}

const NO_VARS: readonly Variable[] = [];
const CHANGED_ELSEWHERE =
  'The variables changed elsewhere (table, undo) while this text has changes: applying it makes them what the text says; Revert shows them.';
/** Texts longer than this (about 200 declarations) are checked once typing pauses for PAUSE_MS. */
const LONG_TEXT = 8000;
const PAUSE_MS = 150;

/** Offset of 1-based line/col in `text`. */
function offsetOf(text: string, line: number, col: number): number {
  let at = 0;
  for (let l = 1; l < line; l++) {
    const nl = text.indexOf('\n', at);
    if (nl < 0) return text.length;
    at = nl + 1;
  }
  const end = text.indexOf('\n', at);
  return Math.min(at + col - 1, end < 0 ? text.length : end);
}

/** 1-based line and column of an offset. */
function lineColOf(text: string, offset: number): { line: number; col: number } {
  const before = text.slice(0, offset);
  const line = before.split('\n').length;
  return { line, col: offset - (before.lastIndexOf('\n') + 1) + 1 };
}

/** Inserts text at the selection through the browser's editing, so its own undo keeps it. */
function insertText(area: HTMLTextAreaElement, text: string): void {
  if (!document.execCommand('insertText', false, text))
    area.setRangeText(text, area.selectionStart, area.selectionEnd, 'end');
}

export function DeclarationText({ scope, pouName }: Props) {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const vars = useDocument((s) =>
    scope === 'globals'
      ? s.project.globals
      : (s.project.pous.find((p) => p.id === scope)?.variables ?? NO_VARS),
  );
  const section: DeclarationSection = scope === 'globals' ? 'globals' : 'pou';
  const printed = useMemo(() => printDeclarations(vars, section), [vars, section]);
  /** The project shown (another one opened: its own lists, none of this one's drafts). */
  const opened = useDocument((s) => s.opened);
  const shown = `${opened}:${scope}`;
  const owner = pouName ?? 'Global variables';
  const [draft, setDraftState] = useState(() => draftOf(scope, opened)?.text ?? printed);
  /** The text the draft started from: while they are equal, model changes re-print the text. */
  const [basis, setBasis] = useState(() => draftOf(scope, opened)?.basis ?? printed);
  /** The variables changed elsewhere while the text had changes (kept with the draft: said again when the view reopens). */
  const [stale, setStale] = useState(() => draftOf(scope, opened)?.stale ?? false);
  const setDraft = (text: string) => {
    setDraftState(text);
    // Kept only while it says something the variables do not (typed back to them: nothing kept).
    keepDraft(scope, text === printed ? undefined : { opened, text, basis, stale });
  };
  const [shownScope, setShownScope] = useState(shown);
  const [note, setNote] = useState(() => (draftOf(scope, opened)?.stale ? CHANGED_ELSEWHERE : ''));
  const area = useRef<HTMLTextAreaElement>(null);
  const gutter = useRef<HTMLDivElement>(null);
  const escaped = useRef(false);

  // Another list, or the model changed while the text has no changes of its own: show it afresh.
  // A draft kept while the view was closed (or showed another list) comes back with the basis it
  // started from, so a change made meanwhile (a name declared from the canvas) is said here too.
  if (shownScope !== shown) {
    const kept = draftOf(scope, opened);
    setShownScope(shown);
    setDraftState(kept?.text ?? printed);
    setBasis(kept?.basis ?? printed);
    setStale(kept?.stale ?? false);
    setNote(kept?.stale ? CHANGED_ELSEWHERE : '');
  } else if (basis !== printed) {
    setBasis(printed);
    if (draft === basis) {
      setDraftState(printed);
      keepDraft(scope, undefined);
    } else {
      setStale(true);
      keepDraft(scope, { opened, text: draft, basis: printed, stale: true });
      setNote(CHANGED_ELSEWHERE);
    }
  }

  // Parsed and checked behind the typing: at once for a POU's few lines (deferred, so the
  // keystroke paints first); on long lists (hundreds of globals) once typing pauses.
  const deferred = useDeferredValue(draft);
  const long = draft.length > LONG_TEXT;
  const [paused, setPaused] = useState(draft);
  useEffect(() => {
    if (!long) return undefined;
    const timer = setTimeout(() => setPaused(draft), PAUSE_MS);
    return () => clearTimeout(timer);
  }, [draft, long]);
  const checkedDraft = long ? paused : deferred;
  const parsed = useMemo(() => parseDeclarations(checkedDraft, section), [checkedDraft, section]);
  const dirty = draft !== printed;
  const issues = useMemo(() => {
    if (!parsed.ok) return [];
    const found = validateVariables(parsed.variables, { project, ...(pouName ? { pou: pouName } : {}) });
    return found.map((i) => {
      const d = parsed.declarations[i.index];
      return { line: d?.line ?? 1, col: d?.col ?? 1, message: `${d?.variable.name ?? ''}: ${i.message}` };
    });
  }, [parsed, project, pouName]);

  // Unapplied text with problems stays listed (Problems list) until fixed or reverted.
  const checkedDirty = checkedDraft !== printed;
  useEffect(() => {
    const errors = parsed.problems.filter((p) => p.severity === 'error');
    setPending(scope, checkedDirty && errors.length > 0 ? { opened, owner, problems: errors } : undefined);
  }, [scope, checkedDirty, parsed, owner, opened]);

  const caretTo = (line: number, col: number, focus = true) => {
    const el = area.current;
    if (!el) return;
    const at = offsetOf(el.value, line, col);
    if (focus) el.focus();
    el.setSelectionRange(at, at);
    const lineHeight = parseFloat(getComputedStyle(el).lineHeight) || 18;
    el.scrollTop = Math.max(0, (line - 3) * lineHeight);
  };
  // "Show line 3 of this text" (a syntax error in the Problems list).
  const reveal = useStore(declarationView, (s) => s.reveal);
  useEffect(() => {
    if (!reveal || reveal.scope !== scope || handled.reveal === reveal.seq) return;
    handled.reveal = reveal.seq;
    caretTo(reveal.line, reveal.col);
  }, [reveal, scope]);
  // "Show this variable" (a variable's problem in the Problems list): its declaration's line.
  const focusRequest = useStore(variableFocus, (s) => s.request);
  useEffect(() => {
    if (!focusRequest || handled.focus === focusRequest.seq) return;
    if (focusRequest.globals !== (scope === 'globals')) return;
    handled.focus = focusRequest.seq;
    const key = focusRequest.name.toUpperCase();
    const decl = parsed.declarations.find((d) => d.variable.name.toUpperCase() === key);
    if (decl) caretTo(decl.line, decl.col);
  }, [focusRequest, scope, parsed]);

  const apply = (): boolean => {
    if (!dirty) return true;
    const now = draft === checkedDraft ? parsed : parseDeclarations(draft, section);
    if (!now.ok) {
      const n = now.problems.filter((p) => p.severity === 'error').length;
      setNote(
        `Not applied: ${n} syntax error${n === 1 ? '' : 's'} (see below). The variables are unchanged; fix the text or Revert.`,
      );
      return false;
    }
    const result = applyDeclarationText(store, scope, now.variables);
    if (!result.ok) {
      setNote(`Not applied: ${result.reason}`);
      return false;
    }
    const reprinted = printDeclarations(scopeVariables(store, scope), section);
    setDraftState(reprinted);
    keepDraft(scope, undefined);
    setBasis(reprinted);
    setStale(false);
    setNote('');
    setPending(scope, undefined);
    return true;
  };

  const revert = () => {
    setDraftState(printed);
    keepDraft(scope, undefined);
    setBasis(printed);
    setStale(false);
    setNote('');
    setPending(scope, undefined);
  };

  const onKeyDown = (e: KeyboardEvent<HTMLTextAreaElement>) => {
    const el = e.currentTarget;
    const mod = e.ctrlKey || e.metaKey;
    if (e.key === 'Escape') {
      escaped.current = true;
      return;
    }
    if (e.key === 'Tab' && !mod && !e.altKey) {
      if (escaped.current) {
        escaped.current = false;
        return; // Escape, then Tab: leave the editor as anywhere else.
      }
      e.preventDefault();
      const { selectionStart: s, selectionEnd: t, value } = el;
      const lineStart = value.lastIndexOf('\n', s - 1) + 1;
      if (!e.shiftKey && s === t) return insertText(el, '\t');
      // Several lines selected (or Shift+Tab): indent or unindent each whole line.
      const last = t > s && value[t - 1] === '\n' ? t - 1 : t;
      const eol = value.indexOf('\n', last);
      const lineEnd = eol < 0 ? value.length : eol;
      const block = value.slice(lineStart, lineEnd);
      const next = e.shiftKey ? block.replace(/^(\t| {1,4})/gm, '') : block.replace(/^/gm, '\t');
      if (next === block) return;
      el.setSelectionRange(lineStart, lineEnd);
      insertText(el, next);
      if (s === t) {
        // Shift+Tab on one line: the caret stays where it was in the text.
        const at = Math.max(lineStart, s - (block.length - next.length));
        el.setSelectionRange(at, at);
      } else el.setSelectionRange(lineStart, lineStart + next.length);
      return;
    }
    escaped.current = false;
    if (mod && e.key === 'Enter') {
      e.preventDefault();
      const caret = lineColOf(el.value, el.selectionStart);
      if (apply())
        requestAnimationFrame(() => {
          const now = area.current;
          if (now) {
            const at = offsetOf(now.value, caret.line, caret.col);
            now.setSelectionRange(at, at);
          }
        });
      return;
    }
    const key = e.key.toLowerCase();
    if (mod && !dirty && (key === 'z' || key === 'y')) {
      // Nothing typed since the text was applied: the document's undo/redo (the applied edit is one step).
      e.preventDefault();
      if (key === 'y' || e.shiftKey) store.getState().redo();
      else store.getState().undo();
    }
  };

  const errors = parsed.problems.filter((p) => p.severity === 'error');
  const lineCount = useMemo(() => {
    let n = 1;
    for (let i = draft.indexOf('\n'); i >= 0; i = draft.indexOf('\n', i + 1)) n++;
    return n;
  }, [draft]);
  const numbers = useMemo(() => Array.from({ length: lineCount }, (_, i) => i + 1).join('\n'), [lineCount]);
  const marks = new Map<number, { severity: 'error' | 'warning'; messages: string[] }>();
  const mark = (line: number, severity: 'error' | 'warning', message: string) => {
    const m = marks.get(line) ?? { severity, messages: [] };
    if (severity === 'error') m.severity = 'error';
    m.messages.push(message);
    marks.set(line, m);
  };
  parsed.problems.forEach((p) => mark(p.line, p.severity, p.message));
  issues.forEach((p) => mark(p.line, 'warning', p.message));
  const listed: (DeclarationProblem & { rule?: string })[] = [
    ...parsed.problems.map((p) => ({
      ...p,
      ...(p.severity === 'error' ? { rule: DECLARATION_SYNTAX_RULE } : {}),
    })),
    ...issues.map((p) => ({ ...p, severity: 'warning' as const })),
  ].sort((a, b) => a.line - b.line || a.col - b.col);

  return (
    <div className="rs-decl-text" data-testid="declaration-text">
      <div className="rs-decl-editor">
        <div className="rs-decl-gutter" ref={gutter} aria-hidden="true">
          <pre className="rs-decl-numbers">{numbers}</pre>
          {[...marks].map(([line, m]) => (
            <div
              key={line}
              className={`rs-decl-line rs-decl-${m.severity}`}
              data-line={line}
              style={{ top: 4 + (line - 1) * 18 }}
              title={m.messages.join('\n')}
            >
              {line}
            </div>
          ))}
        </div>
        <textarea
          ref={area}
          className="rs-decl-area"
          aria-label={`Declarations of ${owner} as IEC text`}
          aria-invalid={errors.length > 0}
          aria-describedby="rs-decl-status"
          spellCheck={false}
          autoCapitalize="off"
          autoComplete="off"
          wrap="off"
          value={draft}
          onChange={(e) => setDraft(e.target.value)}
          onBlur={() => apply()}
          onKeyDown={onKeyDown}
          onScroll={(e) => {
            if (gutter.current) gutter.current.scrollTop = e.currentTarget.scrollTop;
          }}
        />
      </div>
      <div className="rs-decl-status" id="rs-decl-status" aria-live="polite" data-testid="declaration-status">
        {errors.length > 0
          ? `${errors.length} syntax error${errors.length === 1 ? '' : 's'}: not applied`
          : dirty
            ? 'Changes not applied yet: Ctrl+Enter or leave the editor to apply'
            : 'Applied'}
        {dirty && (
          <button
            type="button"
            className="rs-button"
            onMouseDown={(e) => e.preventDefault()}
            onClick={revert}
          >
            Revert
          </button>
        )}
      </div>
      {note && (
        <p role="alert" className="rs-var-refusal" data-testid="declaration-note">
          {note}
        </p>
      )}
      {listed.length > 0 && (
        <ul className="rs-decl-problems" aria-label="Declaration problems">
          {listed.map((p, i) => (
            <li key={i}>
              <button
                type="button"
                className={`rs-decl-problem rs-${p.severity}`}
                data-testid="declaration-problem"
                data-line={p.line}
                onClick={() => caretTo(p.line, p.col)}
              >
                {p.rule ? `${p.rule} ` : ''}line {p.line}, column {p.col}: {p.message}
              </button>
            </li>
          ))}
        </ul>
      )}
    </div>
  );
}
