// Debugging user blocks: stepping into a call's body, the watchdog naming the instance, the power
// of one instance's body, the list of instances, online change keeping nested instance state.
import { describe, expect, test } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Plc } from '../../src/engine/api';
import { breakpointAt, needsStepInto, type Breakpoint } from '../../src/engine/runtime/breakpoints';
import { ladder, plcOf, vars, type BoxSpec } from './ladder';
import { io, multiProject, pou } from './userBlocksHelpers';

const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });

/** Motor (2 networks) with an inner Lamp FB (1 network); Main calls Motor1 in its network 2. */
function project() {
  const lamp = pou('Lamp', 'FUNCTION_BLOCK', [...io('input', 'On BOOL'), ...io('output', 'Lit BOOL')], [ladder(['[On] (Lit)'])]);
  const motor = pou('Motor', 'FUNCTION_BLOCK', [...io('input', 'Start BOOL'), ...io('output', 'Run BOOL'), ...vars('L Lamp')], [
    ladder(['[Start] (Run)']),
    ladder(['[Run] # # .', '. # # .'], { boxes: [box('Lamp', 0, 1, { instance: 'L' })] }),
  ]);
  const main = pou('Main', 'PROGRAM', vars('Go BOOL', 'Before BOOL', 'After BOOL', 'Run BOOL', 'Motor1 Motor', 'Motor2 Motor'), [
    ladder(['[Go] (Before)']),
    ladder(['[Go] # # (Run)', '. # # .'], { boxes: [box('Motor', 0, 1, { instance: 'Motor1' })] }),
    ladder(['[Run] (After)']),
    ladder(['[After] # # .', '. # # .'], { boxes: [box('Motor', 0, 1, { instance: 'Motor2' })] }),
  ]);
  return multiProject([main, motor, lamp]);
}

const where = (plc: Plc) => plc.position().map((f) => `${f.instance ? `${f.instance} (${f.pou})` : f.pou}/${f.network + 1}`).join(' → ');

describe('stepping into calls', () => {
  test('a step into stops before each network of the called bodies, at any depth', () => {
    const plc = plcOf(project());
    plc.write('Go', true);
    const stops: string[] = [];
    for (let k = 0; k < 12; k++) {
      const r = plc.stepNetwork({ into: true });
      stops.push(r.scanDone ? 'scan done' : where(plc));
      if (r.scanDone) break;
    }
    expect(stops).toEqual([
      'Main/2',
      'Main/2 → Motor1 (Motor)/1',
      'Main/2 → Motor1 (Motor)/2',
      'Main/2 → Motor1 (Motor)/2 → Motor1.L (Lamp)/1',
      'Main/3',
      'Main/4',
      'Main/4 → Motor2 (Motor)/1',
      'Main/4 → Motor2 (Motor)/2',
      'Main/4 → Motor2 (Motor)/2 → Motor2.L (Lamp)/1',
      'scan done',
    ]);
    expect([plc.read('Run'), plc.read('After'), plc.read('Motor1.L.Lit'), plc.read('Motor2.Run')]).toEqual([true, true, true, true]);
  });

  test('the step report says where execution stands; a plain step runs a call whole', () => {
    const plc = plcOf(project());
    plc.stepNetwork();
    const into = plc.stepNetwork({ into: true });
    expect(into).toMatchObject({
      executed: 1,
      next: 1,
      scanDone: false,
      frames: [{ pou: 'Main', network: 1 }, { pou: 'Motor', instance: 'Motor1', network: 0 }],
    });
    // A plain step from inside a body finishes the program's network.
    const over = plc.stepNetwork();
    expect(over).toMatchObject({ executed: 1, next: 2, frames: [{ pou: 'Main', network: 2 }] });
    expect(plc.position()).toEqual([{ pou: 'Main', network: 2 }]);
    // scan() completes a scan left inside a body.
    plc.stepNetwork({ into: true });
    plc.stepNetwork({ into: true });
    expect(plc.position().length).toBe(2);
    plc.scan();
    expect(plc.position()).toEqual([]);
    expect(plc.scanCount).toBe(1);
  });
});

describe('watchdog in a body', () => {
  test('a runaway loop inside an FB faults naming the POU, the instance and the network', () => {
    const spin = pou('Spin', 'FUNCTION_BLOCK', io('input', 'In BOOL'), [
      ladder(['[In] (In)']),
      ladder(['- >>AGAIN'], { label: 'AGAIN' }),
    ]);
    const main = pou('Main', 'PROGRAM', vars('S1 Spin'), [ladder(['- # # .'], { boxes: [box('Spin', 0, 1, { instance: 'S1' })] })]);
    const { program } = compileProgram(multiProject([main, spin]));
    const plc = createPlc(program!, { cycleMs: 10, maxNetworkEvaluations: 5000 });
    const report = plc.scan();
    expect(report.fault).toMatchObject({ kind: 'watchdog', pou: 'Spin', instance: 'S1', network: 1, networkLabel: 'AGAIN' });
    expect(report.fault!.message).toBe('watchdog: scan exceeded 5,000 network evaluations; looping in network 2 (label AGAIN) of S1 (Spin)');
    // Stepping into it faults the same way.
    plc.clearFault();
    let fault;
    for (let k = 0; k < 10_000 && !fault; k++) fault = plc.stepNetwork({ into: true }).fault;
    expect(fault).toMatchObject({ pou: 'Spin', instance: 'S1', network: 1 });
  });
});

describe('power and instances', () => {
  test("snapshot({ instance }) gives the instance's body, indexed like the FB's networks", () => {
    const plc = plcOf(project());
    plc.write('Go', true);
    plc.scan();
    expect(plc.instances()).toEqual([
      { path: 'Motor1', type: 'Motor' },
      { path: 'Motor1.L', type: 'Lamp' },
      { path: 'Motor2', type: 'Motor' },
      { path: 'Motor2.L', type: 'Lamp' },
    ]);
    const main = plc.snapshot();
    expect(main.pou).toBe('Main');
    expect(main.networks.length).toBe(4);
    const m1 = plc.snapshot({ instance: 'motor1' });
    expect(m1).toMatchObject({ pou: 'Motor', instance: 'Motor1' });
    expect(m1.networks.length).toBe(2);
    expect(m1.networks[0]!.executed).toBe(true);
    // [Start] (Run): contact and coil energised on both sides, executed.
    expect([...m1.networks[0]!.elements]).toEqual([7, 7]);
    const lamp = plc.snapshot({ instance: 'Motor2.L' });
    expect(lamp.pou).toBe('Lamp');
    expect([...lamp.networks[0]!.elements]).toEqual([7, 7]);
    plc.write('Go', false);
    plc.scan();
    // Start OFF: the contact has power on its left only, the coil none; both executed.
    expect([...plc.snapshot({ instance: 'Motor1' }).networks[0]!.elements]).toEqual([5, 4]);
    expect(() => plc.snapshot({ instance: 'Nope' })).toThrow(/Nope/);
  });

  test('online change keeps the state of nested instances by path and type', () => {
    const p = project();
    const before = plcOf(p);
    before.write('Go', true);
    before.scan();
    before.write('Go', false);
    const after = plcOf(p);
    const transfer = after.importState(before.exportState());
    expect(transfer.kept.map((i) => i.key)).toEqual(expect.arrayContaining(['MOTOR1', 'MOTOR1.L', 'MOTOR2.L']));
    expect(after.read('Motor1.Run')).toBe(true);
    expect(after.read('Motor1.L.Lit')).toBe(true);
    // A changed FB type resets that instance only.
    const renamed = { ...p, pous: p.pous.map((x) => (x.name === 'Main' ? { ...x, variables: x.variables.map((v) => (v.name === 'Motor2' ? { ...v, type: 'Lamp' } : v)) } : x)) };
    const { program } = compileProgram(renamed);
    expect(program).toBeUndefined(); // Motor2 is called as a Motor: LD-R10
  });
});

describe('breakpoints by POU and network', () => {
  const runToBreak = (plc: Plc, bps: Breakpoint[], maxSteps = 50): string | undefined => {
    for (let k = 0; k < maxSteps; k++) {
      const hit = k > 0 ? breakpointAt(plc, bps) : undefined;
      if (hit) return where(plc);
      const r = plc.stepNetwork({ into: needsStepInto(plc, bps) });
      if (r.scanDone) return 'scan done';
    }
    return undefined;
  };

  test('a breakpoint in an FB body stops in every instance, or in the one named', () => {
    const plc = plcOf(project());
    plc.write('Go', true);
    const any: Breakpoint[] = [{ pou: 'Motor', network: 1 }];
    expect(runToBreak(plc, any)).toBe('Main/2 → Motor1 (Motor)/2');
    expect(runToBreak(plc, any)).toBe('Main/4 → Motor2 (Motor)/2');
    expect(runToBreak(plc, any)).toBe('scan done');
    const named: Breakpoint[] = [{ pou: 'lamp', network: 0, instance: 'motor2.l' }];
    expect(runToBreak(plc, named)).toBe('Main/4 → Motor2 (Motor)/2 → Motor2.L (Lamp)/1');
    expect(runToBreak(plc, [{ pou: 'Main', network: 2 }])).toBe('scan done');
    expect(runToBreak(plc, [{ pou: 'Main', network: 2 }])).toBe('Main/3');
  });
});
