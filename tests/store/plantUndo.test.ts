// Choosing the machine and rewiring its points in the Plant panel are undo steps of their own
// (issue 26): Undo right after changing an address takes that address back, not the edit before
// it, and Redo gives it again; choosing None and undoing gives the machine and its map back.
import { expect, test } from 'vitest';
import { newProject, variable } from '../../src/model/factory';
import { createDocumentStore } from '../../src/store/documentStore';

function store() {
  const doc = createDocumentStore(newProject('t'));
  const main = doc.getState().project.pous[0]!.id;
  return { doc, s: () => doc.getState(), main };
}

test('an address changed in the I/O map is undone by the next Undo, not the edit before it', () => {
  const { s, main } = store();
  s().setPlant({ id: 'tank' }, 'Choose the machine tank');
  s().addVariables([variable('Extra', 'BOOL')], 'Add Extra', main);
  s().setPlant({ id: 'tank', map: { Pump: '%QX1.0' } }, 'Change the address of Pump');
  expect(s().undoName).toBe('Change the address of Pump');
  s().undo();
  expect(s().project.plant).toEqual({ id: 'tank' });
  // The variable added before is still there.
  expect(s().project.pous[0]!.variables.map((v) => v.name)).toEqual(['Extra']);
  s().redo();
  expect(s().project.plant).toEqual({ id: 'tank', map: { Pump: '%QX1.0' } });
  expect(s().dirty).toBe(true);
});

test('choosing None is undone back to the machine with its map; undoing the first choice leaves no machine', () => {
  const { s } = store();
  s().setPlant({ id: 'mixer' }, 'Choose the machine mixer');
  s().setPlant({ id: 'mixer', map: { Heater: '%QX1.6' } }, 'Change the address of Heater');
  s().setPlant(undefined, 'Choose no machine');
  expect(s().project.plant).toBe(undefined);
  expect('plant' in s().project).toBe(false);
  s().undo();
  expect(s().project.plant).toEqual({ id: 'mixer', map: { Heater: '%QX1.6' } });
  s().undo();
  s().undo();
  expect('plant' in s().project).toBe(false);
  expect(s().canUndo).toBe(false);
});

test('choosing the machine already chosen is no step', () => {
  const { s } = store();
  s().setPlant({ id: 'lift' });
  s().setPlant({ id: 'lift' });
  expect(s().history.undo.length).toBe(1);
});
