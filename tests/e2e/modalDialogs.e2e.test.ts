// Every modal dialog keeps the focus and the keys: after a field of the Tasks dialog is committed
// with Enter, the focus stays in the dialog, and Ctrl+A then Delete delete no rung behind it; with
// the focus pushed out to the page, keys still never reach the editor; Tab stays inside; Escape
// closes the dialog from anywhere and gives the focus back. The same for the Print dialog and the
// print preview (which share the one modal behaviour, useModal).
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { chooseMenuItem, openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  draw = new DrawPage(page);
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Keys'));
  await draw.canvas().focus();
  await page.keyboard.press('c');
  await draw.typeName('Start');
  await page.keyboard.press('o');
  await draw.typeName('Motor');
});

const elementCount = async () => (await draw.networks()).reduce((n, net) => n + net.elements.length, 0);
const focusInside = (testId: string) =>
  page.evaluate((id) => !!document.querySelector(`[data-testid="${id}"]`)?.contains(document.activeElement), testId);

/** Keys that would delete the whole rung if they reached the editor. */
async function pressEditorKeys() {
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Delete');
  await page.keyboard.press('Backspace');
  await page.keyboard.press('Control+X');
  await page.keyboard.press('Control+Z');
}

test('Tasks dialog: after Enter in a field the focus stays in it, Ctrl+A/Delete delete nothing behind it, Esc closes it', async () => {
  const before = await elementCount();
  expect(before).toBeGreaterThanOrEqual(2);
  await page.getByTestId('tab-project').click();
  await page.getByTestId('tree-tasks-edit').click();
  const dialog = page.getByTestId('tasks-dialog');
  await dialog.waitFor();
  const field = page.getByTestId('task-cycle-0');
  await field.fill('50');
  await field.press('Enter');
  await expect.poll(() => page.evaluate(() => window.rungsmith!.documentStore!.getState().project.tasks[0]!.cycleMs)).toBe(50);
  expect(await focusInside('tasks-dialog')).toBe(true);
  await pressEditorKeys();
  expect(await elementCount()).toBe(before);
  expect(await dialog.isVisible()).toBe(true);

  // The focus pushed out to the page (a field that disappears, a script): keys still stay out of the editor.
  await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
  await pressEditorKeys();
  expect(await elementCount()).toBe(before);
  expect(await focusInside('tasks-dialog')).toBe(true);

  // Tab cycles inside the dialog.
  for (let i = 0; i < 30; i++) {
    await page.keyboard.press('Tab');
    expect(await focusInside('tasks-dialog')).toBe(true);
  }

  await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
  await page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'detached' });
  expect(await elementCount()).toBe(before);
  // The edit made in the dialog is kept, and the editor has its keys again.
  expect(await page.evaluate(() => window.rungsmith!.documentStore!.getState().project.tasks[0]!.cycleMs)).toBe(50);
  await draw.canvas().focus();
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Delete');
  await expect.poll(elementCount).toBe(0);
  await page.keyboard.press('Control+Z');
  await expect.poll(elementCount).toBe(before);
});

test('Print dialog and print preview: keys stay in them, Tab stays in them, Esc closes each', async () => {
  const before = await elementCount();
  await draw.canvas().focus();
  await chooseMenuItem(page, 'File', 'Print / Export PDF…');
  const dialog = page.getByTestId('print-dialog');
  await dialog.waitFor();
  expect(await focusInside('print-dialog')).toBe(true);
  await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
  await pressEditorKeys();
  expect(await elementCount()).toBe(before);
  for (let i = 0; i < 12; i++) {
    await page.keyboard.press('Shift+Tab');
    expect(await focusInside('print-dialog')).toBe(true);
  }
  await page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'detached' });

  await page.keyboard.press('Control+P');
  await dialog.waitFor();
  await dialog.getByRole('button', { name: 'Print preview' }).click();
  const view = page.locator('[data-testid="print-view"][data-ready="true"]');
  await view.waitFor();
  expect(await focusInside('print-view')).toBe(true);
  await page.evaluate(() => (document.activeElement as HTMLElement | null)?.blur());
  await pressEditorKeys();
  expect(await elementCount()).toBe(before);
  await page.keyboard.press('Escape');
  await page.getByTestId('print-view').waitFor({ state: 'detached' });
  expect(await elementCount()).toBe(before);
  expect(errors).toEqual([]);
});
