// The project's tasks (IEC 61131-3 configuration: TASK with INTERVAL or SINGLE and PRIORITY, and
// the PROGRAM instances WITH each task): the checks a PLCopen configuration must pass, and the
// commands that edit them. A command whose result would break a check changes nothing and says why; each is one undo
// step (one 'tasks.update' change).
import { IDENTIFIER_RE } from '../model/iecTypes';
import type { Project, Task } from '../model/project';
import type { Change } from './changes';

const same = (a: string, b: string) => a.trim().toUpperCase() === b.trim().toUpperCase();

/** A problem of the task list, located by task (and program instance) index. */
export interface TaskProblem {
  readonly task: number;
  readonly program?: number;
  readonly field: 'name' | 'cycleMs' | 'single' | 'priority' | 'instance' | 'pou';
  readonly message: string;
}

const isIdentifier = (name: string) => IDENTIFIER_RE.test(name) && !name.includes('__') && !name.endsWith('_');

/** Everything wrong with `tasks` for this project, in task order. */
export function taskProblems(project: Project, tasks: readonly Task[]): TaskProblem[] {
  const out: TaskProblem[] = [];
  const instances = new Map<string, string>();
  tasks.forEach((t, ti) => {
    const name = t.name.trim();
    if (!isIdentifier(name)) out.push({ task: ti, field: 'name', message: `"${t.name}" is not an IEC identifier; a task needs a name like Fast or MainTask` });
    else if (tasks.some((o, k) => k < ti && same(o.name, name))) out.push({ task: ti, field: 'name', message: `Another task is already called ${name}` });
    // An event task may have no interval (0): it runs on its trigger; one it has counts in the tick.
    if (!Number.isInteger(t.cycleMs) || t.cycleMs < (t.single ? 0 : 1) || t.cycleMs > 3_600_000)
      out.push({
        task: ti,
        field: 'cycleMs',
        message: `${name || 'The task'}: the interval is whole milliseconds from 1 ms to 1 h (T#1ms .. T#1h)${t.single ? ', or none for an event task' : ''}`,
      });
    if (t.single !== undefined) {
      const g = project.globals.find((v) => same(v.name, t.single!));
      if (!g || g.type.trim().toUpperCase() !== 'BOOL')
        out.push({
          task: ti,
          field: 'single',
          message: `${name || 'The task'}: ${t.single} ${g ? `is ${g.type}` : 'is not a global variable'}; an event task runs on the rising edge of a BOOL global`,
        });
    }
    if (!Number.isInteger(t.priority) || t.priority < 0 || t.priority > 255)
      out.push({ task: ti, field: 'priority', message: `${name || 'The task'}: the priority is a whole number from 0 (highest) to 255` });
    t.programs.forEach((p, pi) => {
      const inst = p.instance.trim();
      if (!isIdentifier(inst)) out.push({ task: ti, program: pi, field: 'instance', message: `"${p.instance}" is not an IEC identifier for a program instance` });
      else if (instances.has(inst.toUpperCase()))
        out.push({ task: ti, program: pi, field: 'instance', message: `The program instance ${inst} is already run by task ${instances.get(inst.toUpperCase())}` });
      else if (project.globals.some((g) => same(g.name, inst)))
        out.push({ task: ti, program: pi, field: 'instance', message: `${inst} is the name of a global variable; a program instance needs a name of its own` });
      else instances.set(inst.toUpperCase(), name);
      const pou = project.pous.find((x) => same(x.name, p.pou));
      if (!pou) out.push({ task: ti, program: pi, field: 'pou', message: `${inst}: the project has no POU called ${p.pou}` });
      else if (pou.kind !== 'PROGRAM') out.push({ task: ti, program: pi, field: 'pou', message: `${inst}: ${pou.name} is a ${pou.kind === 'FUNCTION' ? 'FUNCTION' : 'FUNCTION_BLOCK'}; a task runs PROGRAMs only` });
    });
  });
  return out;
}

/** `task` run on the rising edge of the BOOL global `single`, or cyclic when it is empty. */
export function withTrigger(task: Task, single: string | undefined): Task {
  const { single: _old, ...cyclic } = task;
  return single ? { ...cyclic, single } : cyclic;
}

/** The project's BOOL globals: what an event task can run on. */
export const triggerCandidates = (project: Project): string[] =>
  project.globals.filter((g) => g.type.trim().toUpperCase() === 'BOOL').map((g) => g.name);

/** A name like `base`, `base2`, ... that `taken` does not hold (case-insensitive). */
function fresh(base: string, taken: Iterable<string>): string {
  const used = new Set([...taken].map((n) => n.toUpperCase()));
  if (!used.has(base.toUpperCase())) return base;
  for (let i = 2; ; i++) if (!used.has(`${base}${i}`.toUpperCase())) return `${base}${i}`;
}

export interface TaskCommandOps {
  project(): Project;
  commit(name: string, changes: readonly Change[]): void;
}

export interface TaskCommands {
  /** Replaces the task list when it passes every check; else changes nothing and returns the first problem. */
  setTasks(tasks: readonly Task[]): TaskProblem | undefined;
  /** A new task `Task2`… at 20 ms, priority 1, running nothing yet. */
  addTask(): TaskProblem | undefined;
  deleteTask(index: number): TaskProblem | undefined;
  /** Adds an instance of program `pou` to task `index` (`<pou>Instance`, numbered when taken). */
  addProgramInstance(index: number, pou: string): TaskProblem | undefined;
}

export function taskCommands({ project, commit }: TaskCommandOps): TaskCommands {
  const set = (name: string, tasks: readonly Task[]): TaskProblem | undefined => {
    const p = project();
    const problem = taskProblems(p, tasks)[0];
    if (problem) return problem;
    commit(name, [{ type: 'tasks.update', before: p.tasks, after: tasks }]);
    return undefined;
  };
  return {
    setTasks: (tasks) => set('setTasks', tasks),
    addTask: () => {
      const p = project();
      const name = fresh(p.tasks.length ? 'Task' : 'MainTask', p.tasks.map((t) => t.name));
      return set('addTask', [...p.tasks, { name, cycleMs: 20, priority: 1, programs: [] }]);
    },
    deleteTask: (index) => set('deleteTask', project().tasks.filter((_, i) => i !== index)),
    addProgramInstance: (index, pou) => {
      const p = project();
      const taken = [...p.tasks.flatMap((t) => t.programs.map((x) => x.instance)), ...p.globals.map((g) => g.name)];
      const instance = fresh(`${pou}Instance`, taken);
      return set(
        'addProgramInstance',
        p.tasks.map((t, i) => (i === index ? { ...t, programs: [...t.programs, { instance, pou }] } : t)),
      );
    },
  };
}
