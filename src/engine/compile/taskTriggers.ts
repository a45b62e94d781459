// Event tasks (IEC 61131-3 `TASK E (SINGLE := StartPulse, PRIORITY := 0)`), as MATIEC compiles
// them (stage4/generate_c/generate_c.cc, generate_c_resources_c, task_initialization_c): the
// SINGLE variable is looked up among the resource's, then the configuration's globals (anything
// else stops the compiler), and the task gets an R_TRIG (`E_R_TRIG`, its M initialised FALSE) run
// once per tick before any program: `E_R_TRIG.CLK = StartPulse; R_TRIG_body__(&E_R_TRIG);
// E = E_R_TRIG.Q;`. The trigger's edge memory is a hidden BOOL of the program's memory, so history,
// snapshots and restarts treat it like the rest of the state (a restart clears it, as the
// runtime's init does).
import type { TaskSchedule } from '../api';
import type { Reporter } from './report';
import { SymbolTable, type VarSymbol } from './symbols';

/** An event task's trigger: the BOOL global it samples and the R_TRIG's memory M. */
export interface TaskTrigger {
  readonly clk: VarSymbol;
  readonly m: VarSymbol;
}

/**
 * The triggers of the schedule's event tasks (indexed like `schedule.tasks`; undefined for a cyclic
 * task), or undefined after reporting LD-E20 when one names no BOOL global, or when no task has an
 * interval (MATIEC: "You must define at least one periodic task (to set cycle period)!").
 */
export function taskTriggers(
  root: SymbolTable,
  schedule: TaskSchedule,
  r: Reporter,
): (TaskTrigger | undefined)[] | undefined {
  const events = schedule.tasks.filter((t) => t.single);
  if (events.length === 0) return [];
  let ok = true;
  if (schedule.tickMs <= 0) {
    ok = false;
    r.error(
      'LD-E20',
      `no task has an interval, so there is no tick to sample ${events.map((t) => t.single).join(', ')} on; MATIEC refuses such a configuration ("You must define at least one periodic task"): give ${events[0]!.name} an interval or add a cyclic task`,
    );
  }
  const hidden = new SymbolTable(root.storage, '', root.library, true);
  const triggers = schedule.tasks.map((t): TaskTrigger | undefined => {
    if (!t.single) return undefined;
    const sym = root.lookup(t.single);
    const what = !sym ? 'names no global variable' : sym.kind !== 'var' ? 'is not a BOOL variable' : sym.type !== 'BOOL' ? `is ${sym.type}, not BOOL` : '';
    if (what || sym?.kind !== 'var') {
      ok = false;
      r.error(
        'LD-E20',
        `task ${t.name}: its trigger ${t.single} ${what}; an event task runs on the rising edge of a BOOL global (MATIEC's SINGLE := reads a global of the configuration or resource)`,
      );
      return undefined;
    }
    const m = hidden.addVar(`${t.name}_R_TRIG.M`, 'BOOL', false, false, false, undefined, false, false);
    return { clk: sym, m };
  });
  return ok ? triggers : undefined;
}
