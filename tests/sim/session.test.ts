import { describe, expect, test } from 'vitest';
import { POWER_OUT } from '../../src/editor/sim/useSimOverlay';
import type { Plc } from '../../src/engine/api';
import { realEngine } from '../../src/sim/engineAdapter';
import type { SimEngine } from '../../src/sim/simEngine';
import { SimHarness } from './harness';
import { brokenProgram, motorProgram, runawayProgram, threeNetworks, timerProgram } from './programs';

describe('compiling on Run', () => {
  test('a program with errors is refused, the problems are named, and nothing runs', () => {
    const h = new SimHarness().send({ type: 'run', project: brokenProgram() });
    const [compiled] = h.of('compiled');
    expect(compiled?.ok).toBe(false);
    expect(compiled?.diagnostics.some((d) => d.rule === 'LD-R08' && d.network === 0 && d.message.includes('Nowhere'))).toBe(true);
    h.advance(100);
    // One frame says so: stopped, no program, nothing scanned.
    expect(h.of('frame')).toHaveLength(1);
    expect(h.frame).toMatchObject({ mode: 'stopped', scan: 0, program: null, values: [] });
  });

  test('a valid program compiles and starts running', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() });
    expect(h.of('compiled')[0]?.ok).toBe(true);
    expect(h.layout.variables.map((v) => v.name)).toEqual(expect.arrayContaining(['Start', 'Stop', 'Motor']));
    h.advance(100);
    expect(h.frame.mode).toBe('running');
    expect(h.frame.scan).toBeGreaterThanOrEqual(10);
  });
});

describe('running the motor seal-in', () => {
  test('Start energises Motor, which stays on after Start is released, until Stop', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(50);
    expect(h.value('Motor')).toBe(false);
    h.send({ type: 'write', name: 'Start', input: { value: true } }).advance(50);
    expect(h.value('Motor')).toBe(true);
    expect(h.powerOf(3) & POWER_OUT).toBe(POWER_OUT); // the coil is lit
    h.send({ type: 'write', name: 'Start', input: { value: false } }).advance(50);
    expect(h.value('Motor')).toBe(true);
    h.send({ type: 'write', name: 'Stop', input: { text: 'TRUE' } }).advance(50);
    expect(h.value('Motor')).toBe(false);
    expect(h.powerOf(3) & POWER_OUT).toBe(0);
  });

  test('the loop keeps the cycle: 1 s of wall time at 10 ms is 100 scans, in virtual steps of the cycle', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(1000).send({ type: 'pause' });
    expect(h.frame.scan).toBe(101); // scans start at 0, 10, ..., 1000 ms
    expect(h.frame.timeMs).toBe(1000);
    expect(h.frame.overruns).toBe(0);
  });

  test('frames are posted at display rate, not once per scan', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(1000);
    const frames = h.of('frame').length;
    expect(frames).toBeLessThan(60);
    expect(frames).toBeGreaterThan(10);
  });

  test('a worker that falls far behind drops scans, counts them as overruns and keeps real time', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() });
    h.scheduler.advance(0);
    // Simulate a stall: the clock jumps 5 s while no timer could fire.
    h.scheduler.stall(5000);
    h.advance(20);
    expect(h.frame.overruns).toBeGreaterThan(400);
    expect(h.frame.timeMs).toBeGreaterThanOrEqual(5000);
  });

  test('Pause stops scanning; Run continues from the same scan', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(100).send({ type: 'pause' });
    const scan = h.frame.scan;
    expect(h.frame.mode).toBe('paused');
    h.advance(500);
    expect(h.frame.scan).toBe(scan);
    h.send({ type: 'run' }).advance(100);
    expect(h.frame.scan).toBeGreaterThan(scan);
  });
});

describe('stepping', () => {
  test("each Step scan advances the PLC clock by one cycle, and TON's ET with it", () => {
    const h = new SimHarness().send({ type: 'setCycle', cycleMs: 20 }, { type: 'step', scans: 1, project: timerProgram() });
    expect(h.frame).toMatchObject({ mode: 'paused', scan: 1, timeMs: 0 });
    expect(h.value('T1.ET')).toBe(0);
    h.send({ type: 'step', scans: 1 });
    expect(h.frame).toMatchObject({ scan: 2, timeMs: 20 });
    expect(h.value('T1.ET')).toBe(20);
    h.send({ type: 'step', scans: 3 }).settle();
    expect(h.frame.scan).toBe(5);
    expect(h.value('T1.ET')).toBe(80);
    expect(h.value('Lamp')).toBe(false);
    h.send({ type: 'step', scans: 1 });
    expect(h.value('T1.ET')).toBe(100);
    expect(h.value('Lamp')).toBe(true);
  });

  test('Step network runs one network at a time and reports the next one', () => {
    const h = new SimHarness().send({ type: 'stepNetwork', project: threeNetworks() });
    expect(h.frame.nextNetwork).toBe(1);
    expect(h.frame.scan).toBe(1); // the scan in progress
    h.send({ type: 'stepNetwork' });
    expect(h.frame.nextNetwork).toBe(2);
    h.send({ type: 'stepNetwork' });
    expect(h.frame.nextNetwork).toBe(-1);
    expect(h.frame.scan).toBe(1);
    expect(h.frame.mode).toBe('paused');
  });

  test('Step scan in the middle of a scan finishes that scan', () => {
    const h = new SimHarness().send({ type: 'stepNetwork', project: threeNetworks() }, { type: 'step', scans: 1 });
    expect(h.frame.scan).toBe(1);
    expect(h.frame.nextNetwork).toBe(-1);
  });
});

describe('breakpoints', () => {
  test('execution pauses before the network with a breakpoint, and Run continues past it', () => {
    const h = new SimHarness().send({ type: 'setBreakpoints', networks: [2] }, { type: 'run', project: threeNetworks() });
    h.advance(50);
    expect(h.frame.mode).toBe('paused');
    expect(h.frame.breakpointHit).toBe(2);
    expect(h.frame.scan).toBe(1); // stopped inside the first scan
    h.send({ type: 'run' }).advance(15);
    // That scan finishes, and the breakpoint stops the next one.
    expect(h.frame).toMatchObject({ mode: 'paused', breakpointHit: 2, scan: 2, nextNetwork: 2 });
  });

  test('a breakpoint on the first network stops before the input read', () => {
    const h = new SimHarness().send({ type: 'setBreakpoints', networks: [0] }, { type: 'step', scans: 5, project: motorProgram() }).settle();
    expect(h.frame).toMatchObject({ mode: 'paused', breakpointHit: 0, scan: 0, nextNetwork: -1 });
    h.send({ type: 'setBreakpoints', networks: [] }, { type: 'step', scans: 5 }).settle();
    expect(h.frame.scan).toBe(5);
  });
});

describe('faults', () => {
  test('a runaway backward jump faults with the network named, and Run is refused until Reset', () => {
    const h = new SimHarness().send({ type: 'run', project: runawayProgram() }).advance(20);
    expect(h.frame.mode).toBe('faulted');
    expect(h.frame.fault?.kind).toBe('watchdog');
    expect(h.frame.fault?.network).toBe(1);
    expect(h.frame.fault?.networkLabel).toBe('LOOP');
    h.send({ type: 'run' });
    expect(h.of('error').at(-1)?.message).toMatch(/faulted/);
    h.send({ type: 'reset' });
    expect(h.frame).toMatchObject({ mode: 'stopped', scan: 0 });
    expect(h.frame.fault).toBeUndefined();
  });
});

describe('design decision: an internal error is reported, never a silent hang', () => {
  test('a scan that throws stops the run in Paused with the error shown', () => {
    // An engine whose fourth scan throws, standing in for a bug; a PLC fault is a different thing (above).
    const failing: SimEngine = {
      ...realEngine,
      createPlc(program, options) {
        const plc = realEngine.createPlc(program, options);
        let scans = 0;
        return new Proxy(plc, {
          get(target, key) {
            if (key === 'scan') return () => (++scans > 3 ? (() => { throw new Error('boom'); })() : target.scan());
            const value: unknown = Reflect.get(target, key);
            return typeof value === 'function' ? (value as (...a: unknown[]) => unknown).bind(target) : value;
          },
        }) as Plc;
      },
    };
    const h = new SimHarness(failing).send({ type: 'run', project: motorProgram() }).advance(100);
    expect(h.frame.mode).toBe('paused');
    expect(h.of('error').at(-1)?.message).toMatch(/the simulation stopped: boom/);
  });
});

describe('values and forcing', () => {
  test('a forced output keeps its forced value whatever the program does, until unforced', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }, { type: 'force', name: 'Motor', input: { value: false } });
    h.send({ type: 'write', name: 'Start', input: { value: true } }).advance(50);
    expect(h.value('Motor')).toBe(false);
    expect(h.frame.forced).toEqual([['Motor', false]]);
    h.send({ type: 'unforceAll' }).advance(50);
    expect(h.frame.forced).toEqual([]);
    expect(h.value('Motor')).toBe(true);
  });

  test('a forced input overrides the input image', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }, { type: 'force', name: 'Start', input: { text: 'TRUE' } }).advance(50);
    expect(h.value('Motor')).toBe(true);
    h.send({ type: 'write', name: 'Start', input: { value: false } }, { type: 'force', name: 'Stop', input: { value: true } }).advance(50);
    expect(h.value('Motor')).toBe(false);
  });

  test('a bad typed value or an unknown name is reported, not thrown', () => {
    const h = new SimHarness().send({ type: 'step', scans: 1, project: timerProgram() });
    h.send({ type: 'write', name: 'Enable', input: { text: 'maybe' } });
    expect(h.of('error').at(-1)?.message).toMatch(/Enable/);
    h.send({ type: 'force', name: 'Nobody', input: { value: true } });
    expect(h.of('error').at(-1)?.message).toMatch(/Nobody/);
  });

  test('Reset (cold) restores initial values and scan 0; forces stay', () => {
    const h = new SimHarness().send({ type: 'step', scans: 3, project: timerProgram() }).settle();
    h.send({ type: 'force', name: 'Lamp', input: { value: true } }, { type: 'reset' });
    expect(h.frame).toMatchObject({ mode: 'stopped', scan: 0, timeMs: 0 });
    expect(h.value('T1.ET')).toBe(0);
    expect(h.frame.forced).toEqual([['Lamp', true]]);
  });
});

describe('trend', () => {
  test('chosen signals are sampled after every scan and delivered with the frames', () => {
    // A busy machine: every read of the real clock is 20 ms later, so each slice of Step N runs one
    // scan and the rest comes on the scheduler (settle), as in the worker.
    let wall = 0;
    const h = new SimHarness(undefined, () => (wall += 20)).send({ type: 'step', scans: 1, project: timerProgram() });
    h.send({ type: 'setTrend', names: ['T1.ET', 'Lamp'], capacity: 100 }, { type: 'step', scans: 12 }).settle();
    const samples = h.of('frame').flatMap((m) => (m.frame.trend ? [m.frame.trend] : []));
    const scans = samples.flatMap((s) => s.scans);
    expect(scans).toEqual([2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13]);
    const et = samples.flatMap((s) => s.series[0]!);
    expect(et.slice(0, 3)).toEqual([10, 20, 30]);
    const lamp = samples.flatMap((s) => s.series[1]!);
    expect(lamp.at(-1)).toBe(1);
  });
});

describe('online change', () => {
  test('an edit while running is swapped in at a scan boundary; variables keep their values', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }, { type: 'write', name: 'Start', input: { value: true } }).advance(50);
    h.send({ type: 'write', name: 'Start', input: { value: false } }).advance(30);
    expect(h.value('Motor')).toBe(true);
    const scan = h.frame.scan;
    h.send({ type: 'load', project: threeNetworks() }).advance(60);
    const online = h.of('compiled').at(-1);
    expect(online).toMatchObject({ ok: true, online: true });
    expect(h.layout.networkIds).toHaveLength(3);
    expect(h.value('Motor')).toBe(true);
    expect(h.value('Lamp')).toBe(true);
    expect(h.frame.scan).toBeGreaterThan(scan);
  });

  test('an edit with errors is not applied and the last good program keeps running', () => {
    const h = new SimHarness().send({ type: 'run', project: motorProgram() }).advance(30);
    h.send({ type: 'load', project: brokenProgram() }).advance(30);
    expect(h.of('compiled').at(-1)).toMatchObject({ ok: false, online: true });
    expect(h.frame.mode).toBe('running');
    expect(h.layout.networkIds).toHaveLength(1);
  });
});

describe('gateway seam', () => {
  test('inputs by IEC location drive the program and the output image is posted when it changes', () => {
    const h = new SimHarness().send({ type: 'subscribeOutputs', enabled: true }, { type: 'run', project: motorProgram() }).advance(30);
    h.send({ type: 'setInputs', values: { '%IX0.0': true } }).advance(30);
    const outputs = h.of('outputs');
    expect(outputs.at(-1)?.outputs['%QX0.0']).toBe(true);
    const count = outputs.length;
    h.advance(100);
    expect(h.of('outputs')).toHaveLength(count); // nothing changed, nothing posted
  });
});
