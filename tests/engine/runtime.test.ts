// The scan cycle: clocks, input/output images, restarts, forcing, watchdog, stepping, snapshots.
import { describe, expect, test } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { ladder, plcOf, project, vars } from './ladder';

const seal = () =>
  project(vars('Start BOOL %IX0.0', 'Stop BOOL %IX0.1', 'Motor BOOL %QX0.0', 'Lamp BOOL %QX0.1'), [
    ladder(['[Start] + [/Stop] (Motor)', '[Motor] + . .']),
    ladder(['[Motor] - - (Lamp)']),
  ]);

describe('scan cycle', () => {
  test('virtual clock: scan k starts at (k-1) x cycle', () => {
    const plc = plcOf(seal(), 25);
    expect(plc.scan()).toMatchObject({ scan: 1, timeMs: 0 });
    expect(plc.scans(3)).toMatchObject({ scan: 4, timeMs: 75 });
    expect(plc.timeMs).toBe(75);
  });

  test('an injected real clock gives timers their time', () => {
    let t = 1_000_000;
    const p = project(vars('Go BOOL := TRUE', 'T1 TON', 'Q BOOL'), [
      ladder(['[Go] # # - (Q)', '. # # . .'], {
        boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#1s' } }],
      }),
    ]);
    const plc = createPlc(compileProgram(p).program!, { cycleMs: 10, clock: { now: () => t } });
    plc.scan();
    t += 999;
    plc.scan();
    expect(plc.read('Q')).toBe(false);
    expect(plc.timeMs).toBe(999);
    t += 1;
    plc.scan();
    expect(plc.read('Q')).toBe(true);
  });

  test('inputs are latched at the start of a scan; outputs are written at its end', () => {
    const plc = plcOf(seal());
    plc.write('Start', true); // an input: goes to the input image, not the variable
    expect(plc.read('Start')).toBe(false);
    plc.scan();
    expect(plc.read('Start')).toBe(true);
    expect(plc.outputs()).toEqual({ '%QX0.0': true, '%QX0.1': true });
  });

  test('stepping runs one network at a time; the output image changes only when the scan ends', () => {
    const plc = plcOf(seal());
    plc.setInputs({ '%IX0.0': true });
    expect(plc.nextNetwork).toBe(-1);
    expect(plc.stepNetwork()).toEqual({ executed: 0, next: 1, scanDone: false });
    expect(plc.read('Motor')).toBe(true);
    expect(plc.outputs()['%QX0.0']).toBe(false);
    expect(plc.snapshot().networks.map((n) => n.executed)).toEqual([true, false]);
    expect(plc.stepNetwork()).toEqual({ executed: 1, next: -1, scanDone: true });
    expect(plc.outputs()).toEqual({ '%QX0.0': true, '%QX0.1': true });
    expect(plc.scanCount).toBe(1);
  });

  test('scan() in the middle of a stepped scan finishes that scan', () => {
    const plc = plcOf(seal());
    plc.stepNetwork();
    expect(plc.scan()).toMatchObject({ scan: 1 });
    expect(plc.nextNetwork).toBe(-1);
  });

  test('runUntil stops when the condition holds', () => {
    const p = project(vars('Go BOOL := TRUE', 'T1 TON', 'Q BOOL'), [
      ladder(['[Go] # # - (Q)', '. # # . .'], {
        boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#100ms' } }],
      }),
    ]);
    const plc = plcOf(p, 10);
    expect(plc.runUntil((x) => x.read('Q') === true, 100)).toBe(true);
    expect(plc.scanCount).toBe(11); // scan 11 starts at 100 ms
    expect(plc.runUntil(() => false, 5)).toBe(false);
  });

  test('power snapshot: element bytes (left, right, executed) and vertical links', () => {
    const plc = plcOf(seal());
    plc.setInputs({ '%IX0.0': true });
    plc.scan();
    const [n1] = plc.snapshot().networks;
    // elements: Start, /Stop, Motor coil, Motor contact; vlink at boundary 1.
    expect([...n1!.elements]).toEqual([7, 7, 7, 5]);
    expect([...n1!.vlinks]).toEqual([1]);
  });
});

describe('reading and writing', () => {
  test('by name, location, FB pin and bit; errors name the problem', () => {
    const p = project(vars('W WORD', 'N INT %MW4', 'T1 TON', 'X BOOL %QX0.3'), [ladder(['[W.2] (X)'])]);
    const plc = plcOf(p);
    plc.write('W.2', true);
    plc.scan();
    expect(plc.read('W')).toBe(4);
    expect(plc.read('%QX0.3')).toBe(true);
    plc.write('%MW4', 40000);
    expect(plc.read('N')).toBe(40000 - 65536); // INT wraps like a PLC store
    plc.write('T1.PT', 1500);
    expect(plc.read('T1.PT')).toBe(1500);
    expect(() => plc.read('Nope')).toThrow(/Nope.*not declared/);
    expect(() => plc.write('X', 3)).toThrow(/BOOL/);
    expect(() => plc.setInputs({ '%IX7.0': true })).toThrow(/no input variable/);
    expect(plc.variableNames()).toEqual(['W', 'N', 'X', 'T1.IN', 'T1.PT', 'T1.Q', 'T1.ET']);
    expect(Object.keys(plc.values())).toEqual(['W', 'N', 'X']);
  });
});

describe('restarts', () => {
  const p = () =>
    project(
      vars(
        'A BOOL',
        'Plain INT := 7',
        'Kept INT := 7 RETAIN',
        'Latched BOOL',
        'Set BOOL',
        'C1 CTU RETAIN',
        'C2 CTU',
      ),
      [
        ladder(['[A] (SM:Latched)']),
        ladder(['[A] (S:Set)']),
        ladder(['[A] # #', '. # #', '. # #'], {
          boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { R: 'FALSE', PV: '5' } }],
        }),
        ladder(['[A] # #', '. # #', '. # #'], {
          boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C2', inputs: { R: 'FALSE', PV: '5' } }],
        }),
      ],
    );
  const run = () => {
    const plc = plcOf(p());
    plc.write('Plain', 1);
    plc.write('Kept', 2);
    plc.write('A', true);
    plc.scan();
    plc.write('A', false);
    return plc;
  };

  test('warm restart keeps RETAIN variables, M/SM/RM-coil variables and RETAIN FB instances', () => {
    const plc = run();
    plc.warmRestart();
    expect(plc.values()).toMatchObject({ Plain: 7, Kept: 2, Latched: true, Set: false });
    expect(plc.read('C1.CV')).toBe(1);
    expect(plc.read('C2.CV')).toBe(0);
  });

  test('cold restart gives every variable its initial value and resets every FB', () => {
    const plc = run();
    plc.coldRestart();
    expect(plc.values()).toMatchObject({ Plain: 7, Kept: 7, Latched: false, Set: false });
    expect(plc.read('C1.CV')).toBe(0);
    expect(plc.scanCount).toBe(0);
  });

  test('cold restart clears edge memories: a P contact fires again on the first scan', () => {
    const plc = plcOf(project(vars('A BOOL := TRUE', 'X BOOL'), [ladder(['[P:A] (X)'])]));
    plc.scans(2);
    expect(plc.read('X')).toBe(false);
    plc.coldRestart();
    plc.scan();
    expect(plc.read('X')).toBe(true);
  });
});

describe('forcing', () => {
  test('a forced input overrides the input image', () => {
    const plc = plcOf(seal());
    plc.force('Start', true);
    plc.setInputs({ '%IX0.0': false });
    plc.scan();
    expect(plc.read('Start')).toBe(true);
    expect(plc.read('Motor')).toBe(true);
    expect(plc.forced()).toEqual(new Map([['Start', true]]));
    plc.unforce('Start');
    plc.scan();
    expect(plc.read('Start')).toBe(false); // the input image comes back at the next input read
  });

  test('a forced output: program writes do not stick, the variable and the output image show the forced value', () => {
    const plc = plcOf(seal());
    plc.force('%QX0.0', true);
    plc.scan();
    expect(plc.read('Motor')).toBe(true);
    // Lamp follows Motor in a later network: it reads the forced value.
    expect(plc.outputs()).toEqual({ '%QX0.0': true, '%QX0.1': true });
    plc.write('Motor', false);
    expect(plc.read('Motor')).toBe(true);
    plc.unforceAll();
    plc.setInputs({ '%IX0.1': true });
    plc.scan();
    expect(plc.read('Motor')).toBe(false);
    expect(plc.forced().size).toBe(0);
  });

  test('a forced variable reads the forced value even right after a coil in the same network', () => {
    const plc = plcOf(project(vars('A BOOL', 'X BOOL', 'Y BOOL'), [ladder(['[A] (X)', '[X] (Y)'])]));
    plc.force('X', true);
    plc.scan();
    expect(plc.read('Y')).toBe(true);
  });

  test('FB pins cannot be forced', () => {
    const plc = plcOf(project(vars('A BOOL', 'X BOOL', 'T1 TON'), [ladder(['[A] (X)'])]));
    expect(() => plc.force('T1.Q', true)).toThrow(/only variables/);
  });
});

describe('watchdog', () => {
  const loop = () =>
    project(vars('A BOOL', 'X BOOL'), [
      ladder(['[A] (X)']),
      ladder(['[A] (X)']),
      ladder(['>>LOOP'], { label: 'LOOP' }),
    ]);

  test('a runaway backward jump faults quickly with the network named', () => {
    const plc = plcOf(loop());
    const report = plc.scan();
    expect(report.fault).toEqual({
      kind: 'watchdog',
      pou: 'Main',
      network: 2,
      networkLabel: 'LOOP',
      message: 'watchdog: scan exceeded 10,300 network evaluations; looping in network 3 (label LOOP)',
    });
    expect(plc.fault).toBe(report.fault);
  });

  test('a faulted PLC stays faulted until clearFault or a cold restart', () => {
    const plc = plcOf(loop());
    plc.scan();
    const count = plc.scanCount;
    plc.scans(5);
    expect(plc.scanCount).toBe(count);
    expect(plc.stepNetwork().fault?.kind).toBe('watchdog');
    plc.clearFault();
    expect(plc.fault).toBeUndefined();
    plc.scan();
    expect(plc.fault?.kind).toBe('watchdog');
    plc.coldRestart();
    expect(plc.fault).toBeUndefined();
  });

  test('the evaluation budget can be set', () => {
    const { program } = compileProgram(loop());
    const plc = createPlc(program!, { cycleMs: 10, maxNetworkEvaluations: 50 });
    expect(plc.scan().fault?.message).toBe(
      'watchdog: scan exceeded 50 network evaluations; looping in network 3 (label LOOP)',
    );
  });
});

describe('stepping through jumps', () => {
  test('stepNetwork follows a jump and reports the network it lands on', () => {
    const p = project(vars('A BOOL := TRUE', 'X BOOL', 'Y BOOL'), [
      ladder(['[A] >>END']),
      ladder(['[A] (X)']),
      ladder(['[A] (Y)'], { label: 'END' }),
    ]);
    const plc = plcOf(p);
    expect(plc.stepNetwork()).toEqual({ executed: 0, next: 2, scanDone: false });
    expect(plc.nextNetwork).toBe(2);
    expect(plc.stepNetwork()).toEqual({ executed: 2, next: -1, scanDone: true });
    expect([plc.read('X'), plc.read('Y')]).toEqual([false, true]);
    expect(plc.snapshot().networks.map((n) => n.executed)).toEqual([true, false, true]);
    // A full scan afterwards runs the same path.
    plc.scan();
    expect(plc.snapshot().networks.map((n) => n.executed)).toEqual([true, false, true]);
  });
});
