// Editing habits (issue 13): box pin operands typed on the canvas, a box on the first column
// wired only through its power-flow input, one Escape to leave a name field, placing + naming as
// one undo step, comments committed by Enter, and the trend's lanes against time.
import { beforeAll, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import type { BoxElement } from '../../src/model/elements';
import { settledBox, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
let editor: EditorPage;
let page: Page;
let draw: DrawPage;

beforeAll(async () => {
  editor = await EditorPage.open(browser());
  page = editor.page;
  draw = new DrawPage(page);
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Habits'));
});

const focused = () =>
  page.evaluate(() => document.activeElement?.getAttribute('data-testid') ?? document.activeElement?.tagName);
const variables = async () =>
  (await editor.project()).pous[0]!.variables.map((v) => `${v.name}:${v.type}`).sort();
const timer = async () =>
  (await draw.networks())[0]!.elements.find((e): e is BoxElement => e.kind === 'box' && e.blockType === 'TON');

test('a TON placed on the first column takes IN from the rail; PT shows ??? and is typed from the keyboard', async () => {
  await draw.canvas().focus();
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('TON');
  await page.keyboard.press('Enter');
  await draw.typeName('T1');
  // The box sits right of the rail; one link joins the rail to IN; PT has no wire and no operand.
  expect(await draw.elements(0)).toEqual([
    { kind: 'link', row: 0, col: 0 },
    { kind: 'box', row: 0, col: 1 },
  ]);
  expect((await timer())!.inputs).toEqual({});

  // Enter on the (still selected) box: the field of its first open pin, PT, opens showing ???.
  await page.keyboard.press('Enter');
  const pin = page.getByTestId('pin-editor');
  await pin.waitFor();
  expect(await page.locator('[data-pin]').getAttribute('data-pin')).toBe('PT');
  expect(await pin.getAttribute('placeholder')).toBe('???');
  await pin.fill('T#2s');
  await page.keyboard.press('Tab');
  // Tab commits and goes to the next open pin: Q (IN is wired, so it is skipped).
  await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('Q');
  expect((await timer())!.inputs).toEqual({ PT: 'T#2s' });
  await pin.fill('Lamp');
  // The offer to declare Lamp comes first; Tab takes it like Enter would.
  await poll(() => page.getByRole('option', { name: /Declare Lamp/ }).count()).toBeGreaterThan(0);
  await page.keyboard.press('Tab');
  await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('ET');
  // Shift+Tab goes back to Q, showing what was typed there.
  await page.keyboard.press('Shift+Tab');
  await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('Q');
  expect(await pin.inputValue()).toBe('Lamp');
  // One Escape leaves the field and gives the keyboard back to the canvas.
  await page.keyboard.press('Escape');
  await pin.waitFor({ state: 'detached' });
  expect(await focused()).toBe('ladder-canvas');
  expect((await timer())!.outputs).toEqual({ Q: 'Lamp' });
  expect(await variables()).toEqual(['Lamp:BOOL', 'T1:TON']);

  // Each pin was one undo step: undo takes back Q (and the declaration made with it), PT stays.
  await page.keyboard.press('Control+z');
  expect((await timer())!).toMatchObject({ inputs: { PT: 'T#2s' }, outputs: {} });
  expect(await variables()).toEqual(['T1:TON']);
  expect(editor.errors).toEqual([]);
});

test('an ADD placed on the first column is wired through EN only', async () => {
  await page.keyboard.press('n');
  await poll(async () => (await draw.networks()).length).toBe(2);
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('ADD');
  await page.keyboard.press('Enter');
  expect(await draw.elements(1)).toEqual([
    { kind: 'link', row: 0, col: 0 },
    { kind: 'box', row: 0, col: 1 },
  ]);
  // Its open pins are IN1, IN2 (rows 2 and 3) and OUT: Enter opens IN1 first.
  await page.keyboard.press('Enter');
  await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('IN1');
  await page.keyboard.press('Escape');
  await page.getByTestId('pin-editor').waitFor({ state: 'detached' });
});

test('placing a contact and naming it is one undo step; one Escape leaves a name field', async () => {
  await page.keyboard.press('n');
  await poll(async () => (await draw.networks()).length).toBe(3);
  await page.keyboard.press('c');
  await draw.typeName('Start');
  expect(await draw.elements(2)).toEqual([{ kind: 'contact', row: 0, col: 0, name: 'Start', type: 'NO' }]);
  expect(await variables()).toContain('Start:BOOL');
  await page.keyboard.press('Control+z');
  // One undo removes the contact and its declaration, not only its name.
  expect(await draw.elements(2)).toEqual([]);
  expect(await variables()).not.toContain('Start:BOOL');

  // The name field opens with its suggestions shown; a single Escape closes it for the canvas.
  // (The cursor stayed right of where Start was.)
  await page.keyboard.press('c');
  const inline = page.getByTestId('inline-editor');
  await inline.waitFor();
  await inline.fill('Sta');
  await page.keyboard.press('Escape');
  await inline.waitFor({ state: 'detached' });
  expect(await focused()).toBe('ladder-canvas');
  expect(await draw.elements(2)).toEqual([{ kind: 'contact', row: 0, col: 1, name: '', type: 'NO' }]);

  // The same in the inspector: one Escape, the name unchanged, the canvas has the keyboard.
  await draw.clickCell(2, 0, 1);
  await editor.tab('Inspector');
  const field = editor.inspector.getByTestId('inspector-variable');
  await field.click();
  await field.fill('Stopp');
  await field.press('Escape');
  expect(await focused()).toBe('ladder-canvas');
  expect(await draw.elements(2)).toEqual([{ kind: 'contact', row: 0, col: 1, name: '', type: 'NO' }]);

  // And in the variable table: Escape puts the name back and leaves the cell.
  await editor.tab('Variables');
  const name = editor.variableRow('T1').getByLabel('Name');
  await name.click();
  await name.fill('T2');
  await name.press('Escape');
  expect(await focused()).toBe('ladder-canvas');
  expect(await variables()).toContain('T1:TON');
  expect(await name.inputValue()).toBe('T1');
  expect(editor.errors).toEqual([]);
});

test('a network comment commits on Enter, Shift+Enter starts a new line, Escape reverts', async () => {
  const net = (await draw.networks())[0]!;
  const comment = page.getByTestId(`network-comment-${net.id}`);
  await comment.click();
  await page.keyboard.type('Timer T1');
  await page.keyboard.press('Shift+Enter');
  await page.keyboard.type('lights the lamp');
  expect((await draw.networks())[0]!.comment).toBe('');
  await page.keyboard.press('Enter');
  await poll(async () => (await draw.networks())[0]!.comment).toBe('Timer T1\nlights the lamp');
  expect(await focused()).toBe('ladder-canvas');
  // Escape throws the edit away.
  await comment.click();
  await page.keyboard.type(' (draft)');
  await page.keyboard.press('Escape');
  expect(await focused()).toBe('ladder-canvas');
  expect((await draw.networks())[0]!.comment).toBe('Timer T1\nlights the lamp');
  expect(await comment.inputValue()).toBe('Timer T1\nlights the lamp');
});

test('the trend draws a BOOL and an INT in separate lanes against time, with a tip naming the scan', async () => {
  const sim = new SimPage(page);
  // Set-up: the drawing above is not kept (no "discard changes?" question).
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().markSaved());
  await sim.openExample('Parts counter (CTU)');
  await sim.tab('Trend');
  for (const name of ['Done', 'PartCount']) {
    await page.getByTestId('trend-add-name').fill(name);
    await page.getByTestId('trend-add').click();
  }
  await page.getByTestId('sim-step-count').fill('300');
  await sim.button('step-n').click();
  await sim.waitForMode('Paused');
  const chart = page.getByTestId('trend-chart');
  // Done in a thin lane on top, PartCount in its own taller lane below.
  await poll(() => chart.getAttribute('data-lanes')).toBe('Done:BOOL:4-3|PartCount:INT:3-0');
  const labels = (await chart.getAttribute('data-time-labels'))!.split('|');
  expect(labels.length).toBeGreaterThan(1);
  for (const label of labels) expect(label).toMatch(/^\d+(\.\d+)? (ms|s)$/);
  const over = chart.locator('.u-over');
  const box = await settledBox(over); // the chart resized to the panel
  await page.mouse.move(box.x + box.width * 0.5, box.y + box.height / 2, { steps: 5 });
  const tip = page.getByTestId('trend-tip');
  await poll(() => tip.textContent()).toMatch(/^t = \d+(\.\d+)? (ms|s) · scan \d+Done = FALSEPartCount = 0$/);
  expect(editor.errors).toEqual([]);
});
