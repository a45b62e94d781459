// Watching the machine (issue 26), in real Chromium against the real server: the tank example's
// `tank.level` and `tank.Pump` added to the watch table by completion, live and at a recorded scan;
// `tank.level` plotted in the trend; "Why?" on HighLevel (wired to the tank's high level switch)
// says the machine writes it and why it is ON, with the machine's quantities. Fast-forwarded with
// Step N (never waiting in real time); one page for the file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

interface Snapshot {
  scan: number;
  state: { level: number };
}
interface MonitorHandle {
  getState(): {
    timeMs: number;
    historyScan?: number;
    plant?: { now: Snapshot };
    plantAtScan?: Snapshot;
    trend: { names: string[]; scans: number[]; series: number[][] };
  };
}
const state = () =>
  page.evaluate(() => {
    const s = (window.rungsmith as unknown as { simStore: MonitorHandle }).simStore.getState();
    return { timeMs: s.timeMs, historyScan: s.historyScan, now: s.plant?.now, atScan: s.plantAtScan, trend: s.trend };
  });
const watchValue = (name: string) => page.getByTestId(`watch-row-${name}`).getByTestId('watch-value').textContent();

async function stepScans(scans: number) {
  const from = (await state()).timeMs;
  await page.getByTestId('sim-step-count').fill(String(scans));
  await sim.button('step-n').click();
  await expect.poll(async () => (await state()).timeMs, { timeout: 120_000 }).toBeGreaterThanOrEqual(from + scans * 100);
  await sim.waitForMode('Paused');
}

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  await sim.openExample('Tank level control (machine: tank)');
  await page.getByTestId('sim-cycle').fill('100');
  await page.getByTestId('sim-cycle').press('Enter');
});

test('tank.level and tank.Pump are added to the watch by completion and show the machine live', async () => {
  await sim.tab('Watch');
  const field = page.getByTestId('watch-add-name');
  await field.fill('tank.le');
  const choices = page.getByTestId('watch-choices').getByTestId('watch-choice');
  await expect.poll(() => choices.allTextContents()).toContain('tank.level');
  await choices.filter({ hasText: /^tank\.level$/ }).click();
  // Spelt exactly: the pump's contactor (tank.Pump), not its speed (tank.pump); both are offered.
  await field.fill('tank.p');
  await expect.poll(() => choices.allTextContents()).toEqual(expect.arrayContaining(['tank.pump', 'tank.Pump']));
  await field.fill('tank.Pump');
  await field.press('Enter');
  await page.getByTestId('watch-row-tank.level').waitFor();
  await page.getByTestId('watch-row-tank.Pump').waitFor();
  await expect.poll(() => page.getByTestId('watch-row-tank.Pump').locator('td').nth(1).textContent()).toBe('BOOL');

  // Run, press Start on the drawing, pause, fast-forward.
  await sim.tab('Plant');
  await sim.button('run').click();
  await sim.waitForMode('Running');
  const start = page.getByTestId('plant-op-Start');
  await start.scrollIntoViewIfNeeded();
  const box = (await start.boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await sim.waitForValue('Running', true);
  await page.mouse.up();
  await sim.button('pause').click();
  await sim.waitForMode('Paused');
  await stepScans(150);
  await sim.tab('Watch');
  const live = await state();
  expect(live.historyScan).toBeUndefined();
  // Filling: the level rose from 100 L, the pump runs.
  expect(live.now!.state.level).toBeGreaterThan(150);
  await expect.poll(() => watchValue('tank.level')).toBe(`${live.now!.state.level.toFixed(1)} L`);
  await expect.poll(() => watchValue('tank.Pump')).toBe('TRUE');
});

test('tank.level is plotted in the trend, sampled every scan as the machine was', async () => {
  await page.getByTestId('watch-row-tank.level').getByRole('checkbox').check();
  await stepScans(100);
  await sim.tab('Trend');
  await expect.poll(async () => (await state()).trend.names).toEqual(['tank.level']);
  await expect.poll(async () => (await state()).trend.scans.length).toBeGreaterThanOrEqual(100);
  const { trend, now } = await state();
  const series = trend.series[0]!;
  // The last sample is the machine after the last scan; the level rose scan by scan while filling.
  expect(trend.scans.at(-1)).toBe(now!.scan);
  expect(series.at(-1)).toBe(now!.state.level);
  expect(series.at(-1)!).toBeGreaterThan(series[0]!);
  // The chart draws it (uPlot's legend names the series).
  await expect.poll(() => page.getByTestId('trend-panel').textContent()).toContain('tank.level');
});

test('at a recorded scan the watch shows the machine as it was, and "Why?" on HighLevel says the machine wrote it', async () => {
  await stepScans(250);
  // The first scan whose HighLevel is ON (the tank reached its high switch).
  await page.getByTestId('history-condition').fill('HighLevel');
  await page.getByTestId('history-find').click();
  await expect.poll(async () => (await state()).atScan?.scan).toBeGreaterThan(1);
  const { historyScan, atScan, now } = await state();
  expect(atScan!.scan).toBe(historyScan);
  await sim.tab('Watch');
  await expect.poll(() => watchValue('tank.level')).toBe(`${atScan!.state.level.toFixed(1)} L`);
  expect(atScan!.state.level).not.toBe(now!.state.level);
  expect(atScan!.state.level).toBeGreaterThanOrEqual(800);

  await sim.tab('Why?');
  await page.getByTestId('why-input').fill('HighLevel');
  await page.getByTestId('why-ask').click();
  const why = page.getByTestId('why-explanation');
  await expect.poll(() => why.textContent()).toContain(`HighLevel is TRUE after scan ${historyScan!.toLocaleString('en-US')}`);
  const text = (await why.textContent())!;
  expect(text).toContain('HighLevel (%IX0.3) is written by the machine tank: HighLevel, high level float switch, ON at 800 L and above.');
  const level = Number(/the level is (\d+\.\d) L, so it is ON/.exec(text)?.[1]);
  expect(level).toBeGreaterThanOrEqual(800);
  expect(text).toMatch(new RegExp(`The machine after scan ${(historyScan! - 1).toLocaleString('en-US')}: level ${level.toFixed(1)} L, percent`));

  // Why? on the machine's own quantity.
  await page.getByTestId('why-input').fill('tank.level');
  await page.getByTestId('why-ask').click();
  await expect.poll(() => why.textContent()).toContain(`tank.level is ${atScan!.state.level.toFixed(1)} L after scan ${historyScan!.toLocaleString('en-US')}`);
  expect(errors).toEqual([]);
});
