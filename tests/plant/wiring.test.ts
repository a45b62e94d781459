// Editing a machine's wiring in the Plant panel (issue 26): an address typed for a point is
// checked against the other points wherever it is spelt (%IX00.2 is %IX0.2), and "Declare the
// machine's I/O" never moves a variable of another type onto a point's address.
import { describe, expect, test } from 'vitest';
import { variable } from '../../src/model/factory';
import { tankReference } from '../../src/plant/exercises';
import { mappedPoints, PlantLoop } from '../../src/plant/loop';
import { tank } from '../../src/plant/tank';
import { declarePlan, rewireAddress } from '../../src/plant/wiring';
import { tankFilledInSession } from './traces';
import { SimHarness } from '../sim/harness';
import type { PlantFrame } from '../../src/sim/sessionPlant';
import type { TankState } from '../../src/plant/tank';

const points = mappedPoints(tank);
const point = (name: string) => points.find((p) => p.name === name)!;

describe('rewireAddress', () => {
  test.each([
    ['%IX00.2', "Start: %IX00.2 is already LowLevel's address (%IX0.2)"],
    ['%I0.1', "Start: %I0.1 is already Stop's address (%IX0.1)"],
    ['%ix0.3', "Start: %ix0.3 is already HighLevel's address (%IX0.3)"],
    ['%IX0.02', "Start: %IX0.02 is already LowLevel's address (%IX0.2)"],
    ['%IX1.0.1', 'Start: %IX1.0.1 is a hierarchical address; a machine\'s point is at a plain one (%IX0.2, %IW1)'],
    ['%QX1.0', 'Start: a sensor or operator control is a %I input, not %QX1.0'],
    ['%IW3', 'Start: a BOOL point needs a %IX address, not %IW3'],
  ])('%s for Start is refused: %s', (text, problem) => {
    expect(rewireAddress(points, point('Start'), text)).toEqual({ problem });
  });

  test('an INT point given a bit address is refused in English: "an INT point"', () => {
    expect(rewireAddress(points, point('Level'), '%IX1.1')).toEqual({
      problem: 'Level: an INT point needs a %IW address, not %IX1.1',
    });
  });

  test('a free address is kept as IEC spells it', () => {
    expect(rewireAddress(points, point('Start'), ' %ix01.5 ')).toEqual({ address: '%IX1.5' });
    expect(rewireAddress(points, point('Level'), '%iw02')).toEqual({ address: '%IW2' });
    // Its own address again is no clash.
    expect(rewireAddress(points, point('Start'), '%I0.0')).toEqual({ address: '%IX0.0' });
  });

  test('a rewired point is checked at its new address', () => {
    const rewired = mappedPoints(tank, { Pump: '%QX2.0' });
    expect(rewireAddress(rewired, rewired.find((p) => p.name === 'RunLamp')!, '%QX02.0').problem).toBe(
      "RunLamp: %QX02.0 is already Pump's address (%QX2.0)",
    );
    expect(rewireAddress(rewired, rewired.find((p) => p.name === 'RunLamp')!, '%QX0.0')).toEqual({ address: '%QX0.0' });
  });
});

describe('declarePlan', () => {
  test('an empty program gets every point at its address', () => {
    const plan = declarePlan(tank, {}, [], []);
    expect(plan.add.map((v) => `${v.name}:${v.type}@${v.location}`)).toEqual(
      points.map((p) => `${p.name}:${p.type}@${p.address}`),
    );
    expect(plan.moves).toEqual([]);
    expect(plan.kept).toEqual([]);
  });

  test('a variable of the point\'s name but another type is left alone and said, not moved onto the point\'s address', () => {
    const plan = declarePlan(
      tank,
      {},
      [variable('Level', 'BOOL', { location: '%IX5.0' }), variable('HighLevel', 'INT'), variable('Pump', 'BOOL', { location: '%QX0.0' })],
      [],
    );
    expect(plan.moves).toEqual([]);
    expect(plan.kept).toEqual([
      "HighLevel (INT; the machine's HighLevel is BOOL at %IX0.3)",
      "Level (BOOL; the machine's Level is INT at %IW0)",
    ]);
    expect(plan.add.map((v) => v.name)).toEqual(['Start', 'Stop', 'LowLevel', 'InletValve', 'DrainValve', 'RunLamp']);
  });

  test('a variable of the point\'s name and type moves to a rewired address; one without an address is said', () => {
    const plan = declarePlan(
      tank,
      { Pump: '%QX1.0', Start: '%IX1.0' },
      [variable('Pump', 'BOOL', { location: '%QX0.0' }), variable('Start', 'BOOL')],
      [],
    );
    expect(plan.moves).toEqual([{ name: 'Pump', from: '%QX0.0', to: '%QX1.0' }]);
    expect(plan.kept).toEqual(["Start (no address; the machine's Start is at %IX1.0)"]);
  });

  test('a global of the point\'s name is not declared again in the program', () => {
    const plan = declarePlan(
      tank,
      {},
      [],
      [variable('Pump', 'BOOL', { location: '%QX0.0' }), variable('RunLamp', 'BOOL', { location: '%QX3.0' }), variable('Level', 'REAL')],
    );
    expect(plan.add.map((v) => v.name)).not.toContain('Pump');
    expect(plan.add.map((v) => v.name)).not.toContain('RunLamp');
    expect(plan.add.map((v) => v.name)).not.toContain('Level');
    expect(plan.moves).toEqual([]);
    expect(plan.kept).toEqual([
      "Level (global, REAL; the machine's Level is INT at %IW0)",
      "RunLamp (global, at %QX3.0; the machine's RunLamp is at %QX0.3)",
    ]);
  });
});

describe('a map with two points on one address', () => {
  test('the loop refuses it, naming both points', () => {
    expect(() => new PlantLoop(tank, { Start: '%IX00.2' })).toThrow(
      'tank: Start and LowLevel are both at %IX0.2; each point of the machine needs an address of its own',
    );
  });

  test('in the session it takes the machine attached before away (its inputs fall to FALSE / 0) and says why', () => {
    const h = tankFilledInSession();
    expect(h.value('LowLevel')).toBe(true);
    expect(h.value('Level')).toBeGreaterThan(200);
    h.send({ type: 'setPlant', plant: { id: 'tank', map: { Start: '%IX0.2' } } }, { type: 'step', scans: 1 });
    while (h.frame.scan < 303) h.settle();
    expect(h.of('error').map((m) => m.message)).toContain(
      'tank: Start and LowLevel are both at %IX0.2; each point of the machine needs an address of its own',
    );
    expect(h.frame.plant).toBeUndefined();
    expect(h.value('LowLevel')).toBe(false);
    expect(h.value('Level')).toBe(0);
  });
});

describe('a point rewired while the program runs', () => {
  test('the machine goes on as it was (level, PLC time, faults, consequences); the input left falls to FALSE', () => {
    const h = new SimHarness().send(
      { type: 'setCycle', cycleMs: 100 },
      { type: 'setPlant', plant: { id: 'tank' } },
      { type: 'load', project: tankReference() },
    );
    h.send({ type: 'plantOperator', name: 'Start', value: true }, { type: 'step', scans: 2 }).settle();
    h.send({ type: 'plantOperator', name: 'Start', value: false }, { type: 'plantFault', id: 'drain_stuck', active: true });
    h.send({ type: 'step', scans: 300 });
    while (h.frame.scan < 302) h.settle();
    const before = (h.frame.plant as PlantFrame).now;
    expect((before.state as TankState).level).toBeGreaterThan(200);
    // LowLevel moved from %IX0.2 to %IX1.5: the program's LowLevel (%IX0.2) is no longer wired.
    h.send({ type: 'setPlant', plant: { id: 'tank', map: { LowLevel: '%IX1.5' } } }, { type: 'step', scans: 1 });
    while (h.frame.scan < 303) h.settle();
    const after = (h.frame.plant as PlantFrame).now;
    expect(after.scan).toBe(303);
    expect(after.timeMs).toBe(before.timeMs + 100);
    expect(Math.abs((after.state as TankState).level - (before.state as TankState).level)).toBeLessThan(5);
    expect(after.faults).toEqual(['drain_stuck']);
    expect(h.value('LowLevel')).toBe(false);
    expect(h.value('Level')).toBeGreaterThan(200);
  });
});

describe('a click on a push button shorter than a scan', () => {
  test('while running, is held until a scan has read it, then springs back: the program sees it for one scan', () => {
    const h = new SimHarness().send(
      { type: 'setCycle', cycleMs: 1000 },
      { type: 'setPlant', plant: { id: 'tank' } },
      { type: 'run', project: tankReference() },
    );
    h.advance(1000);
    const scan = h.frame.scan;
    expect(scan).toBeGreaterThan(0);
    // Pressed and let go between two scans of a slow cycle.
    h.send({ type: 'plantOperator', name: 'Start', value: true }, { type: 'plantOperator', name: 'Start', value: false });
    expect((h.frame.plant as PlantFrame).now.operator.Start).toBe(true);
    h.advance(1000);
    expect(h.frame.scan).toBe(scan + 1);
    expect(h.value('Running')).toBe(true);
    expect(h.value('Start')).toBe(true);
    expect((h.frame.plant as PlantFrame).now.operator.Start).toBe(false);
    h.advance(1000);
    expect(h.value('Start')).toBe(false);
    expect(h.value('Running')).toBe(true);
    // A press held over scans is let go at once.
    h.send({ type: 'plantOperator', name: 'Stop', value: true });
    h.advance(2000);
    h.send({ type: 'plantOperator', name: 'Stop', value: false });
    expect((h.frame.plant as PlantFrame).now.operator.Stop).toBe(false);
    expect(h.value('Running')).toBe(false);
  });

  test('paused or stopped alike, is held until the next step has read it (stepping through a start-up); Reset lets it go', () => {
    const h = new SimHarness().send(
      { type: 'setCycle', cycleMs: 100 },
      { type: 'setPlant', plant: { id: 'tank' } },
      { type: 'load', project: tankReference() },
      { type: 'step', scans: 1 },
    );
    while (h.frame.scan < 1) h.settle();
    h.send({ type: 'plantOperator', name: 'Start', value: true }, { type: 'plantOperator', name: 'Start', value: false });
    h.settle();
    expect((h.frame.plant as PlantFrame).now.operator.Start).toBe(true);
    h.send({ type: 'step', scans: 1 });
    while (h.frame.scan < 2) h.settle();
    expect(h.value('Running')).toBe(true);
    expect((h.frame.plant as PlantFrame).now.operator.Start).toBe(false);
    // Stopped: held too, until Reset lets it go unread.
    h.send({ type: 'reset' });
    h.settle();
    h.send({ type: 'plantOperator', name: 'Stop', value: true }, { type: 'plantOperator', name: 'Stop', value: false });
    h.settle();
    expect((h.frame.plant as PlantFrame).now.operator.Stop).toBe(true);
    h.send({ type: 'reset' });
    h.settle();
    expect((h.frame.plant as PlantFrame).now.operator.Stop).toBe(false);
  });
});
