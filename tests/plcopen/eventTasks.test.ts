// PLCopen event tasks (`<task single="StartPulse">`, IEC `SINGLE := StartPulse`): imported as event
// tasks without a warning, run on the trigger's rising edge as MATIEC runs them, exported back
// (schema-valid, no invented interval) and imported again to the same tasks and trace.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import type { Plc } from '../../src/engine/api';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { runOptions } from '../../src/sim/runTarget';
import { trace } from '../engine/ladder';
import { schemaErrors } from './xsd';

const XML = readFileSync(new URL('../fixtures/plcopen/event-task.xml', import.meta.url), 'utf8');

function imported(xml: string): { project: Project; warnings: { message: string; line?: number; element?: string }[] } {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return { project: r.project, warnings: [...r.report.warnings] };
}

function plcOf(p: Project): Plc {
  const { program, diagnostics } = compileProgram(p, runOptions(p));
  if (!program) throw new Error(diagnostics.map(formatDiagnostic).join('\n'));
  return createPlc(program, { cycleMs: program.schedule!.tickMs });
}

/** The button on %IX0.0 per scan; Main copies it to StartPulse after E's trigger was sampled. */
const BUTTON = [0, 1, 1, 0, 1, 0, 0].map((v) => ({ '%IX0.0': v === 1 }));
const run = (p: Project) => trace(plcOf(p), BUTTON, ['StartPulse', 'Starts']);
const TRACE = [[0, 0], [1, 0], [1, 1], [0, 1], [1, 1], [0, 2], [0, 2]];

describe('a PLCopen event task', () => {
  it('imports as an event task on its BOOL global, without a warning', () => {
    const { project, warnings } = imported(XML);
    expect(warnings.map((w) => w.message)).toEqual([]);
    expect(project.tasks).toEqual([
      { name: 'Cyclic', cycleMs: 10, priority: 1, programs: [{ instance: 'MainInst', pou: 'Main' }] },
      { name: 'E', cycleMs: 0, single: 'StartPulse', priority: 0, programs: [{ instance: 'EvInst', pou: 'OnStart' }] },
    ]);
  });

  it('runs its program once per rising edge of the trigger, in the tick after a program set it', () => {
    expect(run(imported(XML).project)).toEqual(TRACE);
  });

  it('exports single without an interval (schema-valid), and imports back to the same tasks and trace', async () => {
    const { project } = imported(XML);
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml, 'event-task.xml')).toEqual([]);
    expect(xml).toMatch(/<task name="E" single="StartPulse" priority="0">/);
    expect(xml).toMatch(/<task name="Cyclic" interval="T#10ms" priority="1">/);
    const again = imported(xml);
    expect(again.warnings.map((w) => w.message)).toEqual([]);
    expect(again.project.tasks).toEqual(project.tasks);
    expect(run(again.project)).toEqual(TRACE);
  });

  it('with an interval too, keeps it (it only counts in the common tick) and writes it back', async () => {
    const { project } = imported(XML.replace('<task name="E" single="StartPulse"', '<task name="E" single="StartPulse" interval="T#20ms"'));
    expect(project.tasks[1]).toMatchObject({ cycleMs: 20, single: 'StartPulse' });
    expect(run(project)).toEqual(TRACE);
    const xml = exportPlcopen(project);
    expect(await schemaErrors(xml, 'event-task-interval.xml')).toEqual([]);
    expect(xml).toMatch(/<task name="E" single="StartPulse" interval="T#20ms" priority="0">/);
  });

  it('whose trigger is no BOOL global: a warning at the task, and LD-E20 before Run', () => {
    const { project, warnings } = imported(XML.replace('<task name="E" single="StartPulse"', '<task name="E" single="Starts"'));
    const line = XML.split('\n').findIndex((l) => l.includes('<task name="E"')) + 1;
    expect(warnings).toEqual([
      expect.objectContaining({
        line,
        element: 'task',
        message: 'task E: its trigger single="Starts" is DINT, not BOOL; the task cannot run until it names a BOOL global (LD-E20)',
      }),
    ]);
    const errors = compileProgram(project, runOptions(project)).diagnostics.filter((d) => d.severity === 'error');
    expect(errors.map((d) => `${d.rule} ${d.message.split(';')[0]}`)).toEqual(['LD-E20 task E: its trigger Starts is DINT, not BOOL']);
  });
});
