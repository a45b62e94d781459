// The Tasks dialog's "Runs on rising edge of" field: a task becomes an event task on a BOOL global
// (one undo step), back to cyclic when cleared; a trigger that is no BOOL global is refused with the
// reason, and an event task may have no interval.
import { expect, test } from 'vitest';
import { taskSchedule, describeSchedule } from '../../src/engine/compile/taskSchedule';
import { newProject, variable } from '../../src/model/factory';
import { runOptions } from '../../src/sim/runTarget';
import { loadProject, saveProject } from '../../src/model/load';
import { createDocumentStore } from '../../src/store/documentStore';
import { triggerCandidates, withTrigger } from '../../src/store/taskCommands';

function plant() {
  const store = createDocumentStore(newProject('Plant'));
  const s = () => store.getState();
  s().addVariable(variable('StartPulse', 'BOOL'), 'globals');
  s().addVariable(variable('Level', 'INT'), 'globals');
  s().addPou('PROGRAM', 'OnStart');
  s().addTask();
  s().addProgramInstance(1, 'OnStart');
  return s;
}

test('the field offers the BOOL globals; choosing one makes an event task in one undo step, clearing it makes it cyclic again', () => {
  const s = plant();
  expect(triggerCandidates(s().project)).toEqual(['StartPulse']);
  const before = s().project.tasks;
  expect(s().setTasks(before.map((t, i) => (i === 1 ? withTrigger(t, 'StartPulse') : t)))).toBeUndefined();
  expect(s().project.tasks[1]).toEqual({ ...before[1], single: 'StartPulse' });
  expect(describeSchedule(taskSchedule(s().project.tasks))).toBe('MainTask runs every tick (10 ms); Task runs when StartPulse rises');
  expect(runOptions(s().project)).toEqual({ configuration: true });
  s().undo();
  expect(s().project.tasks).toEqual(before);
  s().redo();
  expect(s().project.tasks[1]!.single).toBe('StartPulse');
  expect(s().setTasks(s().project.tasks.map((t) => withTrigger(t, '')))).toBeUndefined();
  expect(s().project.tasks).toEqual(before);
  expect('single' in s().project.tasks[1]!).toBe(false);
});

test('a trigger that is not a BOOL global is refused with the reason; an event task may have no interval, a cyclic one may not', () => {
  const s = plant();
  const tasks = s().project.tasks;
  const on = (single: string, cycleMs = 20) => tasks.map((t, i) => (i === 1 ? { ...withTrigger(t, single), cycleMs } : t));
  expect(s().setTasks(on('Level'))).toMatchObject({ task: 1, field: 'single', message: 'Task: Level is INT; an event task runs on the rising edge of a BOOL global' });
  expect(s().setTasks(on('Nowhere'))).toMatchObject({ field: 'single', message: 'Task: Nowhere is not a global variable; an event task runs on the rising edge of a BOOL global' });
  expect(s().project.tasks).toEqual(tasks);
  expect(s().setTasks(on('StartPulse', 0))).toBeUndefined();
  expect(s().project.tasks[1]).toMatchObject({ cycleMs: 0, single: 'StartPulse' });
  expect(s().setTasks(s().project.tasks.map((t) => withTrigger(t, undefined)))).toMatchObject({ task: 1, field: 'cycleMs' });
});

test('an event task is saved and loaded with its trigger; a cyclic task without an interval is refused on load', () => {
  const s = plant();
  s().setTasks(s().project.tasks.map((t, i) => (i === 1 ? { ...withTrigger(t, 'StartPulse'), cycleMs: 0 } : t)));
  const loaded = loadProject(saveProject(s().project));
  expect(loaded.ok && loaded.project.tasks).toEqual(s().project.tasks);
  const bad = JSON.parse(saveProject(s().project)) as { tasks: { single?: string }[] };
  delete bad.tasks[1]!.single;
  const refused = loadProject(JSON.stringify(bad));
  expect(refused.ok ? [] : refused.errors).toEqual([
    { path: 'tasks[1].cycleMs', message: 'a cyclic task needs an interval above 0 ms (only an event task, with "single", may have none)' },
  ]);
});
