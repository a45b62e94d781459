// The simulator with an event task (E runs when the global StartPulse rises) beside a 10 ms cyclic
// task: writing or forcing the trigger from the watch table runs E once in the next scan; the
// history and a scenario record and replay it; the outputs it sets stay in the output image.
import { describe, expect, test } from 'vitest';
import { runScenario } from '../../src/sim/scenario';
import { eventProject } from '../engine/eventTasksProject';
import { SimHarness } from './harness';

const lastOf = <T>(list: readonly T[]): T => list[list.length - 1]!;

describe('an event task in the simulator', () => {
  test('writing the trigger from the watch table runs the task once, in the next scan', () => {
    const project = eventProject();
    const h = new SimHarness().send({ type: 'step', scans: 2, project }).advance(0);
    expect([h.value('C.N'), h.value('V.N')]).toEqual([2, 0]);
    h.send({ type: 'write', name: 'StartPulse', input: { value: true } }, { type: 'step', scans: 3, project }).advance(0);
    expect([h.value('C.N'), h.value('V.N')]).toEqual([5, 1]);
    expect(h.frame.cycleMs).toBe(10);
  });

  test('forcing the trigger runs the task on each rise of the forced value', () => {
    const project = eventProject();
    const h = new SimHarness().send({ type: 'step', scans: 1, project }).advance(0);
    // Forced, the trigger keeps its value although Cyc's coil writes Go (FALSE) to it every scan.
    h.send({ type: 'force', name: 'StartPulse', input: { text: 'TRUE' } }, { type: 'step', scans: 3, project }).advance(0);
    expect([h.value('StartPulse'), h.value('V.N')]).toEqual([true, 1]);
    h.send({ type: 'force', name: 'StartPulse', input: { text: 'FALSE' } }, { type: 'step', scans: 1, project }).advance(0);
    h.send({ type: 'force', name: 'StartPulse', input: { text: 'TRUE' } }, { type: 'step', scans: 2, project }).advance(0);
    expect(h.value('V.N')).toBe(2);
  });

  test('the history records the event program\'s runs scan by scan; the lamp it toggles is published and stays', () => {
    const project = eventProject();
    const h = new SimHarness().send({ type: 'subscribeOutputs', enabled: true }, { type: 'step', scans: 1, project }).advance(0);
    h.send({ type: 'write', name: 'StartPulse', input: { value: true } }, { type: 'step', scans: 2, project }).advance(0);
    h.send({ type: 'historyExport', id: 1, format: 'trace', names: ['StartPulse', 'V.N'], from: 1, to: 3 });
    // The write is sampled at the start of scan 2 (E runs), then Cyc's coil writes Go (FALSE) to it.
    expect(lastOf(h.of('historyText')).text).toBe('scan,time_ms,StartPulse,V.N\n1,0,0,0\n2,10,0,1\n3,20,0,1\n');
    // The lamp E toggles in scan 2 is published then (outputs go out when they change) and stays on.
    expect(h.of('outputs').map((o) => [o.scan, o.outputs['%QX0.0']])).toEqual([[1, false], [2, true]]);
    expect(h.value('V.Lamp')).toBe(true);
  });

  test('a scenario that sets the trigger checks the runs, in the Tests panel as in the simulator', () => {
    const csv = 'scan,StartPulse,expect V.N,expect C.N\n1,FALSE,0,1\n2,TRUE,1,2\n3,TRUE,1,3\n4,FALSE,1,4\n5,TRUE,2,5\n';
    expect(runScenario(eventProject(), { name: 'pulses', csv }).result).toMatchObject({ ok: true, scans: 5 });
    const h = new SimHarness().send({ type: 'replayScenario', id: 1, project: eventProject(), scenario: { name: 'pulses', csv } });
    expect(lastOf(h.of('scenarioReplayed')).result).toMatchObject({ ok: true, scans: 5 });
  });
});

test('the event program\'s view: nothing ran before its first trigger; then its last run, as a slower task\'s view shows', () => {
  const project = eventProject();
  const h = new SimHarness().send({ type: 'step', scans: 2, project }).advance(0);
  h.send({ type: 'setView', view: { pou: 'Ev', instance: 'V' } });
  expect(Array.from(h.frame.executed)).toEqual([0, 0, 0, 0]);
  h.send({ type: 'write', name: 'StartPulse', input: { value: true } }, { type: 'step', scans: 1, project }).advance(0);
  expect(Array.from(h.frame.executed)).toEqual([1, 1, 1, 1]);
  h.send({ type: 'step', scans: 1, project }).advance(0);
  expect([h.frame.scan, Array.from(h.frame.executed)]).toEqual([4, [1, 1, 1, 1]]);
});
