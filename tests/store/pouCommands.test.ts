// POU commands: add, rename (references follow), duplicate, delete, properties; calls follow the
// callee's interface; each is one undo step.
import { expect, test } from 'vitest';
import type { BoxElement } from '../../src/model/elements';
import { newProject, variable } from '../../src/model/factory';
import type { PouId } from '../../src/model/ids';
import type { Project } from '../../src/model/project';
import { createDocumentStore, type DocumentStore } from '../../src/store/documentStore';
import { freshInstanceName, pouNameProblem, pouUsages, describeUse } from '../../src/store/pouEdits';

const pouByName = (p: Project, name: string) => p.pous.find((x) => x.name === name)!;

/** A project with an FB Motor (Start, Stop in; Run out) called twice from Main. */
function motorProject(): { store: DocumentStore; main: PouId; motor: PouId } {
  const store = createDocumentStore(newProject('Plant'));
  const s = () => store.getState();
  const main = s().activePouId;
  const motor = s().addPou('FUNCTION_BLOCK', 'Motor')!;
  s().addVariable(variable('Start', 'BOOL', { varClass: 'input' }), motor);
  s().addVariable(variable('Stop', 'BOOL', { varClass: 'input' }), motor);
  s().addVariable(variable('Run', 'BOOL', { varClass: 'output' }), motor);
  s().setActivePou(main);
  s().addVariable(variable('Motor1', 'Motor'));
  s().addVariable(variable('Motor2', 'Motor'));
  const net = pouByName(s().project, 'Main').networks[0]!.id;
  const box = (instance: string) =>
    ({
      kind: 'box',
      blockType: 'Motor',
      instance,
      inputs: { Start: 'B1', Stop: 'B2' },
      outputs: { Run: 'Lamp' },
    }) as const;
  s().placeElement(net, { row: 0, col: 1 }, box('Motor1'));
  s().placeElement(net, { row: 2, col: 1 }, box('Motor2'));
  s().placeElement(net, { row: 3, col: 0 }, { kind: 'contact', contact: 'NO', variable: 'Motor1.Run' });
  return { store, main, motor };
}

const boxes = (p: Project) =>
  pouByName(p, 'Main').networks[0]!.elements.filter((e): e is BoxElement => e.kind === 'box');

test('a new FB is opened in a tab; a new program gets a task instance; each is one undo step', () => {
  const store = createDocumentStore(newProject('P'));
  const s = () => store.getState();
  const fb = s().addPou('FUNCTION_BLOCK', 'Motor')!;
  expect(s().activePouId).toBe(fb);
  expect(s().openPouIds).toContain(fb);
  expect(pouByName(s().project, 'Motor').networks).toHaveLength(1);
  const prog = s().addPou('PROGRAM')!;
  const name = s().project.pous.find((p) => p.id === prog)!.name;
  expect(s().project.tasks[0]!.programs.map((x) => x.pou)).toEqual(['Main', name]);
  s().undo();
  expect(s().project.pous.map((p) => p.name)).toEqual(['Main', 'Motor']);
  expect(s().project.tasks[0]!.programs).toHaveLength(1);
  expect(s().activePouId).toBe(fb);
  expect(s().openPouIds).not.toContain(prog);
  const fn = s().addPou('FUNCTION', 'Scale')!;
  expect(s().project.pous.find((p) => p.id === fn)!.returnType).toBe('BOOL');
});

test('a POU name must be a free identifier, not a standard block or type', () => {
  const store = createDocumentStore(newProject('P'));
  const p = store.getState().project;
  expect(pouNameProblem(p, 'Main')).toMatch(/already has a program named Main/);
  expect(pouNameProblem(p, 'TON')).toMatch(/standard block/);
  expect(pouNameProblem(p, 'int')).toMatch(/type INT/);
  expect(pouNameProblem(p, '2Fast')).toMatch(/identifier/);
  expect(pouNameProblem(p, 'Motor')).toBeUndefined();
  expect(store.getState().addPou('FUNCTION_BLOCK', 'TON')).toBeUndefined();
});

test('renaming an FB renames its calls and instance types; undo restores all of it in one step', () => {
  const { store, motor } = motorProject();
  const s = () => store.getState();
  const before = s().project;
  expect(s().renamePou(motor, 'FB_Motor')).toBe(true);
  const p = s().project;
  expect(boxes(p).map((b) => b.blockType)).toEqual(['FB_Motor', 'FB_Motor']);
  expect(pouByName(p, 'Main').variables.map((v) => v.type)).toEqual(['FB_Motor', 'FB_Motor']);
  expect(s().undoName).toBe('renamePou');
  s().undo();
  expect(s().project).toEqual(before);
  expect(s().renamePou(motor, 'Main')).toBe(false);
});

test('renaming a program renames its task entry', () => {
  const store = createDocumentStore(newProject('P'));
  const s = () => store.getState();
  s().renamePou(s().activePouId, 'Conveyor');
  expect(s().project.tasks[0]!.programs).toEqual([{ instance: 'MainInstance', pou: 'Conveyor' }]);
});

test('where an FB is used: calls by POU and network, instances, and the next free instance name', () => {
  const { store } = motorProject();
  const p = store.getState().project;
  const uses = pouUsages(p, 'Motor').map(describeUse);
  expect(uses).toEqual([
    'Main, network 1 (Motor1)',
    'Main, network 1 (Motor2)',
    'Main: instance Motor1',
    'Main: instance Motor2',
  ]);
  expect(freshInstanceName(p, pouByName(p, 'Main'), 'Motor')).toBe('Motor3');
  expect(freshInstanceName(p, pouByName(p, 'Main'), 'FB_Pump')).toBe('Pump1');
});

test('deleting a POU removes it and its task entries; the last POU stays; undo brings it back', () => {
  const { store, motor, main } = motorProject();
  const s = () => store.getState();
  s().setActivePou(motor);
  expect(s().deletePou(motor)).toBe(true);
  expect(s().project.pous.map((p) => p.name)).toEqual(['Main']);
  expect(s().activePouId).toBe(main);
  expect(s().openPouIds).toEqual([main]);
  // Calls stay (the checks report the unknown block); the instances keep their type.
  expect(boxes(s().project)).toHaveLength(2);
  expect(s().deletePou(main)).toBe(false);
  s().undo();
  expect(pouByName(s().project, 'Motor').variables).toHaveLength(3);
  s().renamePou(main, 'Cell');
  s().addPou('PROGRAM', 'Other');
  expect(s().deletePou(pouByName(s().project, 'Cell').id)).toBe(true);
  expect(s().project.tasks[0]!.programs.map((x) => x.pou)).toEqual(['Other']);
});

test('duplicating a POU gives a copy with new ids, opened', () => {
  const { store, motor } = motorProject();
  const s = () => store.getState();
  const copy = s().duplicatePou(motor)!;
  const a = pouByName(s().project, 'Motor');
  const b = s().project.pous.find((p) => p.id === copy)!;
  expect(b.name).toBe('Motor_copy');
  expect(b.variables).toEqual(a.variables);
  expect(b.networks[0]!.id).not.toBe(a.networks[0]!.id);
  expect(s().activePouId).toBe(copy);
  expect(s().duplicatePou(motor)).toBeDefined();
  expect(s().project.pous.map((p) => p.name)).toContain('Motor_copy1');
});

test('renaming an FB input renames the operand on every call and Instance.Pin uses; undo restores', () => {
  const { store, motor } = motorProject();
  const s = () => store.getState();
  s().updateVariable('Run', { name: 'Running' }, motor);
  expect(boxes(s().project).map((b) => b.outputs)).toEqual([{ Running: 'Lamp' }, { Running: 'Lamp' }]);
  const contact = pouByName(s().project, 'Main').networks[0]!.elements.find((e) => e.kind === 'contact');
  expect(contact).toMatchObject({ variable: 'Motor1.Running' });
  s().updateVariable('Start', { name: 'Go' }, motor);
  expect(boxes(s().project).map((b) => b.inputs)).toEqual([
    { Go: 'B1', Stop: 'B2' },
    { Go: 'B1', Stop: 'B2' },
  ]);
  s().undo();
  s().undo();
  expect(boxes(s().project).map((b) => b.outputs)).toEqual([{ Run: 'Lamp' }, { Run: 'Lamp' }]);
  expect(
    pouByName(s().project, 'Main').networks[0]!.elements.find((e) => e.kind === 'contact'),
  ).toMatchObject({
    variable: 'Motor1.Run',
  });
});

test('a new input grows every call; the network makes room below a box that would cover others', () => {
  const { store, motor } = motorProject();
  const s = () => store.getState();
  // Motor1 at row 0 covers rows 0-1; Motor2 sits at row 2: a third input needs row 2 for Motor1.
  s().addVariable(variable('Reset', 'BOOL', { varClass: 'input' }), motor);
  const [m1, m2] = boxes(s().project);
  expect(m1!.row).toBe(0);
  expect(m2!.row).toBe(3);
  const contact = pouByName(s().project, 'Main').networks[0]!.elements.find((e) => e.kind === 'contact')!;
  expect(contact.row).toBe(4);
  expect(pouByName(s().project, 'Main').networks[0]!.rows).toBeGreaterThanOrEqual(6);
  expect(s().undoName).toBe('addVariable');
  s().undo();
  expect(boxes(s().project).map((b) => b.row)).toEqual([0, 2]);
});

test("a function's return type is a property; only functions have one", () => {
  const store = createDocumentStore(newProject('P'));
  const s = () => store.getState();
  const fn = s().addPou('FUNCTION', 'Scale')!;
  expect(s().updatePou(fn, { returnType: 'REAL' })).toBe(true);
  expect(s().project.pous.find((p) => p.id === fn)!.returnType).toBe('REAL');
  s().updatePou(fn, { kind: 'FUNCTION_BLOCK' });
  expect(s().project.pous.find((p) => p.id === fn)).not.toHaveProperty('returnType');
  s().undo();
  expect(s().project.pous.find((p) => p.id === fn)!.returnType).toBe('REAL');
});

test('tabs: opening adds a tab, closing shows the neighbour, the last tab stays', () => {
  const store = createDocumentStore(newProject('P'));
  const s = () => store.getState();
  const main = s().activePouId;
  const fb = s().addPou('FUNCTION_BLOCK', 'Motor')!;
  s().setActivePou(main);
  expect(s().openPouIds).toEqual([main, fb]);
  s().setActivePou(fb);
  s().closePou(fb);
  expect(s().openPouIds).toEqual([main]);
  expect(s().activePouId).toBe(main);
  s().closePou(main);
  expect(s().openPouIds).toEqual([main]);
});
