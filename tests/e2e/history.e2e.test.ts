// Scan history, "Why?" and test scenarios in a real Chromium: the one-scan pulse found on the
// timeline, "Why is Motor off?" naming the open Stop contact, and a recorded scenario that fails
// after an edit and passes after the fix.
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

/** Runs the motor, then gives Start a one-scan pulse followed by Stop for one scan, and runs on. */
async function pulse(): Promise<void> {
  await sim.runExample('Motor start/stop (seal-in)');
  await page.waitForTimeout(300);
  await sim.button('pause').click();
  await sim.waitForMode('Paused');
  const write = (name: string, value: boolean) =>
    page.evaluate(([n, v]) => (window.rungsmith as unknown as { simStore: { getState(): { write(n: string, i: { value: boolean }): void } } }).simStore.getState().write(n as string, { value: v as boolean }), [name, value] as const);
  await write('Start', true);
  await sim.button('step-scan').click();
  await sim.waitForValue('Motor', true);
  await write('Start', false);
  await write('Stop', true);
  await sim.button('step-scan').click();
  await sim.waitForValue('Motor', false);
  await write('Stop', false);
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await page.waitForTimeout(300);
}

test('the one-scan pulse is found on the timeline and shown as it was while the program runs on', async () => {
  await pulse();
  await page.getByTestId('history-condition').fill('Motor');
  await page.getByTestId('history-find').click();
  const marker = page.getByTestId('history-marker');
  await marker.filter({ hasText: 'HISTORY' }).waitFor();
  expect(await sim.value('Motor')).toBe(true); // the view shows the pulse scan
  expect(await sim.value('Start')).toBe(true);
  await expect.poll(() => sim.wireLit(0, 0, 9)).toBe(true); // the coil lit on the canvas, as in that scan
  await page.getByTestId('history-next').click();
  await expect.poll(() => sim.value('Motor')).toBe(false);
  expect(await sim.mode()).toContain('Running');
  await page.getByTestId('history-live').click();
  await marker.filter({ hasText: 'Live' }).waitFor();
  expect(errors).toEqual([]);
});

test('Why is Motor off? names the open Stop contact, and follows the change back', async () => {
  await pulse();
  await page.getByTestId('history-condition').fill('Stop');
  await page.getByTestId('history-find').click();
  await page.getByTestId('history-marker').filter({ hasText: 'HISTORY' }).waitFor();
  await sim.tab('Why?');
  await page.getByTestId('why-input').fill('Motor');
  await page.getByTestId('why-ask').click();
  const why = page.getByTestId('why-explanation');
  await why.filter({ hasText: '|/| Stop is open: Stop is TRUE' }).waitFor();
  expect(await why.textContent()).toMatch(/Motor is FALSE after scan \d+/);
  await page.getByTestId('why-link').first().click();
  await why.filter({ hasText: 'When did it change?' }).waitFor();
  expect(errors).toEqual([]);
});

test('a scenario recorded from the simulation fails after an edit and passes after the fix', async () => {
  await pulse();
  await sim.tab('Tests');
  // The example's own scenario is listed; record another from what was just simulated.
  await page.getByTestId('tests-record').click();
  await expect.poll(() => page.getByTestId('tests-row').count()).toBe(2);
  await page.getByTestId('tests-run-all').click();
  await page.getByTestId('tests-summary').filter({ hasText: '2 passed, 0 failed' }).waitFor();
  // The edit: Stop becomes a normally open contact (a classic wiring mistake).
  await page.evaluate(() => {
    const doc = window.rungsmith!.documentStore!.getState();
    const el = doc.project.pous[0]!.networks[0]!.elements.find((e) => e.kind === 'contact' && e.variable === 'Stop')!;
    doc.updateElement(el.id, { contact: 'NO' } as never);
  });
  await page.getByTestId('tests-run-all').click();
  await page.getByTestId('tests-summary').filter({ hasText: '0 passed, 2 failed' }).waitFor();
  expect(await page.getByTestId('tests-failure').first().textContent()).toMatch(/scan \d+: Motor expected 1, got 0/);
  // Why it failed: the first divergent scan, with Why? on Motor, from a run in a simulation of its
  // own; the live session runs on.
  await page.getByTestId('tests-open').first().click();
  await page.getByTestId('scenario-why').filter({ hasText: '| | Stop is open: Stop is FALSE' }).waitFor();
  expect(await sim.mode()).toMatch(/Running/);
  // The fix (undo), and the scenarios pass again.
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  await sim.tab('Tests');
  await page.getByTestId('tests-run-all').click();
  await page.getByTestId('tests-summary').filter({ hasText: '2 passed, 0 failed' }).waitFor();
  expect(errors).toEqual([]);
});
