// Tasks at several rates or on events: which programs run in a scan (ProgramRates), built once per
// compiled program. The scan cycle sets its flags at each tick (scanCycle.ts dueTasks) and skips
// the programs whose task is not due.
import type { CompiledProgram } from '../compile/program';
import type { TaskTrigger } from '../compile/taskTriggers';

/** Which programs run in a scan when the tasks run at several rates or on events. */
export interface ProgramRates {
  /** Per task (like schedule.tasks): ticks between runs (0: an event task) and its trigger. */
  readonly every: Int32Array;
  readonly triggers: readonly (TaskTrigger | undefined)[];
  /** Per task: due in this scan. */
  readonly taskDue: Uint8Array;
  /** Per program: its task, and whether it runs in this scan. */
  readonly taskOf: Int32Array;
  readonly due: Uint8Array;
  /** The program starting at each network (-1: none). */
  readonly startOf: Int32Array;
}

/** Several rates or event tasks: what decides which programs run in a scan; else undefined. */
export function programRates(program: CompiledProgram): ProgramRates | undefined {
  const { schedule, programTask } = program;
  if (!schedule?.multiRate || !programTask) return undefined;
  const startOf = new Int32Array(program.mainEnd).fill(-1);
  for (let p = 0; p < program.programs; p++) {
    const body = program.bodies[p]!;
    if (body.end > body.first) startOf[body.first] = p;
  }
  return {
    every: Int32Array.from(schedule.tasks, (t) => t.every),
    triggers: schedule.tasks.map((_, k) => program.triggers?.[k]),
    taskDue: new Uint8Array(schedule.tasks.length).fill(1),
    taskOf: programTask,
    due: new Uint8Array(program.programs).fill(1),
    startOf,
  };
}
