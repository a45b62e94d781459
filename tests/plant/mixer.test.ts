// The batch mixer (issue 26): its physics as a table of cases, each fault, each consequence, purity;
// the exercise (reference clean and passing, the wrong one failing where the batch overheats); the
// worker session's trace equal to the CLI's scan by scan; `rungsmith test` and `rungsmith plants`.
import { senseRecord } from '../../src/plant/points';
import { describe, expect, test, vi } from 'vitest';
import { BURNOUT_C, mixer, type MixerState } from '../../src/plant/mixer';
import { PlantLoop } from '../../src/plant/loop';
import { PLANT_EXAMPLES } from '../../src/plant/exercises';
import { MIXER_SCENARIO, mixerReference, mixerWrong } from '../../src/plant/mixerExercise';
import { runScenario } from '../../src/sim/scenario';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { validateProject } from '../../src/model/load';
import type { PlantFrame } from '../../src/sim/sessionPlant';
import { rungsmith } from '../cli/memoryIo';
import { SimHarness } from '../sim/harness';
import { cliTrace, startedPlantDevice, workerTrace } from './traces';
import { csvValue } from '../../src/engine/values/literals';

const none = new Set<string>();
type Drive = Partial<
  Record<'ValveA' | 'ValveB' | 'Agitator' | 'Heater' | 'OutletValve' | 'DoneLamp', boolean>
>;
const run = (s: MixerState, drive: Drive, ms: number, faults = none, dt = 100): MixerState => {
  for (let t = 0; t < ms; t += dt) s = mixer.step(s, drive, dt, faults);
  return s;
};
/** A batch: `a` litres of A and `b` of B dosed (open until the level is reached, as a program would). */
const dosed = (a: number, b: number, faults = none): MixerState => {
  let s = mixer.initial();
  while (s.level < a) s = mixer.step(s, { ValveA: true }, 100, faults);
  while (s.level < a + b) s = mixer.step(s, { ValveB: true }, 100, faults);
  return run(s, {}, 2000, faults);
};
/** Stirred, heated to 60 °C by a thermostat, held `holdMs` at it. */
const heldBatch = (s: MixerState, holdMs: number): MixerState => {
  s = run(s, { Agitator: true }, 3000);
  while (s.temp < 60) s = mixer.step(s, { Agitator: true, Heater: true }, 100, none);
  for (let t = 0; t < holdMs; t += 100) s = mixer.step(s, { Agitator: true, Heater: s.temp < 60 }, 100, none);
  return s;
};
const q = (s: MixerState, name: string) => mixer.quantity(s, name);
const consequences = (before: MixerState, after: MixerState) => mixer.check(before, after).map((c) => c.id);

describe('the mixer model', () => {
  test.each([
    // name, drive, ms, expected level range, ratio
    ['valve A alone: 40 L/s once open (1 s travel)', { ValveA: true }, 10_000, [375, 385], 100],
    ['valve B alone', { ValveB: true }, 5000, [175, 185], 0],
    ['both valves: half and half', { ValveA: true, ValveB: true }, 5000, [355, 365], 50],
    ['the outlet on an empty vessel: nothing', { OutletValve: true }, 5000, [0, 0], 0],
    ['nothing driven: nothing moves', {}, 5000, [0, 0], 0],
  ] as const)('%s', (_name, drive, ms, [lo, hi], ratio) => {
    const s = run(mixer.initial(), drive, ms);
    expect(s.level).toBeGreaterThanOrEqual(lo);
    expect(s.level).toBeLessThanOrEqual(hi);
    expect(q(s, 'ratio')).toBeCloseTo(ratio, 5);
    expect(s.temp).toBeCloseTo(20, 5);
  });

  test('the switches and transmitters follow the vessel: low at 100 L, mid at 400 L, high at 800 L; temperature in 0.1 °C', () => {
    const cases: [number, boolean, boolean, boolean][] = [
      [50, false, false, false],
      [150, true, false, false],
      [450, true, true, false],
      [820, true, true, true],
    ];
    for (const [litres, low, mid, high] of cases) {
      let s = mixer.initial();
      while (s.level < litres) s = mixer.step(s, { ValveA: true }, 100, none);
      s = run(s, {}, 1500);
      expect(senseRecord(mixer, s, none)).toMatchObject({
        LowLevel: low,
        MidLevel: mid,
        HighLevel: high,
        Level: Math.round(s.level),
        Temperature: 200,
        AgitatorOn: false,
      });
    }
  });

  test('the agitator reaches full speed in 2 s (AgitatorOn from 90 %) and turns its blades', () => {
    const s1 = run(mixer.initial(), { Agitator: true }, 1000);
    expect(q(s1, 'agitator')).toBeCloseTo(50, 5);
    expect(senseRecord(mixer, s1, none).AgitatorOn).toBe(false);
    const s2 = run(s1, { Agitator: true }, 1000);
    expect(senseRecord(mixer, s2, none).AgitatorOn).toBe(true);
    expect(s2.angle).not.toBe(s1.angle);
  });

  test('heating a stirred batch: about 1.2 °C/s into 800 L, the element a few degrees above the batch', () => {
    const before = run(dosed(400, 400), { Agitator: true }, 3000);
    const s = run(before, { Agitator: true, Heater: true }, 20_000);
    expect(s.temp).toBeGreaterThan(40);
    expect(s.temp).toBeLessThan(47);
    expect(s.element - s.temp).toBeGreaterThan(3);
    expect(s.element - s.temp).toBeLessThan(15);
    expect(senseRecord(mixer, s, none).Temperature).toBe(Math.round(s.temp * 10));
    expect(consequences(before, s)).toEqual([]);
  });

  test('a hot batch loses heat to the 20 °C room (time constant 200 s)', () => {
    const hot = heldBatch(dosed(400, 400), 0);
    const s = run(hot, {}, 100_000);
    // e^-0.5 of the excess is left, and a little more: the element's zone gives its heat up too.
    const left = (hot.temp - 20) * Math.exp(-0.5);
    expect(s.temp - 20).toBeGreaterThan(left);
    expect(s.temp - 20).toBeLessThan(left + 1.5);
  });

  test('a long cycle is integrated in short steps: one 1 s step is ten 100 ms steps', () => {
    const start = run(dosed(400, 400), { Agitator: true }, 3000);
    const drive = { Agitator: true, Heater: true };
    const one = run(start, drive, 1000, none, 1000);
    const ten = run(start, drive, 1000, none, 100);
    expect(one.temp).toBeCloseTo(ten.temp, 9);
    expect(one.element).toBeCloseTo(ten.element, 9);
  });
});

describe('the mixer consequences', () => {
  test('dosing without end overflows once, the spill taking A and B as mixed', () => {
    const before = mixer.initial();
    const s = run(before, { ValveA: true, ValveB: true }, 20_000);
    expect(s.level).toBe(1000);
    expect(s.overflowing).toBe(true);
    expect(s.overflows).toBe(1);
    expect(q(s, 'ratio')).toBeCloseTo(50, 5);
    expect(consequences(before, s)).toEqual(['overflow']);
    expect(mixer.check(before, s)[0]).toMatchObject({ severity: 'error', counter: 'overflows' });
  });

  test('the heater on an uncovered element runs dry', () => {
    const before = mixer.initial();
    const s = run(before, { Heater: true }, 500);
    expect(s.dryHeats).toBe(1);
    expect(consequences(before, s)).toEqual(['dry_heat']);
    expect(mixer.check(before, s)[0]!.message).toBe('the heater ran dry (its element was not covered)');
    // Covered (above 60 L) it heats the batch instead.
    const covered = run(dosed(100, 0), { Heater: true, Agitator: true }, 500);
    expect(covered.dryHeats).toBe(0);
  });

  test('an element heated uncovered burns out within seconds: it heats no more, even covered, until the machine is reset', () => {
    const before = mixer.initial();
    // Five seconds dry: hot, not yet burnt.
    const warm = run(before, { Heater: true }, 5000);
    expect(warm.burntOut).toBe(false);
    expect(warm.element).toBeLessThan(BURNOUT_C);
    // Kept on: past BURNOUT_C it burns out once, said as a consequence, and no longer carries current.
    const burnt = run(warm, { Heater: true }, 40_000);
    expect(burnt.burntOut).toBe(true);
    expect(burnt.heating).toBe(false);
    expect(burnt.element).toBeLessThan(BURNOUT_C + 5);
    expect(consequences(warm, burnt)).toEqual(['burnout']);
    expect(mixer.check(warm, burnt)[0]).toMatchObject({ severity: 'error', counter: 'burnt_out' });
    expect(q(burnt, 'burnt_out')).toBe(true);
    // A batch dosed and heated afterwards stays at room temperature.
    const batch = run({ ...burnt, level: 400, volA: 400, element: 20 }, { Heater: true, Agitator: true }, 20_000);
    expect(batch.temp).toBeCloseTo(20, 1);
    expect(batch.burntOut).toBe(true);
    // A reset (the initial state) has a new element.
    expect(mixer.initial().burntOut).toBe(false);
  });

  test('heating without the agitator scorches the product on the element within seconds, spoiling the batch', () => {
    const before = dosed(400, 400);
    const s = run(before, { Heater: true }, 10_000);
    expect(s.element).toBeGreaterThan(150);
    expect(s.temp).toBeLessThan(25);
    expect(s.scorches).toBe(1);
    expect(s.spoiled).toBe(1);
    expect(consequences(before, s)).toEqual(['scorch']);
  });

  test('a scorch says why: unstirred, or a stirred batch heated on far past its set point (a frozen transmitter)', () => {
    const still = dosed(400, 400);
    const unstirred = run(still, { Heater: true }, 10_000);
    expect(mixer.check(still, unstirred).map((c) => c.message)).toEqual([
      'the product scorched on the heater (heating without the agitator) and the batch is spoiled',
    ]);
    // Stirred and heated on: overheated first (spoiled once), then the element scorches the product.
    let s = run(still, { Agitator: true }, 3000);
    let scorch: string | undefined;
    for (let t = 0; t < 300_000 && !scorch; t += 100) {
      const next = mixer.step(s, { Agitator: true, Heater: true }, 100, none);
      scorch = mixer.check(s, next).find((c) => c.id === 'scorch')?.message;
      s = next;
    }
    expect(s.agitator).toBe(1);
    expect(scorch).toBe(`the product scorched on the heater (the batch was heated on to ${s.temp.toFixed(0)} °C) and the batch is spoiled`);
    expect(s.temp).toBeGreaterThan(100);
  });

  test('the fault heater_dead is not the burnt-out element: the heater does not heat, burnt_out stays FALSE', () => {
    expect(mixer.faults.find((f) => f.id === 'heater_dead')?.title).toBe('Heater does not heat (element open circuit)');
    const s = run(dosed(400, 400), { Agitator: true, Heater: true }, 20_000, new Set(['heater_dead']));
    expect([q(s, 'heating'), q(s, 'burnt_out')]).toEqual([false, false]);
    expect(s.temp).toBeLessThan(21);
  });

  test('AgitatorOn comes ON where its comment says: from 90 % of full speed, 1.8 s after the contactor (2 s run-up)', () => {
    expect(mixer.points.find((p) => p.name === 'AgitatorOn')?.comment).toBe(
      'Agitator speed monitor, ON from 90 % of full speed (the motor runs up in 2 s)',
    );
    const at = (ms: number) => senseRecord(mixer, run(dosed(400, 400), { Agitator: true }, ms), none).AgitatorOn;
    expect([at(1700), at(1800), at(2000)]).toEqual([false, true, true]);
  });

  test('heating past 80 °C spoils the batch, once (discharging it counts nothing more)', () => {
    const before = run(dosed(400, 400), { Agitator: true }, 3000);
    const s = run(before, { Agitator: true, Heater: true }, 60_000);
    expect(q(s, 'max_temp')).toBeGreaterThan(80);
    expect(s.spoiled).toBe(1);
    expect(consequences(before, s)).toEqual(['spoiled_overheat']);
    expect(mixer.check(before, s)[0]!.message).toBe('a batch overheated above 80 °C and is spoiled');
    const empty = run(s, { OutletValve: true }, 25_000);
    expect(empty.level).toBe(0);
    expect([empty.spoiled, empty.batches]).toEqual([1, 0]);
  });

  test.each([
    ['short', 300, 300, 30_000, 'spoiled_short'],
    ['wrong ratio', 600, 200, 30_000, 'spoiled_ratio'],
    ['not held long enough', 400, 400, 20_000, 'spoiled_unheld'],
  ] as const)('a batch discharged %s is spoiled when the outlet opens', (_n, a, b, hold, id) => {
    const ready = heldBatch(dosed(a, b), hold);
    const s = mixer.step(ready, { OutletValve: true }, 100, none);
    expect(s.spoiled).toBe(1);
    expect(consequences(ready, s)).toEqual([id]);
    const empty = run(s, { OutletValve: true }, 25_000);
    expect(empty.level).toBe(0);
    expect(empty.batches).toBe(0);
  });

  test('a spoiled batch says what it was: the share of A, the time it was held', () => {
    const ratio = heldBatch(dosed(600, 200), 30_000);
    expect(mixer.check(ratio, mixer.step(ratio, { OutletValve: true }, 100, none))[0]!.message).toMatch(
      /^a batch was discharged with A (7[4-6]) % of it \(it must be 40 to 60 %\) and is spoiled$/,
    );
    const unheld = heldBatch(dosed(400, 400), 20_000);
    const s = mixer.step(unheld, { OutletValve: true }, 100, none);
    expect(mixer.check(unheld, s)[0]!.message).toBe(
      `a batch was discharged held only ${(Math.floor(s.heldMs / 100) / 10).toFixed(1)} s at 57 °C or above with the agitator running (it must be held 30 s at 60 °C) and is spoiled`,
    );
    expect(s.heldMs).toBeGreaterThan(10_000);
    expect(s.heldMs).toBeLessThan(30_000);
  });

  test('consequence: the next batch dosed onto what the last one left (the outlet closed early) is an error; the last batch is not counted', () => {
    const ready = heldBatch(dosed(400, 400), 30_500);
    // Discharged for 15 s at 50 L/s: some 60 L are left when the outlet closes.
    const left = run(run(ready, { OutletValve: true }, 15_000), {}, 2000);
    expect(left.level).toBeGreaterThan(20);
    const next = mixer.step(left, { ValveA: true }, 100, none);
    expect(consequences(left, next)).toEqual(['heel']);
    expect(mixer.check(left, next)[0]).toMatchObject({
      severity: 'error',
      counter: 'heels',
      message: `the vessel was not emptied (the outlet closed with ${left.level.toFixed(1)} L left): the next batch was dosed onto it, and the last batch is not counted`,
    });
    expect(q(next, 'heels')).toBe(1);
    const after = run(next, { ValveA: true }, 5000);
    expect([after.batches, after.heels]).toEqual([0, 1]);
    // Emptied before the next batch: no such consequence.
    const emptied = run(ready, { OutletValve: true }, 25_000);
    expect(consequences(emptied, mixer.step(emptied, { ValveA: true }, 100, none))).toEqual([]);
  });

  test('a good batch: judged when the outlet opens, counted once the vessel is empty; the next starts afresh', () => {
    const ready = heldBatch(dosed(400, 400), 30_500);
    expect(q(ready, 'held')).toBeGreaterThanOrEqual(30);
    const opening = mixer.step(ready, { OutletValve: true }, 100, none);
    expect(opening.judged).toBe(true);
    expect(consequences(ready, opening)).toEqual([]);
    const half = run(opening, { OutletValve: true }, 5000);
    expect(half.batches).toBe(0);
    const empty = run(half, { OutletValve: true }, 20_000);
    expect(empty.level).toBe(0);
    expect(empty.batches).toBe(1);
    expect(empty.spoiled).toBe(0);
    // The last batch's ratio: a little more A than B (the dose of A ends with its valve's travel).
    expect(q(empty, 'ratio')).toBeGreaterThan(50);
    expect(q(empty, 'ratio')).toBeLessThan(53);
    expect(q(empty, 'held')).toBe(0);
    // Closing the outlet and opening it again on the empty vessel counts nothing more.
    const again = run(run(empty, {}, 2000), { OutletValve: true }, 2000);
    expect(again.batches).toBe(1);
  });

  test("the next batch's hottest temperature is its own: dosed cold into the emptied vessel, max_temp is about 20 °C, not the last batch's 60", () => {
    const empty = run(heldBatch(dosed(400, 400), 30_500), { OutletValve: true }, 25_000);
    expect(empty.level).toBe(0);
    expect(q(empty, 'max_temp')).toBeGreaterThan(55);
    const next = run(run(empty, {}, 1000), { ValveA: true }, 3000);
    expect(next.level).toBeGreaterThan(0);
    // Cold ingredient (a little warmed by the element still hot from the last batch).
    expect(q(next, 'temperature')).toBeLessThan(21);
    expect(q(next, 'max_temp')).toBeLessThan(21);
    expect(q(next, 'max_temp')).toBeGreaterThanOrEqual(q(next, 'temperature') as number);
  });
});

describe('the mixer faults', () => {
  test('level switches stuck', () => {
    expect(senseRecord(mixer, mixer.initial(), new Set(['low_stuck_on'])).LowLevel).toBe(true);
    const full = dosed(400, 400);
    expect(senseRecord(mixer, full, new Set(['mid_stuck_off'])).MidLevel).toBe(false);
    expect(senseRecord(mixer, full, new Set(['high_stuck_off'])).HighLevel).toBe(false);
    expect(senseRecord(mixer, full, none)).toMatchObject({ MidLevel: true, HighLevel: true });
  });

  test('valve A slow: 15 s to open', () => {
    const s = run(mixer.initial(), { ValveA: true }, 3000, new Set(['valve_a_slow']));
    expect(q(s, 'valve_a')).toBeCloseTo(20, 5);
  });

  test('the agitator does not start: no speed, no AgitatorOn, and heating scorches', () => {
    const dead = new Set(['agitator_dead']);
    const s = run(dosed(400, 400), { Agitator: true, Heater: true }, 10_000, dead);
    expect(s.agitator).toBe(0);
    expect(senseRecord(mixer, s, dead).AgitatorOn).toBe(false);
    expect(s.scorches).toBe(1);
  });

  test('the heater element burnt out: no heat, not even dry', () => {
    const dead = new Set(['heater_dead']);
    const s = run(dosed(400, 400), { Agitator: true, Heater: true }, 20_000, dead);
    expect(s.temp).toBeCloseTo(20, 5);
    expect(s.heating).toBe(false);
    expect(run(mixer.initial(), { Heater: true }, 1000, dead).dryHeats).toBe(0);
  });

  test('the temperature transmitter frozen: it keeps showing what it showed when the fault came', () => {
    const frozen = new Set(['temp_frozen']);
    const start = run(dosed(400, 400), { Agitator: true, Heater: true }, 10_000);
    const shown = senseRecord(mixer, start, frozen).Temperature;
    const later = run(start, { Agitator: true, Heater: true }, 20_000, frozen);
    expect(later.temp).toBeGreaterThan(start.temp + 20);
    expect(senseRecord(mixer, later, frozen).Temperature).toBe(shown);
    // Cleared, it reads the batch again after the next step.
    const cleared = mixer.step(later, { Agitator: true }, 100, none);
    expect(senseRecord(mixer, cleared, none).Temperature).toBe(Math.round(cleared.temp * 10));
  });

  test('"Why?" on a sensor: the level against the switch, the agitator\'s speed, the transmitter (frozen or not), faults named', () => {
    const s = heldBatch(dosed(400, 400), 0);
    const why = (point: string, faults: string[] = []) => mixer.explain!(s, point, new Set(faults));
    const level = `the level is ${s.level.toFixed(1)} L`;
    expect(why('HighLevel')).toBe(`the high level switch is ON at 800 L and above; ${level}, so it is ON`);
    expect(why('HighLevel', ['high_stuck_off'])).toBe(
      `the high level switch is stuck OFF (fault high_stuck_off): it reads OFF whatever the level; ${level}`,
    );
    expect(mixer.explain!(mixer.initial(), 'LowLevel', new Set(['low_stuck_on']))).toBe(
      'the low level switch is stuck ON (fault low_stuck_on): it reads ON whatever the level; the level is 0.0 L',
    );
    expect(why('MidLevel')).toMatch(/^the mid level switch is ON at 400 L and above; .*, so it is ON$/);
    expect(why('AgitatorOn')).toBe('the speed monitor is ON from 90 % of full speed; the agitator runs at 100 % of full speed, so it is ON');
    expect(why('Temperature')).toBe(
      `the transmitter gives the batch's temperature in tenths of a degree; the batch is ${s.temp.toFixed(1)} °C (${Math.round(s.temp * 10)})`,
    );
    // Frozen while the batch heats on: it shows what it showed when the fault came.
    const frozen = new Set(['temp_frozen']);
    const cold = run(dosed(400, 400), { Agitator: true }, 3000);
    const hot = run(cold, { Agitator: true, Heater: true }, 10_000, frozen);
    expect(mixer.explain!(hot, 'Temperature', frozen)).toBe(
      `the transmitter is frozen (fault temp_frozen): it keeps showing ${cold.temp.toFixed(1)} °C (${Math.round(cold.temp * 10)}) whatever the batch; the batch is ${hot.temp.toFixed(1)} °C`,
    );
    expect(mixer.explain!(mixer.initial(), 'AgitatorOn', new Set(['agitator_dead']))).toBe(
      'the speed monitor is ON from 90 % of full speed; the agitator runs at 0 % of full speed (its motor does not start: fault agitator_dead), so it is OFF',
    );
    expect(why('Heater')).toBeUndefined();
  });

  test('a step is pure: the same state, drive, time and faults give the same state, the input is not changed', () => {
    const s0 = dosed(400, 400);
    const copy = JSON.stringify(s0);
    const drive = { Agitator: true, Heater: true, OutletValve: true };
    const a = mixer.step(s0, drive, 100, new Set(['valve_a_slow']));
    const b = mixer.step(s0, drive, 100, new Set(['valve_a_slow']));
    expect(a).toEqual(b);
    expect(JSON.stringify(s0)).toBe(copy);
    expect(() => mixer.quantity(s0, 'pressure')).toThrow('mixer has no quantity "pressure"');
  });
});

describe('the mixer exercise', () => {
  test('the reference solution checks clean and is offered as an example', () => {
    const p = mixerReference();
    expect(validateProject(JSON.parse(JSON.stringify(p)))).toMatchObject({ ok: true });
    expect(checkProject(p).map(formatDiagnostic)).toEqual([]);
    expect(checkProject(mixerWrong()).map(formatDiagnostic)).toEqual([]);
    expect(PLANT_EXAMPLES.map((e) => e.id)).toContain('batch-mixer');
    expect(p.plant).toEqual({ id: 'mixer' });
  });

  test('the reference solution makes three good batches', () => {
    const { result } = runScenario(mixerReference(), MIXER_SCENARIO);
    expect(result).toMatchObject({ ok: true, scans: 3600 });
  });

  test('the wrong solution (no high limit on the heater) fails where the first batch overheats', () => {
    const { result } = runScenario(mixerWrong(), MIXER_SCENARIO);
    expect(result.ok).toBe(false);
    expect(result.error).toBe('a batch overheated above 80 °C and is spoiled at scan 819 (81.80 s)');
  });

  test('Stop pauses the batch (valves closed, heater and agitator off), Start goes on with it', () => {
    const csv = `# plant: mixer
# cycle: 100ms
scan,mixer.Start,mixer.Stop,expect DoseA,expect ValveA,expect mixer.valve_a,expect Agitator,expect Heater,expect mixer.batches
1,1,0,1,1,*,0,0,0
3,0,,1,1,*,0,0,0
50,,1,1,0,*,0,0,0
52,,0,1,0,*,0,0,0
70,,,1,0,0,0,0,0
300,,,1,0,0,0,0,0
301,1,,1,1,*,0,0,0
303,0,,1,1,*,0,0,0
500,,,0,0,0,1,*,0
600,,1,0,0,0,0,0,0
602,,0,0,0,0,0,0,0
700,,,0,0,0,0,0,0
701,1,,0,0,0,1,*,0
703,0,,*,*,*,*,*,0
1500,,,*,*,*,*,*,1
`;
    const { result } = runScenario(mixerReference(), { name: 'pause', csv });
    expect(result).toMatchObject({ ok: true, scans: 1500 });
  });

  test('faults from a scenario: the high switch stuck OFF overflows the reference; the agitator dead, it never heats', () => {
    const stuck =
      '# plant: mixer\n# cycle: 100ms\nscan,mixer.Start,fault high_stuck_off,expect mixer.overflows\n1,1,1,0\n3,0,,0\n400,,,1\n';
    expect(runScenario(mixerReference(), { name: 'stuck', csv: stuck }).result).toMatchObject({ ok: true });
    const dead =
      '# plant: mixer\n# cycle: 100ms\nscan,mixer.Start,fault agitator_dead,expect Heater,expect mixer.temperature ~ 0.5,expect mixer.scorches\n1,1,1,0,20,0\n3,0,,0,20,0\n1500,,,0,20,0\n';
    expect(runScenario(mixerReference(), { name: 'dead', csv: dead }).result).toMatchObject({
      ok: true,
      scans: 1500,
    });
  });
});

describe('the mixer in closed loop', () => {
  test('through a PLC known only by its I/O records (the gateway device): a switch that goes OFF is written OFF', () => {
    const image: Record<string, unknown> = {};
    let agitator = true;
    const io = {
      outputs: () => ({ '%QX0.2': agitator }),
      setInputs: (v: Record<string, unknown>) => Object.assign(image, v),
    };
    const loop = new PlantLoop(mixer);
    loop.bind(io);
    expect(image['%IX0.5']).toBe(false);
    for (let scan = 1; scan <= 30; scan++) loop.afterScan(scan, (scan - 1) * 100, 100);
    expect(image['%IX0.5']).toBe(true);
    agitator = false;
    for (let scan = 31; scan <= 60; scan++) loop.afterScan(scan, (scan - 1) * 100, 100);
    expect(loop.read('mixer.agitator')).toBe(0);
    expect(image['%IX0.5']).toBe(false);
    expect(image['%IW1']).toBe(200);
  });
});

describe("the mixer as the gateway's simulated device (npm start -- --plant mixer)", () => {
  test('its default I/O map fits the device: a master writes the coils, the switches and transmitters come back', async () => {
    const device = await startedPlantDevice('mixer');
    try {
      const inputs = device.inputValues();
      expect([inputs.get('%IX0.2'), inputs.get('%IX0.5'), inputs.get('%IW0'), inputs.get('%IW1')]).toEqual([
        false,
        false,
        0,
        200,
      ]);
      device.drive(
        new Map([
          ['%QX0.0', true],
          ['%QX0.2', true],
        ]),
      );
      await vi.waitFor(() => expect(device.inputValues().get('%IX0.5')).toBe(true), { timeout: 20_000 });
      await vi.waitFor(() => expect(device.inputValues().get('%IW0')).toBeGreaterThan(20), {
        timeout: 20_000,
      });
      device.drive(
        new Map([
          ['%QX0.0', false],
          ['%QX0.2', false],
        ]),
      );
      await vi.waitFor(() => expect(device.inputValues().get('%IX0.5')).toBe(false), { timeout: 20_000 });
      expect(device.plantRead('mixer.ratio')).toBe(100);
    } finally {
      await device.close();
    }
  }, 60_000);
});

const WATCH = [
  'Start',
  'Running',
  'DoseA',
  'DoseB',
  'Mixing',
  'Holding',
  'Emptying',
  'LowLevel',
  'MidLevel',
  'HighLevel',
  'AgitatorOn',
  'Level',
  'Temperature',
  'ValveA',
  'ValveB',
  'Agitator',
  'Heater',
  'OutletValve',
];
const lastOf = <T>(xs: T[]): T => xs[xs.length - 1]!;

describe('the mixer in the simulation session and on the command line', () => {
  test('the worker trace of 2,000 scans equals the CLI trace scan by scan, machine included', () => {
    const h = new SimHarness().send(
      { type: 'setCycle', cycleMs: 100 },
      { type: 'setPlant', plant: { id: 'mixer' } },
      { type: 'load', project: mixerReference() },
    );
    h.send({ type: 'plantOperator', name: 'Start', value: true }, { type: 'step', scans: 2 }).settle();
    h.send({ type: 'plantOperator', name: 'Start', value: false }, { type: 'step', scans: 1998 });
    while (h.frame.scan < 2000) h.settle();
    expect(h.frame.scan).toBe(2000);
    const worker = workerTrace(h, WATCH);
    const cli = cliTrace({
      project: mixerReference(),
      plant: 'mixer',
      stimulus: 'scan,mixer.Start\n1,1\n3,0\n',
      scans: 2000,
      cycle: '100ms',
      watch: [...WATCH, 'mixer.temperature'],
    });
    expect(cli.code).toBe(0);
    expect(cli.err).toBe('');
    const rows = cli.out.trim().split('\n');
    expect(rows).toHaveLength(2001);
    expect(rows.map((r) => r.split(',').slice(0, -1).join(','))).toEqual(worker);
    for (const scan of [1, 2, 3, 250, 777, 1093, 2000]) {
      h.send({ type: 'historySeek', scan });
      const view = lastOf(h.of('historyView')).view;
      expect(view.plant?.scan).toBe(scan);
      expect(csvValue('REAL', (view.plant!.state as MixerState).temp)).toBe(rows[scan]!.split(',').at(-1));
    }
    // The first batch is done and counted, the second under way.
    const now = (h.frame.plant as PlantFrame).now.state as MixerState;
    expect(now.batches).toBe(1);
    expect(now.spoiled).toBe(0);
    expect(h.frame.plant!.eventCount).toBe(0);
  });

  test('rungsmith plants mixer lists its I/O map, faults and quantities', () => {
    const r = rungsmith(['plants', 'mixer']);
    expect(r.code).toBe(0);
    expect(r.out).toMatch(/^mixer: Batch mixer\n/);
    expect(r.out).toContain('Make batches: dose ingredient A, then B');
    expect(r.out).toContain(
      '    %IW1    Temperature INT   sensor             Temperature transmitter, 0.1 °C (600 = 60.0 °C)',
    );
    expect(r.out).toContain('    %QX0.3  Heater      BOOL  actuator           Immersion heater contactor');
    expect(r.out).toContain('    temp_frozen         Temperature transmitter frozen');
    expect(r.out).toContain('    mixer.temperature');
    expect(rungsmith(['plants']).out).toContain('mixer: Batch mixer');
  });
});
