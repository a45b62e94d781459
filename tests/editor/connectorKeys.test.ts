// The keyboard flow for connectors and continuations: X / Shift+X place one at the cursor with its
// default name and open the name field (like a jump's label); G goes from one to its partner.
import { expect, test } from 'vitest';
import { commandById } from '../../src/editor/commands/registry';
import type { EditorContext } from '../../src/editor/commands/editorActions';
import { newProject } from '../../src/model/factory';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';
import { createUiStore } from '../../src/store/uiStore';

function editor(): EditorContext & { run(id: string): void } {
  const doc = createDocumentStore(newProject('t'));
  const ui = createUiStore();
  const ctx = { doc, ui };
  return { ...ctx, run: (id) => commandById(id)!.run(ctx) };
}

const network = (e: EditorContext) => selectNetworks(e.doc.getState())[0]!;

test('X places a connector C1 at the cursor and opens its name field; Shift+X a continuation that pairs with it', () => {
  const e = editor();
  const net = network(e).id;
  e.ui.getState().setCursor({ network: net, row: 0, col: 3 });
  e.run('place.connector');
  const connector = network(e).elements.find((x) => x.kind === 'connector')!;
  expect(connector).toMatchObject({ row: 0, col: 3, name: 'C1' });
  expect(e.ui.getState().editing).toMatchObject({ element: connector.id });

  e.ui.getState().stopEditing();
  e.ui.getState().setCursor({ network: net, row: 1, col: 0 });
  e.run('place.continuation');
  const continuation = network(e).elements.find((x) => x.kind === 'continuation')!;
  expect(continuation).toMatchObject({ row: 1, col: 0, name: 'C1' });
  expect(e.ui.getState().editing).toMatchObject({ element: continuation.id });
  e.ui.getState().stopEditing();

  // G: from the selected continuation to its connector, and back.
  e.ui.getState().select(net, [continuation.id]);
  e.run('nav.partner');
  expect(e.ui.getState().selection.elements).toEqual([connector.id]);
  expect(e.ui.getState().cursor).toMatchObject({ row: 0, col: 3 });
  e.run('nav.partner');
  expect(e.ui.getState().selection.elements).toEqual([continuation.id]);
});

test('G on an element without a partner says why in the status line', () => {
  const e = editor();
  const net = network(e).id;
  e.ui.getState().setCursor({ network: net, row: 0, col: 0 });
  e.run('nav.partner');
  expect(e.ui.getState().status).toBe('Select a connector or continuation to go to its partner.');
  e.run('place.connector');
  e.ui.getState().stopEditing();
  e.run('nav.partner');
  expect(e.ui.getState().status).toBe('The connector >C1> has no continuation in this network (LD-R14).');
});
