// Moving or pasting a box onto the first column behaves like placing one there: the box goes one
// column right and the rail feeds only its power-flow input (EN, else the first BOOL input).
import { describe, expect, test } from 'vitest';
import { buildGraph } from '../../src/engine/compile/graph';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Network } from '../../src/model/project';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';
import { copyElements, type ElementTemplate } from '../../src/store/networkEdits';

const TON: ElementTemplate = { kind: 'box', blockType: 'TON', instance: 'T1', inputs: {}, outputs: {} };
const ADD: ElementTemplate = { kind: 'box', blockType: 'ADD', inputs: {}, outputs: {} };

function setup(networks = 1) {
  const store = createDocumentStore(
    newProject('p', {
      pous: [newPou('Main', { networks: Array.from({ length: networks }, () => newNetwork()) })],
    }),
  );
  const nets = () => selectNetworks(store.getState());
  return { store, s: () => store.getState(), nets };
}

/** Input pins of the network's box that the grid feeds from the left rail. */
function railFedPins(n: Network): string[] {
  const g = buildGraph(n);
  const node = g.nodes.find((x) => x.el.kind === 'box')!;
  return node.inputs.filter((t) => g.nets[t.net]!.leftRail).map((t) => t.pin);
}

const at = (els: readonly LdElement[]) => els.map((e) => `${e.kind}@${e.row},${e.col}`).sort();

describe('a box moved onto the first column', () => {
  test('TON dragged from column 3 to column 1 gets IN from the rail, PT stays open', () => {
    const { s, nets } = setup();
    const id = s().placeElement(nets()[0]!.id, { row: 0, col: 3 }, TON)!;
    expect(s().moveElements(nets()[0]!.id, [id], 0, -3)).toBe(true);
    expect(at(nets()[0]!.elements)).toEqual(['box@0,1', 'link@0,0']);
    expect(railFedPins(nets()[0]!)).toEqual(['IN']);
  });

  test('a function moved down onto the first column gets EN only', () => {
    const { s, nets } = setup();
    const id = s().placeElement(nets()[0]!.id, { row: 0, col: 2 }, ADD)!;
    expect(s().moveElements(nets()[0]!.id, [id], 2, -2)).toBe(true);
    expect(railFedPins(nets()[0]!)).toEqual(['EN']);
    // One undo step brings the box back where it was, without the link.
    s().undo();
    expect(at(nets()[0]!.elements)).toEqual(['box@0,2']);
  });

  test('a box and the coil after it move together, one column further right', () => {
    const { s, nets } = setup();
    const n = nets()[0]!.id;
    const box = s().placeElement(n, { row: 0, col: 2 }, TON)!;
    const coil = s().placeElement(n, { row: 0, col: 5 }, { kind: 'coil', coil: 'COIL', variable: 'Q' })!;
    expect(s().moveElements(n, [box, coil], 0, -2)).toBe(true);
    expect(at(nets()[0]!.elements)).toEqual(['box@0,1', 'coil@0,4', 'link@0,0']);
  });

  test('a rail link on the row of another input goes', () => {
    const { s, nets } = setup();
    const n = nets()[0]!.id;
    s().placeElement(n, { row: 1, col: 0 }, { kind: 'link' });
    const id = s().placeElement(n, { row: 0, col: 3 }, TON)!;
    expect(s().moveElements(n, [id], 0, -3)).toBe(true);
    expect(railFedPins(nets()[0]!)).toEqual(['IN']);
  });

  test('dragged into another network onto its first column', () => {
    const { s, nets } = setup(2);
    const [a, b] = nets();
    const id = s().placeElement(a!.id, { row: 0, col: 2 }, TON)!;
    expect(s().moveElementsToNetwork(a!.id, [id], b!.id, { row: 0, col: 0 })).toBe(true);
    expect(at(nets()[1]!.elements)).toEqual(['box@0,1', 'link@0,0']);
    expect(railFedPins(nets()[1]!)).toEqual(['IN']);
  });

  test('a contact moved onto the first column stays there', () => {
    const { s, nets } = setup();
    const id = s().placeElement(nets()[0]!.id, { row: 0, col: 3 }, { kind: 'contact', contact: 'NO', variable: 'A' })!;
    expect(s().moveElements(nets()[0]!.id, [id], 0, -3)).toBe(true);
    expect(at(nets()[0]!.elements)).toEqual(['contact@0,0']);
  });
});

describe('a box pasted onto the first column', () => {
  test('TON pasted at column 1 gets IN from the rail only', () => {
    const { s, nets } = setup(2);
    const [a, b] = nets();
    const id = s().placeElement(a!.id, { row: 0, col: 3 }, TON)!;
    const clip = copyElements(nets()[0]!, [id as ElementId])!;
    const ids = s().pasteElements(b!.id, clip, { row: 0, col: 0 });
    expect(ids).toHaveLength(1);
    expect(at(nets()[1]!.elements)).toEqual(['box@0,1', 'link@0,0']);
    expect(railFedPins(nets()[1]!)).toEqual(['IN']);
  });

  test('a copied box with its rail link pastes as copied', () => {
    const { s, nets } = setup(2);
    const [a, b] = nets();
    const box = s().placeElement(a!.id, { row: 0, col: 0 }, ADD)!;
    const link = nets()[0]!.elements.find((e) => e.kind === 'link')!.id;
    const clip = copyElements(nets()[0]!, [box, link])!;
    s().pasteElements(b!.id, clip, { row: 0, col: 0 });
    expect(at(nets()[1]!.elements)).toEqual(['box@0,1', 'link@0,0']);
    expect(railFedPins(nets()[1]!)).toEqual(['EN']);
  });
});

describe('a box nudged onto the first column', () => {
  test('from column 2: the first nudge moves it to column 1, the second wires IN from the rail', () => {
    const { s, nets } = setup();
    const n = nets()[0]!.id;
    const id = s().placeElement(n, { row: 0, col: 2 }, TON)!;
    expect(s().moveElements(n, [id], 0, -1)).toBe(true);
    expect(at(nets()[0]!.elements)).toEqual(['box@0,1']);
    expect(s().moveElements(n, [id], 0, -1)).toBe(true);
    expect(at(nets()[0]!.elements)).toEqual(['box@0,1', 'link@0,0']);
    expect(railFedPins(nets()[0]!)).toEqual(['IN']);
  });
});
