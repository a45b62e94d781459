// An online change never delays a scan (issue 24): besides the compile, what the simulator builds
// for the new program before swapping it in (the PLC, the layout the UI monitors, the pins' data
// lines) passes yield points, a network or a few names at a time, where the scans that fell due run.
// And the swap itself, at a scan boundary while Run paces scans, builds no frame before the new
// program's first scan: the frame that follows shows the new program having run.
import { describe, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { realEngine } from '../../src/sim/engineAdapter';
import { buildLayout } from '../../src/sim/layout';
import { pinLines } from '../../src/engine/compile/pinLines';
import type { CompiledProgram } from '../../src/engine/plc';
import { withYieldPoints } from '../../src/engine/yieldPoint';
import { ladder, project, vars } from '../engine/ladder';
import { SimHarness } from './harness';
import { ManualScheduler } from './manualScheduler';

const NETWORKS = 60;

function program(extraLamp: boolean): Project {
  const nets = Array.from({ length: NETWORKS }, (_, i) => ladder([`[In${i % 4}] (Out${i})`]));
  if (extraLamp) nets.push(ladder(['[In0] (Lamp)']));
  const declared = [
    'In0 BOOL',
    'In1 BOOL',
    'In2 BOOL',
    'In3 BOOL',
    'Lamp BOOL',
    ...Array.from({ length: NETWORKS }, (_, i) => `Out${i} BOOL`),
  ];
  return project(vars(...declared), nets);
}

const counted = <T>(work: () => T): { value: T; yields: number } => {
  let yields = 0;
  const value = withYieldPoints(() => yields++, work);
  return { value, yields };
};

describe('what an online change builds besides the compile', () => {
  const p = program(true);
  const { program: compiled } = realEngine.compile(p);
  const plc = realEngine.createPlc(compiled, { cycleMs: 10 });

  test('the PLC, the layout and the data lines pass a yield point at least once a network', () => {
    expect(counted(() => realEngine.createPlc(compiled, { cycleMs: 10 })).yields).toBeGreaterThanOrEqual(
      NETWORKS,
    );
    const layout = counted(() => buildLayout(p, plc.pou, plc.variableNames(), 10));
    expect(layout.yields).toBeGreaterThanOrEqual(NETWORKS + 1);
    expect(layout.value.networkIds).toHaveLength(NETWORKS + 1);
    const lines = counted(() => pinLines(compiled as CompiledProgram, 0, NETWORKS + 1));
    expect(lines.yields).toBeGreaterThanOrEqual(NETWORKS + 1);
  });

  test('while Run paces scans, every yield point of the change runs the scans due: none late; the first frame after the swap shows the new program run', () => {
    const scheduler = new ManualScheduler();
    const h = new SimHarness(realEngine, undefined, scheduler);
    h.send({ type: 'run', project: program(false) }).advance(100);
    const before = { scan: h.frame.scan, time: scheduler.now(), messages: h.messages.length };
    // Every yield point of the load costs 1 ms of wall time: the hundreds of them take seconds.
    withYieldPoints(
      () => scheduler.stall(1),
      () => h.send({ type: 'load', project: program(true) }),
    );
    const loadMs = scheduler.now() - before.time;
    const scansDuringLoad = h.frame.scan - before.scan;
    h.advance(50);
    expect(loadMs).toBeGreaterThan(3 * NETWORKS);
    expect(scansDuringLoad).toBeGreaterThanOrEqual(Math.floor(loadMs / 10) - 2);
    expect(h.frame.exec.late).toBe(0);
    expect(h.frame.overruns).toBe(0);
    const after = h.messages.slice(before.messages);
    const applied = after.findIndex((m) => m.type === 'onlineApplied');
    expect(applied).toBeGreaterThan(0);
    const compiled = after.findIndex((m) => m.type === 'compiled' && m.online);
    const next = after.slice(compiled).find((m) => m.type === 'frame');
    expect(next?.type === 'frame' && next.frame.program).toBe(h.frame.program);
    const appliedAt = after[applied]!;
    expect(
      appliedAt.type === 'onlineApplied' && next?.type === 'frame' && next.frame.scan > appliedAt.scan,
    ).toBe(true);
    h.send({ type: 'write', name: 'In0', input: { value: true } }).advance(60);
    expect(h.value('Lamp')).toBe(true);
  });
});
