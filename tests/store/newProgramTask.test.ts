// A new PROGRAM runs where + Program says: a cyclic task of its own (T_<name>, 10 ms), an existing
// task, or none; one undo step; the task made for it follows a rename of the program.
import { expect, test } from 'vitest';
import { newProject } from '../../src/model/factory';
import { createDocumentStore } from '../../src/store/documentStore';
import { OWN_TASK_MS } from '../../src/store/pouCommands';
import { taskProblems } from '../../src/store/taskCommands';

const tasksOf = (t: { name: string; cycleMs: number; programs: { instance: string; pou: string }[] }[]) =>
  t.map((x) => `${x.name} ${x.cycleMs} ${x.programs.map((p) => `${p.instance}:${p.pou}`).join(',')}`);

test('its own task: T_<name>, cyclic 10 ms, running one instance; valid; one undo step takes both back', () => {
  const store = createDocumentStore(newProject('P'));
  const s = () => store.getState();
  const before = s().project.tasks;
  const steps = s().history.undo.length;
  s().addPou('PROGRAM', 'Conveyor', 'LD', { kind: 'own' });
  expect(tasksOf(s().project.tasks as never)).toEqual([...tasksOf(before as never), `T_Conveyor ${OWN_TASK_MS} ConveyorInstance:Conveyor`]);
  expect(taskProblems(s().project, s().project.tasks)).toEqual([]);
  expect(s().history.undo.length).toBe(steps + 1);
  s().undo();
  expect(s().project.tasks).toEqual(before);
  expect(s().project.pous.map((p) => p.name)).toEqual(['Main']);
});

test('renaming the program renames the task made for it, not a task that runs others too', () => {
  const store = createDocumentStore(newProject('P'));
  const s = () => store.getState();
  const id = s().addPou('PROGRAM', undefined, 'LD', { kind: 'own' })!;
  const name = s().project.pous.find((p) => p.id === id)!.name;
  expect(s().project.tasks.map((t) => t.name)).toContain(`T_${name}`);
  expect(s().renamePou(id, 'Filler')).toBe(true);
  expect(s().project.tasks.at(-1)).toMatchObject({ name: 'T_Filler', programs: [{ pou: 'Filler' }] });
  // MainTask runs Main only and is not called T_Main: it keeps its name.
  const main = s().project.pous.find((p) => p.name === 'Main')!.id;
  expect(s().renamePou(main, 'Plant')).toBe(true);
  expect(s().project.tasks[0]!.name).toBe('MainTask');
});

test('an existing task, or none; a task name already taken gets a number', () => {
  const store = createDocumentStore(newProject('P'));
  const s = () => store.getState();
  s().addPou('PROGRAM', 'A', 'LD', { kind: 'task', task: 0 });
  expect(s().project.tasks).toHaveLength(1);
  expect(s().project.tasks[0]!.programs.map((p) => p.pou)).toEqual(['Main', 'A']);
  s().addPou('PROGRAM', 'B', 'LD', { kind: 'none' });
  expect(s().project.tasks.flatMap((t) => t.programs.map((p) => p.pou))).not.toContain('B');
  s().addTask();
  s().setTasks(s().project.tasks.map((t, i) => (i === 1 ? { ...t, name: 'T_C' } : t)));
  s().addPou('PROGRAM', 'C', 'LD', { kind: 'own' });
  expect(s().project.tasks.map((t) => t.name)).toEqual(['MainTask', 'T_C', 'T_C2']);
});
