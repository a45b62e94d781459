// The scan history includes the machine (issue 26), in real Chromium against the real server: the
// tank exercise run with Start held on the drawing; History Find on the machine's level shows the
// recorded scan where the tank held more than 500 L, the drawing as it was then; Export trace
// has the machine's quantities; Record from simulation makes a scenario against the machine (its
// Start button a column, its sensors not inputs to set) that replays to PASS. One page.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let plants: PlantPage;
let errors: string[];

interface Handle {
  simStore: {
    getState(): { historyScan?: number; plant?: { now: { faults: string[] } }; exportHistory(r: { format: 'trace' }): Promise<string>; seekHistory(scan: number): void };
  };
  documentStore: { getState(): { project: { scenarios?: { name: string; csv: string }[] } } };
}

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
  await plants.openExercise('Tank level control (machine: tank)', 100);
});

test('History Find on tank.level shows a recorded scan above 500 L, and the machine as it was there; Export trace has its quantities', async () => {
  await plants.startAndFastForward(1500);
  const trace = (await page.evaluate(() => (window.rungsmith as unknown as Handle).simStore.getState().exportHistory({ format: 'trace' }))).trim().split('\n');
  const header = trace[0]!.split(',');
  // The machine's quantities are columns of the exported trace, after the program's variables.
  expect(header).toEqual(expect.arrayContaining(['Level', 'Pump', 'tank.level', 'tank.inflow', 'tank.overflows']));
  expect(header.indexOf('tank.level')).toBeGreaterThan(header.indexOf('Pump'));
  const rows = trace.slice(1).map((r) => r.split(','));
  const level = header.indexOf('tank.level');
  const first = rows.findIndex((r) => Number(r[level]) > 500) + 1;
  expect(first).toBeGreaterThan(1);

  await page.getByTestId('history-condition').fill('tank.level > 500');
  await page.getByTestId('history-find').click();
  await page.getByTestId('history-marker').filter({ hasText: 'HISTORY' }).waitFor();
  // A recorded scan where it holds is shown.
  await expect.poll(() => page.evaluate(() => (window.rungsmith as unknown as Handle).simStore.getState().historyScan)).toBeDefined();
  const found = (await page.evaluate(() => (window.rungsmith as unknown as Handle).simStore.getState().historyScan))!;
  expect(Number(rows[found - 1]![level])).toBeGreaterThan(500);
  // The drawing's readout is the machine at that recorded scan.
  await expect
    .poll(() => page.getByTestId('plant-q-level').textContent())
    .toBe(`tank.level${Number(rows[found - 1]![level]).toFixed(1)} L`);
  await page.getByTestId('history-live').click();
  await page.getByTestId('history-marker').filter({ hasText: 'Live' }).waitFor();
  expect(errors).toEqual([]);
});

test('Record from simulation makes a scenario against the machine that replays to PASS', async () => {
  await sim.tab('Tests');
  const rows = page.getByTestId('tests-row');
  const before = await rows.count();
  await page.getByTestId('tests-record').click();
  await expect.poll(() => rows.count()).toBe(before + 1);
  const recorded = (await page.evaluate(() => (window.rungsmith as unknown as Handle).documentStore.getState().project.scenarios ?? [])).at(-1)!;
  const lines = recorded.csv.trim().split('\n');
  expect(lines).toContain('# plant: tank');
  const header = lines.find((l) => l.startsWith('scan,'))!.split(',');
  expect(header).toContain('tank.Start');
  for (const sensor of ['LowLevel', 'HighLevel', 'Level', 'Start']) expect(header).not.toContain(sensor);
  await rows.nth(before).getByTestId('tests-open').click();
  await expect.poll(() => page.getByTestId('scenario-run-result').textContent(), { timeout: 60_000 }).toMatch(/^PASS in \d+ scans$/);
  expect(errors).toEqual([]);
});

test('at a recorded scan the fault boxes show the faults set then; a box used there turns the live fault over and goes back to Live', async () => {
  await sim.tab('Plant');
  const box = page.getByTestId('plant-fault-inlet_slow');
  const state = () => page.evaluate(() => (window.rungsmith as unknown as Handle).simStore.getState());
  const before = (await plants.simScan()) - 5;
  await box.check();
  await expect.poll(async () => (await state()).plant?.now.faults).toEqual(['inlet_slow']);
  await plants.fastForward(20);
  // A scan recorded before the fault: its box is clear, as the machine was then.
  await page.evaluate((scan) => (window.rungsmith as unknown as Handle).simStore.getState().seekHistory(scan), before);
  await expect.poll(async () => (await state()).historyScan).toBe(before);
  await expect.poll(() => box.isChecked()).toBe(false);
  // Used there, it clears the live fault (set now) and shows Live.
  await box.click();
  await expect.poll(async () => (await state()).historyScan).toBeUndefined();
  await expect.poll(async () => (await state()).plant?.now.faults).toEqual([]);
  await expect.poll(() => box.isChecked()).toBe(false);
  expect(errors).toEqual([]);
});

