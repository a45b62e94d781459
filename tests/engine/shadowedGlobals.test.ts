// LD-W05: a POU variable named like a global hides it inside the POU; the check says so, located
// at the POU's variables, naming the POU, the variable and its class. A VAR_EXTERNAL (the global
// itself) and a POU without such a name get nothing.
import { expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { newPou, newProject, variable } from '../../src/model/factory';

const project = newProject('Shadow', {
  globals: [variable('Start', 'BOOL', { location: '%IX0.0' }), variable('Count', 'INT')],
  pous: [
    {
      ...newPou('Main'),
      variables: [variable('start', 'BOOL'), variable('Count', 'INT', { varClass: 'external' })],
    },
    {
      ...newPou('Conveyor', { kind: 'FUNCTION_BLOCK' }),
      variables: [variable('Count', 'INT', { varClass: 'input' })],
    },
    { ...newPou('Other'), variables: [variable('Motor', 'BOOL')] },
  ],
});

test('LD-W05 names the POU, the variable, its class and the global it hides; externals are not warned', () => {
  const shadows = checkProject(project).filter((d) => d.rule === 'LD-W05');
  expect(shadows).toHaveLength(2);
  expect(shadows[0]).toMatchObject({ severity: 'warning', pou: 'Main', network: -1 });
  expect(shadows[0]!.message).toMatch(
    /^the VAR variable "start" of Main has the name of the global variable Start/,
  );
  expect(shadows[1]).toMatchObject({ severity: 'warning', pou: 'Conveyor', network: -1 });
  expect(shadows[1]!.message).toContain('the VAR_INPUT variable "Count" of Conveyor');
  expect(shadows[1]!.message).toContain('declare it VAR_EXTERNAL');
});

test('no global of that name, no warning', () => {
  const { globals: _g, ...rest } = project;
  expect(checkProject({ ...rest, globals: [] }).filter((d) => d.rule === 'LD-W05')).toEqual([]);
});
