// The machine in the simulation worker's session (issue 26): stepped after every scan by the
// scan's PLC time, so the worker's trace equals the CLI's scan by scan; the history shows the
// machine as it was; operator controls and faults act from the next scan.
import { describe, expect, test } from 'vitest';
import { tankReference, tankWrong } from '../../src/plant/exercises';
import { PlantLoop } from '../../src/plant/loop';
import { tank } from '../../src/plant/tank';
import { SimHarness } from '../sim/harness';
import type { PlantFrame } from '../../src/sim/sessionPlant';
import type { TankState } from '../../src/plant/tank';
import { cliTrace, tankFilledInSession, workerTrace } from './traces';

const WATCH = [
  'Start',
  'Running',
  'LowLevel',
  'HighLevel',
  'Level',
  'Pump',
  'InletValve',
  'DrainValve',
  'Filling',
];
const lastOf = <T>(xs: T[]): T => xs[xs.length - 1]!;
const level = (h: SimHarness) => ((h.frame.plant as PlantFrame).now.state as TankState).level;

/** Start pressed before scan 1, released before scan 3, as an operator at the panel would. */
function sessionRun(project = tankReference(), scans = 2000): SimHarness {
  const h = new SimHarness().send(
    { type: 'setCycle', cycleMs: 100 },
    { type: 'setPlant', plant: { id: 'tank' } },
    { type: 'load', project },
  );
  h.send({ type: 'plantOperator', name: 'Start', value: true }, { type: 'step', scans: 2 }).settle();
  h.send({ type: 'plantOperator', name: 'Start', value: false }, { type: 'step', scans: scans - 2 });
  while (h.frame.scan < scans) h.settle();
  return h;
}

describe('the tank in the simulation session', () => {
  test('the worker trace of 2,000 scans equals the CLI trace scan by scan, machine included', () => {
    const h = sessionRun();
    expect(h.frame.scan).toBe(2000);
    const worker = workerTrace(h, WATCH);
    const cli = cliTrace({
      project: tankReference(),
      plant: 'tank',
      stimulus: 'scan,tank.Start\n1,1\n3,0\n',
      scans: 2000,
      cycle: '100ms',
      watch: [...WATCH, 'tank.level'],
    });
    expect(cli.code).toBe(0);
    const rows = cli.out.trim().split('\n');
    expect(rows).toHaveLength(2001);
    // Same columns: the CLI's last one is the machine's level.
    expect(rows.map((r) => r.split(',').slice(0, -1).join(','))).toEqual(worker);
    // The machine itself: the level after each of some scans, as the history shows it.
    for (const scan of [1, 2, 3, 500, 1234, 2000]) {
      h.send({ type: 'historySeek', scan });
      const view = lastOf(h.of('historyView')).view;
      expect(view.plant?.scan).toBe(scan);
      expect(String((view.plant!.state as TankState).level)).toBe(rows[scan]!.split(',').at(-1));
    }
    // It filled and drained: the level is back between the switches and pump cycles happened.
    expect(
      worker
        .slice(1)
        .filter((r, i, all) => i > 0 && r.split(',')[7] === '1' && all[i - 1]!.split(',')[7] === '0').length,
    ).toBeGreaterThanOrEqual(1);
  });

  test('a wrong program: the frame carries the overflow, located', () => {
    const h = sessionRun(tankWrong(), 700);
    const plant = h.frame.plant!;
    expect(plant.events.map((e) => e.text)).toEqual(['the tank overflowed at scan 576 (57.50 s)']);
    expect(level(h)).toBe(1000);
  });

  test('a fault set at the panel acts from the next step; Reset starts the machine over, the fault stays', () => {
    const h = sessionRun(tankReference(), 20);
    const before = level(h);
    h.send({ type: 'plantFault', id: 'pump_dead', active: true }, { type: 'step', scans: 50 });
    while (h.frame.scan < 70) h.settle();
    expect(h.frame.plant!.now.faults).toEqual(['pump_dead']);
    // The pump coasts down in 0.5 s, then no water comes in (the level is below the low switch: no drain).
    const frame = h.frame.plant!.now.state as TankState;
    expect(frame.pump).toBe(0);
    expect(frame.inflow).toBe(0);
    expect(frame.level).toBeLessThan(before + 10);
    h.send({ type: 'reset' });
    expect(level(h)).toBe(100);
    expect(h.frame.plant!.now.faults).toEqual(['pump_dead']);
    expect(() => h.session.handle({ type: 'plantFault', id: 'boiler_burst', active: true })).not.toThrow();
    expect(lastOf(h.of('error')).message).toMatch(/tank has no fault "boiler_burst"; it has low_stuck_off/);
  });
});

describe('taking the machine away', () => {
  test('None chosen while paused: the inputs the machine drove fall to FALSE / 0, as cut wires (a switch does not stay ON)', () => {
    const h = tankFilledInSession();
    // Filling from 100 L: by now above the low switch (200 L), and Level reads the litres.
    expect(h.value('LowLevel')).toBe(true);
    expect(h.value('Level')).toBeGreaterThan(200);
    h.send({ type: 'setPlant', plant: null }, { type: 'step', scans: 1 });
    while (h.frame.scan < 303) h.settle();
    expect(h.frame.plant).toBeUndefined();
    expect(h.value('LowLevel')).toBe(false);
    expect(h.value('Level')).toBe(0);
  });
});

describe('attaching the machine to a program already running', () => {
  test('attached after scan 24 (2.4 s), its first step is one cycle of PLC time, not 2.5 s at once', () => {
    const io = { outputs: () => ({ '%QX0.0': true, '%QX0.1': true }), setInputs: () => undefined };
    const joined = new PlantLoop(tank);
    joined.bind(io);
    joined.afterScan(25, 2400, 100);
    const fromStart = new PlantLoop(tank);
    fromStart.bind(io);
    fromStart.afterScan(1, 0, 100);
    // The pump runs up over 0.5 s: after one 0.1 s step both are at the same speed (%), well short of full.
    expect(joined.read('pump')).toBe(fromStart.read('pump'));
    expect(joined.read('pump')).toBeLessThan(100);
    expect(joined.snapshot()).toMatchObject({ scan: 25, timeMs: 2500 });
  });
});
