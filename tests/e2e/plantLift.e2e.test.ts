// The lift in the Plant panel (issue 26), in real Chromium against the real server: the
// exercise's reference solution answers six calls pressed on the drawing's call buttons (the run
// fast-forwarded with Step N between them), level with the floors and never moving with the door
// open; a fault set from the panel shows in the trace; a wrong program leaves with the door open,
// shown on the panel as a located consequence that opens the recorded scan. One page for the file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { liftWrong } from '../../src/plant/exercises';
import { openApp, useChromium } from './appPage';
import { PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

let plants: PlantPage;
const plant = () => plants.plant();
/** The recorded scans' values of `names`, one row of numbers a scan (scan, time, then the names). */
const trace = (names: string[]) => plants.trace(names);

/** While running: holds a call button on the drawing until the program has registered the call (its lamp lit). */
const call = (floor: number) => plants.holdUntil(`Call${floor}`, `CallLamp${floor}`);

/** Runs, presses the call buttons of `floors` one after the other, pauses, then Step N of `scans` scans (fast-forward). */
async function callAndFastForward(floors: number[], scans: number) {
  await sim.button('run').click();
  await sim.waitForMode('Running');
  for (const f of floors) await call(f);
  await sim.button('pause').click();
  await sim.waitForMode('Paused');
  await plants.fastForward(scans);
}

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
  await plants.openExercise('Three-floor lift (machine: lift)', 20);
});

test('the reference solution answers six calls pressed on the drawing, level with the floors, the door closed whenever the car moves', async () => {
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('lift');
  await expect.poll(() => page.getByTestId('plant-io').locator('tbody tr').count()).toBe(15);
  // The nearer call first: the car sets off for it, however long the second press takes.
  await callAndFastForward([2, 3], 2000);
  expect((await plant())!.now.state.served).toBe(2);
  await callAndFastForward([2, 1], 2000);
  expect((await plant())!.now.state.served).toBe(4);
  await callAndFastForward([2, 3], 2000);
  const p = (await plant())!;
  expect(p.id).toBe('lift');
  expect(p.now.state).toMatchObject({ served: 6, crashes: 0, doorMoves: 0, overruns: 0, misstops: 0 });
  expect(p.eventCount).toBe(0);
  await expect.poll(() => page.getByTestId('plant-events').textContent()).toContain('None so far.');
  await expect.poll(() => page.getByTestId('plant-q-served').textContent()).toBe('lift.served6');
  await expect.poll(() => page.getByTestId('plant-q-floor').textContent()).toBe('lift.floor3');
  // Every recorded scan: the motor ran only with the door closed, the door opened only level with a floor.
  const rows = await trace([
    'MotorUp',
    'MotorDown',
    'DoorClosed',
    'DoorOpened',
    'AtFloor1',
    'AtFloor2',
    'AtFloor3',
  ]);
  expect(rows.length).toBeGreaterThanOrEqual(6000);
  const moving = rows.filter((r) => r[2] === 1 || r[3] === 1);
  expect(moving.length).toBeGreaterThan(1000);
  expect(moving.every((r) => r[4] === 1)).toBe(true);
  const open = rows.filter((r) => r[5] === 1);
  expect(open.length).toBeGreaterThan(100);
  expect(open.every((r) => r[6]! + r[7]! + r[8]! === 1)).toBe(true);
});

test('a fault set from the panel shows in the trace: the top floor sensor stuck OFF, the car runs past floor 3 into the buffer', async () => {
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await page.getByTestId('plant-fault-floor3_stuck_off').check();
  await expect.poll(async () => (await plant())?.now.faults).toEqual(['floor3_stuck_off']);
  await callAndFastForward([3], 1000);
  const rows = await trace(['Position', 'AtFloor3', 'MotorUp']);
  const atTop = rows.filter((r) => Math.abs(r[2]! - 6000) <= 20);
  expect(atTop.length).toBeGreaterThan(0);
  expect(atTop.every((r) => r[3] === 0 && r[4] === 1)).toBe(true);
  expect(Math.max(...rows.map((r) => r[2]!))).toBe(6300);
  await expect
    .poll(() => page.getByTestId('plant-events').textContent())
    .toMatch(
      /the car ran 100 mm past the top floor \(floor 3\) at scan [\d,]+ \(\d+\.\d\d s\).*the car crashed into the buffer above floor 3 at scan/,
    );
  await expect.poll(() => page.getByTestId('plant-q-crashes').textContent()).toBe('lift.crashes1');
  await page.getByTestId('plant-fault-floor3_stuck_off').uncheck();
  await expect.poll(async () => (await plant())?.now.faults).toEqual([]);
});

test('a wrong program leaves floor 2 with the door open: a located consequence that opens the recorded scan with the lift as it was', async () => {
  await sim.load(liftWrong());
  await expect.poll(() => page.getByTestId('project-name').textContent()).toContain('wrong');
  // Call 2 first: the car stops at floor 2 whenever call 3 comes.
  await callAndFastForward([2, 3], 1000);
  const event = page
    .getByTestId('plant-events')
    .getByRole('button', { name: /the car moved with the door 100 % open at scan/ });
  const text = (await event.textContent())!;
  const scan = Number(/at scan ([\d,]+)/.exec(text)![1]!.replace(/,/g, ''));
  await event.click();
  await expect
    .poll(() => page.getByTestId('plant-status').textContent())
    .toMatch(new RegExp(`^Recorded scan ${scan.toLocaleString('en-US')} \\(`));
  // The readouts show that scan's lift: at floor 2, just leaving, the door still open.
  await expect.poll(() => page.getByTestId('plant-q-door_moves').textContent()).toBe('lift.door_moves1');
  await expect.poll(() => page.getByTestId('plant-q-floor').textContent()).toBe('lift.floor2');
  await expect.poll(() => page.getByTestId('plant-q-door').textContent()).toMatch(/^lift\.door9\d\.\d %$/);
  expect(errors).toEqual([]);
});
