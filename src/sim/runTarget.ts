// Which program the simulator runs: the project's task configuration, never "whatever tab is open".
// Several program instances in the tasks, or an event task, run as a configuration (each task at its
// own interval on their common tick or on its trigger, instances in declaration order, variables
// named `Instance.Var`); one instance of a cyclic task runs its program; no task runs the first
// PROGRAM.
import type { CompileOptions } from '../engine/api';
import type { Project } from '../model/project';
import { hasEventTask } from '../engine/compile/taskSchedule';

export interface ProgramInstance {
  readonly instance: string;
  readonly pou: string;
}

/** The program instances of the project's tasks, in task order. */
export const programInstances = (project: Project): ProgramInstance[] =>
  project.tasks.flatMap((t) => t.programs.map((p) => ({ instance: p.instance, pou: p.pou })));

/** The compile options that run what the project's tasks say. */
export function runOptions(project: Project): Pick<CompileOptions, 'pou' | 'configuration'> {
  const instances = programInstances(project);
  // An event task's program runs only on its trigger's rising edge: only the configuration says so.
  if (instances.length > 1 || hasEventTask(project.tasks)) return { configuration: true };
  if (instances.length === 1) return { pou: instances[0]!.pou };
  return {};
}
