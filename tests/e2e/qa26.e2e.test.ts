// Issue 26's machines as found in exploratory QA, in real Chromium against the real server: the
// Plant panel's I/O map refuses an address another point already has however it is spelt
// (%IX00.2 is %IX0.2), and "Declare the machine's I/O" leaves a variable of another type where it
// is (saying so) instead of moving it onto the point's address. One page for the file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

interface DocHandle {
  documentStore: {
    getState(): {
      project: {
        plant?: unknown;
        pous: { id: string; kind: string; name: string; variables: { name: string; type: string; location?: string }[] }[];
      };
      undoName?: string;
      updateVariable(name: string, patch: { type?: string; location?: string }, scope?: string): boolean;
    };
  };
}
const docPlant = () => page.evaluate(() => (window.rungsmith as unknown as DocHandle).documentStore.getState().project.plant);
const mainVariable = (name: string) =>
  page.evaluate((n) => {
    const s = (window.rungsmith as unknown as DocHandle).documentStore.getState();
    const v = s.project.pous.find((p) => p.kind === 'PROGRAM')!.variables.find((x) => x.name === n);
    return v ? `${v.type}@${v.location ?? ''}` : undefined;
  }, name);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  await sim.openExample('Tank level control (machine: tank)');
  await sim.tab('Plant');
});

test("an address another point has, spelt differently, is refused in the I/O map; a free one is kept as IEC spells it", async () => {
  await expect.poll(docPlant).toEqual({ id: 'tank' });
  const start = page.getByTestId('plant-address-Start');
  await start.fill('%IX00.2');
  await start.press('Enter');
  await expect
    .poll(() => page.getByTestId('plant-io-problem').textContent())
    .toBe("Start: %IX00.2 is already LowLevel's address (%IX0.2)");
  expect(await docPlant()).toEqual({ id: 'tank' });
  await start.fill('%I0.1');
  await start.press('Tab');
  await expect
    .poll(() => page.getByTestId('plant-io-problem').textContent())
    .toBe("Start: %I0.1 is already Stop's address (%IX0.1)");
  expect(await docPlant()).toEqual({ id: 'tank' });
  await start.fill('%ix01.5');
  await start.press('Enter');
  await expect.poll(docPlant).toEqual({ id: 'tank', map: { Start: '%IX1.5' } });
  await expect.poll(() => page.getByTestId('plant-io-problem').count()).toBe(0);
  await expect.poll(() => start.inputValue()).toBe('%IX1.5');
  expect(errors).toEqual([]);
});

test("Declare the machine's I/O leaves a variable of another type where it is and says so, in one undo step", async () => {
  // The program's Level is a BOOL at %IX5.0: the machine's Level is an INT at %IW0.
  await page.evaluate(() => {
    const s = (window.rungsmith as unknown as DocHandle).documentStore.getState();
    const main = s.project.pous.find((p) => p.kind === 'PROGRAM')!;
    s.updateVariable('Level', { type: 'BOOL', location: '%IX5.0' }, main.id);
  });
  await expect.poll(() => mainVariable('Level')).toBe('BOOL@%IX5.0');
  await page.getByTestId('plant-declare').click();
  await expect
    .poll(() => page.getByTestId('plant-declared').textContent())
    .toBe(
      "Moved Start from %IX0.0 to %IX1.5. Not wired, left as declared: Level (BOOL; the machine's Level is INT at %IW0).",
    );
  expect(await mainVariable('Level')).toBe('BOOL@%IX5.0');
  expect(await mainVariable('Start')).toBe('BOOL@%IX1.5');
  await expect.poll(() => page.getByTestId('plant-wired-Level').textContent()).toBe('not wired: Level is at %IX5.0');
  await expect.poll(() => page.getByTestId('plant-wired-Start').textContent()).toBe('Start');
  await sim.draw.menu('Edit', 'Undo');
  await expect.poll(() => mainVariable('Start')).toBe('BOOL@%IX0.0');
  expect(await mainVariable('Level')).toBe('BOOL@%IX5.0');
  expect(errors).toEqual([]);
});

test("another machine chosen: the I/O map's refusal and Declare's report of the machine before are gone", async () => {
  const start = page.getByTestId('plant-address-Start');
  await start.fill('%QX0.0');
  await start.press('Enter');
  await expect
    .poll(() => page.getByTestId('plant-io-problem').textContent())
    .toBe('Start: a sensor or operator control is a %I input, not %QX0.0');
  await page.getByTestId('plant-declare').click();
  await expect.poll(() => page.getByTestId('plant-declared').count()).toBe(1);
  await page.getByTestId('plant-choose').selectOption('lift');
  await expect.poll(docPlant).toEqual({ id: 'lift' });
  await expect.poll(() => page.getByTestId('plant-address-Call1').inputValue()).toBe('%IX0.0');
  expect(await page.getByTestId('plant-io-problem').count()).toBe(0);
  expect(await page.getByTestId('plant-declared').count()).toBe(0);
  expect(errors).toEqual([]);
});
