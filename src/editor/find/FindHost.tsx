// Ctrl+F: find across every network of every POU (variables, literals, comments, titles, labels,
// jump targets, block types), results listed with POU, network and element, next/previous;
// replace with a preview, applied as one undo step. Logic in src/store/find.ts.
import { useMemo, useState, type KeyboardEvent } from 'react';
import { findInProject, type FindHit, type FindQuery, type Replacement } from '../../store/find';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { applyFindReplace, planFindReplace, renameInNames, type ReplacePlan } from '../../store/renameVariable';
import { useSimStore } from '../sim/simContext';
import { useUi, useUiStore } from '../../store/uiStore';
import type { EditorContext } from '../commands/editorActions';
import { placeName, revealPlace } from './reveal';
import '../outline/outline.css';
import './find.css';

const SHOWN = 500;

const where = (h: FindHit) =>
  `${placeName(h)} · ${h.elementKind ? `${h.elementKind}${h.pin ? ` ${h.pin}` : ''}` : h.field}`;

function FindPanel({ ctx }: { readonly ctx: EditorContext }) {
  const project = useDocument(selectProject);
  const [text, setText] = useState('');
  const [mode, setMode] = useState<FindQuery['mode']>('text');
  const [caseSensitive, setCase] = useState(false);
  const [index, setIndex] = useState(-1);
  const [by, setBy] = useState('');
  const [preview, setPreview] = useState<ReplacePlan | undefined>(undefined);
  const [refusal, setRefusal] = useState('');
  const sim = useSimStore();
  const query = useMemo<FindQuery>(() => ({ text, mode, caseSensitive }), [text, mode, caseSensitive]);
  const result = useMemo(() => (text ? findInProject(project, query) : []), [project, query, text]);
  const hits = typeof result === 'string' ? [] : result;
  const close = () => ctx.ui.getState().setFinder(undefined);

  /** Shows a hit (the panel keeps the keyboard: data-keeps-focus, see LadderCanvas). */
  const show = (i: number) => {
    setIndex(i);
    revealPlace(ctx, hits[i]!);
  };
  const go = (delta: number) => {
    if (hits.length) show((index + delta + hits.length) % hits.length);
  };
  const onKeyDown = (e: KeyboardEvent) => {
    e.stopPropagation();
    if (e.key === 'Escape') close();
    else if (e.key === 'Enter' && (e.target as HTMLElement).tagName === 'INPUT') {
      e.preventDefault();
      if ((e.target as HTMLElement).dataset.testid === 'replace-input') showPreview();
      else go(e.shiftKey ? -1 : 1);
    } else if (e.key === 'F3') {
      e.preventDefault();
      go(e.shiftKey ? -1 : 1);
    }
  };
  const showPreview = () => {
    const plan = planFindReplace(project, query, by);
    setRefusal(typeof plan === 'string' ? plan : '');
    setPreview(typeof plan === 'string' ? undefined : plan);
  };
  const places = (n: number) => `${n} place${n === 1 ? '' : 's'}`;
  const replaceAll = () => {
    const plan = preview;
    if (!plan) return;
    const before = ctx.doc.getState().revision;
    const done = applyFindReplace(ctx.doc, plan);
    if (!done.ok) {
      setRefusal(`Cannot rename: ${done.reason}.`);
      return;
    }
    const changed = ctx.doc.getState().revision !== before;
    if (plan.rename) {
      // The watch list and the trend name variables too (they are not part of the document).
      const { from, to } = plan.rename;
      const s = sim.getState();
      const watch = renameInNames(s.watch, from, to);
      const trendNames = renameInNames(s.trendNames, from, to);
      if (watch !== s.watch) sim.setState({ watch });
      if (trendNames !== s.trendNames) {
        sim.setState({ trendNames });
        // Re-sends the trend's names to the simulator (and starts the lanes afresh).
        s.setTrendCapacity(s.trendCapacity);
      }
    }
    const n = plan.renamedUses.length + plan.replacements.length;
    ctx.ui
      .getState()
      .setStatus(
        !changed
          ? 'Nothing to replace.'
          : plan.rename
            ? `Renamed ${plan.rename.from} to ${plan.rename.to}${plan.replacements.length ? ` and replaced text in ${places(plan.replacements.length)}` : ''} (one undo step).`
            : `Replaced in ${places(n)} (one undo step).`,
      );
    setPreview(undefined);
    setIndex(-1);
  };
  const previewRows: Replacement[] = preview ? [...preview.renamedUses, ...preview.replacements] : [];
  const previewCount = preview ? (preview.rename ? 1 : 0) + preview.replacements.length : 0;

  return (
    <div className="rs-floating rs-find" role="dialog" aria-label="Find and replace" data-testid="find-panel" data-keeps-focus onKeyDown={onKeyDown}>
      <div className="rs-row">
        <input
          autoFocus
          aria-label="Find"
          placeholder="Find variables, literals, comments, titles…"
          data-testid="find-input"
          value={text}
          onChange={(e) => {
            setText(e.target.value);
            setIndex(-1);
            setPreview(undefined);
          }}
        />
        <select aria-label="Match" value={mode} onChange={(e) => setMode(e.target.value as FindQuery['mode'])} data-testid="find-mode">
          <option value="text">Text</option>
          <option value="word">Whole name</option>
          <option value="regex">Pattern</option>
        </select>
        <label title="Match case">
          <input type="checkbox" checked={caseSensitive} onChange={(e) => setCase(e.target.checked)} />
          Aa
        </label>
        <button type="button" aria-label="Previous match" title="Previous (Shift+Enter)" onClick={() => go(-1)}>
          ↑
        </button>
        <button type="button" aria-label="Next match" title="Next (Enter)" onClick={() => go(1)} data-testid="find-next">
          ↓
        </button>
        <button type="button" aria-label="Close find" onClick={close}>
          ✕
        </button>
      </div>
      <div className="rs-row" data-testid="find-count" aria-live="polite">
        {typeof result === 'string'
          ? result
          : text
            ? `${index >= 0 ? `${index + 1} of ` : ''}${hits.length} match${hits.length === 1 ? '' : 'es'}`
            : ''}
      </div>
      <div className="rs-row">
        <input
          aria-label="Replace with"
          placeholder="Replace with"
          data-testid="replace-input"
          value={by}
          onChange={(e) => {
            setBy(e.target.value);
            setPreview(undefined);
          }}
        />
        <button type="button" onClick={showPreview} disabled={!hits.length} data-testid="replace-preview">
          Preview replace
        </button>
        {preview && (
          <button type="button" onClick={replaceAll} disabled={!previewCount} data-testid="replace-all">
            {preview.undeclared.length
              ? 'Replace anyway'
              : preview.rename
                ? `Rename${preview.replacements.length ? ` and replace ${preview.replacements.length}` : ''}`
                : `Replace ${preview.replacements.length}`}
          </button>
        )}
        {preview && (
          <button type="button" onClick={() => setPreview(undefined)} data-testid="replace-cancel">
            Cancel
          </button>
        )}
      </div>
      {refusal && (
        <div className="rs-row rs-error-text" role="alert" data-testid="replace-refusal">
          {refusal}
        </div>
      )}
      {preview?.rename && (
        <div className="rs-row" data-testid="replace-rename">
          {`Renames the variable ${preview.rename.from} to ${preview.rename.to}: its declaration (${preview.rename.scopes
            .map((sc) => (sc === 'globals' ? 'globals' : (project.pous.find((p) => p.id === sc)?.name ?? sc)))
            .join(', ')}), ${preview.renamedUses.length} use${preview.renamedUses.length === 1 ? '' : 's'}, and the watch list, trend and test scenarios naming it.`}
        </div>
      )}
      {preview && preview.undeclared.length > 0 && (
        <div className="rs-row rs-error-text" role="alert" data-testid="replace-undeclared">
          {`After this replace, ${preview.undeclared.length === 1 ? 'this name would not be declared' : 'these names would not be declared'}: ${[
            ...new Map(preview.undeclared.map((u) => [u.name.toUpperCase(), u])).values(),
          ]
            .map(
              (u) =>
                `${u.name} (${placeName(u.replacement.place)}, ${u.replacement.place.elementKind ?? 'element'}: ${u.replacement.place.elementKind === 'box' ? 'LD-E02' : 'LD-R08'})`,
            )
            .join(', ')}. Declare ${preview.undeclared.length === 1 ? 'it' : 'them'} afterwards, replace anyway, or cancel.`}
        </div>
      )}
      {preview ? (
        <ol className="rs-find-results" aria-label="Replace preview" data-testid="replace-list">
          {previewRows.slice(0, SHOWN).map((r, i) => (
            <li key={i}>
              <span className="rs-find-where">{`${placeName(r.place)} · ${r.place.elementKind ?? r.place.field}`}</span>{' '}
              <del className="rs-mono">{r.before}</del> → <ins className="rs-mono">{r.after}</ins>
            </li>
          ))}
        </ol>
      ) : (
        <ol className="rs-find-results" aria-label="Matches" data-testid="find-results">
          {hits.slice(0, SHOWN).map((h, i) => (
            <li key={i}>
              <button
                type="button"
                aria-current={i === index}
                onClick={() => show(i)}
              >
                <span className="rs-find-where">{where(h)}</span>{' '}
                <span className="rs-mono">
                  {h.text.slice(Math.max(0, h.start - 20), h.start)}
                  <mark>{h.text.slice(h.start, h.start + h.length)}</mark>
                  {h.text.slice(h.start + h.length, h.start + h.length + 30)}
                </span>
              </button>
            </li>
          ))}
          {hits.length > SHOWN && <li>… {hits.length - SHOWN} more</li>}
        </ol>
      )}
    </div>
  );
}

export function FindHost() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  const open = useUi((s) => s.finder === 'find');
  return open ? <FindPanel ctx={ctx} /> : null;
}
