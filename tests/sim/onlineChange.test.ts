// Online change keeps state (issue 10), through the simulator session as the worker runs it: FB
// instances and edge memories survive an edit elsewhere, what is new starts fresh, the plan is
// said before applying (and waits for an answer when hardware is attached), and the change is
// confirmed after applying.
import { describe, expect, test } from 'vitest';
import type { Network } from '../../src/model/project';
import { describeOnlineChange, describeTransfer } from '../../src/sim/carryOver';
import { ladder, project, vars } from '../engine/ladder';
import { SimHarness } from './harness';

const counterNet = (): Network =>
  ladder(['[Pulse] # # (Full)', '. # # .', '. # # .'], {
    boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { R: 'Clear', PV: '100' }, outputs: { CV: 'Count' } }],
  });
const timerNet = (type = 'TON'): Network =>
  ladder(['[Go] # # - (Q)', '. # # . .'], { boxes: [{ row: 0, col: 1, type, instance: 'T1', inputs: { PT: 'T#2s' } }] });
const edgeNet = (): Network => ladder(['[P:A] (S:Latch)']);
const elsewhere = (): Network => ladder(['[Other] (Lamp)']);

const plantVars = (timerType = 'TON') =>
  vars('Pulse BOOL', 'Clear BOOL', 'C1 CTU', 'Count INT', 'Full BOOL', 'Go BOOL := TRUE', `T1 ${timerType}`, 'Q BOOL', 'A BOOL := TRUE', 'Latch BOOL', 'Other BOOL', 'Lamp BOOL');

/** The plant running: 3 parts counted, the timer timing, the |P| contact's one pulse acknowledged. */
function running(counter: Network, timer: Network, edge: Network): SimHarness {
  const h = new SimHarness().send({ type: 'run', project: project(plantVars(), [counter, timer, edge]) }).advance(30);
  expect(h.value('Latch')).toBe(true); // a |P| with A TRUE at its first evaluation fires (R_TRIG, M starts FALSE)
  h.send({ type: 'write', name: 'Latch', input: { value: false } });
  for (let i = 0; i < 3; i++) {
    h.send({ type: 'write', name: 'Pulse', input: { value: true } }).advance(30);
    h.send({ type: 'write', name: 'Pulse', input: { value: false } }).advance(30);
  }
  expect(h.value('C1.CV')).toBe(3);
  return h;
}

describe('an edit elsewhere while running keeps every FB instance and edge memory', () => {
  test('the CTU keeps its count, the |P| contact on a steady TRUE input does not fire again, the TON keeps timing', () => {
    const [counter, timer, edge] = [counterNet(), timerNet(), edgeNet()];
    const h = running(counter, timer, edge);
    h.send({ type: 'load', project: project(plantVars(), [counter, elsewhere(), timer, edge]) }).advance(100);
    expect(h.layout.networkIds).toHaveLength(4); // the edit is in
    expect(h.value('C1.CV')).toBe(3);
    expect(h.value('Count')).toBe(3);
    expect(h.value('Latch')).toBe(false); // no new machine cycle started
    // The TON started at the first scan (0 ms): its ET is the PLC time, not the time since the edit.
    expect(h.value('T1.ET')).toBe(h.frame.timeMs);
    expect(h.frame.timeMs).toBeGreaterThan(250);
    h.send({ type: 'write', name: 'Pulse', input: { value: true } }).advance(30);
    expect(h.value('C1.CV')).toBe(4);
  });

  test('the plan is said before applying and the change confirmed after, with the scan and what was kept', () => {
    const [counter, timer, edge] = [counterNet(), timerNet(), edgeNet()];
    const h = running(counter, timer, edge);
    h.send({ type: 'load', project: project(plantVars(), [counter, elsewhere(), timer, edge]) }).advance(30);
    const [plan] = h.of('onlinePlan');
    expect(plan).toMatchObject({ confirm: false, plan: { kept: 3, reset: [], removed: [] } });
    const [applied] = h.of('onlineApplied');
    expect(applied).toMatchObject({ id: plan!.id, plan: { kept: 3, reset: [], removed: [] } });
    expect(h.messages.indexOf(plan!)).toBeLessThan(h.messages.indexOf(applied!));
    expect(applied!.scan).toBeGreaterThan(0);
    expect(describeOnlineChange(applied!.scan, applied!.plan)).toBe(`Online change applied at scan ${applied!.scan.toLocaleString('en-US')}; kept 3 instances`);
  });

  test('a NEW |P| element placed on a steady TRUE input fires once, as a fresh element does, and is listed as new', () => {
    const [counter, timer, edge] = [counterNet(), timerNet(), edgeNet()];
    const h = running(counter, timer, edge);
    const added = ladder(['[P:A] (S:Lamp)']);
    h.send({ type: 'load', project: project(plantVars(), [counter, timer, edge, added]) }).advance(100);
    expect(h.value('Lamp')).toBe(true);
    expect(h.value('Latch')).toBe(false);
    const applied = h.of('onlineApplied').at(-1)!;
    expect(applied.plan.reset).toEqual([{ name: '|P| A in network 4', reason: 'new' }]);
    expect(describeTransfer(applied.plan)).toBe('kept 3 instances, reset 1: |P| A in network 4 (new)');
  });
});

describe('what an online change resets', () => {
  test('an instance whose FB type changed (TON -> TOF) is reset and listed with the reason; a new instance is listed as new', () => {
    const [counter, timer, edge] = [counterNet(), timerNet(), edgeNet()];
    const h = running(counter, timer, edge);
    const t3 = ladder(['[Go] # # - (Lamp)', '. # # . .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T3', inputs: { PT: 'T#1s' } }] });
    const edited = project([...plantVars('TOF'), ...vars('T3 TON')], [counter, timerNet('TOF'), edge, t3]);
    h.send({ type: 'load', project: edited }).advance(30);
    const applied = h.of('onlineApplied').at(-1)!;
    expect(applied.plan).toEqual({
      kept: 2,
      reset: [
        { name: 'T1', reason: 'TON → TOF' },
        { name: 'T3', reason: 'new' },
      ],
      removed: [],
    });
    expect(describeOnlineChange(12_840, applied.plan)).toBe('Online change applied at scan 12,840; kept 2 instances, reset 2: T1 (TON → TOF), T3 (new)');
    expect(h.value('C1.CV')).toBe(3);
    expect(h.value('T1.ET')).toBe(0); // a TOF with IN ON
  });

  test('plain variables keep their values as before', () => {
    const [counter, timer, edge] = [counterNet(), timerNet(), edgeNet()];
    const h = running(counter, timer, edge);
    h.send({ type: 'write', name: 'Other', input: { value: true } }, { type: 'write', name: 'Clear', input: { value: false } }).advance(30);
    h.send({ type: 'load', project: project(plantVars(), [counter, timer, edge, elsewhere()]) }).advance(100);
    expect(h.value('Other')).toBe(true);
    expect(h.value('Lamp')).toBe(true);
  });
});

describe('with hardware attached, an online change waits for the answer', () => {
  test('Cancel leaves the running program unchanged; Apply puts it in at the next boundary, keeping the state', () => {
    const [counter, timer, edge] = [counterNet(), timerNet(), edgeNet()];
    const h = running(counter, timer, edge);
    h.send({ type: 'setOnlineConfirm', required: true });
    h.send({ type: 'load', project: project(plantVars(), [counter, elsewhere(), timer, edge]) }).advance(100);
    const asked = h.of('onlinePlan').at(-1)!;
    expect(asked.confirm).toBe(true);
    expect(h.of('onlineApplied')).toHaveLength(0);
    expect(h.layout.networkIds).toHaveLength(3); // still the running program
    expect(h.frame.mode).toBe('running');
    h.send({ type: 'confirmOnline', id: asked.id, apply: false }).advance(100);
    expect(h.of('onlineCancelled')).toEqual([{ type: 'onlineCancelled', id: asked.id }]);
    expect(h.layout.networkIds).toHaveLength(3);
    expect(h.of('onlineApplied')).toHaveLength(0);

    h.send({ type: 'load', project: project(plantVars(), [counter, timer, edge, elsewhere()]) }).advance(30);
    const again = h.of('onlinePlan').at(-1)!;
    expect(again.id).not.toBe(asked.id);
    h.send({ type: 'confirmOnline', id: asked.id, apply: true }).advance(30); // a stale answer does nothing
    expect(h.of('onlineApplied')).toHaveLength(0);
    h.send({ type: 'confirmOnline', id: again.id, apply: true }).advance(30);
    expect(h.of('onlineApplied').map((m) => m.id)).toEqual([again.id]);
    expect(h.layout.networkIds).toHaveLength(4);
    expect(h.value('C1.CV')).toBe(3);
    expect(h.value('Latch')).toBe(false);
  });
});

// Issue 22, section 2 item 10: an online change applied while paused (a global renamed) marked
// every network "not run" and showed every input OFF until the next step: the new program had not
// run yet. The display keeps the last scan, mapped to the new program.
describe('an online change while paused keeps showing the last scan', () => {
  const lamp = () => ladder(['[Start] (Lamp)']);
  const other = () => ladder(['[Other] (Out2)']);
  const before = () => vars('Start BOOL %IX0.0', 'Lamp BOOL %QX0.0', 'Other BOOL', 'Out2 BOOL');
  const renamed = (net: Network): Network => ({ ...net, elements: net.elements.map((e) => (e.kind === 'contact' ? { ...e, variable: 'Spare' } : e)) });
  const after = () => vars('Start BOOL %IX0.0', 'Lamp BOOL %QX0.0', 'Spare BOOL', 'Out2 BOOL');
  /** Executed flags, and for each element its power byte, by element id (so layouts compare). */
  const shown = (h: SimHarness) => {
    const l = h.layout;
    const f = h.frame;
    return { executed: [...f.executed], power: Object.fromEntries(l.elementIds.map((id, k) => [id, f.elements[k]])) };
  };
  const paused = (networks: Network[]) => {
    const h = new SimHarness().send({ type: 'run', project: project(before(), networks) }).advance(30);
    h.send({ type: 'setInputs', values: { '%IX0.0': true } }).advance(30);
    h.send({ type: 'pause' }).advance(10);
    expect([h.value('Start'), h.value('Lamp')]).toEqual([true, true]);
    return h;
  };

  test('renaming a variable while paused: networks still ran, the input still ON, power as it was', () => {
    const [n1, n2] = [lamp(), other()];
    const h = paused([n1, n2]);
    const was = shown(h);
    expect(was.executed).toEqual([1, 1]);
    const scan = h.frame.scan;
    h.send({ type: 'load', project: project(after(), [n1, renamed(n2)]) }).advance(10);
    expect(h.of('onlineApplied')).toHaveLength(1);
    expect(h.frame.mode).toBe('paused');
    expect(h.frame.scan).toBe(scan);
    expect([h.value('Start'), h.value('Lamp'), h.value('Spare'), h.value('Out2')]).toEqual([true, true, false, false]);
    expect(shown(h)).toEqual(was); // same element ids: the same power, both networks ran
    // A second change in a row keeps it too.
    h.send({ type: 'load', project: project(before(), [n1, n2]) }).advance(10);
    expect(h.of('onlineApplied')).toHaveLength(2);
    expect(shown(h)).toEqual(was);
    expect(h.value('Start')).toBe(true);
    // The next step shows the new program's own scan.
    h.send({ type: 'setInputs', values: { '%IX0.0': false } });
    h.send({ type: 'step', scans: 1 }).advance(30);
    expect(h.frame.scan).toBe(scan + 1);
    expect([h.value('Start'), h.value('Lamp')]).toEqual([false, false]);
    expect(h.frame.executed[0]).toBe(1);
  });

  test('a network added while paused shows as not run; the others keep their power', () => {
    const [n1, n2] = [lamp(), other()];
    const h = paused([n1, n2]);
    const was = shown(h);
    const added = ladder(['[Start] (Out2)']);
    h.send({ type: 'load', project: project(before(), [n1, added, n2]) }).advance(10);
    const now = shown(h);
    expect(now.executed).toEqual([1, 0, 1]);
    for (const [id, byte] of Object.entries(was.power)) expect(now.power[id]).toBe(byte);
    for (const e of added.elements) expect(now.power[e.id]).toBe(0);
  });

  test('an input renamed while paused shows the value last read at its address', () => {
    const [n1, n2] = [lamp(), other()];
    const h = paused([n1, n2]);
    const moved = (net: Network): Network => ({ ...net, elements: net.elements.map((e) => (e.kind === 'contact' ? { ...e, variable: 'Go' } : e)) });
    h.send({ type: 'load', project: project(vars('Go BOOL %IX0.0', 'Lamp BOOL %QX0.0', 'Other BOOL', 'Out2 BOOL'), [moved(n1), n2]) }).advance(10);
    expect([h.value('Go'), h.value('Lamp')]).toEqual([true, true]);
    expect(h.value('Start')).toBeUndefined();
  });

  test('a cold restart after the change shows the restarted program, not the old scan', () => {
    const [n1, n2] = [lamp(), other()];
    const h = paused([n1, n2]);
    h.send({ type: 'load', project: project(after(), [n1, renamed(n2)]) }).advance(10);
    h.send({ type: 'reset' }).advance(10);
    expect(h.frame.executed).toEqual(new Uint8Array([0, 0]));
    expect(h.value('Lamp')).toBe(false);
  });
});
