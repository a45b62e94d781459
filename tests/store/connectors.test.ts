// Connectors and continuations in the editor's store: the names new ones get, renaming a connector
// with its continuations as one undo step, the partners the hover text lists, and find/replace.
import { expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { newProject } from '../../src/model/factory';
import type { LdElement } from '../../src/model/elements';
import type { ElementId } from '../../src/model/ids';
import {
  defaultConnectionName,
  partnerWords,
  partnersOf,
  renameConnection,
  type ConnectionElement,
} from '../../src/store/connectors';
import { createDocumentStore, selectNetworks } from '../../src/store/documentStore';
import { copyElements, type ElementTemplate } from '../../src/store/networkEdits';
import { applyReplacements, findInProject, planReplace, type FindHit } from '../../src/store/find';

const CONNECTOR = { kind: 'connector', name: '' } as const;
const CONTINUATION = { kind: 'continuation', name: '' } as const;

function editor() {
  const store = createDocumentStore(newProject('t'));
  const net = () => selectNetworks(store.getState())[0]!;
  const place = (row: number, col: number, t: ElementTemplate) =>
    store.getState().placeElement(net().id, { row, col }, t)!;
  const el = (id: ElementId) => net().elements.find((e) => e.id === id) as ConnectionElement;
  const names = () =>
    net()
      .elements.filter((e): e is ConnectionElement => e.kind === 'connector' || e.kind === 'continuation')
      .sort((a, b) => a.row - b.row || a.col - b.col)
      .map((e) => `${e.kind === 'connector' ? '>' : '|>'}${e.name}${e.kind === 'connector' ? '>|' : '>'}`);
  return { store, net, place, el, names };
}

test('a new connector is named C1, C2…; a new continuation takes the name of the only connector nobody reads', () => {
  const e = editor();
  const a = e.place(0, 2, CONNECTOR);
  expect(e.el(a).name).toBe('C1');
  // One connector without continuation: the continuation pairs with it.
  const b = e.place(1, 0, CONTINUATION);
  expect(e.el(b).name).toBe('C1');
  const c = e.place(2, 2, CONNECTOR);
  expect(e.el(c).name).toBe('C2');
  const d = e.place(3, 0, CONTINUATION);
  expect(e.el(d).name).toBe('C2');
  // Every connector is read now, and two are: the user names the next continuation.
  const f = e.place(4, 0, CONTINUATION);
  expect(e.el(f).name).toBe('');
  // A name typed by the user is kept.
  const g = e.store.getState().placeElement(e.net().id, { row: 5, col: 2 }, { kind: 'connector', name: 'Fault' })!;
  expect(e.el(g).name).toBe('Fault');
  expect(e.names()).toEqual(['>C1>|', '|>C1>', '>C2>|', '|>C2>', '|>>', '>Fault>|']);
});

test('a connector name taken by a continuation alone is skipped (it would pair with it)', () => {
  const e = editor();
  e.store.getState().placeElement(e.net().id, { row: 0, col: 0 }, { kind: 'continuation', name: 'c1' });
  expect(defaultConnectionName(e.net(), 'connector')).toBe('C2');
});

test('renaming a connector renames its continuations as one undo step; unticked, only the connector', () => {
  const e = editor();
  const s = () => e.store.getState();
  const a = e.place(0, 2, CONNECTOR);
  e.place(1, 0, CONTINUATION);
  e.place(2, 0, CONTINUATION);
  s().updateElement(e.net().elements.find((x) => x.row === 2)!.id, { name: 'C1' });
  expect(e.names()).toEqual(['>C1>|', '|>C1>', '|>C1>']);
  const steps = s().history.undo.length;

  expect(renameConnection(e.store, a, 'Ready')).toBe(true);
  expect(e.names()).toEqual(['>Ready>|', '|>Ready>', '|>Ready>']);
  expect(s().history.undo.length).toBe(steps + 1);
  s().undo();
  expect(e.names()).toEqual(['>C1>|', '|>C1>', '|>C1>']);
  s().redo();
  expect(e.names()).toEqual(['>Ready>|', '|>Ready>', '|>Ready>']);

  renameConnection(e.store, a, 'Other', false);
  expect(e.names()).toEqual(['>Other>|', '|>Ready>', '|>Ready>']);
  // The continuations now read no connector: the checks say so (LD-R14).
  const errors = checkProject(s().project).filter((d) => d.rule === 'LD-R14');
  expect(errors.map((d) => d.severity)).toEqual(['warning', 'error', 'error']);
  expect(errors[1]!.message).toContain('has no connector of its name in this network');
});

test('renaming a continuation renames only it (it pairs with another connector)', () => {
  const e = editor();
  const a = e.place(0, 2, CONNECTOR);
  const b = e.place(1, 0, CONTINUATION);
  renameConnection(e.store, b, 'c9');
  expect(e.el(a).name).toBe('C1');
  expect(e.el(b).name).toBe('c9');
});

test('partners and the hover words: connector → continuations with their cells, continuation ← connector', () => {
  const e = editor();
  const a = e.place(0, 2, CONNECTOR);
  const b = e.place(2, 0, CONTINUATION);
  const c = e.place(3, 0, CONTINUATION);
  e.store.getState().updateElement(c, { name: 'c1' });
  const n = e.net();
  expect(partnersOf(n, e.el(a)).map((p) => p.id)).toEqual([b, c]);
  expect(partnerWords(n, e.el(a))).toBe('Connector >C1> → 2 continuations (R3C1, R4C1)');
  expect(partnerWords(n, e.el(b))).toBe('Continuation >C1> ← connector (R1C3)');
  e.store.getState().deleteElements(n.id, [b, c]);
  expect(partnerWords(e.net(), e.el(a))).toBe('Connector >C1> → no continuation');
});

test('find lists connector and continuation names (kind connector); replacing renames the pair', () => {
  const e = editor();
  e.place(0, 2, CONNECTOR);
  e.place(1, 0, CONTINUATION);
  const p = e.store.getState().project;
  const hits = findInProject(p, { text: 'C1', mode: 'word' }) as FindHit[];
  expect(hits.map((h) => [h.field, h.elementKind, h.row, h.col])).toEqual([
    ['connector', 'connector', 0, 2],
    ['connector', 'continuation', 1, 0],
  ]);
  expect(findInProject(p, { text: 'C1', mode: 'word', fields: ['variable'] })).toEqual([]);
  const plan = planReplace(p, { text: 'C1', mode: 'word', fields: ['connector'] }, 'Permit');
  expect(Array.isArray(plan) && plan.length).toBe(2);
  e.store.getState().replaceNetworks('replace', applyReplacements(p, plan as Exclude<typeof plan, string>));
  expect(e.names()).toEqual(['>Permit>|', '|>Permit>']);
});

test('unnamed elements of other kinds are not touched by the connector defaults', () => {
  const e = editor();
  const id = e.store.getState().placeElement(e.net().id, { row: 0, col: 0 }, { kind: 'jump', target: '' })!;
  expect((e.net().elements.find((x) => x.id === id) as LdElement & { target: string }).target).toBe('');
});

test('a copied pair pasted into the same network becomes a new pair (C2); into another network it keeps its name', () => {
  const e = editor();
  const s = () => e.store.getState();
  const a = e.place(0, 2, CONNECTOR);
  const b = e.place(1, 0, CONTINUATION);
  const pair = copyElements(e.net(), [a, b])!;
  s().pasteElements(e.net().id, pair, { row: 3, col: 0 });
  expect(e.names()).toEqual(['>C1>|', '|>C1>', '>C2>|', '|>C2>']);
  // A continuation pasted alone still reads the network's connector.
  s().pasteElements(e.net().id, copyElements(e.net(), [b])!, { row: 5, col: 0 });
  expect(e.names()).toEqual(['>C1>|', '|>C1>', '>C2>|', '|>C2>', '|>C1>']);
  expect(checkProject(s().project).filter((d) => d.rule === 'LD-R14')).toEqual([]);

  const other = s().addNetwork();
  s().pasteElements(other, pair, { row: 0, col: 0 });
  const names = selectNetworks(s())
    .find((n) => n.id === other)!
    .elements.map((x) => (x as ConnectionElement).name);
  expect(names).toEqual(['C1', 'C1']);
});
