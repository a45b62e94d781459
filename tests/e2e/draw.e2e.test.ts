// A new user draws a start/stop seal-in rung with the mouse, then another with the keyboard only.
import { beforeAll, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let errors: string[];
/** The live checks run shortly after the drawing stops changing. */
const CHECKS = { timeout: 10_000 };

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Seal-in'));
  draw = new DrawPage(page);
});

/** The seal-in rung: Start and /Stop in series to the Motor coil, Motor in parallel with Start. */
const SEAL_IN = [
  { kind: 'contact', row: 0, col: 0, name: 'Start', type: 'NO' },
  { kind: 'contact', row: 0, col: 1, name: 'Stop', type: 'NC' },
  ...[2, 3, 4, 5, 6, 7, 8].map((col) => ({ kind: 'link', row: 0, col })),
  { kind: 'coil', row: 0, col: 9, name: 'Motor', type: 'COIL' },
  { kind: 'contact', row: 1, col: 0, name: 'Motor', type: 'NO' },
];

test('drawing a seal-in rung with the mouse', async () => {
  // The checks have seen the empty network (a warning), so "No problems" later is about the rung.
  await expect.poll(() => draw.problemsSummary(), CHECKS).not.toBe('No problems');
  await draw.pickPalette('contact-NO');
  await draw.clickCell(0, 0, 0);
  await draw.typeName('Start');
  await draw.pickPalette('contact-NC');
  await draw.clickCell(0, 0, 1);
  await draw.typeName('Stop');
  await draw.pickPalette('coil-COIL');
  await draw.clickCell(0, 0, 9);
  await draw.typeName('Motor');
  await draw.pickPalette('link');
  for (let col = 2; col <= 8; col++) await draw.clickCell(0, 0, col);
  // Select Start and put a parallel branch around it from the Edit menu.
  await draw.pickPalette('select');
  await draw.clickCell(0, 0, 0);
  await draw.menu('Edit', 'Parallel branch around selection');
  // The branch row holds a link; a contact placed on it replaces the link.
  await draw.pickPalette('contact-NO');
  await draw.clickCell(0, 1, 0);
  await draw.typeName('Motor');
  await page.keyboard.press('Escape');

  expect(await draw.elements(0)).toEqual(SEAL_IN);
  expect((await draw.networks())[0]!.vlinks).toEqual([{ row: 0, boundary: 1 }]);
  // Naming each element offered to declare it (BOOL); the checks then find nothing wrong.
  const vars = await page.evaluate(() =>
    window.rungsmith!.documentStore!.getState().project.pous[0]!.variables.map((v) => `${v.name}:${v.type}`),
  );
  expect(vars.sort()).toEqual(['Motor:BOOL', 'Start:BOOL', 'Stop:BOOL']);
  await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
});

test('undo and redo the whole drawing from the keyboard', async () => {
  const before = await draw.elements(0);
  await draw.canvas().focus();
  await page.keyboard.press('Control+z');
  expect(await draw.elements(0)).not.toEqual(before);
  await page.keyboard.press('Control+y');
  expect(await draw.elements(0)).toEqual(before);
});

test('drawing the same rung with the keyboard only', async () => {
  await draw.canvas().focus();
  // N inserts a network below the cursor's network and puts the cursor at its first cell.
  await page.keyboard.press('n');
  await expect.poll(async () => (await draw.networks()).length).toBe(2);
  await expect.poll(() => draw.problemsSummary(), CHECKS).not.toBe('No problems');
  await page.keyboard.press('c');
  await draw.typeName('Start');
  await page.keyboard.press('Shift+C');
  await draw.typeName('Stop');
  for (let i = 0; i < 7; i++) await page.keyboard.press('h');
  await page.keyboard.press('o');
  await draw.typeName('Motor');
  // Back to Start, branch around it, down onto the branch's link, contact Motor.
  for (let i = 0; i < 9; i++) await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('Control+Shift+B');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('c');
  await draw.typeName('Motor');

  expect(await draw.elements(1)).toEqual(SEAL_IN);
  expect((await draw.networks())[1]!.vlinks).toEqual([{ row: 0, boundary: 1 }]);
  await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
  await expect
    .poll(() => page.getByTestId('cursor-position').textContent())
    .toBe('Network 2, row 2, column 2');
});

test('copy and paste a rung into a new network, delete and undo, see a typo reported and fix it', async () => {
  await draw.canvas().focus();
  await page.keyboard.press('Control+a');
  await page.keyboard.press('Control+c');
  await page.keyboard.press('n');
  await page.keyboard.press('Control+v');
  await expect.poll(async () => (await draw.networks()).length).toBe(3);
  await expect.poll(() => draw.elements(2)).toEqual(SEAL_IN);
  // Delete and undo.
  await draw.clickCell(2, 0, 1);
  await page.keyboard.press('Delete');
  expect((await draw.elements(2)).some((e) => e.name === 'Stop')).toBe(false);
  await page.keyboard.press('Control+z');
  expect(await draw.elements(2)).toEqual(SEAL_IN);
  // A typo (an undeclared name, kept as typed with Shift+Enter) is reported as LD-R08.
  await page.keyboard.press('Enter');
  await page.getByTestId('inline-editor').fill('Stopp');
  await page.keyboard.press('Shift+Enter');
  await expect
    .poll(async () => (await page.getByTestId('problem').allTextContents()).join('\n'), CHECKS)
    .toMatch(/LD-R08.*Stopp/);
  await page.keyboard.press('Control+z');
  await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
  expect(errors).toEqual([]);
});
