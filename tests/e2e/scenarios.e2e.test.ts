// Test scenarios against the real server (issue 22, 2.2 and 2.3): a recording the scenario could
// not replay (an online change, a force) is refused with the reason; one recorded from a cold
// start replays to PASS; running a scenario never touches the live session (scan, forces); a new
// scenario starts with the program's columns; the grid always shows the CSV it was saved with.
import type { Page } from 'playwright-core';
import { beforeEach, expect, test } from 'vitest';
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

interface Live {
  scan: number;
  forced: string[];
  onlineChange?: { kind: string };
}
type SimCalls = {
  getState(): Live & {
    write(n: string, i: { value: boolean }): void;
    force(n: string, i: { value: boolean }): void;
    unforceAll(): void;
  };
};
const live = () =>
  page.evaluate(() => {
    const s = (window.rungsmith as unknown as { simStore: { getState(): Live & { forced: Map<string, unknown> } } }).simStore.getState();
    return { scan: s.scan, forced: [...s.forced.keys()], onlineChange: s.onlineChange ? { kind: s.onlineChange.kind } : undefined };
  });
const call = (fn: 'write' | 'force', name: string, value: boolean) =>
  page.evaluate(
    ([f, n, v]) => (window.rungsmith as unknown as { simStore: SimCalls }).simStore.getState()[f as 'write'](n as string, { value: v as boolean }),
    [fn, name, value] as const,
  );
const message = () => page.getByTestId('tests-panel').getByRole('status').textContent();
const rows = () => page.getByTestId('tests-row');

test('a mid-run recording is refused with the reason; one from a cold start replays to PASS; a run leaves the live session alone', async () => {
  await sim.runExample('Motor start/stop (seal-in)');
  await sim.tab('Tests');
  // Mid-run: inputs, a force, and an online change (a variable declared while running).
  await call('write', 'Start', true);
  await sim.waitForValue('Motor', true);
  await call('write', 'Start', false);
  await call('force', 'Stop', true);
  await sim.waitForValue('Motor', false);
  await page.evaluate(() =>
    window.rungsmith!.documentStore!.getState().addVariable({ name: 'Spare', type: 'BOOL', varClass: 'local', retain: false, comment: '' }),
  );
  await expect.poll(async () => (await live()).onlineChange?.kind, { timeout: 15_000 }).toBe('applied');
  await page.getByTestId('tests-record').click();
  await expect.poll(message).toMatch(
    /^A scenario replays from a cold start, and an online change at scan \d+ changed the program or its state since the last one: .*Press Reset \(cold restart\), release the forces, run and switch the inputs, then record again\.$/,
  );
  expect(await rows().count()).toBe(1);
  // Refusing touched nothing: still running, the force still on.
  expect(await sim.mode()).toMatch(/Running/);
  expect((await live()).forced).toEqual(['STOP']);

  // From a cold start, as the message says.
  // Released, a forced input keeps its value until the process (here: the user) switches it.
  await page.evaluate(() => (window.rungsmith as unknown as { simStore: SimCalls }).simStore.getState().unforceAll());
  await call('write', 'Stop', false);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await call('write', 'Start', true);
  await sim.waitForValue('Motor', true);
  await call('write', 'Start', false);
  await page.waitForTimeout(100);
  await call('write', 'Stop', true);
  await sim.waitForValue('Motor', false);
  await call('write', 'Stop', false);
  await page.waitForTimeout(100);
  await page.getByTestId('tests-record').click();
  await expect.poll(() => rows().count()).toBe(2);
  expect(await message()).toMatch(/^Recorded 2 added from the scan history/);

  // The live session is forced and running; running the scenario does not touch it.
  await call('force', 'Stop', true);
  const before = await live();
  await rows().nth(1).getByTestId('tests-open').click();
  await expect.poll(() => page.getByTestId('scenario-run-result').textContent(), { timeout: 30_000 }).toMatch(/^PASS in \d+ scans$/);
  expect(await page.getByTestId('scenario-run-note').textContent()).toContain('the live session (its scan, values and forces) is untouched');
  expect(await sim.mode()).toMatch(/Running/);
  await expect.poll(async () => (await live()).scan).toBeGreaterThan(before.scan);
  expect((await live()).forced).toEqual(['STOP']);
  expect(await page.getByTestId('tests-summary').textContent()).toBe('1 passed, 0 failed');
  expect(errors).toEqual([]);
});

test('New scenario has the program columns; after Edit, a replaced CSV and Save the grid shows the new CSV; the summary counts one scenario once', async () => {
  await sim.openExample('Motor start/stop (seal-in)');
  await sim.tab('Tests');
  await page.getByTestId('tests-new').click();
  await expect.poll(() => rows().count()).toBe(2);
  const editor = page.getByTestId('scenario-editor');
  expect(await editor.getByTestId('scenario-table').locator('th').allTextContents()).toEqual(['scan', 'Start', 'Stop', 'expect Motor']);
  expect(await rows().nth(1).locator('td').first().textContent()).toBe('Scenario 2');

  const csv = editor.getByLabel('Scenario CSV');
  await csv.fill('scan,Start,Stop,expect Motor\n1,1,0,1\n3,0,0,1\n');
  await editor.getByRole('button', { name: 'Save scenario' }).click();
  await rows().nth(1).getByTestId('tests-open').click();
  await expect.poll(() => page.getByTestId('tests-summary').textContent(), { timeout: 30_000 }).toBe('1 passed, 0 failed');

  // Rename it and replace its CSV with other scans and values.
  await editor.getByRole('textbox', { name: 'Name' }).fill('Stop wins');
  await csv.fill('scan,Start,Stop,expect Motor\n2,1,0,1\n5,0,1,0\n');
  await editor.getByRole('button', { name: 'Save scenario' }).click();
  const cell = (scan: number, name: string) => editor.getByRole('textbox', { name: `scan ${scan} ${name}`, exact: true }).inputValue();
  const grid = async () => [await cell(2, 'Start'), await cell(2, 'Stop'), await cell(2, 'Motor'), await cell(5, 'Start'), await cell(5, 'Stop'), await cell(5, 'Motor')];
  expect(await grid()).toEqual(['1', '0', '1', '0', '1', '0']);
  expect(await editor.getByTestId('scenario-table').locator('tbody tr td:first-child').allTextContents()).toEqual(['2', '5']);
  // The old result belonged to the scenario as it was: no summary until it runs again.
  expect(await page.getByTestId('tests-summary').count()).toBe(0);
  await rows().nth(1).getByTestId('tests-open').click();
  await expect.poll(() => page.getByTestId('tests-summary').textContent(), { timeout: 30_000 }).toBe('1 passed, 0 failed');

  // A cell edited in the grid goes into the CSV.
  await editor.getByRole('textbox', { name: 'scan 5 Motor', exact: true }).fill('1');
  await editor.getByRole('textbox', { name: 'scan 5 Motor', exact: true }).press('Tab');
  expect(await csv.inputValue()).toBe('scan,Start,Stop,expect Motor\n2,1,0,1\n5,0,1,1\n');
  expect(errors).toEqual([]);
});
