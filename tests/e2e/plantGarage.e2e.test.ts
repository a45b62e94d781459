// The garage door in the Plant panel (issue 26), in real Chromium against the real server: the
// exercise's reference solution, operated with the key switch on the drawing, opens and closes
// the door three times and reverses for a car driven into the doorway (fast-forwarded with
// Step N); a fault set from the panel (the photo-eye stuck OFF) shows in the trace; a wrong program
// (it ignores the photo-eye) brings the door down on the car, shown as a located consequence that
// opens the recorded scan. One page for the whole file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { garageWrong } from '../../src/plant/garageExercise';
import { openApp, useChromium } from './appPage';
import { PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

let plants: PlantPage;
const plant = () => plants.plant();
const door = async () => (await plant())!.now.state;
const trace = (names: string[]) => plants.trace(names);
const readout = (name: string) => page.getByTestId(`plant-q-${name}`).textContent();

/** Runs, turns the key (a button on the drawing) until the program's `flag` is set, lets it spring back, pauses. */
async function turnKey(key: 'KeyOpen' | 'KeyClose', flag: 'Opening' | 'Closing') {
  await plants.runHoldPause(key, flag);
}

/** Step N of `scans` scans (fast-forward on the virtual clock), waiting until they are done. */
const fastForward = (scans: number) => plants.fastForward(scans);

/** The door opened fully on the key, then closed on it: one full cycle. */
async function cycle() {
  await turnKey('KeyOpen', 'Opening');
  await fastForward(150);
  expect((await door()).position).toBeGreaterThanOrEqual(99);
  await turnKey('KeyClose', 'Closing');
  await fastForward(150);
  expect((await door()).position).toBeLessThanOrEqual(1);
}

/** Opens the door, starts closing it and drives the car in while the door is still high. */
async function carWhileClosing() {
  await turnKey('KeyOpen', 'Opening');
  await fastForward(150);
  await turnKey('KeyClose', 'Closing');
  // The key was held in real time: step on a few scans at a time until the door is down to 92 %.
  while (((await door()).position as number) > 92) await fastForward(4);
  const position = (await door()).position as number;
  expect(position).toBeGreaterThan(65);
  expect(position).toBeLessThan(99);
  const doorway = page.getByTestId('plant-op-Doorway');
  await doorway.click();
  await expect.poll(() => doorway.getAttribute('aria-pressed')).toBe('true');
}

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
  await plants.openExercise('Garage door (machine: garage)', 100);
});

test('the reference solution opens and closes the door three times on the key and reverses for the car', async () => {
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('garage');
  await expect.poll(() => page.getByTestId('plant-io').locator('tbody tr').count()).toBe(10);
  await cycle();
  await expect.poll(() => readout('cycles')).toBe('garage.cycles1');
  // The second close: a car drives in; the photo-eye sees it and the door goes back up, fully open.
  await carWhileClosing();
  await fastForward(100);
  expect(await sim.value('Obstacle')).toBe(true);
  const reopened = await door();
  expect(reopened.carIn).toBe(true);
  expect(reopened.position).toBeGreaterThanOrEqual(99);
  await expect.poll(() => readout('car_in')).toBe('garage.car_inyes');
  // The car leaves; the door closes; one more cycle makes three.
  await page.getByTestId('plant-op-Doorway').click();
  await expect.poll(() => page.getByTestId('plant-op-Doorway').getAttribute('aria-pressed')).toBe('false');
  await turnKey('KeyClose', 'Closing');
  await fastForward(150);
  await cycle();
  await expect.poll(() => readout('cycles')).toBe('garage.cycles3');
  expect(await readout('hits')).toBe('garage.hits0');
  expect(await readout('overruns')).toBe('garage.overruns0');
  expect(await readout('shorts')).toBe('garage.shorts0');
  expect((await plant())!.eventCount).toBe(0);
  await expect.poll(() => page.getByTestId('plant-events').textContent()).toContain('None so far.');
  // The trace: the door reversed the scan after the photo-eye saw the car (MotorUp with the door not open).
  const rows = await trace(['Obstacle', 'MotorUp', 'MotorDown', 'OpenLimit']);
  const seen = rows.findIndex((r) => r[2] === 1);
  expect(seen).toBeGreaterThan(0);
  expect(rows[seen - 1]![4]).toBe(1);
  expect(rows[seen + 1]!.slice(3, 6)).toEqual([1, 0, 0]);
});

test('a fault set from the panel shows in the trace: the photo-eye stuck OFF stays 0 with the car in, and the door hits it', async () => {
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await page.getByTestId('plant-fault-eye_stuck_off').check();
  await expect.poll(async () => (await plant())?.now.faults).toEqual(['eye_stuck_off']);
  await carWhileClosing();
  await fastForward(60);
  const rows = await trace(['Doorway', 'Obstacle', 'MotorDown']);
  const withCar = rows.filter((r) => r[2] === 1);
  expect(withCar.length).toBeGreaterThan(20);
  expect(withCar.every((r) => r[3] === 0)).toBe(true);
  await expect
    .poll(() => page.getByTestId('plant-events').textContent())
    .toMatch(/the door came down on the car in the doorway at scan \d+ \(\d+\.\d\d s\)/);
  expect(await readout('on_car')).toBe('garage.on_caryes');
  await page.getByTestId('plant-fault-eye_stuck_off').uncheck();
  await expect.poll(async () => (await plant())?.now.faults).toEqual([]);
  await page.getByTestId('plant-op-Doorway').click();
  await expect.poll(() => page.getByTestId('plant-op-Doorway').getAttribute('aria-pressed')).toBe('false');
});

test('a wrong program (it ignores the photo-eye) brings the door down on the car: located, opening the recorded scan', async () => {
  await sim.load(garageWrong());
  await expect.poll(() => page.getByTestId('project-name').textContent()).toContain('wrong');
  await carWhileClosing();
  await fastForward(60);
  expect((await door()).onCar).toBe(true);
  const event = page
    .getByTestId('plant-events')
    .getByRole('button', { name: /the door came down on the car in the doorway at scan/ });
  const text = (await event.textContent())!;
  const scan = Number(/at scan ([\d,]+)/.exec(text)![1]!.replace(/,/g, ''));
  // Move on so the live door differs, then open the consequence's scan.
  await page.getByTestId('plant-op-Doorway').click();
  await fastForward(5);
  expect(await readout('car_in')).toBe('garage.car_inno');
  await event.click();
  await expect
    .poll(() => page.getByTestId('plant-status').textContent())
    .toMatch(new RegExp(`^Recorded scan ${scan.toLocaleString('en-US')} \\(`));
  // The drawing's readouts show that scan's door: resting on the car's roof.
  await expect.poll(() => readout('on_car')).toBe('garage.on_caryes');
  expect(await readout('position')).toBe('garage.position60.0 %');
  expect(errors).toEqual([]);
});
