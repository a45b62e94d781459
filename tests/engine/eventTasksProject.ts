// Test helper: a configuration with a cyclic task and an event task (PLCopen `single`, IEC
// `SINGLE :=`). Cyc (task Cyclic, 10 ms) counts its runs in N, appends 1 to the global Trace and
// copies the global Go to the trigger StartPulse; Ev (task E, runs when StartPulse rises) counts its
// runs in N, appends 2 and toggles the lamp %QX0.0.
import { newProject } from '../../src/model/factory';
import type { Project, Task } from '../../src/model/project';
import { ladder, vars } from './ladder';
import { append, twoIn } from './taskRatesProject';
import { io, pou } from './userBlocksHelpers';

const cyc = () =>
  pou('Cyc', 'PROGRAM', [...vars('N DINT'), ...io('external', 'Trace DINT', 'Go BOOL', 'StartPulse BOOL')], [
    twoIn('ADD', 'N', '1'),
    ...append('1'),
    ladder(['[Go] (StartPulse)']),
  ]);

const ev = () =>
  pou('Ev', 'PROGRAM', [...vars('N DINT', 'Lamp BOOL %QX0.0'), ...io('external', 'Trace DINT')], [
    twoIn('ADD', 'N', '1'),
    ...append('2'),
    ladder(['[/Lamp] (Lamp)']),
  ]);

export interface EventOptions {
  /** Declare the event task first. */
  readonly eventFirst?: boolean;
  /** The event task's trigger (default StartPulse). */
  readonly single?: string;
  /** The event task's interval (default 0: none). */
  readonly eventMs?: number;
  /** The cyclic task's interval (default 10). */
  readonly cyclicMs?: number;
  /** StartPulse's initial value. */
  readonly pulseInitial?: boolean;
  /** Leave the cyclic task out (its program is not run). */
  readonly noCyclic?: boolean;
}

/** Instances C (program Cyc, task Cyclic) and V (program Ev, task E). */
export function eventProject(opts: EventOptions = {}): Project {
  const cyclic: Task = { name: 'Cyclic', cycleMs: opts.cyclicMs ?? 10, priority: 1, programs: [{ instance: 'C', pou: 'Cyc' }] };
  const event: Task = { name: 'E', cycleMs: opts.eventMs ?? 0, single: opts.single ?? 'StartPulse', priority: 0, programs: [{ instance: 'V', pou: 'Ev' }] };
  const tasks = opts.noCyclic ? [event] : opts.eventFirst ? [event, cyclic] : [cyclic, event];
  return newProject('Events', {
    pous: [cyc(), ev()],
    globals: vars('Trace DINT', 'Go BOOL', `StartPulse BOOL${opts.pulseInitial ? ' := TRUE' : ''}`, 'Level INT'),
    tasks,
  });
}
