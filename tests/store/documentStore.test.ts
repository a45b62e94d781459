import { describe, expect, test } from 'vitest';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import { validateProject } from '../../src/model/load';
import type { NetworkId } from '../../src/model/ids';
import type { Project } from '../../src/model/project';
import { createDocumentStore, selectNetworks, type DocumentStore } from '../../src/store/documentStore';
import { createUiStore } from '../../src/store/uiStore';
import type { ElementTemplate } from '../../src/store/networkEdits';

const NO = (variable: string): ElementTemplate => ({ kind: 'contact', contact: 'NO', variable });
const NC = (variable: string): ElementTemplate => ({ kind: 'contact', contact: 'NC', variable });
const COIL = (variable: string): ElementTemplate => ({ kind: 'coil', coil: 'COIL', variable });

/** A small test editor: one store, the first network, helpers to read the grid as text. */
function editor(project: Project = newProject('t')) {
  const store = createDocumentStore(project);
  const s = () => store.getState();
  const net = () => selectNetworks(s())[0]!;
  const id = () => net().id;
  /** Row r as text: one token per cell ("-" link, "NO:Start", "." empty). */
  const row = (r: number) => {
    const n = net();
    const cells: string[] = [];
    for (let c = 0; c < n.cols; c++) {
      const el = n.elements.find((e) => e.row === r && e.col === c);
      cells.push(el ? token(el) : '.');
    }
    while (cells[cells.length - 1] === '.') cells.pop();
    return cells.join(' ');
  };
  const vlinks = () => [...net().vlinks].map((v) => `${v.row}|${v.boundary}`).sort();
  return { store, s, net, id, row, vlinks };
}

function token(el: LdElement): string {
  switch (el.kind) {
    case 'link':
      return '-';
    case 'contact':
      return `${el.contact}:${el.variable}`;
    case 'coil':
      return `(${el.coil}):${el.variable}`;
    case 'box':
      return `[${el.blockType}]`;
    case 'jump':
      return `>>${el.target}`;
    case 'return':
      return '<RET>';
    case 'connector':
    case 'continuation':
      return `>${el.name}>`;
  }
}

/** Start/stop seal-in: Start, /Stop, (Motor) on row 0, Motor in parallel with Start on row 1. */
function sealIn(e: ReturnType<typeof editor>) {
  const s = e.s();
  const start = s.placeElement(e.id(), { row: 0, col: 0 }, NO('Start'))!;
  s.placeElement(e.id(), { row: 0, col: 1 }, NC('Stop'));
  s.placeElement(e.id(), { row: 0, col: 9 }, COIL('Motor'));
  for (let c = 2; c < 9; c++) s.placeElement(e.id(), { row: 0, col: c }, { kind: 'link' });
  s.wrapInParallelBranch(e.id(), [start]);
  const motor = s.placeElement(e.id(), { row: 1, col: 0 }, NO('Motor'))!;
  return { start, motor };
}

const valid = (store: DocumentStore) =>
  validateProject(JSON.parse(JSON.stringify(store.getState().project))).ok;

describe('placing and inserting in series', () => {
  test('placing on an empty cell puts the element there and the document stays loadable', () => {
    const e = editor();
    const id = e.s().placeElement(e.id(), { row: 0, col: 2 }, NO('Start'));
    expect(id).toBeDefined();
    expect(e.row(0)).toBe('. . NO:Start');
    expect(e.s().dirty).toBe(true);
    expect(valid(e.store)).toBe(true);
  });

  test('placing on a horizontal link replaces the link without moving anything', () => {
    const e = editor();
    for (let c = 0; c < 3; c++) e.s().placeElement(e.id(), { row: 0, col: c }, { kind: 'link' });
    e.s().placeElement(e.id(), { row: 0, col: 1 }, NO('A'));
    expect(e.row(0)).toBe('- NO:A -');
  });

  test('placing between two elements inserts in series and shifts the rest of the row right', () => {
    const e = editor();
    e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'));
    e.s().placeElement(e.id(), { row: 0, col: 1 }, COIL('Q'));
    e.s().placeElement(e.id(), { row: 0, col: 1 }, NC('B'));
    expect(e.row(0)).toBe('NO:A NC:B (COIL):Q');
  });

  test('inserting at a full row grows the network by a column', () => {
    const e = editor();
    e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'));
    e.s().placeElement(e.id(), { row: 0, col: 9 }, COIL('Q'));
    e.s().insertInSeries(e.id(), { row: 0, col: 0 }, NO('X'));
    expect(e.net().cols).toBe(11);
    expect(e.row(0)).toBe('NO:X NO:A . . . . . . . . (COIL):Q');
    expect(valid(e.store)).toBe(true);
  });

  test('inserting before a contact in a branch keeps the parallel path with a link', () => {
    const e = editor();
    sealIn(e);
    e.s().insertInSeries(e.id(), { row: 0, col: 0 }, NO('Enable'));
    // Row 1 keeps its connection from the left rail to Motor through a new link.
    expect(e.row(0)).toBe('NO:Enable NO:Start NC:Stop - - - - - - - (COIL):Motor');
    expect(e.row(1)).toBe('- NO:Motor');
    expect(e.vlinks()).toEqual(['0|2']);
    expect(valid(e.store)).toBe(true);
  });

  test('inserting after a branch join leaves the vertical link on the left', () => {
    const e = editor();
    sealIn(e);
    e.s().insertInSeries(e.id(), { row: 0, col: 1 }, NC('EStop'));
    expect(e.row(0)).toBe('NO:Start NC:EStop NC:Stop - - - - - - - (COIL):Motor');
    expect(e.row(1)).toBe('NO:Motor');
    expect(e.vlinks()).toEqual(['0|1']);
  });
});

describe('parallel branch', () => {
  test('wrapping a selection adds a row below with links and vertical links at both ends in one step', () => {
    const e = editor();
    const s = e.s();
    s.placeElement(e.id(), { row: 0, col: 0 }, NO('A'));
    const b = s.placeElement(e.id(), { row: 0, col: 1 }, NO('B'))!;
    const c = s.placeElement(e.id(), { row: 0, col: 2 }, NO('C'))!;
    s.placeElement(e.id(), { row: 0, col: 3 }, COIL('Q'));
    const steps = e.s().history.undo.length;
    expect(e.s().wrapInParallelBranch(e.id(), [b, c])).toBe(true);
    expect(e.row(1)).toBe('. - -');
    expect(e.vlinks()).toEqual(['0|1', '0|3']);
    expect(e.s().history.undo.length).toBe(steps + 1);
    e.s().undo();
    expect(e.row(1)).toBe('');
    expect(e.vlinks()).toEqual([]);
  });

  test('a branch inserted above existing rows moves them down and extends vertical links through it', () => {
    const e = editor();
    const s = e.s();
    const a = s.placeElement(e.id(), { row: 0, col: 0 }, NO('A'))!;
    s.placeElement(e.id(), { row: 1, col: 0 }, NO('B'));
    s.addVLink(e.id(), { row: 0, boundary: 1 });
    s.wrapInParallelBranch(e.id(), [a]);
    expect(e.row(1)).toBe('-');
    expect(e.row(2)).toBe('NO:B');
    expect(e.vlinks()).toEqual(['0|1', '1|1']);
  });
});

describe('undo and redo', () => {
  test('every command is one step and undo then redo round-trips the document exactly', () => {
    const e = editor();
    const before = e.s().project;
    sealIn(e);
    e.s().addVariable(variable('Start', 'BOOL'));
    e.s().updateNetwork(e.id(), { title: 'Motor', label: 'M1', comment: 'seal-in' });
    const after = e.s().project;
    const steps = e.s().history.undo.length;
    for (let i = 0; i < steps; i++) e.s().undo();
    expect(e.s().project).toEqual(before);
    expect(e.s().canUndo).toBe(false);
    for (let i = 0; i < steps; i++) e.s().redo();
    expect(e.s().project).toEqual(after);
  });

  test('history stores diffs, not copies of the project', () => {
    const e = editor();
    e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'));
    const entry = e.s().history.undo[0]!;
    expect(entry.name).toBe('placeElement');
    expect(entry.changes.every((c) => !('project' in c))).toBe(true);
    expect(entry.changes.map((c) => c.type)).toContain('element.add');
  });

  test('a new command after undo clears redo; selection changes do not', () => {
    const e = editor();
    const ui = createUiStore();
    const a = e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'))!;
    e.s().placeElement(e.id(), { row: 0, col: 1 }, NO('B'));
    e.s().undo();
    const revision = e.s().revision;
    ui.getState().select(e.id(), [a]);
    ui.getState().setCursor({ network: e.id(), row: 0, col: 1 });
    expect(e.s().canRedo).toBe(true);
    expect(e.s().revision).toBe(revision);
    e.s().placeElement(e.id(), { row: 0, col: 2 }, NO('C'));
    expect(e.s().canRedo).toBe(false);
  });

  test('a drag of several elements is one undo step', () => {
    const e = editor();
    const a = e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'))!;
    const b = e.s().placeElement(e.id(), { row: 0, col: 1 }, NO('B'))!;
    const mark = e.s().mark();
    e.s().moveElements(e.id(), [a, b], 1, 1);
    e.s().moveElements(e.id(), [a, b], 0, 2);
    e.s().squash(mark, 'moveElements');
    expect(e.row(1)).toBe('. . . NO:A NO:B');
    e.s().undo();
    expect(e.row(0)).toBe('NO:A NO:B');
  });

  test('moving onto another element is refused and changes nothing', () => {
    const e = editor();
    const a = e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'))!;
    e.s().placeElement(e.id(), { row: 0, col: 1 }, NO('B'));
    const rev = e.s().revision;
    expect(e.s().moveElements(e.id(), [a], 0, 1)).toBe(false);
    expect(e.s().revision).toBe(rev);
  });

  test('batch groups several commands into one step', () => {
    const e = editor();
    e.s().batch('draw', () => {
      e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'));
      e.s().placeElement(e.id(), { row: 0, col: 1 }, COIL('Q'));
    });
    expect(e.s().history.undo.length).toBe(1);
    e.s().undo();
    expect(e.net().elements).toEqual([]);
  });
});

describe('delete, duplicate and paste', () => {
  test('delete removes the elements and undo puts them back in their place', () => {
    const e = editor();
    const { start } = sealIn(e);
    const before = e.net();
    e.s().deleteElements(e.id(), [start]);
    expect(e.row(0).startsWith('. NC:Stop')).toBe(true);
    e.s().undo();
    expect(e.net()).toEqual(before);
  });

  test('duplicate pastes a copy below the network content with new ids', () => {
    const e = editor();
    const a = e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'))!;
    const ids = e.s().duplicateElements(e.id(), [a]);
    expect(ids).toHaveLength(1);
    expect(ids[0]).not.toBe(a);
    expect(e.row(1)).toBe('NO:A');
  });

  test('paste into another network keeps relative positions and vertical links', async () => {
    const { copyElements } = await import('../../src/store/networkEdits');
    const second = newNetwork();
    const pou = newPou('Main', { networks: [newNetwork(), second] });
    const e = editor(newProject('p', { pous: [pou] }));
    const { start, motor } = sealIn(e);
    const clip = copyElements(e.net(), [start, motor])!;
    expect(clip.elements).toHaveLength(2);
    const target = second.id as NetworkId;
    const ids = e.s().pasteElements(target, clip, { row: 0, col: 3 });
    expect(ids).toHaveLength(2);
    const pasted = selectNetworks(e.s())[1]!.elements;
    expect(pasted.map((el) => `${el.row},${el.col}`).sort()).toEqual(['0,3', '1,3']);
  });

  test('pasting where elements are in the way goes below them', async () => {
    const { copyElements } = await import('../../src/store/networkEdits');
    const e = editor();
    const a = e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'))!;
    const clip = copyElements(e.net(), [a])!;
    e.s().pasteElements(e.id(), clip, { row: 0, col: 0 });
    expect(e.row(1)).toBe('NO:A');
  });
});

describe('networks and variables', () => {
  test('insert, move and delete networks, each undoable', () => {
    const e = editor();
    const first = e.id();
    const second = e.s().addNetwork({ title: 'Second' });
    const zero = e.s().insertNetwork(0, { title: 'Zero' });
    expect(selectNetworks(e.s()).map((n) => n.id)).toEqual([zero, first, second]);
    e.s().moveNetwork(0, 2);
    expect(selectNetworks(e.s()).map((n) => n.id)).toEqual([first, second, zero]);
    e.s().deleteNetwork(second);
    expect(selectNetworks(e.s()).map((n) => n.id)).toEqual([first, zero]);
    e.s().undo();
    e.s().undo();
    expect(selectNetworks(e.s()).map((n) => n.id)).toEqual([zero, first, second]);
  });

  test('clearing a network label removes it', () => {
    const e = editor();
    e.s().updateNetwork(e.id(), { label: 'L1' });
    expect(e.net().label).toBe('L1');
    e.s().updateNetwork(e.id(), { label: '' });
    expect('label' in e.net()).toBe(false);
  });

  test('renaming a variable renames its references, including Instance.Pin operands', () => {
    const e = editor();
    e.s().addVariable(variable('Start', 'BOOL'));
    e.s().addVariable(variable('T1', 'TON'));
    e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('Start'));
    e.s().placeElement(e.id(), { row: 1, col: 0 }, NO('T1.Q'));
    expect(e.s().addVariable(variable('start', 'INT'))).toBe(false);
    e.s().updateVariable('Start', { name: 'StartButton' });
    e.s().updateVariable('T1', { name: 'Delay' });
    expect(e.row(0)).toBe('NO:StartButton');
    expect(e.row(1)).toBe('NO:Delay.Q');
    e.s().undo();
    expect(e.row(1)).toBe('NO:T1.Q');
  });

  test('loading a project clears history and the unsaved flag', () => {
    const e = editor();
    e.s().placeElement(e.id(), { row: 0, col: 0 }, NO('A'));
    e.s().loadProject(newProject('other'));
    expect(e.s().canUndo).toBe(false);
    expect(e.s().dirty).toBe(false);
    expect(e.s().project.name).toBe('other');
  });
});
