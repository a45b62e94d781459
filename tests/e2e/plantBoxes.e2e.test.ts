// The box sorter in the Plant panel (issue 26), in real Chromium against the real server: the
// exercise's reference solution, started with the Start button on the drawing, sorts 10 boxes
// (fast-forwarded with Step N); a fault set from the panel (the size sensor stuck OFF) shows in
// the trace and sends a large box into the wrong place; a wrong program (it pushes on the size
// sensor) shows the missorted box as a located consequence that opens the recorded scan. One page
// for the whole file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { boxesWrong } from '../../src/plant/boxesExercise';
import { openApp, useChromium } from './appPage';
import { PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

let plants: PlantPage;
const plant = () => plants.plant<Record<string, number | boolean | unknown[]>>();
const trace = (names: string[]) => plants.trace(names);

const startAndFastForward = (scans: number) => plants.startAndFastForward(scans);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
  await plants.openExercise('Box sorter (machine: boxes)', 100);
});

test('the reference solution sorts 10 boxes by size: large ones pushed into the chute, small ones into the bin', async () => {
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('boxes');
  await expect.poll(() => page.getByTestId('plant-io').locator('tbody tr').count()).toBe(10);
  await startAndFastForward(490);
  const p = (await plant())!;
  expect(p.id).toBe('boxes');
  expect(p.eventCount).toBe(0);
  expect(p.now.state.sorted).toBeGreaterThanOrEqual(10);
  expect(p.now.state.missorted).toBe(0);
  await expect.poll(() => page.getByTestId('plant-events').textContent()).toContain('None so far.');
  await expect.poll(() => page.getByTestId('plant-q-sorted').textContent()).toMatch(/^boxes\.sorted(1\d)$/);
  // In the trace: the pusher went out once for each large box the size sensor saw, and only once
  // the box had reached the pusher (PusherEye ON at the scan it started).
  const rows = await trace(['SizeEye', 'PusherEye', 'Pusher']);
  const pushes = rows.filter((r, i) => i > 0 && r[4] === 1 && rows[i - 1]![4] === 0);
  const larges = rows.filter((r, i) => i > 0 && r[2] === 1 && rows[i - 1]![2] === 0).length;
  expect(pushes.length).toBe(p.now.state.largeChute);
  expect(pushes.length).toBeGreaterThanOrEqual(5);
  expect(larges).toBeGreaterThanOrEqual(pushes.length);
  expect(pushes.every((r) => r[3] === 1)).toBe(true);
});

test('a fault set from the panel shows in the trace: the size sensor stuck OFF reads 0, and a large box rides into the small-box bin', async () => {
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await page.getByTestId('plant-fault-size_stuck_off').check();
  await expect.poll(async () => (await plant())?.now.faults).toEqual(['size_stuck_off']);
  await startAndFastForward(150);
  const rows = await trace(['SizeEye', 'Pusher']);
  expect(rows.length).toBeGreaterThanOrEqual(150);
  expect(rows.every((r) => r[2] === 0 && r[3] === 0)).toBe(true);
  await expect
    .poll(() => page.getByTestId('plant-events').textContent())
    .toMatch(/box 2 \(large\) ran into the small-box bin at scan \d+ \(\d+\.\d\d s\)/);
  await page.getByTestId('plant-fault-size_stuck_off').uncheck();
  await expect.poll(async () => (await plant())?.now.faults).toEqual([]);
});

test('a wrong program pushes on the size sensor: the missorted box is a located consequence that opens the recorded scan', async () => {
  await sim.load(boxesWrong());
  await expect.poll(() => page.getByTestId('project-name').textContent()).toContain('wrong');
  await startAndFastForward(150);
  const p = (await plant())!;
  expect(p.now.state.missorted).toBeGreaterThanOrEqual(1);
  const event = page
    .getByTestId('plant-events')
    .getByRole('button', { name: /box 2 \(large\) ran into the small-box bin at scan/ });
  const text = (await event.textContent())!;
  const scan = Number(/at scan ([\d,]+)/.exec(text)![1]!.replace(/,/g, ''));
  await event.click();
  await expect
    .poll(() => page.getByTestId('plant-status').textContent())
    .toMatch(new RegExp(`^Recorded scan ${scan.toLocaleString('en-US')} \\(`));
  // The readouts show that scan's machine: the first box in the wrong place.
  await expect.poll(() => page.getByTestId('plant-q-missorted').textContent()).toBe('boxes.missorted1');
  expect(errors).toEqual([]);
});
