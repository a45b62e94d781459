// Watching the machine (issue 26): its names (`tank.level`, `tank.Pump`) read off a live or a
// recorded snapshot; the trend samples them in the worker as the history shows them; "Why?" on an
// input the machine writes says it is the machine's and why it has its value, with the machine's
// quantities as the scan read them; "Why?" on a machine name explains it from the recorded machine.
import { describe, expect, test } from 'vitest';
import { tankReference } from '../../src/plant/exercises';
import { tank, type TankState } from '../../src/plant/tank';
import { PlantLoop } from '../../src/plant/loop';
import { findPlantName, formatPlantValue, plantNames, plantSpelling, plantValue } from '../../src/plant/values';
import { SimHarness } from '../sim/harness';
import { PLANTS } from '../../src/plant/machines';
import type { TrendSamples } from '../../src/sim/protocol';
import { createSimStore } from '../../src/store/simStore';
import { loopback } from '../sim/loopback';
import { plantWatchText } from '../../src/editor/plant/plantWatch';

const lastOf = <T>(xs: T[]): T => xs[xs.length - 1]!;

/** The reference solution with Start pressed for the first two scans, `scans` scans at 100 ms. */
function run(scans: number, extra: Parameters<SimHarness['send']> = []): SimHarness {
  const h = new SimHarness().send(
    { type: 'setCycle', cycleMs: 100 },
    { type: 'setPlant', plant: { id: 'tank' } },
    { type: 'load', project: tankReference() },
    ...extra,
  );
  h.send({ type: 'plantOperator', name: 'Start', value: true }, { type: 'step', scans: 2 }).settle();
  h.send({ type: 'plantOperator', name: 'Start', value: false }, { type: 'step', scans: scans - 2 });
  while (h.frame.scan < scans) h.settle();
  return h;
}

const view = (h: SimHarness, scan: number) => {
  h.send({ type: 'historySeek', scan });
  return lastOf(h.of('historyView')).view;
};
const why = (h: SimHarness, scan: number, name: string) => {
  h.send({ type: 'explain', id: scan, scan, target: { kind: 'variable', name } });
  return lastOf(h.of('explanation')).explanation;
};

describe("a machine's names", () => {
  test('every machine lists its quantities and points under its id, each found again by name (any case)', () => {
    for (const model of PLANTS) {
      const names = plantNames(model);
      expect(names).toHaveLength(model.quantities.length + model.points.length);
      // Each spelt exactly names itself.
      for (const n of names) expect(plantSpelling(model, n.name)).toBe(n.name);
      for (const n of names) {
        expect(n.name.startsWith(`${model.id}.`)).toBe(true);
        expect(findPlantName(model, n.name.toUpperCase())).toBeDefined();
        expect(findPlantName(model, n.name)?.quantity?.name ?? findPlantName(model, n.name)?.point?.name).toBe(n.name.slice(model.id.length + 1));
      }
      expect(findPlantName(model, 'level')).toBeUndefined();
      expect(findPlantName(model, `${model.id}.nothing`)).toBeUndefined();
    }
  });

  test('a snapshot gives quantities, sensors as sensed (faults applied), actuators as driven, controls as held', () => {
    const loop = new PlantLoop(tank);
    const image: Record<string, boolean | number> = { '%QX0.0': true, '%QX0.1': true, '%QX0.2': false, '%QX0.3': true };
    loop.bind({ outputs: () => image, setInputs: () => {} });
    loop.setOperator('Start', true);
    for (let k = 1; k <= 400; k++) loop.afterScan(k, (k - 1) * 100, 100);
    loop.setFault('high_stuck_off', true);
    const s = loop.snapshot();
    const level = (s.state as TankState).level;
    expect(level).toBeGreaterThan(800);
    expect(plantValue(tank, s, 'tank.level')).toBe(level);
    expect(plantValue(tank, s, 'TANK.Pump')).toBe(true);
    // Spelt in lower case, the pump's speed (a quantity), in percent.
    expect(plantValue(tank, s, 'tank.pump')).toBe(100);
    expect(loop.read('tank.Pump')).toBe(true);
    expect(loop.read('tank.pump')).toBe(100);
    expect(plantValue(tank, s, 'tank.DrainValve')).toBe(false);
    expect(plantValue(tank, s, 'tank.Start')).toBe(true);
    expect(plantValue(tank, s, 'tank.Level')).toBe(Math.round(level));
    // The stuck switch reads OFF though the water is above it.
    expect(plantValue(tank, s, 'tank.HighLevel')).toBe(false);
    expect(plantValue(tank, s, 'tank.nothing')).toBeUndefined();
    expect(formatPlantValue('REAL', 812.345, 'L')).toBe('812.3 L');
    expect(formatPlantValue('BOOL', true)).toBe('TRUE');
  });
});

describe('the machine in the trend and "Why?" of the simulation session', () => {
  test('the trend samples tank.level and tank.Pump every scan, equal to the machine the history shows at that scan', () => {
    const h = run(300, [{ type: 'setTrend', names: ['TANK.LEVEL', 'tank.Pump', 'Pump'], capacity: 1000 }]);
    const samples = h.of('frame').flatMap((m) => (m.frame.trend ? [m.frame.trend] : [])) as TrendSamples[];
    expect(samples.length).toBeGreaterThan(0);
    // The names as the machine spells them.
    expect(samples[0]!.names).toEqual(['tank.level', 'tank.Pump', 'Pump']);
    const scans = samples.flatMap((s) => s.scans);
    const level = samples.flatMap((s) => s.series[0]!);
    const pump = samples.flatMap((s) => s.series[1]!);
    const programPump = samples.flatMap((s) => s.series[2]!);
    expect(scans).toEqual(Array.from({ length: 300 }, (_, i) => i + 1));
    for (const scan of [1, 2, 50, 123, 300]) {
      const v = view(h, scan);
      expect(level[scan - 1]).toBe((v.plant!.state as TankState).level);
      // The machine was driven by the output the scan wrote.
      expect(pump[scan - 1]).toBe(programPump[scan - 1]);
    }
    // The level rose while the pump ran.
    expect(Math.max(...level)).toBeGreaterThan(level[0]! + 100);
    expect(pump).toContain(1);
  });

  test('the trend drops the machine names when the machine is detached', () => {
    const h = run(20, [{ type: 'setTrend', names: ['tank.level', 'Pump'], capacity: 100 }]);
    h.send({ type: 'setPlant', plant: null }, { type: 'step', scans: 3 });
    while (h.frame.scan < 23) h.settle();
    const last = h.of('frame').flatMap((m) => (m.frame.trend ? [m.frame.trend] : [])).at(-1)!;
    expect(last.names).toEqual(['Pump']);
  });

  test('"Why?" on HighLevel says the machine writes it, why it is ON, and the machine as the scan read it', () => {
    const h = run(600);
    // The first scan whose HighLevel is TRUE.
    h.send({ type: 'historyExport', id: 1, format: 'trace', names: ['HighLevel'] });
    const rows = lastOf(h.of('historyText')).text.trim().split('\n').slice(1);
    const scan = rows.findIndex((r) => r.endsWith(',1')) + 1;
    expect(scan).toBeGreaterThan(1);
    const e = why(h, scan, 'HighLevel');
    expect(e.title).toBe(`HighLevel is TRUE after scan ${scan.toLocaleString('en-US')}`);
    const before = view(h, scan - 1).plant!;
    const level = (before.state as TankState).level.toFixed(1);
    const text = e.lines.join('\n');
    expect(text).toContain('Nothing in the program writes HighLevel: it is an input (%IX0.3)');
    expect(text).toContain(
      `HighLevel (%IX0.3) is written by the machine tank: HighLevel, high level float switch, ON at 800 L and above. It presented TRUE after scan ${(scan - 1).toLocaleString('en-US')}`,
    );
    expect(text).toContain(`the high level switch is ON at 800 L and above; the level is ${level} L, so it is ON`);
    expect(text).toContain(`The machine after scan ${(scan - 1).toLocaleString('en-US')}: level ${level} L, percent`);
    // One scan earlier the switch was still OFF, below 800 L.
    const earlier = why(h, scan - 1, 'HighLevel').lines.join('\n');
    expect(earlier).toMatch(/the level is 7\d\d\.\d L, so it is OFF/);
  });

  test('"Why?" names a fault that holds the sensor, and explains an output the machine reads', () => {
    const h = run(30);
    h.send({ type: 'plantFault', id: 'low_stuck_on', active: true }, { type: 'step', scans: 2 });
    while (h.frame.scan < 32) h.settle();
    const low = why(h, 32, 'LowLevel').lines.join('\n');
    expect(low).toContain('the low level switch is stuck ON (fault low_stuck_on)');
    expect(low).toContain('Fault set on the machine: Low level switch stuck ON (low_stuck_on).');
    const pump = why(h, 32, 'Pump').lines.join('\n');
    expect(pump).toContain('Pump (%QX0.0) drives the machine tank: Pump, feed pump contactor.');
    expect(pump).toContain('The machine after scan 32, driven by it: level');
    const start = why(h, 1, 'Start').lines.join('\n');
    expect(start).toContain('Start (%IX0.0) is written by the machine tank: Start, start push button (NO), an operator button held when scan 1 read it.');
  });

  test('"Why?" on a contact of a sensor (the canvas menu) says the machine wrote it too', () => {
    const project = tankReference();
    const pou = project.pous.find((p) => p.kind === 'PROGRAM')!;
    let at: { network: number; element: number } | undefined;
    pou.networks.forEach((n, network) =>
      n.elements.forEach((el, element) => {
        if (!at && el.kind === 'contact' && el.variable === 'LowLevel') at = { network, element };
      }),
    );
    expect(at).toBeDefined();
    const h = run(50);
    h.send({ type: 'explain', id: 1, scan: 50, target: { kind: 'element', ...at! } });
    const text = lastOf(h.of('explanation')).explanation.lines.join('\n');
    expect(text).toContain('LowLevel (%IX0.2) is written by the machine tank: LowLevel, low level float switch, ON at 200 L and above.');
    expect(text).toContain('The machine after scan 49: level');
  });

  test('"Why?" at a scan from before the machine was chosen says nothing of it; after, it does; the frame says where it began', () => {
    // The program runs 20 scans with no machine, then the tank is chosen.
    const h = new SimHarness().send({ type: 'setCycle', cycleMs: 100 }, { type: 'load', project: tankReference() }, { type: 'step', scans: 20 });
    while (h.frame.scan < 20) h.settle();
    h.send({ type: 'setPlant', plant: { id: 'tank' } }, { type: 'step', scans: 10 });
    while (h.frame.scan < 30) h.settle();
    expect(h.frame.plant?.since).toBe(20);
    // Scan 15 read LowLevel as nobody wrote it: not the machine's.
    const early = why(h, 15, 'LowLevel').lines.join('\n');
    expect(early).not.toContain('machine');
    expect(why(h, 20, 'Pump').lines.join('\n')).not.toContain('drives the machine');
    // Scan 21 read what the machine presented when it was chosen, after scan 20.
    const first = why(h, 21, 'LowLevel').lines.join('\n');
    expect(first).toContain('LowLevel (%IX0.2) is written by the machine tank');
    expect(why(h, 25, 'Pump').lines.join('\n')).toContain('Pump (%QX0.0) drives the machine tank');
    // A machine name at scan 10: the machine came later, not "no longer kept".
    expect(why(h, 10, 'tank.level').lines).toEqual(['The machine tank was chosen or rewired after scan 20: scan 10 came before it drove the program.']);
    // A cold restart: the machine drives from the start again.
    h.send({ type: 'reset' }, { type: 'step', scans: 3 });
    while (h.frame.scan < 3) h.settle();
    expect(h.frame.plant?.since).toBe(0);
    expect(why(h, 1, 'LowLevel').lines.join('\n')).toContain('written by the machine tank');
  });

  test('"Why?" on a machine name explains it from the recorded machine', () => {
    const h = run(100);
    const snap = view(h, 60).plant!;
    const e = why(h, 60, 'tank.level');
    expect(e.title).toBe(`tank.level is ${(snap.state as TankState).level.toFixed(1)} L after scan 60`);
    expect(e.lines[0]).toContain('tank.level is a quantity of the machine tank (water in the tank)');
    expect(e.lines.join('\n')).toContain('The machine after scan 60 (6.00 s): level');
    const hl = why(h, 60, 'tank.HighLevel');
    expect(hl.title).toBe('tank.HighLevel is FALSE after scan 60');
    expect(hl.lines.join('\n')).toContain('The high level switch is ON at 800 L and above');
  });
});

describe('the machine in the simulation store (watch and trend lists)', () => {
  test('tank.Pump and tank.pump are two names: both watched and trended; values live and at a recorded scan', () => {
    const { transport, scheduler } = loopback();
    const store = createSimStore(transport);
    const s = () => store.getState();
    s().setPlant({ id: 'tank' });
    s().plantOperator('Start', true);
    s().step(tankReference(), 40);
    scheduler.advance(1000);
    expect(s().plant?.now.scan).toBe(40);
    for (const n of ['tank.Pump', 'tank.pump', 'tank.level', 'tank.Pump']) s().addWatch(n);
    expect(s().watch).toEqual(['tank.Pump', 'tank.pump', 'tank.level']);
    s().toggleTrend('tank.Pump');
    s().toggleTrend('tank.pump');
    expect(s().trendNames).toEqual(['tank.Pump', 'tank.pump']);
    s().toggleTrend('tank.pump');
    expect(s().trendNames).toEqual(['tank.Pump']);
    expect(plantWatchText(s(), 'tank.Pump')).toBe('TRUE');
    // Spelt in lower case, the pump's speed in percent (ramping up).
    expect(plantWatchText(s(), 'tank.pump')).toBe(`${((s().plant!.now.state as TankState).pump * 100).toFixed(1)} %`);
    expect((s().plant!.now.state as TankState).pump).toBeGreaterThan(0);
    const live = plantWatchText(s(), 'tank.level');
    expect(live).toBe(`${(s().plant!.now.state as TankState).level.toFixed(1)} L`);
    s().seekHistory(3);
    scheduler.advance(10);
    expect(s().historyScan).toBe(3);
    expect(plantWatchText(s(), 'tank.level')).toBe(`${(s().plantAtScan!.state as TankState).level.toFixed(1)} L`);
    expect(plantWatchText(s(), 'tank.level')).not.toBe(live);
    expect(plantWatchText(s(), 'tank.nothing')).toBeUndefined();
  });
});
