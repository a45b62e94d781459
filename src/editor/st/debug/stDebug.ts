// Debugging in the ST editor (issue 25), as CODESYS's inline monitoring: after the statement that
// last wrote a variable in the scan shown (live or recorded), its value at the end of the line; the
// statement lines that did not run in that scan dim; a breakpoint gutter (click: every instance,
// Ctrl/Cmd+click: the picked instance only; F9 on the cursor line, see simCommands.ts); the line
// where execution is paused highlighted (and a fault's line). The simulator's state comes from the
// running app's simulator store (simCommands.ts simControls), which the engine fills from the
// instrumented tier (runtime/scanCycle.ts: only the shown ST body is observed).
import { commitStEdit } from '../stModelSync';
import { Prec, RangeSetBuilder, StateEffect, StateField, type Extension } from '@codemirror/state';
import {
  Decoration,
  EditorView,
  GutterMarker,
  gutter,
  keymap,
  ViewPlugin,
  WidgetType,
  type DecorationSet,
} from '@codemirror/view';
import type { StepRequest } from '../../../bridge/steppingLease';
import type { StepFrame } from '../../../engine/api';
import type { LineBreakpoint, SimTextTrace } from '../../../sim/protocol';
import type { SimState } from '../../../store/simState';
import { simControls } from '../../commands/simCommands';
import { formatLive } from '../../sim/liveValues';
import type { StEditorContext } from '../context';

/** What the editor shows of the simulator for its POU. */
export interface StDebugState {
  readonly pou: string;
  /** The shown scan's trace of this POU's body (the picked instance), if monitored. */
  readonly trace: SimTextTrace | undefined;
  /** The line where execution is paused in this body (in the picked instance), 0: none. */
  readonly pause: number;
  /** The line of a fault in this body, 0: none. */
  readonly fault: number;
  readonly breakpoints: readonly LineBreakpoint[];
  /** The picked instance (the one monitored). */
  readonly instance: string | undefined;
}

const EMPTY: StDebugState = {
  pou: '',
  trace: undefined,
  pause: 0,
  fault: 0,
  breakpoints: [],
  instance: undefined,
};

const same = (a: string | undefined, b: string | undefined) =>
  (a ?? '').toUpperCase() === (b ?? '').toUpperCase();

/** The debug state of `pou` in the simulator's state (pure: tested without a page). */
export function debugStateOf(s: SimState, pou: string): StDebugState {
  const instance = s.canvasScope?.view.instance;
  const trace = s.text && same(s.text.pou, pou) ? s.text : undefined;
  const at: StepFrame | undefined =
    s.mode === 'paused' && s.historyScan === undefined ? s.position.at(-1) : undefined;
  const pause =
    at &&
    same(at.pou, pou) &&
    at.line !== undefined &&
    (instance === undefined || same(at.instance, instance))
      ? at.line
      : 0;
  const fault =
    s.fault &&
    same(s.fault.pou, pou) &&
    s.fault.line !== undefined &&
    (instance === undefined || same(s.fault.instance, instance))
      ? s.fault.line
      : 0;
  return {
    pou,
    trace,
    pause,
    fault,
    breakpoints: s.lineBreakpoints.filter((b) => same(b.pou, pou)),
    instance,
  };
}

const setDebug = StateEffect.define<StDebugState>();

const debugField = StateField.define<StDebugState>({
  create: () => EMPTY,
  update: (v, tr) => {
    for (const e of tr.effects) if (e.is(setDebug)) return e.value;
    return v;
  },
});

/** `Out = 42  Count = 3`: the values written on a line, at its end. */
class ValuesWidget extends WidgetType {
  constructor(readonly text: string) {
    super();
  }
  override eq(other: ValuesWidget): boolean {
    return other.text === this.text;
  }
  toDOM(): HTMLElement {
    const span = document.createElement('span');
    span.className = 'cm-st-values';
    span.textContent = this.text;
    span.setAttribute('data-testid', 'st-inline-values');
    return span;
  }
}

const dimLine = Decoration.line({ class: 'cm-st-not-run', attributes: { 'data-st-run': 'no' } });
const ranLine = Decoration.line({ attributes: { 'data-st-run': 'yes' } });
const pauseLine = Decoration.line({ class: 'cm-st-pause', attributes: { 'data-testid': 'st-pause-line' } });
const faultLine = Decoration.line({ class: 'cm-st-fault', attributes: { 'data-testid': 'st-fault-line' } });

function decorationsOf(state: { doc: EditorView['state']['doc']; field: StDebugState }): DecorationSet {
  const { doc, field } = state;
  const b = new RangeSetBuilder<Decoration>();
  const t = field.trace;
  const ran = new Set(t && !t.stale ? t.lines : []);
  const stops = new Set(t?.stops ?? []);
  const byLine = new Map<number, string[]>();
  for (const v of t?.values ?? []) {
    const list = byLine.get(v.line) ?? [];
    list.push(`${v.name} = ${formatLive(v.type, v.value)}`);
    byLine.set(v.line, list);
  }
  for (let n = 1; n <= doc.lines; n++) {
    const line = doc.line(n);
    if (n === field.fault) b.add(line.from, line.from, faultLine);
    else if (n === field.pause) b.add(line.from, line.from, pauseLine);
    if (t && stops.has(n)) b.add(line.from, line.from, ran.has(n) ? ranLine : dimLine);
    const values = byLine.get(n);
    if (values)
      b.add(line.to, line.to, Decoration.widget({ widget: new ValuesWidget(values.join('   ')), side: 1 }));
  }
  return b.finish();
}

const debugDecorations = EditorView.decorations.compute(['doc', debugField], (state) =>
  decorationsOf({ doc: state.doc, field: state.field(debugField) }),
);

class BreakpointMarker extends GutterMarker {
  constructor(
    readonly instance: string | undefined,
    /** The gutter's (invisible) width spacer. */
    readonly spacer = false,
  ) {
    super();
  }
  override eq(other: BreakpointMarker): boolean {
    return other.instance === this.instance && other.spacer === this.spacer;
  }
  override toDOM(): Node {
    const dot = document.createElement('span');
    dot.className = this.instance ? 'cm-st-breakpoint cm-st-breakpoint-instance' : 'cm-st-breakpoint';
    dot.textContent = '●';
    dot.title = this.instance ? `Breakpoint in ${this.instance} only` : 'Breakpoint (every instance)';
    if (!this.spacer) dot.setAttribute('data-testid', 'st-breakpoint');
    return dot;
  }
}

/** Sets or clears the breakpoint on a line of the POU (`picked`: in the picked instance only). */
export function toggleLineBreakpoint(view: EditorView, line: number, picked = false): boolean {
  const sim = simControls.current?.sim;
  const field = view.state.field(debugField, false);
  if (!sim || !field?.pou) return false;
  sim.getState().toggleLineBreakpoint(field.pou, line, picked ? field.instance : undefined);
  return true;
}

const breakpointGutter = gutter({
  class: 'cm-st-breakpoint-gutter',
  markers: (view) => {
    const b = new RangeSetBuilder<GutterMarker>();
    const doc = view.state.doc;
    const list = [...view.state.field(debugField).breakpoints]
      .filter((x) => x.line <= doc.lines)
      .sort((x, y) => x.line - y.line);
    let last = 0;
    for (const bp of list) {
      if (bp.line === last) continue;
      last = bp.line;
      const at = doc.line(bp.line).from;
      b.add(at, at, new BreakpointMarker(bp.instance));
    }
    return b.finish();
  },
  initialSpacer: () => new BreakpointMarker(undefined, true),
  domEventHandlers: {
    mousedown: (view, block, event) => {
      const line = view.state.doc.lineAt(block.from).number;
      const e = event as MouseEvent;
      return toggleLineBreakpoint(view, line, e.ctrlKey || e.metaKey);
    },
  },
});

/** The editor that has the focus, for F9 (simCommands.ts): its POU and cursor line. */
export const focusedStEditor: { current?: EditorView } = {};

/** The line and POU F9 toggles a breakpoint on, when an ST editor is shown (the last one focused). */
export function focusedStLine(): { view: EditorView; line: number } | undefined {
  // The last focused ST editor still on the page (the palette takes the focus while it runs a command).
  const view = focusedStEditor.current;
  if (!view || !view.dom.isConnected) return undefined;
  return { view, line: view.state.doc.lineAt(view.state.selection.main.head).number };
}

/** Follows the simulator's store: the state of this POU into the editor, the pause line into view. */
const simLink = (ctx: StEditorContext) =>
  ViewPlugin.define((view) => {
    let off: (() => void) | undefined;
    let timer: ReturnType<typeof setTimeout> | undefined;
    let shown = EMPTY;
    const push = () => {
      const c = simControls.current;
      if (!c) return;
      const pou = c.project().pous.find((p) => p.id === ctx.pouId)?.name ?? '';
      const next = debugStateOf(c.sim.getState(), pou);
      if (
        next.pou === shown.pou &&
        next.trace === shown.trace &&
        next.pause === shown.pause &&
        next.fault === shown.fault &&
        next.breakpoints === shown.breakpoints &&
        next.instance === shown.instance
      )
        return;
      const moved = next.pause !== shown.pause && next.pause > 0 && next.pause <= view.state.doc.lines;
      shown = next;
      view.dispatch({
        effects: [
          setDebug.of(next),
          ...(moved
            ? [EditorView.scrollIntoView(view.state.doc.line(next.pause).from, { y: 'nearest' })]
            : []),
        ],
      });
    };
    const connect = () => {
      const c = simControls.current;
      if (!c) {
        timer = setTimeout(connect, 100);
        return;
      }
      off = c.sim.subscribe(push);
      push();
    };
    timer = setTimeout(connect, 0);
    const focus = () => (focusedStEditor.current = view);
    view.contentDOM.addEventListener('focus', focus);
    return {
      destroy: () => {
        clearTimeout(timer);
        off?.();
        view.contentDOM.removeEventListener('focus', focus);
        if (focusedStEditor.current === view) focusedStEditor.current = undefined;
      },
    };
  });

const debugTheme = EditorView.theme({
  '.cm-st-values': {
    marginLeft: '2em',
    padding: '0 4px',
    borderRadius: '3px',
    fontSize: '90%',
    color: 'var(--text-muted)',
    backgroundColor: 'color-mix(in srgb, var(--accent) 10%, transparent)',
    whiteSpace: 'pre',
  },
  '.cm-st-not-run': { opacity: '0.45' },
  '.cm-st-pause': { backgroundColor: 'color-mix(in srgb, var(--warning) 30%, transparent) !important' },
  '.cm-st-fault': { backgroundColor: 'color-mix(in srgb, var(--danger) 25%, transparent) !important' },
  '.cm-st-breakpoint-gutter .cm-gutterElement': { cursor: 'pointer', minWidth: '14px', textAlign: 'center' },
  '.cm-st-breakpoint': { color: 'var(--danger)' },
  '.cm-st-breakpoint-instance': { color: 'var(--warning)' },
});

/** A step from the editor's keys (the app's shortcuts do not fire while typing in it), as the toolbar's. */
const stepKey = (request: StepRequest) => (): boolean => {
  const c = simControls.current;
  if (!c) return false;
  const mode = c.sim.getState().mode;
  if (mode !== 'running' && mode !== 'faulted') c.commands.step(request);
  return true;
};

/** A key that acts on the program: the typing burst goes into the model first (Run must compile what is shown). */
const committed =
  (run: (view: EditorView) => boolean) =>
  (view: EditorView): boolean => {
    commitStEdit(view);
    return run(view);
  };

/** The simulator's keys inside the editor: F9 on the cursor line, F5 / Shift+F5, F10 / F11 / Shift+F11. */
const debugKeys = keymap.of(
  [
    {
      key: 'F9',
      run: (view: EditorView) =>
        toggleLineBreakpoint(view, view.state.doc.lineAt(view.state.selection.main.head).number),
    },
    { key: 'F10', run: stepKey({ kind: 'network' }) },
    { key: 'F11', run: stepKey({ kind: 'network', into: true }) },
    { key: 'Shift-F11', run: stepKey({ kind: 'network', out: true }) },
    {
      key: 'F5',
      run: () => {
        const c = simControls.current;
        if (c && c.sim.getState().mode !== 'running' && c.sim.getState().mode !== 'faulted') c.commands.run();
        return !!c;
      },
    },
    {
      key: 'Shift-F5',
      run: () => {
        simControls.current?.sim.getState().pause();
        return !!simControls.current;
      },
    },
  ].map((b) => ({ ...b, run: committed(b.run) })),
);

/** The debugging extensions of the ST editor of one POU. */
export function stDebugExtensions(ctx: StEditorContext): Extension[] {
  return [debugField, Prec.high(breakpointGutter), debugDecorations, simLink(ctx), debugKeys, debugTheme];
}
