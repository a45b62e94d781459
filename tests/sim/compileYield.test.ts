// Compiling an online change never delays a scan (issue 24): the compile of the edited program
// runs on the thread that scans, so the scans that fall due meanwhile run at the compile's yield
// points (between networks). Here the hand-turned clock moves on 2 ms between two yield points of
// the compile: a 61-network edit takes hundreds of milliseconds, and no cycle is missed.
import { describe, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { realEngine } from '../../src/sim/engineAdapter';
import type { SimEngine } from '../../src/sim/simEngine';
import { withYieldPoints } from '../../src/engine/yieldPoint';
import { ladder, project, vars } from '../engine/ladder';
import { SimHarness } from './harness';
import { ManualScheduler } from './manualScheduler';

const NETWORKS = 60;
const MS_PER_YIELD = 2;

function program(extraLamp: boolean): Project {
  const nets = Array.from({ length: NETWORKS }, (_, i) => ladder([`[In${i % 4}] (Out${i})`]));
  if (extraLamp) nets.push(ladder(['[In0] (Lamp)']));
  const declared = ['In0 BOOL', 'In1 BOOL', 'In2 BOOL', 'In3 BOOL', 'Lamp BOOL', ...Array.from({ length: NETWORKS }, (_, i) => `Out${i} BOOL`)];
  return project(vars(...declared), nets);
}

describe('an online change compiled while running', () => {
  test('scans keep the 10 ms cycle during a long compile: none is late or dropped, the edit goes in at a boundary', () => {
    const scheduler = new ManualScheduler();
    // The real engine, whose work costs 2 ms of wall time between two yield points (some 6 ms a network).
    const slow = <T,>(work: () => T): T => withYieldPoints(() => scheduler.stall(MS_PER_YIELD), work);
    const engine: SimEngine = {
      ...realEngine,
      compile: (p) => slow(() => realEngine.compile(p)),
      createPlc: (program, options) => slow(() => realEngine.createPlc(program, options)),
    };
    const h = new SimHarness(engine, undefined, scheduler);
    h.send({ type: 'run', project: program(false) }).advance(100);
    const before = { scan: h.frame.scan, time: scheduler.now() };
    h.send({ type: 'load', project: program(true) });
    const compileMs = scheduler.now() - before.time;
    const scansDuringCompile = h.frame.scan - before.scan;
    h.advance(50);
    // The compile took hundreds of milliseconds of wall time; the scans due meanwhile ran during it, on time.
    expect(compileMs).toBeGreaterThan(200);
    expect(scansDuringCompile).toBeGreaterThanOrEqual(Math.floor(compileMs / 10) - 2);
    expect(h.frame.exec.late).toBe(0);
    expect(h.frame.overruns).toBe(0);
    expect(h.of('onlineApplied')).toHaveLength(1);
    h.send({ type: 'write', name: 'In0', input: { value: true } }).advance(60);
    expect(h.value('Lamp')).toBe(true);
  });
});
