// The keyboard cursor: a coil that ends its rung is drawn at the right rail, the cells between its
// own cell and the rail lie under its wire, and the cursor never stops there (it lands on the
// coil); a box nudged onto the first column stays right of the rail, the cursor with it.
import { expect, test } from 'vitest';
import type { EditorContext } from '../../src/editor/commands/editorActions';
import { commandById } from '../../src/editor/commands/registry';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';
import { createUiStore } from '../../src/store/uiStore';

const el = (id: string, kind: 'contact' | 'coil', row: number, col: number, variable: string): LdElement =>
  (kind === 'contact'
    ? { id: id as ElementId, kind, contact: 'NO', variable, row, col }
    : { id: id as ElementId, kind, coil: 'COIL', variable, row, col }) as LdElement;

/** Row 0: A, then the coil Q at column 1 (drawn at the rail of a 6-column network); row 1: B B B B B Q2. */
function editor() {
  const net = newNetwork({
    rows: 2,
    cols: 6,
    elements: [
      el('a', 'contact', 0, 0, 'A'),
      el('q', 'coil', 0, 1, 'Q'),
      ...[0, 1, 2, 3, 4].map((c) => el(`b${c}`, 'contact', 1, c, `B${c}`)),
      el('q2', 'coil', 1, 5, 'Q2'),
    ],
  });
  const doc = createDocumentStore(newProject('t', { pous: [newPou('Main', { networks: [net] })] }));
  const ui = createUiStore();
  const ctx: EditorContext = { doc, ui };
  const id = selectNetworks(doc.getState())[0]!.id;
  ui.getState().setCursor({ network: id, row: 0, col: 0 });
  const run = (cmd: string) => commandById(cmd)!.run(ctx);
  const at = () => {
    const c = ui.getState().cursor!;
    return [c.row, c.col];
  };
  return { run, at, ui };
}

test('right from the contact lands on the coil, and further right stays on it', () => {
  const e = editor();
  e.run('nav.right');
  expect(e.at()).toEqual([0, 1]);
  expect(e.ui.getState().selection.elements).toEqual(['q']);
  e.run('nav.right');
  e.run('nav.right');
  expect(e.at()).toEqual([0, 1]);
  e.run('nav.left');
  expect(e.at()).toEqual([0, 0]);
});

test('up from a cell under the coil’s wire lands on the coil', () => {
  const e = editor();
  e.run('nav.down');
  for (let i = 0; i < 4; i++) e.run('nav.right');
  expect(e.at()).toEqual([1, 4]);
  e.run('nav.up');
  expect(e.at()).toEqual([0, 1]);
  expect(e.ui.getState().selection.elements).toEqual(['q']);
});

test('a row whose coil already stands in the last column is walked cell by cell', () => {
  const e = editor();
  e.run('nav.down');
  for (let i = 0; i < 6; i++) e.run('nav.right');
  expect(e.at()).toEqual([1, 5]);
});

test('Alt+Left puts a box onto the first column right of the rail; the cursor stays on the box', () => {
  const doc = createDocumentStore(newProject('t'));
  const ui = createUiStore();
  const ctx: EditorContext = { doc, ui };
  const net = selectNetworks(doc.getState())[0]!.id;
  const id = doc.getState().placeElement(net, { row: 0, col: 1 }, {
    kind: 'box',
    blockType: 'TON',
    instance: 'T1',
    inputs: {},
    outputs: {},
  })!;
  ui.getState().select(net, [id]);
  ui.getState().setCursor({ network: net, row: 0, col: 1 });
  commandById('edit.moveLeft')!.run(ctx);
  const els = selectNetworks(doc.getState())[0]!.elements.map((e) => `${e.kind}@${e.row},${e.col}`).sort();
  expect(els).toEqual(['box@0,1', 'link@0,0']);
  expect(ui.getState().cursor).toMatchObject({ row: 0, col: 1 });
});
