// Declaring a new name as a global from where it is typed (canvas or inspector): the offers list the
// POU's own declarations first, then global ones (with the I/O address in a program); a global goes
// to the project's globals, with a VAR_EXTERNAL in the POU where the project names its globals that
// way (OpenPLC, whose MATIEC build requires it, or a POU that already has externals); one undo step.
import { expect, test } from 'vitest';
import { declareChoice, declareChoices, needsExternal, typedDeclaration } from '../../src/editor/inspector/declareOffer';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { createDocumentStore } from '../../src/store/documentStore';

const plant = (extra: Partial<Project> = {}): Project =>
  newProject('Plant', {
    globals: [variable('Start', 'BOOL', { location: '%IX0.0' })],
    pous: [
      newPou('Main'),
      newPou('Conveyor', { kind: 'FUNCTION_BLOCK' }),
      newPou('Permit', { kind: 'FUNCTION' }),
    ],
    ...extra,
  });

test('in a program a coil offers local and global declarations, the global one also at the next free output', () => {
  const project = plant();
  const labels = declareChoices(project, 'Motor', { kind: 'coil' }, project.pous[0]).map((c) => c.label);
  expect(labels).toEqual([
    'BOOL',
    'BOOL output at %QX0.0',
    'BOOL memory at %MX0.0',
    'BOOL global (VAR_GLOBAL)',
    'BOOL global at %QX0.0 (VAR_GLOBAL)',
  ]);
});

test('inside a function block: VAR_INPUT, VAR_IN_OUT, VAR_OUTPUT, VAR, then global; a box pin gets the pin type', () => {
  const project = plant();
  const fb = project.pous[1]!;
  expect(declareChoices(project, 'Run', { kind: 'contact' }, fb).map((c) => c.label)).toEqual([
    'BOOL input (VAR_INPUT)',
    'BOOL in-out (VAR_IN_OUT)',
    'BOOL output (VAR_OUTPUT)',
    'BOOL local (VAR)',
    'BOOL global (VAR_GLOBAL)',
  ]);
  const pin = declareChoices(project, 'Preset', { kind: 'pin', direction: 'input', pinType: 'TIME' }, fb);
  expect(pin.at(-1)).toMatchObject({ global: true, variable: { name: 'Preset', type: 'TIME' } });
});

test('VAR_EXTERNAL is added where the project names its globals that way, never in a function', () => {
  const iec = plant();
  expect(needsExternal(iec, iec.pous[0]!)).toBe(false);
  const withExternal = { ...iec.pous[0]!, variables: [variable('Start', 'BOOL', { varClass: 'external' })] };
  expect(needsExternal(iec, withExternal)).toBe(true);
  const openplc = plant({ profile: 'openplc' });
  expect(needsExternal(openplc, openplc.pous[1]!)).toBe(true);
  expect(needsExternal(openplc, openplc.pous[2]!)).toBe(false);
  expect(declareChoices(openplc, 'Run', { kind: 'contact' }, openplc.pous[1]).at(-1)?.label).toBe(
    'BOOL global + VAR_EXTERNAL in Conveyor',
  );
});

test('declaring a global with its VAR_EXTERNAL is one undo step; a local one stays in the POU', () => {
  const doc = createDocumentStore(plant({ profile: 'openplc' }));
  const project = doc.getState().project;
  const fb = project.pous[1]!;
  const choice = declareChoices(project, 'Alarm', { kind: 'coil' }, fb).find((c) => c.global)!;
  expect(declareChoice(doc.getState(), choice, fb.id)).toBe(true);
  const after = doc.getState().project;
  expect(after.globals.map((g) => g.name)).toEqual(['Start', 'Alarm']);
  expect(after.pous[1]!.variables).toEqual([
    { name: 'Alarm', type: 'BOOL', varClass: 'external', retain: false, comment: '' },
  ]);
  doc.getState().undo();
  expect(doc.getState().project.globals.map((g) => g.name)).toEqual(['Start']);
  expect(doc.getState().project.pous[1]!.variables).toEqual([]);
  const local = declareChoices(project, 'Busy', { kind: 'coil' }, fb)[0]!;
  declareChoice(doc.getState(), local, fb.id);
  expect(doc.getState().project.pous[1]!.variables.map((v) => [v.name, v.varClass])).toEqual([
    ['Busy', 'output'],
  ]);
  expect(doc.getState().project.globals).toHaveLength(1);
});

test('a global name already taken is refused and nothing is added', () => {
  const doc = createDocumentStore(plant());
  const project = doc.getState().project;
  const choice = { label: 'BOOL global', variable: variable('start', 'BOOL'), global: true, external: true };
  expect(declareChoice(doc.getState(), choice, project.pous[0]!.id)).toBe(false);
  expect(doc.getState().project.pous[0]!.variables).toEqual([]);
});

test('"Speed : INT" typed in a name field declares Speed with the type written; an unknown type offers nothing', () => {
  const project = plant();
  expect(typedDeclaration(project, 'Speed : int')).toEqual({ name: 'Speed', type: 'INT' });
  expect(typedDeclaration(project, 'T1:ton;')).toEqual({ name: 'T1', type: 'TON' });
  expect(typedDeclaration(project, 'Speed : FLOAT')).toBeUndefined();
  expect(typedDeclaration(project, 'Speed')).toBeUndefined();
  const pin = { kind: 'pin', direction: 'output', pinType: 'ANY_NUM' } as const;
  const choices = declareChoices(project, 'Speed', pin, project.pous[0], 'DINT');
  expect(choices.map((c) => c.label)).toEqual([
    'DINT',
    'DINT output at %QD0',
    'DINT memory at %MD0',
    'DINT global (VAR_GLOBAL)',
    'DINT global at %QD0 (VAR_GLOBAL)',
  ]);
});
