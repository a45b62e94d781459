// Recording a scenario from the simulation (issue 22, 2.2): a scenario replays from a cold start
// and only sets inputs, so it is recorded from scan 1 after a cold start; a recording that an
// online change, a warm restart or a force made unreplayable is refused with the reason and what
// to do, never written as a scenario that fails.
import { expect, test } from 'vitest';
import type { HostMessage, WorkerMessage } from '../../src/sim/protocol';
import { runScenario } from '../../src/sim/scenario';
import { SimHarness } from './harness';
import { motorProgram } from './programs';

type HistoryText = Extract<WorkerMessage, { type: 'historyText' }>;
const exported = (h: SimHarness, id: number): HistoryText => {
  h.send({ type: 'historyExport', id, format: 'scenario', inputs: ['Start', 'Stop'], outputs: ['Motor'] });
  return h.of('historyText').find((m) => m.id === id)!;
};
const write = (name: string, value: boolean): HostMessage => ({ type: 'write', name, input: { value } });

/** Start pressed for a while then released (Motor seals in), then Stop pulsed. */
function operate(h: SimHarness) {
  h.send(write('Start', true)).advance(50);
  h.send(write('Start', false)).advance(50);
  h.send(write('Stop', true)).advance(50);
  h.send(write('Stop', false)).advance(50);
  h.send(write('Start', true)).advance(30);
  h.send(write('Start', false)).advance(80);
}

test('recorded from a cold start, with inputs switched while running, the scenario replays to PASS', () => {
  const project = motorProgram();
  const h = new SimHarness().send({ type: 'run', project }).advance(100);
  operate(h);
  const reply = exported(h, 1);
  expect(reply.refused).toBeUndefined();
  expect(reply.text).toMatch(/^scan,Start,Stop,expect Motor\n1,0,0,0$/m);
  expect(runScenario(project, { name: 'recorded', csv: reply.text }).result).toMatchObject({ ok: true, divergences: [] });
  // The live session is where it was: running on, nothing reset.
  expect(h.frame.mode).toBe('running');
});

test('after an online change the recording is refused with the scan and what to do; after Reset it records again', () => {
  const project = motorProgram();
  const h = new SimHarness().send({ type: 'run', project }).advance(100);
  h.send(write('Start', true)).advance(30);
  h.send(write('Start', false)).advance(30);
  // An online change: the document changed while running (a comment is not enough: a new variable).
  const changed = {
    ...project,
    pous: [{ ...project.pous[0]!, variables: [...project.pous[0]!.variables, { name: 'Spare', type: 'BOOL', varClass: 'local' as const, retain: false, comment: '' }] }],
  };
  h.send({ type: 'load', project: changed }).advance(30);
  expect(h.of('onlineApplied').length).toBe(1);
  const at = h.of('onlineApplied')[0]!.scan;
  const reply = exported(h, 1);
  expect(reply.text).toBe('');
  expect(reply.refused).toBe(
    `A scenario replays from a cold start, and an online change at scan ${at} changed the program or its state since the last one: ` +
      'the scenario would not replay as it ran. Press Reset (cold restart), release the forces, run and switch the inputs, then record again.',
  );
  h.send({ type: 'reset' }, { type: 'run' }).advance(50);
  operate(h);
  const again = exported(h, 2);
  expect(again.refused).toBeUndefined();
  expect(runScenario(changed, { name: 'recorded', csv: again.text }).result).toMatchObject({ ok: true });
});

test('forces while recording are refused by name, also after they were released', () => {
  const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(100);
  h.send({ type: 'force', name: 'Motor', input: { value: true } }).advance(50);
  h.send({ type: 'unforce', name: 'Motor' }).advance(50);
  expect(exported(h, 1).refused).toMatch(/^Forces were active while recording \(Motor\): a scenario sets inputs and cannot force/);
  // Reset with no force left: a clean start.
  h.send({ type: 'reset' }, { type: 'run' }).advance(50);
  expect(exported(h, 2).refused).toBeUndefined();
});

test('a recording whose first scans no longer fit in the history is refused', () => {
  const h = new SimHarness().send({ type: 'setHistory', maxScans: 30, budgetBytes: 1 << 20 }, { type: 'run', project: motorProgram() }).advance(1000);
  expect(exported(h, 1).refused).toMatch(/the recording starts at scan \d+ \(the oldest scans no longer fit in the history\), not at scan 1/);
});

test('a warm restart while recording is refused too: retained state is not a cold start', () => {
  const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(100);
  h.send({ type: 'warmRestart' }).advance(50);
  expect(exported(h, 1).refused).toMatch(/^A scenario replays from a cold start, and a warm restart at scan \d+ changed the program or its state since the last one/);
});
