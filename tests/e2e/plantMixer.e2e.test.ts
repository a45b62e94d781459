// The batch mixer in the Plant panel (issue 26), in real Chromium against the real server: the
// exercise's reference solution, started with the Start button on the drawing, makes three good
// batches (fast-forwarded with Step N); a frozen temperature transmitter set from the panel shows
// in the trace and overheats the batch; a wrong program (no high limit on the heater) spoils the
// first batch, shown as a located consequence that opens the recorded scan. One page for the file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { mixerWrong } from '../../src/plant/mixerExercise';
import { openApp, useChromium } from './appPage';
import { PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

let plants: PlantPage;
const plant = () => plants.plant();
const trace = (names: string[]) => plants.trace(names);

const startAndFastForward = (scans: number) => plants.startAndFastForward(scans);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
  await plants.openExercise('Batch mixer (machine: mixer)', 100);
});

test('the reference solution makes three good batches: dosed, heated to 60 °C, held, discharged', async () => {
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('mixer');
  await expect.poll(() => page.getByTestId('plant-io').locator('tbody tr').count()).toBe(14);
  await startAndFastForward(3300);
  const p = (await plant())!;
  expect(p.id).toBe('mixer');
  expect(p.now.state.batches).toBe(3);
  expect(p.now.state.spoiled).toBe(0);
  expect(p.eventCount).toBe(0);
  await expect.poll(() => page.getByTestId('plant-events').textContent()).toContain('None so far.');
  await expect.poll(() => page.getByTestId('plant-q-batches').textContent()).toBe('mixer.batches3');
  // The program's view: never above 61 °C, the heater only with the agitator at speed, three discharges.
  const rows = await trace(['Temperature', 'Heater', 'AgitatorOn', 'OutletValve']);
  expect(rows.length).toBeGreaterThanOrEqual(3300);
  expect(Math.max(...rows.map((r) => r[2]!))).toBeLessThanOrEqual(610);
  expect(rows.filter((r) => r[3] === 1).every((r) => r[4] === 1)).toBe(true);
  const discharges = rows.filter((r, i) => i > 0 && r[5] === 1 && rows[i - 1]![5] === 0).length;
  expect(discharges).toBe(3);
});

test('a frozen temperature transmitter set from the panel shows in the trace: Temperature stays while the heater heats, and the batch overheats', async () => {
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await page.getByTestId('plant-fault-temp_frozen').check();
  await expect.poll(async () => (await plant())?.now.faults).toEqual(['temp_frozen']);
  await startAndFastForward(900);
  const rows = await trace(['Temperature', 'Heater']);
  expect(new Set(rows.map((r) => r[2])).size).toBe(1);
  expect(rows.filter((r) => r[3] === 1).length).toBeGreaterThan(400);
  await expect
    .poll(() => page.getByTestId('plant-events').textContent())
    .toMatch(/a batch overheated above 80 °C and is spoiled at scan \d+ \(\d+\.\d\d s\)/);
  expect(((await plant())!.now.state.temp as number) > 80).toBe(true);
  await page.getByTestId('plant-fault-temp_frozen').uncheck();
  await expect.poll(async () => (await plant())?.now.faults).toEqual([]);
});

test('a wrong program (no high limit on the heater) spoils the first batch: a located consequence that opens the recorded scan', async () => {
  await sim.load(mixerWrong());
  await expect.poll(() => page.getByTestId('project-name').textContent()).toContain('wrong');
  await startAndFastForward(900);
  const event = page
    .getByTestId('plant-events')
    .getByRole('button', { name: /a batch overheated above 80 °C and is spoiled at scan/ });
  const text = (await event.textContent())!;
  const scan = Number(/at scan ([\d,]+)/.exec(text)![1]!.replace(/,/g, ''));
  // Where it happens depends on how long Start was held in real time: some 80 s into the run.
  expect(scan).toBeGreaterThan(700);
  await event.click();
  await expect
    .poll(() => page.getByTestId('plant-status').textContent())
    .toMatch(new RegExp(`^Recorded scan ${scan.toLocaleString('en-US')} \\(`));
  // The readouts show that scan's machine: just above 80 °C, the batch counted spoiled.
  await expect.poll(() => page.getByTestId('plant-q-spoiled').textContent()).toBe('mixer.spoiled1');
  await expect
    .poll(() => page.getByTestId('plant-q-temperature').textContent())
    .toMatch(/^mixer\.temperature80\.\d °C$/);
  expect(errors).toEqual([]);
});

test('the drawing fits the panel: wider than the panel, it is scaled down, never cut off, and its buttons stay on it', async () => {
  const box = async (sel: string) => (await page.locator(sel).first().boundingBox())!;
  const panel = await page.getByTestId('plant-panel').evaluate((e) => ({ x: e.getBoundingClientRect().x, width: e.clientWidth }));
  const drawing = await box('.rs-plant-drawing');
  const canvas = await box('.rs-plant-drawing canvas');
  // The mixer is drawn 340 px wide, more than the right panel has inside at this window size.
  expect(panel.width).toBeLessThan(340);
  expect(Number(await page.locator('.rs-plant-drawing').getAttribute('data-scale'))).toBeLessThan(1);
  expect(drawing.x + drawing.width).toBeLessThanOrEqual(panel.x + panel.width + 0.5);
  expect(canvas.width).toBeLessThanOrEqual(drawing.width);
  const start = await page.getByTestId('plant-op-Start').boundingBox();
  expect(start!.x + start!.width).toBeLessThanOrEqual(drawing.x + drawing.width);
  expect(start!.y + start!.height).toBeLessThanOrEqual(drawing.y + drawing.height);
});
