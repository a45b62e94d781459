// Online change that keeps state (issue 10) in a real Chromium: run the parts counter, count a few
// parts, draw a new network while it runs, and see the count kept and the change confirmed.
import { beforeEach, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import { openApp, useChromium } from './appPage';
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

/** One part past the sensor: a double-click on the PartSensor contact switches it on, another off. */
async function part(count: number) {
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('PartSensor', true);
  await sim.waitForValue('PartCount', count);
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('PartSensor', false);
}

test('parts counter: an edit in another network while running keeps the count and confirms what was kept', async () => {
  await sim.runExample('Parts counter (CTU)');
  await sim.tab('Watch');
  await page.getByTestId('watch-add-name').fill('PartCount');
  await page.getByTestId('watch-add').click();
  const shown = page.getByTestId('watch-row-PartCount').getByTestId('watch-value');
  for (let n = 1; n <= 3; n++) await part(n);
  await expect.poll(() => shown.textContent()).toBe('3');

  // A new network below, drawn from the keyboard while the program runs: Reset -> Done.
  await sim.draw.canvas().focus();
  await page.keyboard.press('n');
  await expect.poll(async () => (await sim.draw.networks()).length).toBe(2);
  await page.keyboard.press('c');
  await sim.draw.typeName('Reset');
  for (let i = 0; i < 8; i++) await page.keyboard.press('h');
  await page.keyboard.press('o');
  await sim.draw.typeName('Done');

  const applied = page.getByTestId('sim-online-applied');
  await expect.poll(() => applied.textContent(), { timeout: 30_000 }).toMatch(/^Online change applied at scan [\d,]+; kept 1 instance\b/);
  await page.waitForFunction(
    () => (window.rungsmith as unknown as { simStore: { getState(): { layout?: { networkIds: string[] } } } }).simStore.getState().layout?.networkIds.length === 2,
  );
  expect(await sim.mode()).toBe('Running');
  await expect.poll(() => shown.textContent()).toBe('3');
  expect(await sim.value('Parts.CV')).toBe(3);

  // The counter counts on from where it was.
  await part(4);
  await expect.poll(() => shown.textContent()).toBe('4');
  expect(errors).toEqual([]);
});

test('with the hardware attached as controller the edit waits for an answer: Cancel keeps the running program, Apply puts the edit in', async () => {
  await sim.runExample('Parts counter (CTU)');
  for (let n = 1; n <= 2; n++) await part(n);
  // What the Hardware tab's link does when it is open as controller (no gateway runs in this test).
  await page.evaluate(() => (window.rungsmith as unknown as { simStore: { getState(): { setOnlineConfirmRequired(r: boolean): void } } }).simStore.getState().setOnlineConfirmRequired(true));
  await sim.draw.canvas().focus();
  await page.keyboard.press('n');
  const dialog = page.getByTestId('online-change-dialog');
  await dialog.waitFor();
  expect(await dialog.textContent()).toMatch(/keeps the state of 1 instance/);
  await page.getByTestId('online-change-cancel').click();
  await expect.poll(() => page.getByTestId('sim-online-cancelled').textContent()).toMatch(/^Edit not applied online: the running program is unchanged/);
  expect(await sim.mode()).toBe('Running');
  expect(await sim.value('PartCount')).toBe(2);

  // Drawn up to the coil (the unfinished rung does not compile, so nothing is asked meanwhile).
  await sim.draw.canvas().focus();
  await page.keyboard.press('c');
  await sim.draw.typeName('Reset');
  for (let i = 0; i < 8; i++) await page.keyboard.press('h');
  await page.keyboard.press('o');
  await sim.draw.typeName('Done');
  await dialog.waitFor();
  await page.getByTestId('online-change-apply').click();
  await expect.poll(() => page.getByTestId('sim-online-applied').textContent()).toMatch(/^Online change applied at scan [\d,]+; kept 1 instance\b/);
  await part(3);
  expect(errors).toEqual([]);
});
