// A PLC programmer declares a structure Point (X, Y : INT) in the project tree's data-type editor,
// declares P : Point in the variable table, writes 42 into P.X with a MOVE box (the inspector
// accepts the member operand), runs, expands P in the watch table to see X's value and forces P.Y.
// Renaming the type in the tree retypes P; deleting it while used says where first.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let editor: EditorPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Plant'));
  draw = new DrawPage(page);
  editor = new EditorPage(page);
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
