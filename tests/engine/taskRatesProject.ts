// Test helper: a project whose two tasks run at different intervals, as a whole IEC configuration.
// Fast (task Fast) counts its runs in N, toggles %QX0.0 and appends 1 to the global Trace;
// Slow (task Slow) counts its runs in N, runs a TON (ET in Et), lights %QX0.1, appends 2 and
// calls the user function Twice (D := Twice(21)).
import { newProject } from '../../src/model/factory';
import type { Project, Task } from '../../src/model/project';
import { ladder, vars, type BoxSpec } from './ladder';
import { io, pou } from './userBlocksHelpers';

const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });
/** One network: v := type(v, k). */
export const twoIn = (type: 'ADD' | 'MUL', v: string, k: string) =>
  ladder(['- # # .', '. # # .', '. # # .'], { boxes: [box(type, 0, 1, { inputs: { IN1: v, IN2: k }, outputs: { OUT: v } })] });
/** Trace := Trace * 10 + id: the order in which programs ran, one digit per run. */
export const append = (id: string) => [twoIn('MUL', 'Trace', '10'), twoIn('ADD', 'Trace', id)];

const fast = () =>
  pou('Fast', 'PROGRAM', [...vars('N DINT', 'Blink BOOL %QX0.0'), ...io('external', 'Trace DINT')], [
    twoIn('ADD', 'N', '1'),
    ladder(['[/Blink] (Blink)']),
    ...append('1'),
  ]);

/** Twice(X) = X + X, called by Slow's last network. */
const twice = () =>
  pou('Twice', 'FUNCTION', io('input', 'X INT'), [
    ladder(['- # # .', '. # # .', '. # # .'], { boxes: [box('ADD', 0, 1, { inputs: { IN1: 'X', IN2: 'X' }, outputs: { OUT: 'Twice' } })] }),
  ], 'INT');

const slow = () =>
  pou('Slow', 'PROGRAM', [...vars('N DINT', 'Go BOOL := TRUE', 'Et TIME', 'T1 TON', 'Lamp BOOL %QX0.1', 'D INT'), ...io('external', 'Trace DINT')], [
    twoIn('ADD', 'N', '1'),
    ladder(['[Go] # # .', '. # # .', '. # # .'], {
      boxes: [box('TON', 0, 1, { instance: 'T1', inputs: { PT: 'T#1s' }, outputs: { ET: 'Et' } })],
    }),
    ladder(['[Go] (Lamp)']),
    ...append('2'),
    ladder(['- # # .', '. # # .', '. # # .', '. # # .'], { boxes: [box('Twice', 0, 1, { inputs: { X: '21' }, outputs: { OUT: 'D' } })] }),
  ]);

export interface RatesOptions {
  readonly fastMs?: number;
  readonly slowMs?: number;
  /** Declare the slow task (and so its instance) first. */
  readonly slowFirst?: boolean;
  /** Priority of the slow task (default 2; the fast one has 1). */
  readonly slowPriority?: number;
}

/** Instances F (program Fast, task Fast) and S (program Slow, task Slow). */
export function ratesProject(opts: RatesOptions = {}): Project {
  const fastTask: Task = { name: 'Fast', cycleMs: opts.fastMs ?? 10, priority: 1, programs: [{ instance: 'F', pou: 'Fast' }] };
  const slowTask: Task = { name: 'Slow', cycleMs: opts.slowMs ?? 30, priority: opts.slowPriority ?? 2, programs: [{ instance: 'S', pou: 'Slow' }] };
  return newProject('Rates', {
    pous: [fast(), slow(), twice()],
    globals: vars('Trace DINT'),
    tasks: opts.slowFirst ? [slowTask, fastTask] : [fastTask, slowTask],
  });
}
