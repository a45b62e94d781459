// Placing a box on the first column wires only its power-flow input to the rail; placing an
// element and naming it right away is one undo step.
import { describe, expect, test } from 'vitest';
import { buildGraph } from '../../src/engine/compile/graph';
import type { BoxElement, LdElement } from '../../src/model/elements';
import { newProject, variable } from '../../src/model/factory';
import type { NetworkId } from '../../src/model/ids';
import type { Network } from '../../src/model/project';
import { createDocumentStore, selectNetworks, type DocumentStore } from '../../src/store/documentStore';
import { HISTORY_LIMIT } from '../../src/store/history';
import type { ElementTemplate } from '../../src/store/networkEdits';

const TON: ElementTemplate = { kind: 'box', blockType: 'TON', instance: 'T1', inputs: {}, outputs: {} };
const ADD: ElementTemplate = { kind: 'box', blockType: 'ADD', inputs: {}, outputs: {} };
const contact = (variable: string): ElementTemplate => ({ kind: 'contact', contact: 'NO', variable });

function setup(): { store: DocumentStore; net: NetworkId; network: () => Network } {
  const store = createDocumentStore(newProject('p'));
  const net = selectNetworks(store.getState())[0]!.id;
  return { store, net, network: () => selectNetworks(store.getState())[0]! };
}

/** Input pins of the network's box that the grid feeds from the left rail. */
function railFedPins(n: Network): string[] {
  const g = buildGraph(n);
  const node = g.nodes.find((x) => x.el.kind === 'box')!;
  return node.inputs.filter((t) => g.nets[t.net]!.leftRail).map((t) => t.pin);
}

const box = (n: Network) => n.elements.find((e): e is BoxElement => e.kind === 'box')!;
const at = (els: readonly LdElement[]) => els.map((e) => `${e.kind}@${e.row},${e.col}`).sort();

describe('a box placed on the first column', () => {
  test('TON gets IN from the rail; PT stays unwired for an operand', () => {
    const { store, net, network } = setup();
    store.getState().placeElement(net, { row: 0, col: 0 }, TON);
    expect(box(network())).toMatchObject({ row: 0, col: 1 });
    expect(railFedPins(network())).toEqual(['IN']);
    expect(at(network().elements)).toEqual(['box@0,1', 'link@0,0']);
  });

  test('ADD (a function) gets EN only; IN1 and IN2 stay unwired', () => {
    const { store, net, network } = setup();
    store.getState().placeElement(net, { row: 0, col: 0 }, ADD);
    expect(railFedPins(network())).toEqual(['EN']);
  });

  test('an FB with EN/ENO takes the power flow on EN, not on IN', () => {
    const { store, net, network } = setup();
    store.getState().placeElement(net, { row: 0, col: 0 }, { ...TON, executionControl: true } as ElementTemplate);
    expect(railFedPins(network())).toEqual(['EN']);
  });

  test('on a contact in the first column the box goes in front of it, the contact after the box', () => {
    const { store, net, network } = setup();
    store.getState().placeElement(net, { row: 0, col: 0 }, contact('Start'));
    store.getState().placeElement(net, { row: 0, col: 0 }, TON);
    expect(at(network().elements)).toEqual(['box@0,1', 'contact@0,3', 'link@0,0']);
    expect(railFedPins(network())).toEqual(['IN']);
  });

  test('rail links on the rows of its other inputs go', () => {
    const { store, net, network } = setup();
    store.getState().placeElement(net, { row: 1, col: 0 }, { kind: 'link' });
    store.getState().placeElement(net, { row: 0, col: 0 }, TON);
    expect(railFedPins(network())).toEqual(['IN']);
  });

  test('the same box placed further right is placed where it was dropped', () => {
    const { store, net, network } = setup();
    store.getState().placeElement(net, { row: 0, col: 2 }, TON);
    expect(at(network().elements)).toEqual(['box@0,2']);
  });

  test('placing it is one undo step', () => {
    const { store, net, network } = setup();
    store.getState().placeElement(net, { row: 0, col: 0 }, TON);
    store.getState().undo();
    expect(network().elements).toEqual([]);
  });
});

describe('placing and naming: one undo step', () => {
  test('undo after naming removes the element, not only its name', () => {
    const { store, net, network } = setup();
    const s = store.getState();
    s.placeElement(net, { row: 0, col: 0 }, contact('First'));
    const id = s.placeElement(net, { row: 0, col: 1 }, contact(''))!;
    const step = store.getState().lastStep();
    s.updateElement(id, { variable: 'Start' });
    store.getState().joinSince(step, 'placeElement');
    expect(store.getState().undoName).toBe('placeElement');
    store.getState().undo();
    expect(network().elements.map((e) => (e.kind === 'contact' ? e.variable : e.kind))).toEqual(['First']);
    store.getState().redo();
    expect(network().elements.map((e) => (e.kind === 'contact' ? e.variable : e.kind))).toEqual([
      'First',
      'Start',
    ]);
  });

  test('a declaration made while naming joins the same step', () => {
    const { store, net, network } = setup();
    const id = store.getState().placeElement(net, { row: 0, col: 0 }, contact(''))!;
    const step = store.getState().lastStep();
    // As the name field does it: the declaration's batch runs the naming, which asks to join.
    store.getState().batch('declareVariable', () => {
      store.getState().addVariable(variable('Start', 'BOOL'));
      store.getState().updateElement(id, { variable: 'Start' });
      store.getState().joinSince(step, 'placeElement');
    });
    expect(store.getState().history.undo.map((e) => e.name)).toEqual(['placeElement']);
    store.getState().undo();
    expect(network().elements).toEqual([]);
    expect(store.getState().project.pous[0]!.variables).toEqual([]);
    expect(store.getState().canUndo).toBe(false);
  });

  test('with a full history the step is found by identity, not by position', () => {
    const { store, net, network } = setup();
    const s = store.getState();
    for (let i = 0; i < HISTORY_LIMIT; i++) s.updateNetwork(net, { title: `t${i}` });
    const id = s.placeElement(net, { row: 0, col: 0 }, contact(''))!;
    const step = store.getState().lastStep();
    s.updateElement(id, { variable: 'Start' });
    store.getState().joinSince(step, 'placeElement');
    expect(store.getState().history.undo.length).toBe(HISTORY_LIMIT - 1);
    store.getState().undo();
    expect(network().elements).toEqual([]);
  });

  test('naming nothing leaves the placement a step of its own', () => {
    const { store, net } = setup();
    store.getState().updateNetwork(net, { title: 'Motor' });
    store.getState().placeElement(net, { row: 0, col: 0 }, contact(''));
    const step = store.getState().lastStep();
    store.getState().joinSince(step, 'placeElement');
    expect(store.getState().history.undo.map((e) => e.name)).toEqual(['updateNetwork', 'placeElement']);
  });
});
