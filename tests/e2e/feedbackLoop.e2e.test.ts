// An explicit feedback loop drawn on the canvas (issue 23 class 4): a user draws a blinker,
// `>C>` → inverting contact → TON T1 → `>C>`, and `>C>` → coil Q below, so that T1's Q comes back
// to its own IN.
// The Problems list shows a warning LD-W30 naming T1 (no error: the loop reads T1.Q of the
// previous call, as IEC 61131-3 4.1.3 does for FBD and MATIEC does for LD), and the program runs:
// Q blinks.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newPou, newProject } from '../../src/model/factory';
import type { Variable } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

const CHECKS = { timeout: 30_000 };
const v = (name: string, type: string, location?: string): Variable => ({
  name,
  type,
  varClass: 'local',
  ...(location ? { location } : {}),
  retain: false,
  comment: '',
});

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
});

test('draw a blinker whose TON feeds its own IN through a connector pair: a located LD-W30 warning, no error, and Q blinks', async () => {
  const main = newPou('Main');
  await sim.load(newProject('Blinker', { pous: [{ ...main, variables: [v('Q', 'BOOL', '%QX0.0'), v('T1', 'TON')] }] }));
  const draw = sim.draw;

  await draw.pickPalette('continuation');
  await draw.clickCell(0, 0, 0);
  await draw.typeName('C');
  await draw.pickPalette('contact-NOT');
  await draw.clickCell(0, 0, 1);
  await draw.pickPalette('select');
  await draw.clickCell(0, 0, 2);
  await draw.canvas().focus();
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('TON');
  await page.keyboard.press('Enter');
  await draw.typeName('T1');
  // Enter on the selected box opens its first open pin, PT.
  await page.keyboard.press('Enter');
  const pin = page.getByTestId('pin-editor');
  await pin.waitFor();
  await expect.poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('PT');
  await pin.fill('T#200ms');
  await page.keyboard.press('Enter');
  await page.keyboard.press('Escape');
  await pin.waitFor({ state: 'detached' });
  const box = (await draw.elements(0)).find((e) => e.kind === 'box')!;
  // T1.Q ends in >C>; a row below the box starts with >C> and drives the coil Q.
  await draw.pickPalette('connector');
  await draw.clickCell(0, 0, box.col + 2);
  await draw.typeName('C');
  await draw.pickPalette('continuation');
  await draw.clickCell(0, 2, 0);
  await draw.typeName('C');
  await draw.pickPalette('coil-COIL');
  await draw.clickCell(0, 2, 1);
  await draw.typeName('Q');
  await draw.pickPalette('select');
  const kinds = (row: number) =>
    draw.elements(0).then((els) => els.filter((e) => e.row === row && e.kind !== 'link').sort((a, b) => a.col - b.col).map((e) => e.kind));
  expect(await kinds(0)).toEqual(['continuation', 'contact', 'box', 'connector']);
  expect(await kinds(2)).toEqual(['continuation', 'coil']);

  // The Problems list: the loop is a warning on T1, located, not an error.
  await page.getByRole('tab', { name: 'Problems' }).click();
  await expect.poll(() => page.getByTestId('problems-panel').textContent(), CHECKS).toContain('LD-W30');
  const text = (await page.getByTestId('problems-panel').textContent()) ?? '';
  expect(text).toMatch(/TON block "T1" feeds back into the inverting contact/);
  expect(text).not.toContain('LD-R01');
  expect(await draw.problemsSummary()).toBe('0 errors, 1 warning');

  // It runs, and Q blinks: on, off, on again.
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.waitForValue('Q', true);
  await sim.waitForValue('Q', false);
  await sim.waitForValue('Q', true);
  expect(errors).toEqual([]);
});
