// Debugging ST in the simulator: the shown ST body's trace in every frame (values after the
// statement that last wrote them, lines that ran), breakpoints on lines, step into / over / out
// between LD and ST with the status path, a recorded scan's trace, the watchdog line.
import { describe, expect, test } from 'vitest';
import { SimHarness } from './harness';
import { project } from '../engine/stDebugProject';
import { positionWords, faultWords } from '../../src/editor/sim/position';
import { io, stProject, textPou, vars } from '../engine/stHelpers';
import type { SimFrame } from '../../src/sim/protocol';

const valuesOf = (t: SimFrame['text']) => Object.fromEntries((t?.values ?? []).map((v) => [v.name, `${String(v.value)}@${v.line}`]));

describe('the shown ST body in the frames', () => {
  test('the picked instance: values after the writing statement, lines that ran; another instance when picked', () => {
    const h = new SimHarness().send(
      { type: 'setView', view: { pou: 'Hyst', instance: 'H1' } },
      { type: 'load', project: project() },
      { type: 'write', name: 'Go', input: { value: true } },
      { type: 'write', name: 'Level', input: { value: 12 } },
      { type: 'step', scans: 1 },
    ).advance(0);
    expect(h.frame.text).toMatchObject({ pou: 'Hyst', instance: 'H1', scan: 1, stale: false, lines: [1, 2, 6, 7, 8, 9] });
    expect(valuesOf(h.frame.text)).toEqual({ Q: 'true@2', Count: '2@7', Twice: '2@8', Shown: 'true@9' });
    h.send({ type: 'write', name: 'Go', input: { value: false } }, { type: 'step', scans: 1 }).advance(0);
    // EN off: the body did not run in scan 2: every line dim, the values of scan 1.
    expect(h.frame.text).toMatchObject({ scan: 1, stale: true });
    h.send({ type: 'setView', view: { pou: 'Hyst', instance: 'H2' } }, { type: 'write', name: 'Go', input: { value: true } }, { type: 'step', scans: 1 }).advance(0);
    expect(h.frame.text).toMatchObject({ instance: 'H2', scan: 3, lines: [1, 3, 4, 6, 7, 8, 9] });
    // An LD body shown: no trace (the program runs on the fast path).
    h.send({ type: 'setView', view: { pou: 'Main' } });
    expect(h.frame.text).toBeUndefined();
  });

  test('a recorded scan carries the values it had', () => {
    const h = new SimHarness().send(
      { type: 'setView', view: { pou: 'Hyst', instance: 'H1' } },
      { type: 'load', project: project() },
      { type: 'write', name: 'Go', input: { value: true } },
      { type: 'step', scans: 3 },
    ).advance(0);
    expect(valuesOf(h.frame.text).Count).toBe('14@7');
    h.send({ type: 'historySeek', scan: 2 });
    const view = h.of('historyView').at(-1)!.view;
    expect(view.text).toMatchObject({ scan: 2, stale: false, lines: [1, 3, 4, 6, 7, 8, 9] });
    expect(valuesOf(view.text)).toMatchObject({ Count: '6@7', Twice: '6@8' });
    // The live frame is unchanged by the replay.
    h.send({ type: 'setCycle', cycleMs: 10 });
    expect(valuesOf(h.frame.text).Count).toBe('14@7');
  });
});

describe('breakpoints and steps', () => {
  test('a breakpoint on a line of one instance pauses there; step over, out, and into from LD', () => {
    const h = new SimHarness().send(
      { type: 'setView', view: { pou: 'Hyst', instance: 'H2' } },
      { type: 'setBreakpoints', lines: [{ pou: 'Hyst', line: 7, instance: 'H2' }] },
      { type: 'load', project: project() },
      { type: 'write', name: 'Go', input: { value: true } },
      { type: 'run' },
    );
    h.advance(30);
    expect(h.frame.mode).toBe('paused');
    expect(positionWords(h.frame.position!)).toBe('Main / network 3 → H2 (Hyst) / line 7');
    expect(h.frame.breakpointAt).toMatchObject({ pou: 'Hyst', instance: 'H2', line: 7 });
    // While paused the trace is the scan so far: line 7 is reached, its statement has not run.
    expect(h.frame.text?.lines).toEqual([1, 3, 4, 6, 7]);
    expect(valuesOf(h.frame.text).Count).toBe('1@6');
    h.send({ type: 'stepNetwork' });
    expect(positionWords(h.frame.position!)).toBe('Main / network 3 → H2 (Hyst) / line 8');
    expect(valuesOf(h.frame.text).Count).toBe('2@7');
    h.send({ type: 'stepNetwork', out: true });
    expect(positionWords(h.frame.position!)).toBe('Main / network 4');
    // Finish the scan, then into from the LD call of H1 (no breakpoint there).
    h.send({ type: 'setBreakpoints', lines: [] }, { type: 'stepNetwork', out: true }, { type: 'stepNetwork' }, { type: 'stepNetwork', into: true });
    expect(positionWords(h.frame.position!)).toBe('Main / network 2 → H1 (Hyst) / line 1');
    h.send({ type: 'stepNetwork', out: true });
    expect(positionWords(h.frame.position!)).toBe('Main / network 3');
  });

  test('a runaway WHILE loop faults naming the line', () => {
    const spin = textPou('Main', 'PROGRAM', [...io('input', 'Run BOOL'), ...vars('N DINT')], 'Run := TRUE;\nN := 0;\nWHILE Run DO\n  N := N + 1;\nEND_WHILE;');
    const h = new SimHarness().send({ type: 'step', scans: 1, project: stProject([spin]) }).advance(0);
    h.advance(3000);
    expect(h.frame.mode).toBe('faulted');
    expect(h.frame.fault).toMatchObject({ kind: 'watchdog', pou: 'Main', line: 3 });
    expect(faultWords(h.frame.fault!)).toMatch(/^Watchdog fault in Main line 3: scan exceeded .*looping in the loop at line 3 of Main/);
  });
});
