// Forcing from the canvas menu and the watch table, and reading the trend with its cursor.
import { beforeEach, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import { openApp, settledBox, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

beforeEach(async () => {
  await page?.close();
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
});

test('forcing Stop from the canvas menu holds the motor off until all forces are removed', async () => {
  await sim.runExample('Motor start/stop (seal-in)');
  const stop = await sim.draw.cellPoint(0, 0, 1);
  await page.mouse.click(stop.x, stop.y, { button: 'right' });
  const menu = page.getByTestId('sim-context-menu');
  await menu.getByRole('menuitem', { name: 'Force TRUE' }).click();
  await sim.waitForValue('Stop', true);
  await sim.switchCell(0, 0, 0); // Start switched on
  await sim.waitForValue('Start', true);
  await page.waitForTimeout(200);
  expect(await sim.value('Motor')).toBe(false);

  await sim.tab('Breakpoints & forces');
  await expect.poll(() => page.getByTestId('simulation-panel').textContent()).toContain('Stop = TRUE');
  await page.getByTestId('simulation-panel').getByRole('button', { name: 'Remove all forces' }).click();
  await sim.waitForValue('Motor', true);
  expect(errors).toEqual([]);
});

test('the watch table forces a number, marks it, and unforces it', async () => {
  await sim.openExample('Parts counter (CTU)');
  await sim.tab('Watch');
  await page.getByTestId('watch-add-name').fill('PartCount');
  await page.getByTestId('watch-add').click();
  const row = page.getByTestId('watch-row-PartCount');
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('0');
  await row.getByTestId('watch-input').fill('42');
  await row.getByTestId('watch-force').click();
  await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('42 F');
  await row.getByTestId('watch-unforce').click();
  await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('0');
  // Counting: each toggle of the sensor on is one part.
  for (let i = 0; i < 3; i++) {
    await sim.switchCell(0, 0, 0);
    await sim.waitForValue('PartSensor', i % 2 === 0);
  }
  await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('2');
  expect(errors).toEqual([]);
});

test('the trend draws chosen signals over the last scans and its cursor reads values at a scan', async () => {
  await sim.openExample('Traffic light (TON chain)');
  await sim.tab('Trend');
  for (const name of ['Red', 'Green', 'RedTime.ET']) {
    await page.getByTestId('trend-add-name').fill(name);
    await page.getByTestId('trend-add').click();
  }
  await page.getByTestId('sim-step-count').fill('700');
  await sim.button('step-n').click();
  await sim.waitForMode('Paused');
  expect(await page.getByTestId('sim-scan').textContent()).toBe('700');
  const chart = page.getByTestId('trend-chart');
  const over = chart.locator('.u-over');
  await over.waitFor();
  const box = await settledBox(over); // the chart resized to the panel
  // The window holds the last 500 scans (201..700): red is on until 5 s (scan 501), then green.
  await page.mouse.move(box.x + box.width * 0.1, box.y + box.height / 2, { steps: 5 });
  const legend = chart.locator('.u-legend');
  await expect.poll(() => legend.textContent()).toMatch(/Red\s*TRUE.*Green\s*FALSE/);
  await page.mouse.move(box.x + box.width * 0.9, box.y + box.height / 2, { steps: 5 });
  await expect.poll(() => legend.textContent()).toMatch(/Red\s*FALSE.*Green\s*TRUE/);
  expect(await legend.textContent()).toMatch(/scan\s*6\d\d \(t = \d+ ms\)/);
  expect(errors).toEqual([]);
});

test('the inputs panel: Hold is a push-button, the switch latches', async () => {
  await sim.runExample('Motor start/stop (seal-in)');
  await sim.tab('Inputs');
  const start = page.getByTestId('input-Start');
  const hold = start.getByTestId('input-hold');
  const box = (await hold.boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await sim.waitForValue('Start', true);
  await page.mouse.up();
  await sim.waitForValue('Start', false);
  await sim.waitForValue('Motor', true);
  const stopSwitch = page.getByTestId('input-Stop').getByTestId('input-switch');
  await stopSwitch.click();
  await sim.waitForValue('Motor', false);
  await expect.poll(() => stopSwitch.getAttribute('aria-checked')).toBe('true');
  expect(errors).toEqual([]);
});

test('editing while running is applied online: a new network joins, the motor keeps running', async () => {
  await sim.runExample('Motor start/stop (seal-in)');
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('Motor', true);
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('Start', false);
  await page.getByRole('button', { name: 'Insert network after network 1' }).click();
  await page.waitForFunction(() => {
    const s = (window.rungsmith as unknown as { simStore: { getState(): { layout?: { networkIds: string[] } } } }).simStore.getState();
    return s.layout?.networkIds.length === 2;
  });
  expect(await sim.mode()).toBe('Running');
  expect(await sim.value('Motor')).toBe(true);
  expect(await page.getByTestId('sim-refusal').count()).toBe(0);
});
