// The road intersection in the Plant panel (issue 26), in real Chromium against the real server:
// the exercise's reference solution, with a pedestrian's press of the button on the drawing,
// serves the side road and the pedestrians for 5 minutes of PLC time with no conflict
// (fast-forwarded with Step N); a fault set from the panel shows in the trace; a wrong program
// shows conflicting signals as a located consequence that opens the recorded scan. One page.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { intersectionWrong } from '../../src/plant/intersectionExercise';
import { openApp, useChromium } from './appPage';
import { PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

let plants: PlantPage;
const plant = () => plants.plant<{ buttonMain: boolean }>();
/** The trace of `names`, one row of numbers per recorded scan (scan, time, then the names). */
const trace = (names: string[]) => plants.trace(names);
/** A quantity as the panel's readout shows it ("22.6 s" reads 22.6). */
const readout = async (name: string) =>
  Number.parseFloat((await page.getByTestId(`plant-q-${name}`).locator('td').textContent())!);

/** Step N of `scans` scans (the virtual clock: fast-forward), from a paused or stopped simulation. */
const fastForward = (scans: number) => plants.fastForward(scans);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
  await plants.openExercise('Road intersection (machine: intersection)', 100);
});

test('the reference solution serves the side road and a pedestrian for 5 minutes of PLC time, no conflict', async () => {
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('intersection');
  await expect.poll(() => page.getByTestId('plant-io').locator('tbody tr').count()).toBe(14);
  await sim.button('run').click();
  await sim.waitForMode('Running');
  // A pedestrian presses the button to cross the main road, on the drawing, until the machine has seen it.
  const button = page.getByTestId('plant-op-CrossMain');
  await button.scrollIntoViewIfNeeded();
  const box = (await button.boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await expect.poll(() => button.getAttribute('aria-pressed'), { timeout: 10_000 }).toBe('true');
  // Held until the machine has stepped with it held (a press between two scans is not seen, as on a real PLC).
  await expect.poll(async () => (await plant())?.now.state.buttonMain, { timeout: 10_000 }).toBe(true);
  await page.mouse.up();
  await expect.poll(async () => (await plant())?.now.operator.CrossMain, { timeout: 10_000 }).toBe(false);
  await sim.button('pause').click();
  await sim.waitForMode('Paused');
  await fastForward(3000);
  const p = (await plant())!;
  expect(p.id).toBe('intersection');
  expect(p.now.scan).toBeGreaterThanOrEqual(3000);
  expect(p.eventCount).toBe(0);
  await expect.poll(() => page.getByTestId('plant-events').textContent()).toContain('None so far.');
  // The readouts: traffic through on both roads, the pedestrian across, nothing conflicting.
  expect(await readout('served')).toBeGreaterThanOrEqual(80);
  expect(await readout('served_side')).toBeGreaterThanOrEqual(25);
  expect(await readout('ped_served')).toBe(1);
  expect(await readout('conflicts')).toBe(0);
  expect(await readout('max_wait')).toBeLessThan(35);
  // Scan by scan: never both roads going, never WALK over a road with its traffic going.
  const rows = await trace(['MainGreen', 'MainYellow', 'SideGreen', 'SideYellow', 'WalkMain', 'WalkSide']);
  expect(rows.length).toBeGreaterThanOrEqual(3000);
  const bad = rows.filter(([, , mg, my, sg, sy, wm, ws]) => {
    const main = mg === 1 || my === 1;
    const side = sg === 1 || sy === 1;
    return (main && side) || (main && wm === 1) || (side && ws === 1);
  });
  expect(bad).toEqual([]);
  // The side road had its green several times, the main road came back each time.
  const sideGreens = rows.filter((r, i) => i > 0 && r[4] === 1 && rows[i - 1]![4] === 0).length;
  expect(sideGreens).toBeGreaterThanOrEqual(5);
});

test('a fault set from the panel shows in the trace: the side loop stuck OFF reads 0, the side road is never served', async () => {
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await page.getByTestId('plant-fault-side_loop_stuck_off').check();
  await expect.poll(async () => (await plant())?.now.faults).toEqual(['side_loop_stuck_off']);
  await fastForward(1300);
  const rows = await trace(['LoopSide', 'SideGreen']);
  expect(rows.length).toBeGreaterThanOrEqual(1300);
  expect(rows.every((r) => r[2] === 0 && r[3] === 0)).toBe(true);
  // Cars wait on the side road all the while: the first fails the 120 s limit, located.
  expect(await readout('waiting_side')).toBeGreaterThanOrEqual(12);
  await expect
    .poll(() => page.getByTestId('plant-events').textContent())
    .toContain('a vehicle waited more than 120 s on the side road at scan 1,240 (123.90 s)');
  await page.getByTestId('plant-fault-side_loop_stuck_off').uncheck();
  await expect.poll(async () => (await plant())?.now.faults).toEqual([]);
});

test('a wrong program turns the side road green with the main road yellow: a located consequence that opens the recorded scan', async () => {
  await sim.load(intersectionWrong());
  await expect.poll(() => page.getByTestId('project-name').textContent()).toContain('wrong');
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await fastForward(300);
  const event = page.getByTestId('plant-events').getByRole('button', {
    name: 'conflicting signals: main road yellow with side road green at scan 201 (20.00 s)',
  });
  await event.click();
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toMatch(/^Recorded scan 201 \(/);
  // The drawing's readouts show that scan's machine: the conflict counted.
  await expect.poll(() => readout('conflicts')).toBe(1);
  expect(errors).toEqual([]);
});
