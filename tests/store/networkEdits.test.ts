import { describe, expect, test } from 'vitest';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { validateProject } from '../../src/model/load';
import type { Network } from '../../src/model/project';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';
import { insertInSeries, wrapInParallelBranch, type ElementTemplate } from '../../src/store/networkEdits';

let counter = 0;
const id = () => `t${++counter}` as ElementId;
const contact = (row: number, col: number, v: string): LdElement => ({
  kind: 'contact',
  contact: 'NO',
  variable: v,
  id: id(),
  row,
  col,
});
const TON: ElementTemplate = {
  kind: 'box',
  blockType: 'TON',
  instance: 'T1',
  inputs: { PT: 'T#5s' },
  outputs: {},
};
const loadable = (n: Network) =>
  validateProject(newProject('x', { pous: [newPou('Main', { networks: [n] })] })).ok;

describe('insert in series with boxes', () => {
  test('a box inserted before a contact shifts the row by its two columns', () => {
    const n = newNetwork({ elements: [contact(0, 0, 'A'), contact(0, 1, 'B')] });
    const out = insertInSeries(n, { row: 0, col: 1 }, TON, id())!;
    const pos = out.elements.map(
      (e) => `${e.kind === 'box' ? 'TON' : (e as { variable: string }).variable}@${e.row},${e.col}`,
    );
    expect(pos).toContain('TON@0,1');
    expect(pos).toContain('B@0,3');
    expect(loadable(out)).toBe(true);
  });

  test('a parallel path crossing the insertion column gets two links for a one-row box', () => {
    const n = newNetwork({
      elements: [contact(0, 0, 'A'), contact(0, 1, 'B'), contact(1, 0, 'C'), contact(1, 1, 'D')],
    });
    const trig: ElementTemplate = {
      kind: 'box',
      blockType: 'R_TRIG',
      instance: 'E1',
      inputs: {},
      outputs: {},
    };
    const out = insertInSeries(n, { row: 0, col: 1 }, trig, id())!;
    const links = out.elements.filter((e) => e.kind === 'link').map((e) => `${e.row},${e.col}`);
    expect(links.sort()).toEqual(['1,1', '1,2']);
    expect(loadable(out)).toBe(true);
  });

  test('a box straddling the insertion column on the rows the new box needs is reported, not overlapped', () => {
    const box: LdElement = {
      kind: 'box',
      blockType: 'TON',
      instance: 'T0',
      inputs: {},
      outputs: {},
      id: id(),
      row: 1,
      col: 0,
    };
    const n = newNetwork({ rows: 4, elements: [contact(0, 0, 'A'), contact(0, 1, 'B'), box] });
    expect(insertInSeries(n, { row: 0, col: 1 }, TON, id())).toBeUndefined();
  });
});

describe('insert in series refusals', () => {
  test('a two-row box whose lower row would join a parallel path is refused', () => {
    const n = newNetwork({
      elements: [contact(0, 0, 'A'), contact(0, 1, 'B'), contact(1, 0, 'C'), contact(1, 1, 'D')],
    });
    expect(insertInSeries(n, { row: 0, col: 1 }, TON, id())).toBeUndefined();
  });
});

describe('insert in series refusals', () => {
  test('a two-row box whose lower row would join a parallel path is refused', () => {
    const n = newNetwork({
      elements: [contact(0, 0, 'A'), contact(0, 1, 'B'), contact(1, 0, 'C'), contact(1, 1, 'D')],
    });
    expect(insertInSeries(n, { row: 0, col: 1 }, TON, id())).toBeUndefined();
  });
});

describe('parallel branch around boxes', () => {
  test('the new row goes below a box that spans several rows', () => {
    const box: LdElement = {
      kind: 'box',
      blockType: 'TON',
      instance: 'T1',
      inputs: {},
      outputs: {},
      id: id(),
      row: 0,
      col: 1,
    };
    const a = contact(0, 0, 'A');
    const n = newNetwork({ elements: [a, box] });
    const out = wrapInParallelBranch(n, [a.id], id)!;
    // TON covers rows 0-1, so the branch row is 2 and the vertical link spans rows 0..2.
    expect(out.elements.filter((e) => e.kind === 'link').map((e) => `${e.row},${e.col}`)).toEqual(['2,0']);
    expect(out.vlinks).toEqual([
      { row: 0, boundary: 1 },
      { row: 1, boundary: 1 },
    ]);
    expect(loadable(out)).toBe(true);
  });
});

describe('variables and element updates through the store', () => {
  test('renaming a global renames references except in a POU that declares its own variable of that name', () => {
    const shadowing = newPou('Other', {
      variables: [variable('Lamp', 'BOOL')],
      networks: [newNetwork({ elements: [contact(0, 0, 'Lamp')] })],
    });
    const main = newPou('Main', { networks: [newNetwork({ elements: [contact(0, 0, 'Lamp')] })] });
    const store = createDocumentStore(
      newProject('p', { pous: [main, shadowing], globals: [variable('Lamp', 'BOOL')] }),
    );
    store.getState().updateVariable('Lamp', { name: 'Beacon' }, 'globals');
    const vars = (i: number) =>
      store
        .getState()
        .project.pous[i]!.networks[0]!.elements.map((e) => (e as { variable: string }).variable);
    expect(vars(0)).toEqual(['Beacon']);
    expect(vars(1)).toEqual(['Lamp']);
  });

  test('renaming an FB instance renames the box and Instance.Pin operands of other boxes', () => {
    const store = createDocumentStore(newProject('p'));
    const s = store.getState();
    const net = selectNetworks(s)[0]!.id;
    s.addVariable(variable('T1', 'TON'));
    s.placeElement(net, { row: 0, col: 0 }, TON);
    s.placeElement(
      net,
      { row: 2, col: 0 },
      { kind: 'box', blockType: 'MOVE', inputs: { IN: 'T1.ET' }, outputs: { OUT: 'Copy' } },
    );
    s.updateVariable('T1', { name: 'Delay' });
    const boxes = selectNetworks(store.getState())[0]!.elements.filter((e) => e.kind === 'box');
    expect(boxes.map((b) => (b.kind === 'box' ? [b.instance, b.inputs.IN] : []))).toEqual([
      ['Delay', undefined],
      [undefined, 'Delay.ET'],
    ]);
  });

  test('updating an element is one undo step and keeps its id and kind', () => {
    const store = createDocumentStore(newProject('p'));
    const net = selectNetworks(store.getState())[0]!.id;
    const el = store
      .getState()
      .placeElement(net, { row: 0, col: 0 }, { kind: 'coil', coil: 'COIL', variable: '' })!;
    store.getState().updateElement(el, { variable: 'Motor', coil: 'SET' });
    const after = selectNetworks(store.getState())[0]!.elements[0]!;
    expect(after).toMatchObject({ id: el, kind: 'coil', coil: 'SET', variable: 'Motor' });
    store.getState().undo();
    expect(selectNetworks(store.getState())[0]!.elements[0]).toMatchObject({ coil: 'COIL', variable: '' });
  });
});

describe('rows', () => {
  test('inserting a row moves the rows below down and extends vertical links through it', () => {
    const store = createDocumentStore(newProject('p'));
    const s = store.getState();
    const net = selectNetworks(s)[0]!.id;
    s.placeElement(net, { row: 0, col: 0 }, { kind: 'contact', contact: 'NO', variable: 'A' });
    s.placeElement(net, { row: 1, col: 0 }, { kind: 'contact', contact: 'NO', variable: 'B' });
    s.addVLink(net, { row: 0, boundary: 1 });
    s.insertRow(net, 1);
    const n = selectNetworks(store.getState())[0]!;
    expect(n.rows).toBe(4);
    expect(n.elements.map((e) => e.row)).toEqual([0, 2]);
    expect(n.vlinks).toEqual([
      { row: 0, boundary: 1 },
      { row: 1, boundary: 1 },
    ]);
    expect(store.getState().deleteRow(net, 1)).toBe(true);
    const back = selectNetworks(store.getState())[0]!;
    expect(back.elements.map((e) => e.row)).toEqual([0, 1]);
    expect(back.vlinks).toEqual([{ row: 0, boundary: 1 }]);
    expect(store.getState().deleteRow(net, 0)).toBe(false);
  });
});
