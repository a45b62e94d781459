// Networks (add, title, label, comment, collapse, reorder, delete) and canvas gestures (drag to
// move, rubber band, zoom, block picker), driven with mouse and keyboard in Chromium.
import { afterAll, beforeAll, beforeEach, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
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

beforeEach(async () => {
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Networks'));
});

afterAll(() => {
  expect(errors).toEqual([]);
});

const titles = async () => (await draw.networks()).map((n) => n.title);

test('networks: insert, title, label, comment, collapse, reorder, delete and undo', async () => {
  await page.getByRole('button', { name: 'Insert network after network 1' }).click();
  await page.getByRole('textbox', { name: 'Title of network 2' }).fill('Second');
  await page.keyboard.press('Enter');
  await page.getByRole('textbox', { name: 'Title of network 1' }).fill('First');
  await page.keyboard.press('Enter');
  expect(await titles()).toEqual(['First', 'Second']);

  // L focuses the label of the cursor's network.
  await draw.clickCell(1, 0, 0);
  await page.keyboard.press('l');
  // The label field takes focus on the next frame; type only once it has it.
  await page.waitForFunction(() => document.activeElement?.getAttribute('aria-label') === 'Label of network 2');
  await page.keyboard.type('Loop');
  await page.keyboard.press('Enter');
  expect((await draw.networks())[1]!.label).toBe('Loop');

  await page.getByRole('textbox', { name: 'Comment of network 1' }).fill('Motor control');
  await page.getByRole('textbox', { name: 'Title of network 1' }).focus();
  expect((await draw.networks())[0]!.comment).toBe('Motor control');

  await page.getByRole('button', { name: 'Collapse network 1' }).click();
  expect((await draw.networks())[0]!.collapsed).toBe(true);
  await page.getByRole('button', { name: 'Expand network 1' }).click();
  expect((await draw.networks())[0]!.collapsed).toBeUndefined();

  await page.getByRole('button', { name: 'Move network 1 down' }).click();
  expect(await titles()).toEqual(['Second', 'First']);
  // Reorder by dragging network 2's handle onto network 1's header.
  await page
    .getByRole('button', { name: 'Drag to reorder network 2' })
    .dragTo(page.getByRole('group', { name: /^Network 1( |$)/ }));
  expect(await titles()).toEqual(['First', 'Second']);
  await page.getByRole('button', { name: 'Move network 2 up' }).click();
  expect(await titles()).toEqual(['Second', 'First']);

  await page.getByRole('button', { name: 'Delete network 2' }).click();
  expect(await titles()).toEqual(['Second']);
  await draw.canvas().focus();
  await page.keyboard.press('Control+z');
  expect(await titles()).toEqual(['Second', 'First']);
});

test('dragging elements moves them by whole cells as one undo step', async () => {
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('A');
  await page.keyboard.press('c');
  await draw.typeName('B');
  // Rubber band around both contacts, starting on an empty cell of the row under the rung (↓ shows it).
  await page.keyboard.press('ArrowDown');
  const from = await draw.cellPoint(0, 1, 3);
  const to = await draw.cellPoint(0, 0, 0);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(to.x - 20, to.y - 20, { steps: 5 });
  await page.mouse.up();
  expect(await page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements.length)).toBe(2);

  const grab = await draw.cellPoint(0, 0, 1);
  const drop = await draw.cellPoint(0, 1, 4);
  await page.mouse.move(grab.x, grab.y);
  await page.mouse.down();
  await page.mouse.move(drop.x, drop.y, { steps: 8 });
  await page.mouse.up();
  expect((await draw.elements(0)).map((e) => `${e.name}@${e.row},${e.col}`)).toEqual(['A@1,3', 'B@1,4']);
  const steps = await page.evaluate(() => window.rungsmith!.documentStore!.getState().history.undo.length);
  await page.keyboard.press('Control+z');
  expect((await draw.elements(0)).map((e) => `${e.name}@${e.row},${e.col}`)).toEqual(['A@0,0', 'B@0,1']);
  expect(await page.evaluate(() => window.rungsmith!.documentStore!.getState().history.undo.length)).toBe(
    steps - 1,
  );
  // Alt+arrows move the selection from the keyboard.
  await page.keyboard.press('Alt+ArrowDown');
  expect((await draw.elements(0)).map((e) => `${e.name}@${e.row},${e.col}`)).toEqual(['A@1,0', 'B@1,1']);
});

test('the block picker places a function block and declares its instance', async () => {
  await draw.clickCell(0, 0, 1);
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('TON');
  await page.keyboard.press('Enter');
  await draw.typeName('DelayTimer');
  const box = (await draw.networks())[0]!.elements.find((e) => e.kind === 'box');
  expect(box).toMatchObject({ blockType: 'TON', instance: 'DelayTimer', row: 0, col: 1 });
  const vars = await page.evaluate(() =>
    window.rungsmith!.documentStore!.getState().project.pous[0]!.variables.map((v) => `${v.name}:${v.type}`),
  );
  expect(vars).toContain('DelayTimer:TON');
});

test('zooming with Ctrl+wheel keeps clicks on the right cell', async () => {
  const p = await draw.cellPoint(0, 0, 2);
  await page.mouse.move(p.x, p.y);
  await page.keyboard.down('Control');
  await page.mouse.wheel(0, -300);
  await page.keyboard.up('Control');
  await expect
    .poll(() => page.evaluate(() => window.rungsmith!.uiStore!.getState().viewport.zoom))
    .toBeGreaterThan(1.2);
  await draw.pickPalette('coil-SET');
  await draw.clickCell(0, 1, 5);
  await draw.typeName('Alarm');
  expect(await draw.elements(0)).toEqual([{ kind: 'coil', row: 1, col: 5, name: 'Alarm', type: 'SET' }]);
  await page.keyboard.press('Control+0');
  expect(await page.evaluate(() => window.rungsmith!.uiStore!.getState().viewport.zoom)).toBe(1);
});
