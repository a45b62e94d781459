// Running whole IEC programs in the simulator (issue 11): which program runs, the power and values
// of one chosen FB instance, step into / over / out, breakpoints in FB bodies.
import { describe, expect, test } from 'vitest';
import { buildLayout, describeName, readableNames } from '../../src/sim/layout';
import { SimHarness } from './harness';
import { configurationProject, mainProgram, motorFb, motorProject } from './monitorPrograms';
import { io, multiProject, pou } from '../engine/userBlocksHelpers';
import { ladder, vars } from '../engine/ladder';
import { faultWords, positionWords } from '../../src/editor/sim/position';
import type { SimFrame } from '../../src/sim/protocol';

const POWER_OUT = 2;
const where = (f: SimFrame) => (f.position ?? []).map((p) => `${p.instance ? `${p.instance} (${p.pou})` : p.pou}/${p.network + 1}`).join(' → ');

/** The layout after the last `compiled` or `layout` message. */
function currentLayout(h: SimHarness) {
  for (let i = h.messages.length - 1; i >= 0; i--) {
    const m = h.messages[i]!;
    if (m.type === 'layout') return m.layout;
    if (m.type === 'compiled' && m.layout) return m.layout;
  }
  throw new Error('no layout');
}

describe('which program runs', () => {
  test("the task's program runs, not the first PROGRAM of the project", () => {
    const other = { ...mainProgram('Other'), networks: [] };
    const project = { ...multiProject([other, mainProgram(), motorFb()]) };
    const tasked = { ...project, tasks: [{ ...project.tasks[0]!, programs: [{ instance: 'Inst', pou: 'Main' }] }] };
    const h = new SimHarness().send({ type: 'step', scans: 1, project: tasked });
    expect(h.layout.pou).toBe('Main');
    expect(h.layout.programs).toBeUndefined();
    expect(h.layout.instances?.map((i) => i.path)).toEqual(['Motor1', 'Motor2']);
  });

  test('several program instances in the tasks run as a configuration, each with its own variables', () => {
    const h = new SimHarness().send({ type: 'step', scans: 1, project: configurationProject() });
    expect(h.layout.programs).toEqual([
      { instance: 'Line1', pou: 'Main' },
      { instance: 'Line2', pou: 'Main' },
    ]);
    expect(h.layout.view).toEqual({ pou: 'Main', instance: 'Line1' });
    h.send({ type: 'write', name: 'Line2.Start1', input: { value: true } }, { type: 'step', scans: 1 });
    expect(h.value('Line2.Motor1.Run')).toBe(true);
    expect(h.value('Line1.Motor1.Run')).toBe(false);
    expect(h.layout.variables.find((v) => v.name === 'Line2.Motor1.Run')).toMatchObject({ type: 'BOOL', role: 'local' });
    expect(h.layout.instances?.map((i) => i.path)).toContain('Line2.Motor1');
    // The second program instance's networks, as the canvas shows them for Line2.
    h.send({ type: 'setView', view: { pou: 'Main', instance: 'Line2' } });
    expect(currentLayout(h).view).toEqual({ pou: 'Main', instance: 'Line2' });
  });
});

describe('monitoring one FB instance', () => {
  test("the canvas gets the power of the picked instance's body, aligned with the FB's networks", () => {
    const project = motorProject();
    const h = new SimHarness().send({ type: 'load', project }, { type: 'write', name: 'Start1', input: { value: true } }, { type: 'step', scans: 2 }).advance(0);
    expect(h.value('Motor1.Run')).toBe(true);
    h.send({ type: 'setView', view: { pou: 'Motor', instance: 'Motor1' } });
    let layout = currentLayout(h);
    const fb = project.pous.find((p) => p.name === 'Motor')!;
    expect(layout.networkIds).toEqual(fb.networks.map((n) => n.id));
    const coil = fb.networks[0]!.elements.findIndex((e) => e.kind === 'coil');
    const at = (k: number) => h.frame.elements[layout.elementOffsets[0]! + k]!;
    expect(at(coil) & POWER_OUT).toBe(POWER_OUT);
    h.send({ type: 'setView', view: { pou: 'Motor', instance: 'Motor2' } });
    layout = currentLayout(h);
    expect(layout.view).toEqual({ pou: 'Motor', instance: 'Motor2' });
    expect(at(coil) & POWER_OUT).toBe(0);
    // An edit keeps the view: the new program's layout describes the same body.
    const edited = { ...project, pous: project.pous.map((p) => (p.name === 'Main' ? { ...p, networks: [...p.networks] } : p)), name: 'edited' };
    h.send({ type: 'load', project: { ...edited, pous: [...edited.pous] } });
    expect(currentLayout(h).view).toEqual({ pou: 'Motor', instance: 'Motor2' });
  });

  test('a body variable of an instance can be forced by its path', () => {
    const h = new SimHarness().send({ type: 'step', scans: 1, project: motorProject() });
    h.send({ type: 'force', name: 'Motor2.Run', input: { value: true } }, { type: 'step', scans: 1 });
    expect(h.value('Motor2.Run')).toBe(true);
    expect(h.value('Motor2.Lamp')).toBe(true);
  });
});

describe('step into, over and out', () => {
  test('step into stops in the called body with the caller frame; over inside a body runs its network; out returns to the caller', () => {
    const project = motorProject();
    const h = new SimHarness().send({ type: 'load', project }, { type: 'write', name: 'Start1', input: { value: true } });
    // From a scan boundary, into the call of Main's network 1.
    h.send({ type: 'stepNetwork', into: true, project });
    expect(where(h.frame)).toBe('Main/1 → Motor1 (Motor)/1');
    // Over, inside the body: the body's network 1 runs whole, execution stays in the body.
    h.send({ type: 'stepNetwork' });
    expect(where(h.frame)).toBe('Main/1 → Motor1 (Motor)/2');
    expect(h.value('Motor1.Run')).toBe(true);
    expect(h.value('Motor1.Lamp')).toBe(false);
    // Over the body's last network: back in the caller, before its next network.
    h.send({ type: 'stepNetwork' });
    expect(where(h.frame)).toBe('Main/2');
    expect(h.value('Motor1.Lamp')).toBe(true);
    // Over a call: the whole call runs.
    h.send({ type: 'stepNetwork' });
    expect(where(h.frame)).toBe('Main/3');
    h.send({ type: 'stepNetwork' });
    expect(h.frame.position).toEqual([]);
    expect(h.frame.scan).toBe(1);
  });
});

describe('breakpoints in FB bodies', () => {
  test('a breakpoint in a body (by network id) stops in every instance, named; resuming goes on to the next one', () => {
    const project = motorProject();
    const fbNetwork = project.pous.find((p) => p.name === 'Motor')!.networks[1]!.id;
    const h = new SimHarness().send({ type: 'setBreakpoints', ids: [fbNetwork] }, { type: 'run', project });
    h.advance(30);
    expect(h.frame).toMatchObject({ mode: 'paused', breakpointHit: 1, breakpointAt: { pou: 'Motor', instance: 'Motor1', network: 1 } });
    expect(where(h.frame)).toBe('Main/1 → Motor1 (Motor)/2');
    const scan = h.frame.scan;
    h.send({ type: 'run' });
    h.advance(5);
    // The same scan, in the other instance's call.
    expect(h.frame.breakpointAt).toEqual({ pou: 'Motor', instance: 'Motor2', network: 1 });
    expect(where(h.frame)).toBe('Main/2 → Motor2 (Motor)/2');
    expect(h.frame.scan).toBe(scan);
    // Without the breakpoint the program runs on.
    h.send({ type: 'setBreakpoints', ids: [] }, { type: 'run' });
    h.advance(30);
    expect(h.frame.mode).toBe('running');
  });

  test('a breakpoint in a configuration program stops at the boundary of its first instance', () => {
    const project = configurationProject();
    const first = project.pous.find((p) => p.name === 'Main')!.networks[0]!.id;
    const h = new SimHarness().send({ type: 'setBreakpoints', ids: [first] }, { type: 'run', project });
    h.advance(30);
    expect(h.frame.breakpointAt).toEqual({ pou: 'Main', instance: 'Line1', network: 0 });
    h.send({ type: 'run' });
    h.advance(5);
    expect(h.frame.breakpointAt).toEqual({ pou: 'Main', instance: 'Line2', network: 0 });
  });
});

describe('names of a whole program', () => {
  test('instance paths are described from the project, nested and in a configuration', () => {
    const project = configurationProject();
    const main = project.pous[0]!;
    expect(describeName(project, main, 'Motor1.Run')).toMatchObject({ type: 'BOOL', role: 'local' });
    expect(describeName(project, main, 'Line1.Motor2.Lamp')).toMatchObject({ type: 'BOOL', role: 'local' });
    expect(describeName(project, main, 'Line1.Start1')).toMatchObject({ type: 'BOOL', role: 'input', location: '%IX0.0' });
    expect(describeName(project, main, 'Motor1.Nothing')).toBeUndefined();
    const names = readableNames(project, main).map((v) => v.name);
    expect(names).toEqual(expect.arrayContaining(['Start1', 'Motor1.Start', 'Motor1.Stop', 'Motor1.Run', 'Motor2.Lamp']));
    // A standard FB inside a user FB: its pins by path.
    const timed = { ...project, pous: project.pous.map((p) => (p.name === 'Motor' ? { ...p, variables: [...p.variables, ...vars('T1 TON')] } : p)) };
    expect(describeName(timed, main, 'Motor2.T1.ET')).toEqual({ name: 'Motor2.T1.ET', type: 'TIME', role: 'pin' });
    expect(readableNames(timed, main).map((v) => v.name)).toContain('Motor1.T1.Q');
    const layout = buildLayout(project, 'Main', ['Start1', 'Motor1.Run', 'Motor1.Lamp'], 10);
    expect(layout.variables.map((v) => v.name)).toEqual(['Start1', 'Motor1.Run', 'Motor1.Lamp']);
  });
});

describe('faults inside a body', () => {
  test('a runaway loop in an FB faults naming the instance, the POU and the network', () => {
    const loop = pou('Looper', 'FUNCTION_BLOCK', [...io('input', 'Go BOOL')], [ladder(['[Go] (Go)']), ladder(['>>AGAIN'], { label: 'AGAIN' })]);
    const main = pou('Main', 'PROGRAM', vars('L1 Looper', 'Go BOOL'), [ladder(['[Go] # .'], { boxes: [{ row: 0, col: 1, type: 'Looper', instance: 'L1' }] })]);
    const h = new SimHarness().send({ type: 'step', scans: 1, project: multiProject([main, loop]) });
    expect(h.frame.mode).toBe('faulted');
    expect(h.frame.fault).toMatchObject({ kind: 'watchdog', pou: 'Looper', instance: 'L1', network: 1 });
    expect(faultWords(h.frame.fault!)).toMatch(/^Watchdog fault in L1 \(Looper\) network 2 \(AGAIN\): /);
    expect(positionWords([{ pou: 'Main', network: 3 }, { pou: 'FB_Motor', instance: 'Motor1', network: 1 }])).toBe('Main / network 4 → Motor1 (FB_Motor) / network 2');
  });
});

describe('the scan history while an instance is monitored', () => {
  test("an FB's view of a recorded scan shows that instance's power flow as it was in that scan", () => {
    const project = motorProject();
    const fb = project.pous.find((p) => p.name === 'Motor')!;
    const coil = fb.networks[0]!.elements.findIndex((e) => e.kind === 'coil');
    // Start1 pressed in scan 2 only: Motor1's Run coil is lit in scans 2 and 3 (seal-in), off in scan 1.
    const h = new SimHarness().send({ type: 'setView', view: { pou: 'Motor', instance: 'Motor1' } }, { type: 'step', scans: 1, project });
    h.send({ type: 'write', name: 'Start1', input: { value: true } }, { type: 'step', scans: 1 });
    h.send({ type: 'write', name: 'Start1', input: { value: false } }, { type: 'step', scans: 1 });
    expect(h.layout.view).toEqual({ pou: 'Motor', instance: 'Motor1' });
    const layout = currentLayout(h);
    const coilOf = (scan: number) => {
      h.send({ type: 'historySeek', scan });
      const view = h.of('historyView').at(-1)!.view;
      expect(view.elements).toHaveLength(layout.elementOffsets.at(-1)!);
      return view.elements[layout.elementOffsets[0]! + coil]! & POWER_OUT;
    };
    expect(coilOf(1)).toBe(0);
    expect(coilOf(2)).toBe(POWER_OUT);
    // Motor2 never started: its body's coil is dark in the same recorded scan.
    h.send({ type: 'setView', view: { pou: 'Motor', instance: 'Motor2' } });
    expect(coilOf(2)).toBe(0);
    h.send({ type: 'setView', view: { pou: 'Main' } }, { type: 'historySeek', scan: 2 });
    const main = currentLayout(h);
    const view = h.of('historyView').at(-1)!.view;
    expect(view.elements).toHaveLength(main.elementOffsets.at(-1)!);
    expect(view.executed).toEqual(new Uint8Array([1, 1, 1]));
  });

  test('"Why?" inside an FB body explains the monitored instance in the recorded scan, naming values by path', () => {
    const project = motorProject();
    const fb = project.pous.find((p) => p.name === 'Motor')!;
    const coil = fb.networks[0]!.elements.findIndex((e) => e.kind === 'coil');
    // Motor1 started in scan 2 and Stop1 pressed in scan 3; Motor2 never ran its motor.
    const h = new SimHarness().send({ type: 'setView', view: { pou: 'Motor', instance: 'Motor1' } }, { type: 'step', scans: 1, project });
    h.send({ type: 'write', name: 'Start1', input: { value: true } }, { type: 'step', scans: 1 });
    h.send({ type: 'write', name: 'Start1', input: { value: false } }, { type: 'write', name: 'Stop1', input: { value: true } }, { type: 'step', scans: 1 });
    const why = (scan: number) => {
      h.send({ type: 'explain', id: scan, scan, target: { kind: 'element', network: 0, element: coil } });
      return h.of('explanation').at(-1)!.explanation;
    };
    const on = why(2);
    expect(on.title).toBe('( ) Motor1.Run: Motor1.Run is TRUE after scan 2');
    expect(on.lines.join('\n')).toMatch(/energised through/);
    const off = why(3);
    expect(off.title).toBe('( ) Motor1.Run: Motor1.Run is FALSE after scan 3');
    expect(off.lines.join('\n')).toMatch(/\|\/\| Motor1\.Stop is open: Motor1\.Stop is TRUE/);
    // The marks name the FB body's elements, which the FB tab shows.
    const stop = fb.networks[0]!.elements.find((e) => e.kind === 'contact' && e.variable === 'Stop')!;
    expect(off.marks.some((m) => m.elementId === stop.id && m.role === 'blocking')).toBe(true);
    // The other instance, in the same scan: its own story.
    h.send({ type: 'setView', view: { pou: 'Motor', instance: 'Motor2' } });
    expect(why(3).title).toBe('( ) Motor2.Run: Motor2.Run is FALSE after scan 3');
  });

  test('"Why?" on the program follows a value into the FB body that wrote it', () => {
    const project = motorProject();
    const h = new SimHarness().send({ type: 'step', scans: 1, project });
    h.send({ type: 'write', name: 'Start1', input: { value: true } }, { type: 'step', scans: 1 });
    h.send({ type: 'explain', id: 1, scan: 2, target: { kind: 'variable', name: 'Motor1.Run' } });
    const text = h.of('explanation').at(-1)!.explanation.lines.join('\n');
    expect(text).toMatch(/network 1 of Motor1 \(Motor\)/);
  });
});
