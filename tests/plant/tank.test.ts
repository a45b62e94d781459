import { senseRecord } from '../../src/plant/points';
import { describe, expect, test } from 'vitest';
import { tank, type TankState } from '../../src/plant/tank';
import { PlantLoop } from '../../src/plant/loop';
import { PLANT_EXAMPLES, TANK_SCENARIO, tankReference, tankWrong } from '../../src/plant/exercises';
import { runScenario } from '../../src/sim/scenario';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { validateProject } from '../../src/model/load';

const none = new Set<string>();
const run = (
  s: TankState,
  drive: Record<string, boolean>,
  ms: number,
  faults = none,
  dt = 100,
): TankState => {
  for (let t = 0; t < ms; t += dt) s = tank.step(s, drive, dt, faults);
  return s;
};

describe('the tank model', () => {
  test('pump and inlet fill it at 25 L/s once both are up to speed; the switches follow the level', () => {
    const s = run(tank.initial(), { Pump: true, InletValve: true }, 10_000);
    expect(s.inflow).toBe(25);
    // 10 s, less the ramps (pump 0.5 s, valve 1 s): a little under 250 L added to the first 100 L.
    expect(s.level).toBeGreaterThan(320);
    expect(s.level).toBeLessThan(350);
    expect(senseRecord(tank, s, none)).toEqual({ LowLevel: true, HighLevel: false, Level: Math.round(s.level) });
  });

  test('the pump alone moves no water and counts as running against the closed valve', () => {
    const s = run(tank.initial(), { Pump: true }, 5000);
    expect(s.level).toBe(100);
    expect(s.deadheads).toBe(1);
    expect(tank.check(tank.initial(), s).map((c) => c.id)).toEqual(['deadhead']);
  });

  test('filling without end overflows once and spills what comes in', () => {
    const s = run(tank.initial(), { Pump: true, InletValve: true }, 60_000);
    expect(s.level).toBe(1000);
    expect(s.overflowing).toBe(true);
    expect(s.overflows).toBe(1);
    expect(s.spilled).toBeGreaterThan(0);
  });

  test('the drain on an empty tank runs it dry', () => {
    const s = run(tank.initial(), { DrainValve: true }, 12_000);
    expect(s.level).toBe(0);
    expect(s.dryRuns).toBe(1);
  });

  test('faults: a switch stuck, a dead pump, a slow inlet valve', () => {
    const full = run(tank.initial(), { Pump: true, InletValve: true }, 40_000);
    expect(senseRecord(tank, full, new Set(['high_stuck_off'])).HighLevel).toBe(false);
    expect(senseRecord(tank, tank.initial(), new Set(['low_stuck_on'])).LowLevel).toBe(true);
    expect(run(tank.initial(), { Pump: true, InletValve: true }, 5000, new Set(['pump_dead'])).level).toBe(
      100,
    );
    const slow = run(tank.initial(), { Pump: true, InletValve: true }, 3000, new Set(['inlet_slow']));
    expect(slow.inlet).toBeCloseTo(0.2, 5);
    // Slow both ways, as its title says: 3 s after the solenoid drops it is still 80 % open.
    const open = { ...tank.initial(), inlet: 1 };
    expect(run(open, {}, 3000, new Set(['inlet_slow'])).inlet).toBeCloseTo(0.8, 5);
    expect(tank.faults.find((f) => f.id === 'inlet_slow')?.title).toBe('Inlet valve slow (15 s to open or close)');
  });

  test('a step is pure: the same state, drive and time give the same state, the input is not changed', () => {
    const s0 = tank.initial();
    const copy = JSON.stringify(s0);
    const a = tank.step(s0, { Pump: true, InletValve: true }, 10, none);
    const b = tank.step(s0, { Pump: true, InletValve: true }, 10, none);
    expect(a).toEqual(b);
    expect(JSON.stringify(s0)).toBe(copy);
  });
});

describe('the tank in closed loop', () => {
  test('the loop only wires the points a program declares and reads its outputs by address', () => {
    const image: Record<string, unknown> = {};
    const io = {
      outputs: () => ({ '%QX0.0': true, '%qx0.1': true }),
      setInputs: (v: Record<string, unknown>) => {
        for (const k of Object.keys(v))
          if (!['%IX0.2', '%IW0'].includes(k)) throw new Error(`${k}: no input variable`);
        Object.assign(image, v);
      },
    };
    const loop = new PlantLoop(tank);
    loop.bind(io);
    for (let scan = 1; scan <= 100; scan++) loop.afterScan(scan, (scan - 1) * 100, 100);
    expect(loop.read('tank.inflow')).toBe(25);
    expect(image['%IW0']).toBe(Math.round(loop.read('level') as number));
    expect(image['%IX0.2']).toBe(true);
    expect(loop.at(50)?.scan).toBe(50);
  });

  test('an address that does not fit a point is refused, named', () => {
    expect(() => new PlantLoop(tank, { Pump: '%IX0.0' })).toThrow(
      /Pump: an actuator is a %Q output, not %IX0.0/,
    );
    expect(() => new PlantLoop(tank, { Level: '%IX1.0' })).toThrow(/Level: an INT point needs a %IW address/);
  });
});

describe('the tank exercise', () => {
  test('the reference solution checks clean and is offered as an example', () => {
    const p = tankReference();
    expect(validateProject(JSON.parse(JSON.stringify(p)))).toMatchObject({ ok: true });
    expect(checkProject(p).map(formatDiagnostic)).toEqual([]);
    expect(PLANT_EXAMPLES.map((e) => e.id)).toContain('tank-level');
  });

  test('the reference solution holds the tank between the switches for 5 minutes', () => {
    const { result } = runScenario(tankReference(), TANK_SCENARIO);
    expect(result).toMatchObject({ ok: true, scans: 3000 });
  });

  test('the wrong solution fails where the tank overflows', () => {
    const scenario = {
      name: 'no overflow',
      csv: '# plant: tank\n# cycle: 100ms\nscan,tank.Start,expect Running\n1,1,\n3,0,1\n3000,,1\n',
    };
    const { result } = runScenario(tankWrong(), scenario);
    expect(result.ok).toBe(false);
    expect(result.error).toMatch(/^the tank overflowed at scan \d{3}(,\d{3})? \(\d+\.\d\d s\)$/);
  });

  test('a fault from the scenario: the high switch stuck off overflows the reference too; expecting the count checks it', () => {
    const csv =
      '# plant: tank\n# cycle: 100ms\nscan,tank.Start,fault high_stuck_off,expect tank.overflows\n1,1,1,\n3,0,,0\n1200,,,1\n';
    const { result } = runScenario(tankReference(), { name: 'stuck', csv });
    expect(result).toMatchObject({ ok: true, scans: 1200 });
  });

  test('a machine or name the scenario does not know is a located error', () => {
    expect(
      runScenario(tankReference(), { name: 'x', csv: '# plant: boiler\nscan,Start\n1,1\n' }).result.error,
    ).toMatch(/line 1: there is no machine "boiler"; the machines are tank/);
    expect(
      runScenario(tankReference(), { name: 'x', csv: '# plant: tank\nscan,expect tank.volume\n1,1\n' }).result
        .error,
    ).toMatch(/line 2: tank has no quantity or point "volume"/);
    expect(
      runScenario(tankReference(), { name: 'x', csv: '# plant: tank\nscan,tank.Level\n1,1\n' }).result.error,
    ).toMatch(/only the machine's operator controls can be set/);
  });
});
