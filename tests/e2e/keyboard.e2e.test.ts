// CODESYS keyboard habits in real Chromium: F9 toggles a breakpoint on the network at the cursor
// and Run (F5) stops there; Shift+F5 stops; a prepared value of the watch table is written with
// Ctrl+F7 and forced with F7; `?` lists every shortcut; Ctrl+Shift+P finds and runs a command.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  await sim.openExample('Traffic light (TON chain)');
  // A reload (the browser's F5) would lose this mark.
  await page.evaluate(() => ((window as unknown as { keyboardTestMark: number }).keyboardTestMark = 1));
});

const notReloaded = () => page.evaluate(() => (window as unknown as { keyboardTestMark?: number }).keyboardTestMark === 1);

test('F9 sets and clears a breakpoint on the cursor network; F5 runs to it; Shift+F5 stops', async () => {
  const marker = page.getByTestId('network-breakpoint-2');
  await sim.draw.clickCell(2, 0, 0);
  await page.keyboard.press('F9');
  await expect.poll(() => marker.getAttribute('aria-pressed')).toBe('true');
  await page.keyboard.press('F9');
  await expect.poll(() => marker.getAttribute('aria-pressed')).toBe('false');
  await page.keyboard.press('F9');
  await expect.poll(() => marker.getAttribute('aria-pressed')).toBe('true');
  // F5 runs (and does not reload the page): the run stops before network 3.
  await page.keyboard.press('F5');
  await page.getByTestId('sim-breakpoint-hit').filter({ hasText: 'before network 3' }).waitFor({ timeout: 30_000 });
  expect(await sim.mode()).toBe('Paused');
  expect(await notReloaded()).toBe(true);
  await page.keyboard.press('F9');
  await expect.poll(() => marker.getAttribute('aria-pressed')).toBe('false');
  await page.keyboard.press('F5');
  await sim.waitForMode('Running');
  await page.keyboard.press('Shift+F5');
  await sim.waitForMode('Paused');
  // Still the same page: neither F5 nor Shift+F5 reloaded it.
  expect(await notReloaded()).toBe(true);
  expect(errors).toEqual([]);
});

test('Ctrl+F7 writes the prepared value once; F7 forces it', async () => {
  await sim.tab('Watch');
  for (const name of ['Yellow', 'Green']) {
    await page.getByTestId('watch-add-name').fill(name);
    await page.getByTestId('watch-add').click();
  }
  const yellow = page.getByTestId('watch-row-Yellow');
  const green = page.getByTestId('watch-row-Green');
  await expect.poll(() => yellow.getByTestId('watch-value').textContent()).toBe('FALSE');
  await yellow.getByTestId('watch-input').fill('TRUE');
  // Straight from the field, as in CODESYS.
  await page.keyboard.press('Control+F7');
  await sim.waitForValue('Yellow', true);
  await expect.poll(() => yellow.getByTestId('watch-input').inputValue()).toBe('');
  expect(await page.getByTestId('watch-unforce').first().isDisabled()).toBe(true);
  await green.getByTestId('watch-input').fill('TRUE');
  await page.getByTestId('watch-panel').click({ position: { x: 5, y: 5 } });
  await page.keyboard.press('F7');
  await expect.poll(() => green.getByTestId('watch-value').textContent()).toBe('TRUE F');
  await page.getByTestId('unforce-all').click();
  await expect.poll(() => green.getByTestId('watch-value').textContent()).not.toContain('F');
  // Nothing prepared: the status line says how to prepare one.
  await page.keyboard.press('Control+F7');
  await expect.poll(() => page.getByTestId('status-bar').textContent()).toContain('No prepared values');
  expect(errors).toEqual([]);
});

test('? lists every shortcut, grouped and searchable', async () => {
  // With an element selected while simulating, ? asks "Why?" (issue 14); with none, it lists the shortcuts.
  await page.locator('body').click({ position: { x: 2, y: 2 } });
  await page.keyboard.press('Escape');
  await expect.poll(() => page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements.length)).toBe(0);
  await page.keyboard.press('?');
  const list = page.getByTestId('shortcut-list');
  await list.waitFor();
  await expect.poll(() => list.getByRole('heading', { level: 3 }).allTextContents()).toEqual(expect.arrayContaining(['Edit', 'Simulation', 'File', 'Help']));
  expect(await list.getByTestId('shortcut-sim.run').textContent()).toBe('RunF5');
  await list.getByTestId('shortcut-search').fill('breakpoint');
  await expect.poll(() => list.locator('tr').allTextContents()).toEqual(['Toggle breakpoint on the network or ST lineF9']);
  // F5 in a dialog neither runs nor reloads the page.
  await page.keyboard.press('F5');
  expect(await list.isVisible()).toBe(true);
  expect(await notReloaded()).toBe(true);
  expect(await sim.mode()).toBe('Paused');
  await page.keyboard.press('Escape');
  await list.waitFor({ state: 'detached' });
  // The View menu has both, with their keys.
  await page.getByTestId('menu-view').click();
  expect(await page.getByTestId('menuitem-help.palette').textContent()).toBe('Command palette…Ctrl+Shift+P');
  await page.getByTestId('menuitem-help.shortcuts').click();
  await list.waitFor();
  await page.keyboard.press('Escape');
  await list.waitFor({ state: 'detached' });
  expect(errors).toEqual([]);
});

test('Ctrl+Shift+P finds a command by a fuzzy name, shows its shortcut and why one is disabled, and runs it', async () => {
  const theme = () => page.evaluate(() => document.documentElement.dataset.theme);
  const before = await theme();
  await page.keyboard.press('Control+Shift+P');
  const palette = page.getByTestId('command-palette');
  await palette.waitFor();
  await page.keyboard.type('redo');
  const redo = palette.getByTestId('palette-item-edit.redo');
  await expect.poll(() => redo.getAttribute('aria-disabled')).toBe('true');
  expect(await redo.textContent()).toContain('Nothing to redo');
  expect(await redo.textContent()).toContain('Ctrl+Y');
  await palette.getByTestId('palette-input').fill('tgl drk');
  await expect.poll(() => palette.getByRole('option').first().getAttribute('data-testid')).toBe('palette-item-view.theme');
  await page.keyboard.press('Enter');
  await palette.waitFor({ state: 'detached' });
  await expect.poll(theme).not.toBe(before);
  // Arrows move through the list; Enter runs the one marked.
  await page.keyboard.press('Control+Shift+P');
  await palette.getByTestId('palette-input').fill('theme');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowUp');
  await expect.poll(() => palette.locator('[aria-selected="true"]').getAttribute('data-testid')).toBe('palette-item-view.theme');
  await page.keyboard.press('Enter');
  await expect.poll(theme).toBe(before);
  expect(errors).toEqual([]);
});
