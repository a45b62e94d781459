// Debugging ST bodies: statement-level observation (the value each variable had after the statement
// that last wrote it, the lines that ran), breakpoints on lines, stepping over, into and out across
// LD and ST calls, the path of a pause, the watchdog naming the line of a runaway loop.
import { describe, expect, test } from 'vitest';
import type { Plc } from '../../src/engine/api';
import { breakpointAt, describePosition, step, type Breakpoint } from '../../src/engine/runtime/breakpoints';
import { ladder } from './ladder';
import { io, stPlc, stProject, textPou, vars } from './stHelpers';
import { pou } from './userBlocksHelpers';
import { box, project } from './stDebugProject';

const where = (plc: Plc) => describePosition(plc.position());

describe('observing an ST body', () => {
  test('per scan and instance: the lines that ran, and each value after the statement that last wrote it', () => {
    const plc = stPlc(project());
    plc.observeText([{ pou: 'Hyst', instance: 'H1' }]);
    plc.write('Go', true);
    plc.write('Level', 12);
    plc.scan();
    const t = plc.textTrace({ pou: 'Hyst', instance: 'H1' })!;
    expect(t).toMatchObject({ pou: 'Hyst', instance: 'H1', scan: 1 });
    // Line 3 (ELSIF) and 4 did not run: X > Hi.
    expect(t.lines).toEqual([1, 2, 6, 7, 8, 9]);
    // Every statement's line (END_IF holds none).
    expect(t.stops).toEqual([1, 2, 3, 4, 6, 7, 8, 9]);
    const byName = Object.fromEntries(t.values.map((v) => [v.name, [v.line, v.value]]));
    // Count: 2 after line 7 (written twice in the scan: the last write wins).
    expect(byName).toEqual({ Q: [2, true], Count: [7, 2], Twice: [8, 2], Shown: [9, true] });
    expect(plc.read('On1')).toBe(true);

    // The next scan, X between Lo and Hi: the ELSIF is tested, nothing written on line 2 or 4.
    plc.write('Level', 7);
    plc.scan();
    const t2 = plc.textTrace({ pou: 'Hyst', instance: 'H1' })!;
    expect(t2.scan).toBe(2);
    expect(t2.lines).toEqual([1, 3, 6, 7, 8, 9]);
    expect(t2.values.map((v) => `${v.name}@${v.line}=${String(v.value)}`)).toEqual(['Count@7=6', 'Twice@8=6', 'Shown@9=true']);
    // Only the picked instance is observed.
    expect(plc.textTrace({ pou: 'Hyst', instance: 'H2' })).toBeUndefined();
  });

  test('a body that did not run keeps the scan it last ran in; observing nothing returns to the fast path', () => {
    const plc = stPlc(project());
    plc.observeText([{ pou: 'Hyst', instance: 'H2' }]);
    plc.write('Go', true);
    plc.scans(3);
    expect(plc.textTrace({ pou: 'Hyst', instance: 'H2' })!.scan).toBe(3);
    // EN off: H2 no longer runs; its trace still describes scan 3.
    plc.write('Go', false);
    plc.scan();
    expect(plc.textTrace({ pou: 'Hyst' })!.scan).toBe(3);
    plc.observeText([]);
    plc.write('Go', true);
    plc.scan();
    expect(plc.textTrace({ pou: 'Hyst' })).toBeUndefined();
    // Same results on both tiers: Count doubled-plus-one 4 times (scans 1-3 and 5).
    expect(plc.read('H2.Count')).toBe(30);
  });

  test('values of a scan replayed from a saved image are the ones it had', () => {
    const plc = stPlc(project());
    plc.observeText([{ pou: 'Hyst', instance: 'H1' }]);
    plc.write('Go', true);
    plc.scan();
    const probe = plc.probe!();
    const image = probe.save();
    plc.write('Level', 20);
    plc.scan();
    expect(plc.textTrace({ pou: 'Hyst', instance: 'H1' })!.values.find((v) => v.name === 'Q')).toEqual({ name: 'Q', line: 2, type: 'BOOL', value: true });
    probe.restore(image);
    probe.replay(plc.timeMs + 10);
    const replayed = plc.textTrace({ pou: 'Hyst', instance: 'H1' })!;
    expect(replayed.scan).toBe(2);
    expect(replayed.values.find((v) => v.name === 'Q')).toEqual({ name: 'Q', line: 4, type: 'BOOL', value: false });
    expect(replayed.values.find((v) => v.name === 'Count')).toEqual({ name: 'Count', line: 7, type: 'INT', value: 6 });
  });
});

describe('breakpoints on lines', () => {
  const runToBreak = (plc: Plc, bps: readonly Breakpoint[], maxSteps = 200): Breakpoint | undefined => {
    for (let k = 0; k < maxSteps; k++) {
      const hit = breakpointAt(plc, bps);
      if (hit && k > 0) return hit;
      const r = plc.stepNetwork({ into: true });
      if (r.fault) throw new Error(r.fault.message);
    }
    return undefined;
  };

  test('a breakpoint on a line of one instance pauses there, with the path of the pause', () => {
    const plc = stPlc(project());
    plc.write('Go', true);
    const bp: Breakpoint = { pou: 'Hyst', network: -1, line: 7, instance: 'H2' };
    expect(runToBreak(plc, [bp])).toBe(bp);
    expect(where(plc)).toBe('Main / network 3 → H2 (Hyst) / line 7');
    // Line 6 ran, line 7 not yet.
    expect(plc.read('H2.Count')).toBe(1);
    expect(plc.read('H1.Count')).toBe(2);
  });

  test('a breakpoint in every instance pauses in each', () => {
    const plc = stPlc(project());
    plc.write('Go', true);
    const bp: Breakpoint = { pou: 'Hyst', network: -1, line: 8 };
    runToBreak(plc, [bp]);
    expect(where(plc)).toBe('Main / network 2 → H1 (Hyst) / line 8');
    runToBreak(plc, [bp]);
    expect(where(plc)).toBe('Main / network 3 → H2 (Hyst) / line 8');
  });

  test('observed values while paused are those of the scan so far', () => {
    const plc = stPlc(project());
    plc.observeText([{ pou: 'Hyst', instance: 'H1' }]);
    plc.write('Go', true);
    runToBreak(plc, [{ pou: 'Hyst', network: -1, line: 7 }]);
    const t = plc.textTrace({ pou: 'Hyst', instance: 'H1' })!;
    expect(t.lines).toEqual([1, 3, 4, 6, 7]);
    expect(t.values).toEqual([
      { name: 'Q', line: 4, type: 'BOOL', value: false },
      { name: 'Count', line: 6, type: 'INT', value: 1 },
    ]);
  });
});

describe('stepping across LD and ST', () => {
  test('into from the LD call to the ST body, over statements, into the LD FB it calls, out back to LD', () => {
    const plc = stPlc(project());
    plc.write('Go', true);
    const stops: string[] = [];
    const go = (kind: 'over' | 'into' | 'out') => {
      const r = step(plc, kind);
      stops.push(`${kind}: ${r.scanDone ? 'scan done' : where(plc)}`);
    };
    go('over'); // network 1 runs
    go('into'); // network 2 calls H1: before its first statement
    go('over'); // the IF (X = 0: not > 10): the ELSIF on line 3
    go('over'); // X < 5: line 4
    go('over');
    go('over');
    go('over');
    go('over');
    go('into'); // line 9 calls L (LD): before its network 1
    go('out'); // back in Hyst: after line 9, the body ends: on to Main network 3
    go('into'); // H2
    go('out'); // the rest of H2 whole: Main network 4
    go('out'); // out of the program: the scan ends
    expect(stops).toEqual([
      'over: Main / network 2',
      'into: Main / network 2 → H1 (Hyst) / line 1',
      'over: Main / network 2 → H1 (Hyst) / line 3',
      'over: Main / network 2 → H1 (Hyst) / line 4',
      'over: Main / network 2 → H1 (Hyst) / line 6',
      'over: Main / network 2 → H1 (Hyst) / line 7',
      'over: Main / network 2 → H1 (Hyst) / line 8',
      'over: Main / network 2 → H1 (Hyst) / line 9',
      'into: Main / network 2 → H1 (Hyst) / line 9 → H1.L (Lamp) / network 1',
      'out: Main / network 3',
      'into: Main / network 3 → H2 (Hyst) / line 1',
      'out: Main / network 4',
      'out: scan done',
    ]);
    expect([plc.read('After'), plc.read('H1.Count'), plc.read('H2.Count')]).toEqual([true, 2, 2]);
  });

  test('over a statement that calls an LD FB runs it whole; ST calling ST functions steps into the function', () => {
    const scale = textPou('Scale', 'FUNCTION', io('input', 'V INT'), 'Scale := V * 10;\nScale := Scale + 1;', { returnType: 'INT' });
    const main = textPou('Main', 'PROGRAM', vars('A INT', 'B INT'), 'A := 3;\nB := Scale(A);\nA := B;');
    const plc = stPlc(stProject([main, scale]));
    const stops: string[] = [];
    const go = (kind: 'over' | 'into' | 'out') => {
      const r = step(plc, kind);
      stops.push(r.scanDone ? 'scan done' : where(plc));
    };
    go('over'); // the scan starts: before line 1, which has not run
    expect(plc.read('A')).toBe(0);
    go('over');
    go('into');
    go('over');
    go('out');
    go('over');
    expect(stops).toEqual([
      'Main / line 1',
      'Main / line 2',
      'Main / line 2 → Scale / line 1',
      'Main / line 2 → Scale / line 2',
      'Main / line 3',
      'scan done',
    ]);
    expect(plc.read('A')).toBe(31);
  });
});

describe('the watchdog in an ST body', () => {
  test('a runaway WHILE loop faults naming the line, also while observed', () => {
    const loop = textPou('Spin', 'FUNCTION_BLOCK', [...io('input', 'Run BOOL'), ...vars('N DINT')], 'N := 0;\nWHILE Run DO\n  N := N + 1;\nEND_WHILE;');
    const main = pou('Main', 'PROGRAM', vars('Go BOOL', 'S1 Spin'), [ladder(['[Go] # # .', '. # # .'], { boxes: [box('Spin', 0, 1, { instance: 'S1' })] })]);
    for (const observed of [false, true]) {
      const plc = stPlc(stProject([main, loop]), { maxScanMs: 50 });
      if (observed) plc.observeText([{ pou: 'Spin' }]);
      plc.write('Go', true);
      const fault = plc.scan().fault!;
      expect(fault).toMatchObject({ kind: 'watchdog', pou: 'Spin', instance: 'S1', line: 2 });
      expect(fault.message).toMatch(/looping in the loop at line 2 of S1 \(Spin\)/);
    }
  });
});
