// Exploratory QA of issue 24's features (a day's work at CODESYS speed), in a real Chromium on the
// real server: what a user found broken, kept fixed. One page for the file; each test says what it
// starts from.
import { afterAll, beforeAll, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import { appUrl, openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';

const browser = useChromium();
let page: Page;
let errors: string[];
let draw: DrawPage;
const poll = <T>(fn: () => T | Promise<T>) => expect.poll(fn, { timeout: 15_000 });

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.context().grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(appUrl()).origin });
  draw = new DrawPage(page);
  await page.evaluate(() => localStorage.removeItem('rungsmith.variablesView'));
});

afterAll(() => {
  expect(errors).toEqual([]);
});

const mainVariables = () =>
  page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    return s.project.pous.find((p) => p.id === s.activePouId)!.variables.map((v) => v.name);
  });

test('text with a syntax error left in the text view: a name declared from the canvas meanwhile is said to have changed the variables, also after the view was closed', async () => {
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Decl'));
  const panel = page.getByTestId('variables-panel');
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
  await panel.getByText('Text', { exact: true }).click();
  const area = panel.getByRole('textbox', { name: /as IEC text/ });
  await area.fill('VAR\n\tA : BOOL;\nEND_VAR\n');
  await area.press('Control+Enter');
  await poll(mainVariables).toEqual(['A']);
  // A declaration typed without its ";", then the user goes elsewhere: not applied, kept.
  await area.press('Control+End');
  await page.keyboard.type('VAR\n\tB : INT\nEND_VAR\n');
  await poll(() => panel.getByTestId('declaration-status').textContent()).toContain('1 syntax error');
  await page.getByRole('tab', { name: 'Inspector', exact: true }).click();
  // Foo declared from the canvas while the text view is closed.
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('Foo');
  await poll(mainVariables).toEqual(['A', 'Foo']);
  // Back in the text: still the text as typed, and it says the variables changed meanwhile
  // (applying it as it stands would drop Foo).
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
  expect(await area.inputValue()).toBe('VAR\n\tA : BOOL;\nEND_VAR\nVAR\n\tB : INT\nEND_VAR\n');
  await poll(() => panel.getByTestId('declaration-note').textContent()).toMatch(/^The variables changed elsewhere/);
  // Revert shows them, Foo included, and the note goes.
  await panel.getByRole('button', { name: 'Revert' }).click();
  await poll(() => area.inputValue()).toBe('VAR\n\tA : BOOL;\n\tFoo : BOOL;\nEND_VAR\n');
  expect(await panel.getByTestId('declaration-note').count()).toBe(0);
  await panel.getByText('Table', { exact: true }).click();
});

test("another project opened: the last one's unapplied globals text and its LD-E18 stay with it", async () => {
  const panel = page.getByTestId('variables-panel');
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
  await panel.getByText('Global', { exact: true }).click();
  await panel.getByText('Text', { exact: true }).click();
  const area = panel.getByRole('textbox', { name: /as IEC text/ });
  await area.fill('VAR_GLOBAL\n\tG1 : INT\nEND_VAR\n');
  await page.getByRole('tab', { name: 'Problems', exact: true }).click();
  const syntax = page.getByTestId('problems-panel').locator('[data-rule="LD-E18"]');
  await poll(() => syntax.count()).toBe(1);
  // File > New project (the unsaved project is discarded).
  await page.getByTestId('menu-file').click();
  await page.getByRole('menuitem', { name: /^New project/ }).click();
  await page.getByRole('button', { name: 'Discard and start new' }).click();
  await page.getByTestId('project-name').filter({ hasText: 'Untitled' }).waitFor();
  await poll(() => syntax.count()).toBe(0);
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
  await poll(() => area.inputValue()).toBe('VAR_GLOBAL\nEND_VAR\n');
  expect(await panel.getByTestId('declaration-status').textContent()).toBe('Applied');
  await panel.getByText('Table', { exact: true }).click();
});

test('the command palette and the list of shortcuts give the keyboard back to the canvas when they close', async () => {
  // Still the new project: one empty network.
  const canvasFocused = () => page.evaluate(() => document.activeElement?.getAttribute('aria-label')?.startsWith('Ladder diagram') ?? false);
  await draw.clickCell(0, 0, 0);
  await poll(canvasFocused).toBe(true);
  await page.keyboard.press('Control+Shift+P');
  const palette = page.getByTestId('command-palette');
  await palette.getByTestId('palette-input').fill('cursor right');
  await page.keyboard.press('Enter');
  await palette.waitFor({ state: 'detached' });
  await poll(() => page.evaluate(() => window.rungsmith!.uiStore!.getState().cursor?.col)).toBe(1);
  await poll(canvasFocused).toBe(true);
  // Closed with Escape.
  await page.keyboard.press('Control+Shift+P');
  await palette.waitFor();
  await page.keyboard.press('Escape');
  await palette.waitFor({ state: 'detached' });
  await poll(canvasFocused).toBe(true);
  await page.keyboard.press('?');
  const shortcuts = page.getByTestId('shortcut-list');
  await shortcuts.waitFor();
  await page.keyboard.press('Escape');
  await shortcuts.waitFor({ state: 'detached' });
  await poll(canvasFocused).toBe(true);
});

test('Ctrl+V in the declarations text view pastes the text there (declarations copied from another tool), not a symbol table preview', async () => {
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Paste'));
  const panel = page.getByTestId('variables-panel');
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
  await panel.getByText(/^Main/).click();
  await panel.getByText('Text', { exact: true }).click();
  const area = panel.getByRole('textbox', { name: /as IEC text/ });
  await poll(() => area.inputValue()).toBe('VAR\nEND_VAR\n');
  await page.evaluate((t) => navigator.clipboard.writeText(t), '\tStart AT %IX0.0 : BOOL;\n\tCount : INT := 0;\n');
  await area.focus();
  await page.keyboard.press('Control+Home');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('Control+V');
  await poll(() => area.inputValue()).toBe('VAR\n\tStart AT %IX0.0 : BOOL;\n\tCount : INT := 0;\nEND_VAR\n');
  expect(await page.getByTestId('symbol-paste-dialog').count()).toBe(0);
  await page.keyboard.press('Control+Enter');
  await poll(mainVariables).toEqual(['Start', 'Count']);
  await panel.getByText('Table', { exact: true }).click();
});

test('? with an element selected after Reset (nothing recorded) lists the shortcuts instead of an empty Why?', async () => {
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Why'));
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('Start');
  await page.getByTestId('sim-run').click();
  await page.getByTestId('sim-mode').filter({ hasText: 'Running' }).waitFor();
  await page.getByTestId('sim-reset').click();
  await page.getByTestId('sim-mode').filter({ hasText: 'Stopped' }).waitFor();
  await draw.clickCell(0, 0, 0);
  await poll(() => page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements.length)).toBe(1);
  await page.keyboard.press('?');
  const shortcuts = page.getByTestId('shortcut-list');
  await shortcuts.waitFor();
  await page.keyboard.press('Escape');
  await shortcuts.waitFor({ state: 'detached' });
});
