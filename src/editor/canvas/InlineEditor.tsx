// The name field that opens over an element on the canvas (after placing it, Enter, or a
// double-click): the variable of a contact or coil, the instance of a function block, the
// label a jump goes to. Enter commits (or keeps an unchanged name) and moves the cursor on;
// Escape or clicking elsewhere leaves the name as it was. Naming an element right after placing it
// joins the placing's undo step. On a box, Tab goes on to its pin operands (PinOperandEditor).
import { useEffect, useMemo } from 'react';
import type { LdElement } from '../../model/elements';
import type { NetworkId } from '../../model/ids';
import { connectionNamesFor, isConnection, renameConnection } from '../../store/connectors';
import { selectNetworks, useDocument, useDocumentStore } from '../../store/documentStore';
import { useUi, useUiStore } from '../../store/uiStore';
import { advancePast, tabToField, type EditorContext } from '../commands/editorActions';
import { VariableInput, type EndKey } from '../inspector/VariableInput';
import { PinOperandEditor } from './PinOperandEditor';
import { INSTANCE_FIELD } from './pinOperands';
import { cellRect, columnsOf, headerHeight, pitchOf, RAIL_X, type CanvasLayout } from './geometry';

export interface InlineEditorProps {
  readonly layout: CanvasLayout;
  readonly zoom: number;
  readonly onDone: () => void;
}

function currentName(el: LdElement): string {
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return el.variable;
    case 'box':
      return el.instance ?? '';
    case 'jump':
      return el.target;
    case 'connector':
    case 'continuation':
      return el.name;
    case 'link':
    case 'return':
      return '';
  }
}

/** Positioned in the canvas's scrolled world layer (screen pixels of the whole content). */
export function InlineEditor({ layout, zoom, onDone }: InlineEditorProps) {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const editing = useUi((s) => s.editing);
  const networks = useDocument(selectNetworks);
  const found = useMemo(() => {
    if (!editing) return undefined;
    for (let i = 0; i < networks.length; i++) {
      const el = networks[i]!.elements.find((e) => e.id === editing.element);
      if (el) return { index: i, network: networks[i]!, el };
    }
    return undefined;
  }, [editing, networks]);
  // The element went away (undo, delete): stop editing so the shortcuts work again.
  useEffect(() => {
    if (editing && (!found || found.network.collapsed)) ui.getState().stopEditing();
  }, [editing, found, ui]);
  const labels = useMemo(
    () => networks.map((n) => n.label).filter((l): l is string => Boolean(l)),
    [networks],
  );
  if (!found || found.network.collapsed) return null;
  const { el, network, index } = found;
  const ctx: EditorContext = { doc, ui };

  const close = (advance: boolean) => {
    ui.getState().stopEditing();
    if (advance) {
      const now = doc
        .getState()
        .project.pous.flatMap((p) => p.networks)
        .find((n) => n.id === network.id);
      const latest = now?.elements.find((e) => e.id === el.id);
      if (latest) advancePast(ctx, network.id as NetworkId, latest);
    }
    onDone();
  };
  const join = editing?.joinUndo;
  const moveOn = (how: EndKey | undefined) =>
    how === 'tab' || how === 'backtab'
      ? tabToField(ctx, network.id as NetworkId, el.id, INSTANCE_FIELD, how === 'backtab')
      : close(true);
  const commit = (text: string, how?: EndKey) => {
    const name = text.trim();
    if (el.kind === 'contact' || el.kind === 'coil') doc.getState().updateElement(el.id, { variable: name });
    else if (el.kind === 'box') doc.getState().updateElement(el.id, { instance: name });
    else if (el.kind === 'jump') doc.getState().updateElement(el.id, { target: name });
    else if (isConnection(el)) renameConnection(doc, el.id, name);
    if (join) doc.getState().joinSince(join, 'placeElement');
    if (el.kind === 'box') moveOn(how);
    else close(true);
  };

  const cell = cellRect(columnsOf(layout, network), el);
  const x = (RAIL_X + cell.x) * zoom;
  const y = (layout.tops[index]! + headerHeight(network) + el.row * pitchOf(layout, index) + 4) * zoom;
  const width = Math.max(140, cell.width * zoom + 40);
  const style = { left: x - 20, top: y, width };
  const what =
    el.kind === 'box'
      ? `Instance name of ${el.blockType}`
      : el.kind === 'jump'
        ? 'Jump target label'
        : isConnection(el)
          ? `Name of the ${el.kind}`
          : `Variable of the ${el.kind}`;

  if (editing?.pin !== undefined && el.kind === 'box') {
    return (
      <PinOperandEditor
        pitch={pitchOf(layout, index)}
        box={el}
        network={network}
        pin={editing.pin}
        left={x}
        width={cell.width * zoom}
        top={y}
        zoom={zoom}
        close={close}
      />
    );
  }
  if (el.kind === 'jump' || isConnection(el)) {
    const options = isConnection(el) ? connectionNamesFor(network, el) : labels;
    return (
      <div className="rs-inline-editor" style={style}>
        <input
          autoFocus
          aria-label={what}
          data-testid="inline-editor"
          className="rs-cell-input rs-mono"
          list="rs-network-labels"
          defaultValue={currentName(el)}
          onFocus={(e) => e.currentTarget.select()}
          onKeyDown={(e) => {
            e.stopPropagation();
            if (e.key === 'Enter') commit(e.currentTarget.value);
            else if (e.key === 'Escape') close(false);
          }}
          onBlur={() => close(false)}
        />
        <datalist id="rs-network-labels">
          {options.map((l) => (
            <option key={l} value={l} />
          ))}
        </datalist>
      </div>
    );
  }
  const role =
    el.kind === 'box'
      ? ({ kind: 'instance', blockType: el.blockType } as const)
      : el.kind === 'coil'
        ? ({ kind: 'coil' } as const)
        : ({ kind: 'contact' } as const);
  return (
    <div className="rs-inline-editor" style={style}>
      <VariableInput
        value={currentName(el)}
        role={role}
        autoFocus
        commitOnBlur={false}
        tabMoves={el.kind === 'box'}
        aria-label={what}
        data-testid="inline-editor"
        placeholder={el.kind === 'box' ? 'instance' : 'variable'}
        onCommit={commit}
        onCancel={(how) => {
          if (how === 'tab' || how === 'backtab') moveOn(how);
          // A blur after Tab moved to a pin (this field going away) ends nothing.
          else if (how !== 'blur' || (ui.getState().editing?.element === el.id && !ui.getState().editing?.pin))
            close(how === 'enter');
        }}
      />
    </div>
  );
}
