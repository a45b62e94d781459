// Which program the simulator runs: the project's task configuration, never "whatever tab is open".
// Several program instances in the tasks run as a configuration (each task at its own interval on
// their common tick, instances in declaration order, variables named `Instance.Var`); one instance
// runs its program; no task runs the first PROGRAM.
import type { CompileOptions } from '../engine/api';
import type { Project } from '../model/project';

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
  if (instances.length > 1) return { configuration: true };
  if (instances.length === 1) return { pou: instances[0]!.pou };
  return {};
}
