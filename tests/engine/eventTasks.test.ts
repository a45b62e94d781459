// Event tasks (PLCopen `single`, IEC `SINGLE := StartPulse`) as MATIEC's resource runs them: each
// tick, before any program, the trigger goes through an R_TRIG whose memory starts FALSE; the task's
// programs run only in the ticks where it rose, in declaration order with the cyclic tasks due.
import { describe, expect, test } from 'vitest';
import type { Plc } from '../../src/engine/api';
import { describeSchedule, taskSchedule } from '../../src/engine/compile/taskSchedule';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Project } from '../../src/model/project';
import { runOptions } from '../../src/sim/runTarget';
import { trace } from './ladder';
import { eventProject } from './eventTasksProject';

function configPlc(project: Project): Plc {
  const { program, diagnostics } = compileProgram(project, { configuration: true });
  if (!program) throw new Error(diagnostics.map(formatDiagnostic).join('\n'));
  return createPlc(program, { cycleMs: program.schedule!.tickMs });
}

const errorsOf = (project: Project) =>
  compileProgram(project, { configuration: true }).diagnostics.filter((d) => d.severity === 'error').map((d) => `${d.rule} ${d.message}`);

describe('an event task', () => {
  test('runs its program only in the ticks where its trigger rose', () => {
    const plc = configPlc(eventProject());
    const pulse = [0, 1, 1, 0, 1, 0, 0, 1, 1].map((v) => ({ StartPulse: v === 1 }));
    expect(trace(plc, pulse, ['C.N', 'V.N'])).toEqual([
      [1, 0], [2, 1], [3, 1], [4, 1], [5, 2], [6, 2], [7, 2], [8, 3], [9, 3],
    ]);
  });

  test('a trigger TRUE in the first tick is a rising edge (the R_TRIG memory starts FALSE), and again after a cold restart', () => {
    const plc = configPlc(eventProject({ pulseInitial: true }));
    expect(trace(plc, [{}, {}, {}], ['V.N'])).toEqual([[1], [1], [1]]);
    plc.coldRestart();
    expect(trace(plc, [{}, {}], ['V.N'])).toEqual([[1], [1]]);
    expect(trace(plc, [{ StartPulse: false }, { StartPulse: true }], ['V.N'])).toEqual([[1], [2]]);
  });

  test('runs in declaration order with the cyclic task due in the same tick', () => {
    // Trace gets 1 when Cyc runs and 2 when Ev runs.
    const cyclicFirst = configPlc(eventProject());
    expect(trace(cyclicFirst, [{}, { StartPulse: true }, {}], ['Trace'])).toEqual([[1], [112], [1121]]);
    const eventFirst = configPlc(eventProject({ eventFirst: true }));
    expect(trace(eventFirst, [{}, { StartPulse: true }, {}], ['Trace'])).toEqual([[1], [121], [1211]]);
  });

  test('samples its trigger once per tick before the programs: a program that sets it runs the task in the next tick', () => {
    // Cyc copies Go to StartPulse after the tick's trigger was read.
    const plc = configPlc(eventProject());
    expect(trace(plc, [{}, { Go: true }, {}, {}, { Go: false }, {}, { Go: true }], ['StartPulse', 'V.N'])).toEqual([
      [0, 0], [1, 0], [1, 1], [1, 1], [0, 1], [0, 1], [1, 1],
    ]);
  });

  test('forcing the trigger from the watch table runs the task once per rise', () => {
    const plc = configPlc(eventProject());
    plc.scan();
    plc.force('StartPulse', true);
    expect(trace(plc, [{}, {}, {}], ['V.N'])).toEqual([[1], [1], [1]]);
    plc.force('StartPulse', false);
    plc.scan();
    plc.force('StartPulse', true);
    expect(trace(plc, [{}], ['V.N'])).toEqual([[2]]);
  });

  test('every tick writes the whole output image: the lamp the event program toggles stays as it was', () => {
    const plc = configPlc(eventProject());
    const lamps: boolean[] = [];
    for (const v of [false, true, false, false, true, false]) {
      plc.write('StartPulse', v);
      plc.scan();
      lamps.push(plc.outputs()['%QX0.0'] === true);
    }
    expect(lamps).toEqual([false, true, true, true, false, false]);
  });

  test('its interval, when it has one, counts in the common tick (as MATIEC counts it) but never runs it', () => {
    const p = eventProject({ cyclicMs: 20, eventMs: 30 });
    const s = taskSchedule(p.tasks);
    expect([s.tickMs, s.multiRate, s.tasks.map((t) => [t.name, t.every])]).toEqual([10, true, [['Cyclic', 2], ['E', 0]]]);
    const plc = configPlc(p);
    expect(trace(plc, [{}, {}, {}, {}], ['C.N', 'V.N'])).toEqual([[1, 0], [1, 0], [2, 0], [2, 0]]);
    expect(plc.timeMs).toBe(30);
  });

  test('in words: "E runs when StartPulse rises"', () => {
    expect(describeSchedule(taskSchedule(eventProject().tasks))).toBe('Cyclic runs every tick (10 ms); E runs when StartPulse rises');
    expect(describeSchedule(taskSchedule(eventProject({ eventFirst: true }).tasks))).toBe('E runs when StartPulse rises; Cyclic runs every tick (10 ms)');
  });

  test('one event task with one program still runs as a configuration (only on its trigger)', () => {
    const p = eventProject({ noCyclic: true, eventMs: 10 });
    expect(runOptions(p)).toEqual({ configuration: true });
    const plc = configPlc(p);
    expect(trace(plc, [{}, { StartPulse: true }, {}, {}], ['V.N'])).toEqual([[0], [1], [1], [1]]);
  });
});

describe('an event task that cannot run (LD-E20)', () => {
  test('its trigger must be a BOOL global', () => {
    expect(errorsOf(eventProject({ single: 'Level' }))).toEqual([
      "LD-E20 task E: its trigger Level is INT, not BOOL; an event task runs on the rising edge of a BOOL global (MATIEC's SINGLE := reads a global of the configuration or resource)",
    ]);
    expect(errorsOf(eventProject({ single: 'Nowhere' }))[0]).toMatch(/^LD-E20 task E: its trigger Nowhere names no global variable;/);
  });

  test('some task must have an interval: MATIEC refuses a configuration without a periodic task', () => {
    expect(errorsOf(eventProject({ noCyclic: true }))[0]).toMatch(/^LD-E20 no task has an interval, so there is no tick to sample StartPulse on; MATIEC refuses/);
  });
});
