// The keyboard cursor stands on a box, never inside it: after C, a CTU and a coil, Ctrl+Z then ←
// lands on the CTU (framed whole, "column 2"), and `O` puts the coil after the CTU, not before it
// (which LD-R04 would flag). → from the box goes past it; a click on the box's right half puts the
// cursor on the box too.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  draw = new DrawPage(page);
});

const cursor = () =>
  page.evaluate(() => {
    const c = window.rungsmith!.uiStore!.getState().cursor;
    return c ? { row: c.row, col: c.col } : undefined;
  });
const position = async () => (await page.getByTestId('cursor-position').textContent()) ?? '';

test('C, CTU, coil, Ctrl+Z, ←: the cursor is on the CTU, not its right half, and O puts the coil after the CTU', async () => {
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Count'));
  await draw.canvas().focus();
  await page.keyboard.press('c');
  await draw.typeName('PartSensor');
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('CTU');
  await page.keyboard.press('Enter');
  await draw.typeName('Counter');
  const box = (await draw.elements(0)).find((e) => e.kind === 'box')!;
  expect(box).toMatchObject({ row: 0, col: 1 });
  // After placing and naming, the cursor is right of the whole box.
  const width = (await cursor())!.col - 1;
  expect(width).toBeGreaterThan(1); // the CTU is wider than one cell: the case the cursor must not split
  expect(await page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    const n = s.project.pous.find((p) => p.id === s.activePouId)!.networks[0]!;
    return n.elements.filter((e) => e.kind !== 'link').map((e) => e.col);
  })).toEqual([0, 1]);

  await page.keyboard.press('o');
  await draw.typeName('Done');
  expect((await draw.elements(0)).filter((e) => e.row === 0).map((e) => e.kind)).toEqual(['contact', 'box', 'coil']);

  await page.keyboard.press('Control+z');
  await expect.poll(async () => (await draw.elements(0)).some((e) => e.kind === 'coil')).toBe(false);
  await page.keyboard.press('ArrowLeft');
  expect(await cursor()).toEqual({ row: 0, col: 1 });
  await expect.poll(position).toBe('Network 1, row 1, column 2');
  // The CTU is selected: what the cursor stands on.
  expect(await page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements.length)).toBe(1);

  await page.keyboard.press('o');
  await draw.typeName('Done');
  const row0 = (await draw.elements(0)).filter((e) => e.row === 0);
  expect(row0.map((e) => e.kind)).toEqual(['contact', 'box', 'coil']);
  expect(row0.find((e) => e.kind === 'box')!.col).toBe(1);
  // No "coil not at the right end" warning.
  await page.getByRole('tab', { name: 'Problems' }).click();
  await expect.poll(() => page.getByTestId('problems-summary').textContent()).toMatch(/error|problem|No /);
  expect(await page.getByTestId('problems-panel').textContent()).not.toContain('LD-R04');

  // ← to the contact; → from the contact goes onto the box, → again past the whole box onto the coil.
  await draw.canvas().focus();
  for (let i = 0; i < 6; i++) await page.keyboard.press('ArrowLeft');
  expect(await cursor()).toEqual({ row: 0, col: 0 });
  await page.keyboard.press('ArrowRight');
  expect(await cursor()).toEqual({ row: 0, col: 1 });
  await page.keyboard.press('ArrowRight');
  const coil = row0.find((e) => e.kind === 'coil')!;
  const after = await cursor();
  expect(after!.col).toBeGreaterThanOrEqual(1 + width);
  expect(after!.col).toBeLessThanOrEqual(Math.max(coil.col, 1 + width));

  // A click on the box's right half (and on its lower row) puts the cursor on the box.
  await draw.clickCell(0, 0, 1 + width - 1);
  await expect.poll(cursor).toEqual({ row: 0, col: 1 });
  await draw.clickCell(0, 1, 1 + width - 1);
  await expect.poll(cursor).toEqual({ row: 0, col: 1 });
  await expect.poll(position).toBe('Network 1, row 1, column 2');
  // ↓ from the box goes below the whole box (its CU, R and PV rows): onto the empty row the network
  // shows under its rung (room for a branch), then into the next network; ↑ comes back onto it.
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().addNetwork());
  await draw.canvas().focus();
  await page.keyboard.press('ArrowDown');
  const networks = await draw.networks();
  expect(await page.evaluate(() => window.rungsmith!.uiStore!.getState().cursor)).toMatchObject({ network: networks[0]!.id, row: 3 });
  await page.keyboard.press('ArrowDown');
  expect(await page.evaluate(() => window.rungsmith!.uiStore!.getState().cursor)).toMatchObject({ network: networks[1]!.id, row: 0 });
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowUp');
  expect(await cursor()).toEqual({ row: 2, col: 0 }); // under the contact, beside the box's PV row
  await page.keyboard.press('ArrowRight');
  expect(await cursor()).toEqual({ row: 0, col: 1 }); // onto the box, not into its PV row
  expect(errors).toEqual([]);
});
