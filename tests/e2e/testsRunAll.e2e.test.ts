// The Tests panel's Run all under the real server (its CSP forbids compiling a program on the
// page): scenarios run in a worker of their own, pass or fail as they should, and leave the
// running simulation alone.
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

const liveScan = () =>
  page.evaluate(() => (window.rungsmith as unknown as { simStore: { getState(): { scan: number } } }).simStore.getState().scan);

const write = (name: string, value: boolean) =>
  page.evaluate(
    ([n, v]) =>
      (window.rungsmith as unknown as { simStore: { getState(): { write(n: string, i: { value: boolean }): void } } }).simStore
        .getState()
        .write(n as string, { value: v as boolean }),
    [name, value] as const,
  );

test('Run all passes the example’s scenario, fails an edited one with its scan and values, and the running simulation carries on untouched', async () => {
  // The live session: the motor sealed in, running.
  await sim.runExample('Motor start/stop (seal-in)');
  await write('Start', true);
  await sim.waitForValue('Motor', true);
  await write('Start', false);
  const before = await liveScan();

  await sim.tab('Tests');
  await page.getByTestId('tests-run-all').click();
  await page.getByTestId('tests-summary').filter({ hasText: '1 passed, 0 failed' }).waitFor();
  expect(await page.getByTestId('tests-row').first().textContent()).toContain('PASS');

  // A scenario run starts its own PLC from a cold restart: the live one keeps its scans and its Motor.
  expect(await sim.mode()).toContain('Running');
  expect(await sim.value('Motor')).toBe(true);
  await expect.poll(liveScan, { timeout: 30_000 }).toBeGreaterThan(before);

  // Edited through the panel: scan 2 now expects the motor off, which the program does not do.
  await page.getByTestId('tests-row').first().getByRole('button', { name: 'Edit' }).click();
  const csv = page.getByLabel('Scenario CSV');
  await csv.fill((await csv.inputValue()).replace('\n2,1,0,1\n', '\n2,1,0,0\n'));
  await page.getByRole('button', { name: 'Save scenario' }).click();
  await page.getByTestId('tests-run-all').click();
  await page.getByTestId('tests-summary').filter({ hasText: '0 passed, 1 failed' }).waitFor();
  expect(await page.getByTestId('tests-failure').textContent()).toBe('scan 2: Motor expected 0, got 1');
  expect(await sim.value('Motor')).toBe(true);
  expect(await sim.mode()).toContain('Running');
  expect(errors).toEqual([]);
});

test('a scenario naming a variable the program lacks fails with the reason, and a fixed one passes again', async () => {
  await sim.openExample('Motor start/stop (seal-in)');
  await sim.tab('Tests');
  await page.getByTestId('tests-row').first().getByRole('button', { name: 'Edit' }).click();
  const csv = page.getByLabel('Scenario CSV');
  const original = await csv.inputValue();
  await csv.fill(original.replace('expect Motor', 'expect Pump'));
  await page.getByRole('button', { name: 'Save scenario' }).click();
  await page.getByTestId('tests-run-all').click();
  await page.getByTestId('tests-summary').filter({ hasText: '0 passed, 1 failed' }).waitFor();
  expect(await page.getByTestId('tests-failure').textContent()).toMatch(/unknown variable "Pump"/);

  await csv.fill(original);
  await page.getByRole('button', { name: 'Save scenario' }).click();
  await page.getByTestId('tests-run-all').click();
  await page.getByTestId('tests-summary').filter({ hasText: '1 passed, 0 failed' }).waitFor();
  expect(errors).toEqual([]);
});
