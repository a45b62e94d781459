// A PLC programmer declares a structure Point (X, Y : INT) in the project tree's data-type editor,
// declares P : Point in the variable table, writes 42 into P.X with a MOVE box (the inspector
// accepts the member operand), runs, expands P in the watch table to see X's value and forces P.Y.
// Renaming the type in the tree retypes P; deleting it while used says where first. An enumeration
// shows and is written by value name; an array expands into its elements.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let editor: EditorPage;
let sim: SimPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Plant'));
  draw = new DrawPage(page);
  editor = new EditorPage(page);
  sim = new SimPage(page);
});

const project = (): Promise<Project> => editor.project();

/** Renames a member row of the open structure editor. */
async function nameMember(from: string, to: string) {
  const field = page.getByTestId(`member-row-${from}`).getByLabel('Member name');
  await editor.fill(field, to);
  await page.getByTestId(`member-row-${to}`).waitFor();
}

test('a structure Point is declared in the data-type editor and P : Point in the variable table', async () => {
  await page.getByTestId('tab-project').click();
  await page.getByTestId('datatype-kind').selectOption('struct');
  await page.getByTestId('add-datatype').click();
  const rename = page.getByTestId('datatype-rename');
  await rename.fill('Point');
  await rename.press('Enter');
  await page.getByTestId('datatype-tab-Point').waitFor();
  const typeEditor = page.getByTestId('datatype-editor-Point');
  await typeEditor.waitFor();
  await nameMember('Member1', 'X');
  await page.getByTestId('add-struct-member').click();
  await nameMember('Member2', 'Y');
  // A duplicate member is shown at once, on its row and in the list; renaming it clears it.
  await nameMember('Y', 'x');
  await poll(() => page.getByTestId('datatype-problems').textContent()).toContain('member x is already in row 1');
  expect(await page.getByTestId('member-row-x').getByLabel('Member name').getAttribute('aria-invalid')).toBe('true');
  await nameMember('x', 'Y');
  await poll(() => page.getByTestId('datatype-problems').count()).toBe(0);
  expect(await page.getByTestId('datatype-text').textContent()).toBe(
    'TYPE\n  Point : STRUCT\n    X : INT;\n    Y : INT;\n  END_STRUCT;\nEND_TYPE',
  );

  // Back to the program: the type picker offers Point.
  await page.getByTestId('pou-tab-Main').click();
  await page.getByTestId('ladder-canvas').waitFor();
  await editor.tab('Variables');
  await editor.declare('P', { type: 'Point' });
  const types = await editor.variableRow('P').getByLabel('Type').locator('optgroup[label="This project\'s data types"] option').allTextContents();
  expect(types).toEqual(['Point']);
  expect((await project()).pous[0]!.variables.map((v) => `${v.name} : ${v.type}`)).toEqual(['P : Point']);
  expect(await editor.variableRow('P').getAttribute('class')).not.toContain('rs-has-issue');
});

test('P.X on a MOVE output is accepted by the inspector with its member type', async () => {
  await page.getByTestId('tab-palette').click();
  await page.getByRole('searchbox', { name: 'Search blocks' }).fill('MOVE');
  await page.getByTestId('palette-block-MOVE').click();
  await draw.clickCell(0, 0, 0);
  const inline = page.getByTestId('inline-editor');
  if (await inline.isVisible()) await page.keyboard.press('Escape');
  await draw.pickPalette('select');
  const box = async () => (await project()).pous[0]!.networks[0]!.elements.find((e) => e.kind === 'box');
  const at = (await box())!;
  await draw.clickCell(0, at.row, at.col);
  await editor.tab('Inspector');
  const out = editor.inspector.getByTestId('pin-OUT');
  await out.click();
  await out.fill('P.');
  // Completion offers P's members after "P.".
  await poll(() => page.getByRole('option', { name: /P\.X/ }).count()).toBe(1);
  await out.fill('P.X');
  await out.press('Shift+Enter');
  await editor.fill(editor.inspector.getByTestId('pin-IN'), '42');
  await poll(async () => (await box())).toMatchObject({ blockType: 'MOVE', inputs: { IN: '42' }, outputs: { OUT: 'P.X' } });
  await poll(() => editor.inspector.getByText('INT', { exact: true }).count()).toBeGreaterThan(0);
});

test('running, P expands in the watch table to X = 42; P.Y is forced', async () => {
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.tab('Watch');
  await page.getByTestId('watch-add-name').fill('P');
  await page.getByTestId('watch-add').click();
  const p = page.getByTestId('watch-row-P');
  await p.waitFor();
  // Collapsed at first: the members appear when P is expanded.
  expect(await page.getByTestId('watch-row-P.X').count()).toBe(0);
  await p.getByTestId('watch-expand').click();
  const x = page.getByTestId('watch-row-P.X');
  await poll(() => x.getByTestId('watch-value').textContent()).toBe('42');
  const y = page.getByTestId('watch-row-P.Y');
  await y.getByTestId('watch-input').fill('7');
  await y.getByTestId('watch-force').click();
  await poll(() => y.getByTestId('watch-value').textContent()).toBe('7 F');
  await sim.waitForValue('P.Y', 7);
  await y.getByTestId('watch-unforce').click();
  await poll(() => y.getByTestId('watch-value').textContent()).toBe('7');
  await sim.button('pause').click();
});

test('renaming Point in the tree retypes P; deleting it while used says where first', async () => {
  await page.getByTestId('tab-project').click();
  await page.getByTestId('tree-datatype-Point').getByRole('button', { name: 'Rename Point' }).click();
  const rename = page.getByTestId('datatype-rename');
  await rename.fill('Coord');
  await rename.press('Enter');
  await page.getByTestId('datatype-tab-Coord').waitFor();
  expect((await project()).pous[0]!.variables.map((v) => v.type)).toEqual(['Coord']);
  await page.getByTestId('tree-datatype-Coord').getByRole('button', { name: 'Delete Coord' }).click();
  const dialog = page.getByTestId('delete-datatype-dialog');
  await dialog.waitFor();
  expect(await dialog.getByTestId('datatype-uses').textContent()).toBe('Main: variable P');
  await dialog.getByRole('button', { name: 'Cancel' }).click();
  expect((await project()).dataTypes!.map((t) => t.name)).toEqual(['Coord']);
  // One undo step brings the old name back everywhere.
  await draw.menu('Edit', 'Undo');
  await poll(async () => (await project()).pous[0]!.variables.map((v) => v.type)).toEqual(['Point']);
  expect(errors).toEqual([]);
});

test('an enumeration shows and is written by value name; an array expands into its elements', async () => {
  const base = newProject('Colors');
  const main = {
    ...base.pous[0]!,
    variables: [variable('C', 'Color', { initial: 'GREEN' }), variable('A', 'ARRAY[1..3] OF INT', { initial: '[1, 2, 3]' })],
  };
  await sim.load({ ...base, pous: [main], dataTypes: [{ name: 'Color', def: { kind: 'enum', values: ['RED', 'GREEN', 'BLUE'] } }] });
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.tab('Watch');
  for (const name of ['C', 'A']) {
    await page.getByTestId('watch-add-name').fill(name);
    await page.getByTestId('watch-add').click();
  }
  const c = page.getByTestId('watch-row-C');
  await poll(() => c.getByTestId('watch-value').textContent()).toBe('GREEN');
  await c.getByTestId('watch-input').selectOption('BLUE');
  await c.getByTestId('watch-write').click();
  await poll(() => c.getByTestId('watch-value').textContent()).toBe('BLUE');
  await page.getByTestId('watch-row-A').getByTestId('watch-expand').click();
  await poll(() => page.getByTestId('watch-row-A[3]').getByTestId('watch-value').textContent()).toBe('3');
  expect(errors).toEqual([]);
});
