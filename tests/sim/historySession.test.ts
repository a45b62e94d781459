// The scan history in the simulation session: every scan recorded while running, a frozen view of
// any scan (power and values as they were) while the program runs on, change and condition search,
// "Why?" at a recorded scan, trace and scenario export, and a scenario replayed into the timeline.
import { describe, expect, test } from 'vitest';
import { POWER_OUT } from '../../src/editor/sim/useSimOverlay';
import { EXAMPLES } from '../../src/model/examples';
import { SimHarness } from './harness';
import { motorProgram, timerProgram } from './programs';

const lastOf = <T,>(xs: T[]): T => xs[xs.length - 1]!;

/** Runs the motor, with a one-scan pulse of Start at a known scan. */
function pulsed(): { h: SimHarness; pulseScan: number } {
  const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(200);
  h.send({ type: 'pause' });
  const pulseScan = h.frame.scan + 1;
  h.send({ type: 'write', name: 'Start', input: { value: true } }, { type: 'step', scans: 1 });
  h.advance(5);
  h.send({ type: 'write', name: 'Start', input: { value: false } }, { type: 'write', name: 'Stop', input: { value: true } }, { type: 'step', scans: 1 });
  h.advance(5);
  h.send({ type: 'write', name: 'Stop', input: { value: false } }, { type: 'run' }).advance(300);
  return { h, pulseScan };
}

describe('scan history in the session', () => {
  test('records every scan while running; frames say which scans can be seeked', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(1000);
    expect(h.frame.history).toMatchObject({ first: 1, last: h.frame.scan });
  });

  test('shows a one-scan pulse exactly as it was while the program runs on', () => {
    const { h, pulseScan } = pulsed();
    const start = h.layout.variables.findIndex((v) => v.name === 'Start');
    const motor = h.layout.variables.findIndex((v) => v.name === 'Motor');
    h.send({ type: 'historySeek', scan: pulseScan });
    const view = lastOf(h.of('historyView')).view;
    expect(view.scan).toBe(pulseScan);
    expect(view.values[start]).toBe(true);
    expect(view.values[motor]).toBe(true);
    expect(view.elements[3]! & POWER_OUT).toBe(POWER_OUT); // the Motor coil was lit in that scan
    h.send({ type: 'historySeek', scan: pulseScan + 1 });
    expect(lastOf(h.of('historyView')).view.values[motor]).toBe(false);
    expect(h.frame.mode).toBe('running');
  });

  test('finds the next change of a variable and the next scan where a condition holds', () => {
    const { h, pulseScan } = pulsed();
    h.send({ type: 'historyFind', from: 1, direction: 1, change: 'Start' });
    expect(lastOf(h.of('historyView')).view.scan).toBe(pulseScan);
    h.send({ type: 'historyFind', from: 1, direction: 1, condition: 'Motor AND NOT Start' });
    // Motor was on only while Start was pressed (Stop came in the next scan).
    expect(lastOf(h.of('historyNotFound')).message).toMatch(/^Motor AND NOT Start does not hold in any later recorded scan \(scans 1 to \d+ are recorded\)$/);
    h.send({ type: 'historyFind', from: 1, direction: 1, condition: 'Stop AND NOT Motor' });
    expect(lastOf(h.of('historyView')).view.scan).toBe(pulseScan + 1);
    h.send({ type: 'historyFind', from: pulseScan + 1, direction: 1, condition: 'Start OR Stop' });
    expect(lastOf(h.of('historyNotFound')).message).toMatch(/^Start OR Stop does not hold in any later recorded scan/);
  });

  test('explains why Motor is off at a recorded scan: the open Stop contact', () => {
    const { h, pulseScan } = pulsed();
    h.send({ type: 'explain', id: 7, scan: pulseScan + 1, target: { kind: 'variable', name: 'Motor' } });
    const e = lastOf(h.of('explanation'));
    expect(e.id).toBe(7);
    expect(e.explanation.title).toBe(`Motor is FALSE after scan ${pulseScan + 1}`);
    expect(e.explanation.lines.join('\n')).toContain('|/| Stop is open: Stop is TRUE');
    expect(e.explanation.links[0]).toMatchObject({ scan: pulseScan + 1, label: expect.stringContaining('When did it change?') });
  });

  test('exports the recorded range as a trace CSV and as a scenario that passes', () => {
    const { h, pulseScan } = pulsed();
    h.send({ type: 'historyExport', id: 1, format: 'trace', names: ['Start', 'Motor'], from: pulseScan - 1, to: pulseScan + 1 });
    expect(lastOf(h.of('historyText')).text).toBe(
      `scan,time_ms,Start,Motor\n${pulseScan - 1},${(pulseScan - 2) * 10},0,0\n${pulseScan},${(pulseScan - 1) * 10},1,1\n${pulseScan + 1},${pulseScan * 10},0,0\n`,
    );
    h.send({ type: 'historyExport', id: 2, format: 'scenario', inputs: ['Start', 'Stop'], outputs: ['Motor'], from: 1 });
    const csv = lastOf(h.of('historyText')).text;
    expect(csv).toContain('scan,Start,Stop,expect Motor\n1,0,0,0\n');
    expect(csv).toContain(`${pulseScan},1,,1\n${pulseScan + 1},0,1,0\n${pulseScan + 2},,0,0\n`);
    // Replayed in the simulator, the recorded scenario passes.
    h.send({ type: 'replayScenario', id: 3, project: motorProgram(), scenario: { name: 'recorded', csv } });
    expect(lastOf(h.of('scenarioReplayed')).result).toMatchObject({ ok: true });
  });

  test('a failing scenario replay stops at the first divergent scan, recorded for the timeline', () => {
    const motor = EXAMPLES.find((e) => e.id === 'motor-start-stop')!.build();
    const bad = { name: 'wrong', csv: 'scan,Start,Stop,expect Motor\n1,1,0,1\n4,0,1,1\n8,0,0,0\n' };
    const h = new SimHarness().send({ type: 'replayScenario', id: 1, project: motor, scenario: bad });
    const result = lastOf(h.of('scenarioReplayed')).result;
    expect(result).toMatchObject({ ok: false, scans: 4, divergences: [{ scan: 4, name: 'Motor', expected: '1', actual: '0', line: 3 }] });
    expect(h.frame).toMatchObject({ mode: 'paused', scan: 4, history: { first: 1, last: 4 } });
    // Run goes on from there, in time.
    h.send({ type: 'step', scans: 2 }).advance(10);
    expect(h.frame.scan).toBe(6);
    expect(h.frame.timeMs).toBe(50);
  });

  test('scans from thousands of scans ago show exactly what the frames showed then, through writes, forces and gateway inputs', () => {
    const h = new SimHarness().send({ type: 'run', project: timerProgram() }).advance(1000);
    const seen: { scan: number; values: unknown[]; elements: number[] }[] = [];
    const snap = () => {
      h.send({ type: 'pause' });
      seen.push({ scan: h.frame.scan, values: [...h.frame.values], elements: [...h.frame.elements] });
    };
    snap();
    h.send({ type: 'write', name: 'Enable', input: { value: false } }, { type: 'step', scans: 3 }).advance(50);
    snap();
    h.send({ type: 'setInputs', values: { '%IX0.0': true } }, { type: 'step', scans: 6 }).advance(100);
    snap(); // the timer half-way
    h.send({ type: 'run' }).advance(250);
    snap();
    h.send({ type: 'force', name: 'Lamp', input: { value: false } }, { type: 'run' }).advance(20_000);
    h.send({ type: 'setInputs', values: { '%IX0.0': false } }).advance(300);
    h.send({ type: 'setInputs', values: { '%IX0.0': true } }).advance(35);
    snap();
    h.send({ type: 'unforce', name: 'Lamp' }, { type: 'setInputs', values: { '%IX0.0': false } }, { type: 'run' }).advance(30_000);
    const et = h.layout.variables.findIndex((v) => v.name === 'T1.ET');
    expect(seen.map((s) => s.values[et])).toEqual([100, 0, 50, 100, expect.any(Number)]);
    expect(h.frame.history!.last - h.frame.history!.first).toBeGreaterThan(5000);
    for (const then of seen.reverse()) {
      h.send({ type: 'historySeek', scan: then.scan });
      const view = lastOf(h.of('historyView')).view;
      expect(view.values, `values after scan ${then.scan}`).toEqual(then.values);
      expect([...view.elements], `power of scan ${then.scan}`).toEqual(then.elements);
    }
  });

  test('a cold restart and a new program start the history over; the budget applies', () => {
    const h = new SimHarness().send({ type: 'setHistory', maxScans: 30, budgetBytes: 1 << 20 }, { type: 'run', project: motorProgram() }).advance(1000);
    expect(h.frame.history!.last - h.frame.history!.first + 1).toBe(30);
    h.send({ type: 'reset' });
    expect(h.frame.history).toBeUndefined();
  });
});
