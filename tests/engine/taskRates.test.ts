// Tasks at their own intervals, as a MATIEC-compiled resource runs them: one scan per common tick
// (the gcd of the intervals), a task's programs in the ticks that are a multiple of interval/tick
// (tick 0 = the first scan: every task), instances in declaration order, timers on real time.
import { describe, expect, test } from 'vitest';
import { commonTickMs, describeSchedule, taskSchedule } from '../../src/engine/compile/taskSchedule';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Plc } from '../../src/engine/api';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { newProject } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { ScanPlc } from '../../src/engine/runtime/scanner';
import { DEFAULT_TIERING } from '../../src/engine/runtime/tiering';
import { trace } from './ladder';
import { ratesProject } from './taskRatesProject';

function configPlc(project: Project, cycleMs?: number): Plc {
  const { program, diagnostics } = compileProgram(project, { configuration: true });
  if (!program) throw new Error(diagnostics.map(formatDiagnostic).join('\n'));
  return createPlc(program, { cycleMs: cycleMs ?? program.schedule!.tickMs });
}

const scans = (n: number) => Array.from({ length: n }, () => ({}));

describe('common tick', () => {
  test('is the greatest common divisor of the task intervals', () => {
    expect(commonTickMs([20, 30])).toBe(10);
    expect(commonTickMs([10, 30])).toBe(10);
    expect(commonTickMs([100])).toBe(100);
    expect(commonTickMs([7, 5])).toBe(1);
    expect(commonTickMs([0.5, 2])).toBe(0.5);
    const s = taskSchedule(ratesProject({ fastMs: 20, slowMs: 30 }).tasks);
    expect(s.tickMs).toBe(10);
    expect(s.tasks.map((t) => [t.name, t.every])).toEqual([['Fast', 2], ['Slow', 3]]);
    expect(s.multiRate).toBe(true);
  });

  test('in words, as the Tasks dialog says it', () => {
    expect(describeSchedule(taskSchedule(ratesProject().tasks))).toBe('Fast runs every tick (10 ms); Slow every 3rd tick (30 ms)');
    expect(describeSchedule(taskSchedule(ratesProject({ fastMs: 20 }).tasks))).toBe('Fast runs every 2nd tick (20 ms); Slow every 3rd tick (30 ms)');
  });
});

describe('tasks of 10 ms and 30 ms', () => {
  test('after 9 scans the fast program ran 9 times, the slow one 3 times (scans 1, 4, 7)', () => {
    const plc = configPlc(ratesProject());
    expect(plc.schedule?.tickMs).toBe(10);
    const rows = trace(plc, scans(9), ['F.N', 'S.N']);
    expect(rows).toEqual([[1, 1], [2, 1], [3, 1], [4, 2], [5, 2], [6, 2], [7, 3], [8, 3], [9, 3]]);
    expect(plc.timeMs).toBe(80);
  });

  test('a timer in the slow program advances by the real time between its runs (30 ms), not by 10 ms', () => {
    const plc = configPlc(ratesProject());
    // TON ET at the scan-start time of each slow run: scans 1, 4, 7, 10 start at 0, 30, 60, 90 ms.
    expect(trace(plc, scans(10), ['S.Et'])).toEqual([[0], [0], [0], [30], [30], [30], [60], [60], [60], [90]]);
  });

  test('within a tick, instances run in declaration order (task order), whatever their priority', () => {
    // Trace gets 1 when Fast runs and 2 when Slow runs: tick 0 runs both, in the order declared.
    const fastFirst = configPlc(ratesProject());
    expect(trace(fastFirst, scans(4), ['Trace'])).toEqual([[12], [121], [1211], [121112]]);
    const slowFirst = configPlc(ratesProject({ slowFirst: true, slowPriority: 9 }));
    expect(trace(slowFirst, scans(4), ['Trace'])).toEqual([[21], [211], [2111], [211121]]);
  });

  test('a tick in which no task is due still reads inputs and writes the whole output image', () => {
    // 20 ms and 30 ms on a 10 ms tick: tick 1 runs nothing, tick 2 Fast, tick 3 Slow, tick 4 Fast.
    const plc = configPlc(ratesProject({ fastMs: 20 }));
    expect(trace(plc, scans(5), ['F.N', 'S.N', 'Trace'])).toEqual([[1, 1, 12], [1, 1, 12], [2, 1, 121], [2, 2, 1212], [3, 2, 12121]]);
    // The slow program's lamp (set on its first run) is in every scan's output image; Fast's blink
    // changes only in the ticks Fast runs.
    const outputs: string[] = [];
    const again = configPlc(ratesProject({ fastMs: 20 }));
    for (let k = 0; k < 5; k++) {
      again.scan();
      const o = again.outputs();
      outputs.push(`${Number(o['%QX0.0'])}${Number(o['%QX0.1'])}`);
    }
    expect(outputs).toEqual(['11', '11', '01', '01', '11']);
  });

  test('stepping network by network passes over the programs whose task is not due', () => {
    const plc = configPlc(ratesProject());
    plc.scan(); // tick 0: both ran
    // Tick 1: only Fast's four networks run, then the scan ends.
    const executed: number[] = [];
    for (;;) {
      const r = plc.stepNetwork();
      if (r.executed >= 0) executed.push(r.executed);
      if (r.scanDone) break;
    }
    expect(executed).toEqual([0, 1, 2, 3]);
    expect(plc.read('S.N')).toBe(1);
    // Stepping into calls takes the same path.
    plc.scans(2); // ticks 2 and 3 (Slow ran at 3)
    const into: string[] = [];
    for (;;) {
      const r = plc.stepNetwork({ into: true });
      if (r.scanDone) break;
      into.push(plc.position().map((f) => `${f.instance ?? f.pou}:${f.network}`).join('>'));
    }
    expect(into.every((p) => p.startsWith('F:'))).toBe(true);
  });

  test('the slow program shows the power flow of its last run in the ticks it does not run', () => {
    const plc = configPlc(ratesProject());
    plc.scans(2);
    const slow = plc.snapshot({ instance: 'S' });
    expect(slow.networks.every((n) => n.executed)).toBe(true);
    const lamp = slow.networks[2]!;
    expect(Array.from(lamp.elements)).toEqual([7, 7]);
  });

  test('the same scan by scan whether networks run in the dispatch loops or in straight-line code', () => {
    const { program } = compileProgram(ratesProject({ fastMs: 20 }), { configuration: true });
    const loops = new ScanPlc(program!, { cycleMs: 10 }, { ...DEFAULT_TIERING, startAfterEvals: Infinity });
    const straight = new ScanPlc(program!, { cycleMs: 10 }, { ...DEFAULT_TIERING, startAfterEvals: 0, minScans: 1, msPerNetwork: 0, batch: 1 });
    const names = ['F.N', 'S.N', 'S.Et', 'Trace'];
    for (let k = 0; k < 12; k++) {
      loops.scan();
      straight.scan();
      expect(names.map((n) => straight.read(n))).toEqual(names.map((n) => loops.read(n)));
      expect(straight.outputs()).toEqual(loops.outputs());
    }
    // Ticks 0..11: Fast (every 2nd) ran 6 times, Slow (every 3rd) 4 times.
    expect([straight.read('F.N'), straight.read('S.N')]).toEqual([6, 4]);
  });

  test('a virtual clock other than the common tick is refused', () => {
    const { program } = compileProgram(ratesProject(), { configuration: true });
    expect(() => createPlc(program!, { cycleMs: 30 })).toThrow(/common tick of 10 ms/);
  });
});

describe('unchanged without several rates', () => {
  test('one task: every program every scan, at the task interval', () => {
    const one = ratesProject();
    const project = newProject('One', { pous: one.pous, globals: one.globals, tasks: [{ ...one.tasks[0]!, programs: [...one.tasks[0]!.programs, ...one.tasks[1]!.programs] }] });
    const { program } = compileProgram(project, { configuration: true });
    expect(program!.schedule?.multiRate).toBe(false);
    // The cycle may be chosen freely: it is the one task's.
    const plc = createPlc(program!, { cycleMs: 25 });
    expect(trace(plc, scans(4), ['F.N', 'S.N', 'S.Et', 'Trace'])).toEqual([[1, 1, 0, 12], [2, 2, 25, 1212], [3, 3, 50, 121212], [4, 4, 75, 12121212]]);
  });

  test('a task without program instances does not count in the tick', () => {
    const p = ratesProject();
    const spare = { name: 'Spare', cycleMs: 7, priority: 3, programs: [] };
    const s = taskSchedule([...p.tasks, spare]);
    expect(s.tickMs).toBe(10);
    expect(s.tasks.map((t) => t.name)).toEqual(['Fast', 'Slow']);
  });

  test('two tasks of the same interval run every scan', () => {
    const plc = configPlc(ratesProject({ slowMs: 10 }));
    expect(trace(plc, scans(3), ['F.N', 'S.N'])).toEqual([[1, 1], [2, 2], [3, 3]]);
  });
});
