// The task configuration: tasks with interval and priority and the program instances they run,
// edited as one undo step each, refused with a reason when the result is not a valid configuration.
import { expect, test } from 'vitest';
import { newProject, variable } from '../../src/model/factory';
import { createDocumentStore } from '../../src/store/documentStore';
import { runOptions, programInstances } from '../../src/sim/runTarget';

function plant() {
  const store = createDocumentStore(newProject('Plant'));
  const s = () => store.getState();
  s().addPou('PROGRAM', 'Conveyor');
  s().addPou('FUNCTION_BLOCK', 'Motor');
  return { store, s };
}

test('a new project runs its program from one task; a second program added later runs too', () => {
  const { s } = plant();
  expect(s().project.tasks).toHaveLength(1);
  expect(programInstances(s().project).map((p) => p.pou)).toEqual(['Main', 'Conveyor']);
  expect(runOptions(s().project)).toEqual({ configuration: true });
});

test('interval, priority and name are edited in one undo step each; bad values are refused with the reason', () => {
  const { s } = plant();
  const task = s().project.tasks[0]!;
  expect(s().setTasks([{ ...task, cycleMs: 50, priority: 2 }])).toBeUndefined();
  expect(s().project.tasks[0]).toMatchObject({ cycleMs: 50, priority: 2 });
  s().undo();
  expect(s().project.tasks[0]).toMatchObject({ cycleMs: task.cycleMs, priority: task.priority });

  expect(s().setTasks([{ ...task, cycleMs: 0 }])?.message).toMatch(/interval is whole milliseconds from 1 ms/);
  expect(s().setTasks([{ ...task, priority: 300 }])?.message).toMatch(/priority is a whole number from 0 \(highest\) to 255/);
  expect(s().setTasks([{ ...task, name: '2fast' }])?.message).toMatch(/"2fast" is not an IEC identifier/);
  expect(s().project.tasks[0]).toEqual(task);
});

test('a task runs PROGRAMs only, each instance name once across tasks and apart from the globals', () => {
  const { s } = plant();
  s().addVariable(variable('Line', 'BOOL'), 'globals');
  const task = s().project.tasks[0]!;
  expect(s().setTasks([{ ...task, programs: [...task.programs, { instance: 'M1', pou: 'Motor' }] }])?.message).toBe(
    'M1: Motor is a FUNCTION_BLOCK; a task runs PROGRAMs only',
  );
  expect(s().setTasks([{ ...task, programs: [...task.programs, { instance: 'Line', pou: 'Main' }] }])?.message).toBe(
    'Line is the name of a global variable; a program instance needs a name of its own',
  );
  expect(s().addTask()).toBeUndefined();
  const [first, second] = s().project.tasks;
  expect(second).toMatchObject({ name: 'Task', cycleMs: 20, priority: 1, programs: [] });
  const clash = first!.programs[0]!.instance;
  expect(s().setTasks([first!, { ...second!, programs: [{ instance: clash, pou: 'Main' }] }])?.message).toBe(
    `The program instance ${clash} is already run by task ${first!.name}`,
  );
});

test('adding a program instance numbers the name when taken; the order in the task is the run order', () => {
  const { s } = plant();
  expect(s().addProgramInstance(0, 'Conveyor')).toBeUndefined();
  const names = s().project.tasks[0]!.programs.map((p) => p.instance);
  expect(names).toEqual(['MainInstance', 'ConveyorInstance', 'ConveyorInstance2']);
  const task = s().project.tasks[0]!;
  s().setTasks([{ ...task, programs: [...task.programs].reverse() }]);
  expect(programInstances(s().project).map((p) => p.instance)).toEqual([...names].reverse());
  s().undo();
  expect(programInstances(s().project).map((p) => p.instance)).toEqual(names);
});

test('deleting the only task leaves no program to run, which the simulator says rather than guessing', () => {
  const { s } = plant();
  expect(s().deleteTask(0)).toBeUndefined();
  expect(s().project.tasks).toEqual([]);
  expect(runOptions(s().project)).toEqual({});
});
