// The language services of the ST editor as CodeMirror extensions (issue 25), over the pure
// services of engine/st/services: the compiler's findings as you type (underlines, gutter marks,
// re-checked when the project changes elsewhere), completion with signatures, hover, go to
// definition (F12, Ctrl/Cmd+click), rename (F2), and the Problems list's "show this line".
import {
  autocompletion,
  snippetCompletion,
  type Completion,
  type CompletionContext,
  type CompletionResult,
} from '@codemirror/autocomplete';
import {
  forceLinting,
  linter,
  lintGutter,
  lintKeymap,
  type Diagnostic as CmDiagnostic,
} from '@codemirror/lint';
import { EditorSelection, type Extension } from '@codemirror/state';
import { EditorView, hoverTooltip, keymap, ViewPlugin, type ViewUpdate } from '@codemirror/view';
import { stCompletions, stDiagnostics, stHover, type CompletionKind } from '../../../engine/st/services';
import type { Project } from '../../../model/project';
import type { StEditorContext } from '../context';
import { stModelLink } from '../stModelSync';
import { takeReveal, stReveal } from './reveal';
import { goToDefinition, stRename } from './rename';
import './services.css';

/** Pause after the last keystroke before the body is checked again (ms). */
export const ST_CHECK_DELAY_MS = 120;

/** The compiler's findings for the text in the editor (not yet committed to the project, maybe). */
function lintSource(view: EditorView): CmDiagnostic[] {
  const link = stModelLink(view.state);
  if (!link) return [];
  const { located } = stDiagnostics(link.store.getState().project, link.pouId, view.state.doc.toString());
  const doc = view.state.doc;
  const offset = (line: number, col: number) => {
    const l = doc.line(Math.max(1, Math.min(line, doc.lines)));
    return Math.min(l.to, l.from + col - 1);
  };
  return located.map((d) => {
    const from = offset(d.line, d.col);
    const to = Math.max(from, offset(d.endLine, d.endCol));
    return {
      from,
      to,
      severity: d.severity,
      source: d.rule,
      message: `${d.detail}`,
      markClass: `rs-st-${d.severity}`,
    };
  });
}

/** True when the only change is this editor's own text committed (already checked as typed). */
function onlyThisText(a: Project, b: Project, pouId: string, text: string): boolean {
  if (
    a.globals !== b.globals ||
    a.dataTypes !== b.dataTypes ||
    a.libraries !== b.libraries ||
    a.externalBlocks !== b.externalBlocks ||
    a.profile !== b.profile
  )
    return false;
  if (a.pous.length !== b.pous.length) return false;
  return a.pous.every((p, i) => {
    const q = b.pous[i]!;
    if (p === q) return true;
    if (p.id !== pouId || q.id !== pouId || q.source !== text) return false;
    const { source: _a, ...restA } = p;
    const { source: _b, ...restB } = q;
    return (
      (Object.keys(restA) as (keyof typeof restA)[]).every((k) => restA[k] === restB[k]) &&
      Object.keys(restA).length === Object.keys(restB).length
    );
  });
}

/** Checks again when the project changes elsewhere (a variable declared, a block's pins renamed). */
const recheckOnProject = ViewPlugin.define((view) => {
  const link = stModelLink(view.state);
  let timer: ReturnType<typeof setTimeout> | undefined;
  const unsubscribe = link?.store.subscribe((s, prev) => {
    if (
      s.project === prev.project ||
      onlyThisText(prev.project, s.project, link.pouId, view.state.doc.toString())
    )
      return;
    if (timer) clearTimeout(timer);
    timer = setTimeout(() => forceLinting(view), ST_CHECK_DELAY_MS);
  });
  return {
    destroy() {
      if (timer) clearTimeout(timer);
      unsubscribe?.();
    },
  };
});

const CM_TYPES: Record<CompletionKind, string> = {
  variable: 'variable',
  member: 'property',
  enum: 'enum',
  function: 'function',
  fb: 'class',
  keyword: 'keyword',
  snippet: 'keyword',
  parameter: 'property',
  type: 'type',
};

function completionSource(context: CompletionContext): CompletionResult | null {
  const link = stModelLink(context.state);
  if (!link) return null;
  const r = stCompletions(
    link.store.getState().project,
    link.pouId,
    context.state.doc.toString(),
    context.pos,
    context.explicit,
  );
  if (!r) return null;
  // Nothing typed and no `.`/`#`/`(` before the cursor: no list unless asked (Ctrl+Space).
  if (!r.explicit && r.from === context.pos) return null;
  // A word typed out whole (THEN, END_IF, a variable's name) closes the list, so Enter after it
  // starts a new line instead of accepting what is already written.
  const labels = new Set(r.options.map((o) => o.label.toUpperCase()));
  const whole = (text: string) => !context.explicit && text !== '' && labels.has(text.toUpperCase());
  if (whole(context.state.sliceDoc(r.from, context.pos))) return null;
  const options = r.options.map((o): Completion => {
    const base: Completion = {
      label: o.label,
      type: CM_TYPES[o.kind],
      detail: o.detail,
      ...(o.info ? { info: o.info } : {}),
      ...(o.boost ? { boost: o.boost } : {}),
    };
    if (o.apply?.includes('${')) return snippetCompletion(o.apply.replace('${}', '${1}'), base);
    return o.apply ? { ...base, apply: o.apply } : base;
  });
  return { from: r.from, options, validFor: (text) => /^\w*$/.test(text) && !whole(text) };
}

const hover = hoverTooltip((view, pos) => {
  const link = stModelLink(view.state);
  if (!link) return null;
  const h = stHover(link.store.getState().project, link.pouId, view.state.doc.toString(), pos);
  if (!h) return null;
  return {
    pos: h.from,
    end: h.to,
    above: true,
    create: () => {
      const dom = document.createElement('div');
      dom.className = 'rs-st-hover';
      dom.setAttribute('data-testid', 'st-hover');
      const title = dom.appendChild(document.createElement('code'));
      title.className = 'rs-st-hover-title';
      title.textContent = h.title;
      for (const line of h.lines) dom.appendChild(document.createElement('div')).textContent = line;
      return { dom };
    },
  };
});

/** Puts the cursor where the Problems list asked (now, or when the editor of that POU opens). */
const revealPlugin = ViewPlugin.fromClass(
  class {
    private readonly unsubscribe: () => void;
    constructor(private readonly view: EditorView) {
      this.unsubscribe = stReveal.subscribe(() => this.take());
      // The editor is being created: reveal once it is in the page.
      queueMicrotask(() => this.take());
    }
    private take() {
      const link = stModelLink(this.view.state);
      const r = link && takeReveal(link.pouId);
      if (!r) return;
      const doc = this.view.state.doc;
      const line = doc.line(Math.max(1, Math.min(r.line, doc.lines)));
      const at = Math.min(line.to, line.from + Math.max(0, r.col - 1));
      this.view.dispatch({
        selection: EditorSelection.cursor(at),
        effects: EditorView.scrollIntoView(at, { y: 'center' }),
      });
      this.view.focus();
    }
    update(_u: ViewUpdate) {}
    destroy() {
      this.unsubscribe();
    }
  },
);

/** Every language service of the ST editor of one POU. */
export function stLanguageServices(ctx: StEditorContext): Extension[] {
  void ctx;
  return [
    linter(lintSource, { delay: ST_CHECK_DELAY_MS }),
    lintGutter(),
    recheckOnProject,
    autocompletion({ override: [completionSource], icons: true, activateOnTyping: true }),
    hover,
    revealPlugin,
    stRename(),
    keymap.of([...lintKeymap, { key: 'F12', run: goToDefinition, preventDefault: true }]),
    EditorView.domEventHandlers({
      mousedown(e, view) {
        if (!(e.ctrlKey || e.metaKey) || e.button !== 0) return false;
        const pos = view.posAtCoords({ x: e.clientX, y: e.clientY });
        if (pos === null) return false;
        view.dispatch({ selection: EditorSelection.cursor(pos) });
        e.preventDefault();
        return goToDefinition(view);
      },
    }),
  ];
}
