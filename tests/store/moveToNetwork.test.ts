// Moving elements from one network into another (the drag between networks): one undo step,
// refused when something other than a horizontal link is in the way; and an update that changes
// nothing, which records no undo step.
import { expect, test } from 'vitest';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Network } from '../../src/model/project';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';

const id = (s: string) => s as ElementId;
const contact = (name: string, row: number, col: number): LdElement => ({
  kind: 'contact',
  contact: 'NO',
  variable: name,
  id: id(name),
  row,
  col,
});
const link = (k: string, row: number, col: number): LdElement => ({ kind: 'link', id: id(k), row, col });

function twoNetworks(a: Partial<Network>, b: Partial<Network>) {
  const store = createDocumentStore(
    newProject('t', { pous: [newPou('Main', { networks: [newNetwork(a), newNetwork(b)] })] }),
  );
  const nets = () => selectNetworks(store.getState());
  const cells = (i: number) => {
    const n = nets()[i]!;
    return n.elements.map((e) => `${e.kind === 'link' ? '-' : e.id}@${e.row},${e.col}`).sort();
  };
  return { store, nets, cells };
}

test('moves the selection with its relative layout, keeping ids, and replaces links in the way', () => {
  const { store, nets, cells } = twoNetworks(
    { rows: 2, cols: 4, elements: [contact('A', 0, 1), contact('B', 1, 2), contact('Stay', 0, 3)] },
    { rows: 1, cols: 3, elements: [link('l0', 0, 0), link('l1', 0, 1), link('l2', 0, 2)] },
  );
  const [from, to] = nets();
  expect(
    store.getState().moveElementsToNetwork(from!.id, [id('A'), id('B')], to!.id, { row: 0, col: 1 }),
  ).toBe(true);
  expect(cells(0)).toEqual(['Stay@0,3']);
  expect(cells(1)).toEqual(['-@0,0', '-@0,2', 'A@0,1', 'B@1,2']);
  // The target grew a row for B.
  expect(nets()[1]!.rows).toBe(2);
  expect(store.getState().undoName).toBe('moveElementsToNetwork');

  store.getState().undo();
  expect(cells(0)).toEqual(['A@0,1', 'B@1,2', 'Stay@0,3']);
  expect(cells(1)).toEqual(['-@0,0', '-@0,1', '-@0,2']);
  expect(nets()[1]!.rows).toBe(1);
  store.getState().redo();
  expect(cells(1)).toEqual(['-@0,0', '-@0,2', 'A@0,1', 'B@1,2']);
});

test('refuses when another element is in the way, and records nothing', () => {
  const { store, nets, cells } = twoNetworks(
    { rows: 1, cols: 2, elements: [contact('A', 0, 0)] },
    { rows: 1, cols: 2, elements: [contact('X', 0, 1)] },
  );
  const [from, to] = nets();
  expect(store.getState().moveElementsToNetwork(from!.id, [id('A')], to!.id, { row: 0, col: 1 })).toBe(false);
  expect(cells(0)).toEqual(['A@0,0']);
  expect(cells(1)).toEqual(['X@0,1']);
  expect(store.getState().canUndo).toBe(false);
});

test('vertical links inside the moved area go along; links on its edges stay behind', () => {
  const { store, nets } = twoNetworks(
    {
      rows: 2,
      cols: 4,
      elements: [contact('A', 0, 1), contact('B', 0, 2), contact('C', 1, 1), contact('D', 1, 2)],
      vlinks: [
        { row: 0, boundary: 1 },
        { row: 0, boundary: 2 },
        { row: 0, boundary: 3 },
      ],
    },
    { rows: 1, cols: 1, elements: [] },
  );
  const [from, to] = nets();
  const ids = ['A', 'B', 'C', 'D'].map(id);
  expect(store.getState().moveElementsToNetwork(from!.id, ids, to!.id, { row: 0, col: 0 })).toBe(true);
  expect(nets()[0]!.vlinks).toEqual([
    { row: 0, boundary: 1 },
    { row: 0, boundary: 3 },
  ]);
  expect(nets()[1]!.vlinks).toEqual([{ row: 0, boundary: 1 }]);
  expect(nets()[1]!.cols).toBe(2);
  store.getState().undo();
  expect(nets()[0]!.vlinks).toHaveLength(3);
  expect(nets()[1]!.vlinks).toEqual([]);
});

test('the same network or an unknown one is refused', () => {
  const { store, nets } = twoNetworks({ rows: 1, cols: 2, elements: [contact('A', 0, 0)] }, {});
  const [from] = nets();
  expect(store.getState().moveElementsToNetwork(from!.id, [id('A')], from!.id, { row: 0, col: 1 })).toBe(
    false,
  );
  expect(
    store.getState().moveElementsToNetwork(from!.id, [id('A')], 'nope' as Network['id'], { row: 0, col: 1 }),
  ).toBe(false);
  expect(store.getState().canUndo).toBe(false);
});

test('an element update that changes nothing records no undo step', () => {
  const { store } = twoNetworks({ rows: 1, cols: 1, elements: [contact('A', 0, 0)] }, {});
  store.getState().updateElement(id('A'), { variable: 'A' });
  expect(store.getState().canUndo).toBe(false);
  store.getState().updateElement(id('A'), { variable: 'B' });
  expect(store.getState().undoName).toBe('updateElement');
});
