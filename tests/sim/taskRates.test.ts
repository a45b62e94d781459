// The simulator with tasks of 10 ms and 30 ms: a scan is one 10 ms tick everywhere (Run's pace,
// Step N, the scan counter, history, scenarios, outputs), the slow task's program runs every third
// scan, and the Cycle is the common tick, not the value the toolbar sends.
import { describe, expect, test } from 'vitest';
import { newProject } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { runScenario } from '../../src/sim/scenario';
import { ratesProject } from '../engine/taskRatesProject';
import { SimHarness } from './harness';

const lastOf = <T>(list: readonly T[]): T => list[list.length - 1]!;

/** One task running both programs: the cycle is the one the toolbar sets. */
function oneTask(): Project {
  const p = ratesProject();
  return newProject('One', { pous: p.pous, globals: p.globals, tasks: [{ ...p.tasks[0]!, programs: p.tasks.flatMap((t) => t.programs) }] });
}

describe('tasks at 10 ms and 30 ms in the simulator', () => {
  test('Run scans every 10 ms tick, whatever cycle the toolbar sent; Slow runs in every third scan', () => {
    const h = new SimHarness().send({ type: 'setCycle', cycleMs: 30 }, { type: 'run', project: ratesProject() });
    expect(h.layout.cycleMs).toBe(10);
    h.advance(1000).send({ type: 'pause' });
    expect(h.frame).toMatchObject({ scan: 101, timeMs: 1000, cycleMs: 10 });
    // Ticks 0..100: Fast in all 101, Slow in ticks 0, 3, ..., 99.
    expect([h.value('F.N'), h.value('S.N'), h.value('S.Et')]).toEqual([101, 34, 990]);
  });

  test('the cycle stays the common tick while this program is loaded, and comes back for one task', () => {
    const h = new SimHarness().send({ type: 'run', project: ratesProject() }, { type: 'pause' });
    h.send({ type: 'setCycle', cycleMs: 25 });
    expect(h.frame.cycleMs).toBe(10);
    h.send({ type: 'step', scans: 3, project: ratesProject() }).advance(0);
    expect(h.frame.timeMs).toBe(20); // scans at 0, 10, 20 ms
    h.send({ type: 'reset' }, { type: 'step', scans: 2, project: oneTask() }).advance(0);
    expect(h.frame.cycleMs).toBe(25);
    expect(h.frame.timeMs).toBe(25);
    expect([h.value('F.N'), h.value('S.N')]).toEqual([2, 2]);
  });

  test('Step 9 scans: Fast ran 9 times, Slow 3; the history records one row per tick', () => {
    const h = new SimHarness().send({ type: 'step', scans: 9, project: ratesProject() }).advance(0);
    expect(h.frame).toMatchObject({ scan: 9, timeMs: 80, history: { first: 1, last: 9 } });
    expect([h.value('F.N'), h.value('S.N')]).toEqual([9, 3]);
    h.send({ type: 'historyExport', id: 1, format: 'trace', names: ['F.N', 'S.N', 'S.Et'], from: 3, to: 5 });
    expect(lastOf(h.of('historyText')).text).toBe('scan,time_ms,F.N,S.N,S.Et\n3,20,3,1,0\n4,30,4,2,30\n5,40,5,2,30\n');
  });

  test('every scan publishes the whole output image: the slow program\'s lamp stays on in the ticks it does not run', () => {
    const h = new SimHarness().send({ type: 'subscribeOutputs', enabled: true }, { type: 'step', scans: 3, project: ratesProject() }).advance(0);
    const outputs = h.of('outputs');
    expect(outputs.map((o) => [o.scan, o.outputs['%QX0.0'], o.outputs['%QX0.1']])).toEqual([
      [1, true, true],
      [2, false, true],
      [3, true, true],
    ]);
  });

  test('in a tick Slow does not run, its tab and the function it calls show the power flow of its last run', () => {
    const h = new SimHarness().send({ type: 'step', scans: 2, project: ratesProject() }).advance(0);
    expect(h.value('S.D')).toBe(42);
    h.send({ type: 'setView', view: { pou: 'Slow', instance: 'S' } });
    expect(Array.from(h.frame.executed)).toEqual([1, 1, 1, 1, 1, 1]);
    h.send({ type: 'setView', view: { pou: 'Twice' } });
    expect(Array.from(h.frame.executed)).toEqual([1]);
    h.send({ type: 'setView', view: { pou: 'Fast', instance: 'F' } });
    expect(Array.from(h.frame.executed)).toEqual([1, 1, 1, 1]);
  });

  test('a breakpoint in the slow program stops only in the ticks its task runs: scans 1, 4, 7', () => {
    const project = ratesProject();
    const slowNet = project.pous.find((p) => p.name === 'Slow')!.networks[0]!.id;
    const h = new SimHarness().send({ type: 'setBreakpoints', ids: [slowNet] });
    const hits: number[] = [];
    for (let k = 0; k < 3; k++) {
      h.send({ type: 'step', scans: 20, project }).advance(0);
      expect(h.frame.breakpointAt).toMatchObject({ pou: 'Slow', instance: 'S', network: 0 });
      hits.push(h.frame.scan);
    }
    expect(hits).toEqual([1, 4, 7]);
  });

  test('a scenario replays on the tick; a "# cycle:" other than the tick is refused with the reason', () => {
    const csv = 'scan,expect F.N,expect S.N,expect S.Et\n1,1,1,0\n4,4,2,30\n7,7,3,60\n';
    const h = new SimHarness().send({ type: 'replayScenario', id: 1, project: ratesProject(), scenario: { name: 'rates', csv } });
    expect(lastOf(h.of('scenarioReplayed')).result).toMatchObject({ ok: true, scans: 7 });
    h.send({ type: 'replayScenario', id: 2, project: ratesProject(), scenario: { name: 'slow', csv: `# cycle: 30ms\n${csv}` } });
    expect(lastOf(h.of('scenarioReplayed')).result.error).toMatch(/the tasks run at different intervals \(Fast runs every tick \(10 ms\); Slow every 3rd tick \(30 ms\)\), so a scan is their common tick of 10 ms/);
    // The Tests panel (and `rungsmith test`) runs the same configuration on the same tick.
    expect(runScenario(ratesProject(), { name: 'rates', csv }).result).toMatchObject({ ok: true, scans: 7 });
    expect(runScenario(ratesProject(), { name: 'slow', csv: `# cycle: 30ms\n${csv}` }).result.error).toMatch(/common tick of 10 ms/);
  });
});
