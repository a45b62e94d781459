// Declarations as fast as typing (issue 24): a symbol table pasted from a spreadsheet into the
// globals through the real clipboard, with the preview (added, renamed, refused with the reason)
// and one undo step; Enter on the last row adds a row and the class is typed; a name declared as a
// global from the canvas and from the completion list; a POU variable hiding a global warned in
// Problems (LD-W05). One page for the file: each test goes on from the last one's project.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { appUrl, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();
let editor: EditorPage;
let page: Page;
let draw: DrawPage;

const project = (): Promise<Project> =>
  page.evaluate(
    () => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project,
  );
const globalNames = async () => (await project()).globals.map((g) => g.name);

beforeAll(async () => {
  editor = await EditorPage.open(browser());
  page = editor.page;
  await page
    .context()
    .grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(appUrl()).origin });
  draw = new DrawPage(page);
  await page.evaluate(() => {
    const doc = window.rungsmith!.documentStore!.getState();
    doc.newProject('Bottles');
    doc.addVariable(
      { name: 'Level', type: 'INT', varClass: 'local', retain: false, comment: 'tank level' },
      'globals',
    );
  });
});

const TSV = [
  'Name\tData Type\tLogical Address\tInitial\tComment',
  'StartButton\tBool\t%I0.0\t\tgreen button',
  'StopButton\tBool\t%I0.1\tFALSE\tred button',
  'FillValve\tBool\t%Q0.0\t\tfill valve',
  'Level\tInt\t%IW64\t\ttank level, analog',
  'Fill pump\tBool\t%Q0.1\t\tspace in the name',
  'BottleCount\tInt\t%MW10\t0\tbottles filled',
].join('\r\n');

test('a TSV pasted into the globals: the preview says added, renamed and refused; confirm adds the rows; Ctrl+Z removes them all', async () => {
  await editor.tab('Variables');
  await editor.variables.getByRole('radio', { name: 'Global' }).check();
  await editor.variableRow('Level').waitFor();
  await page.evaluate((text) => navigator.clipboard.writeText(text), TSV);
  // Ctrl+V with the focus in the table (on its scope switch), as after clicking in it.
  await editor.variables.getByRole('radio', { name: 'Global' }).focus();
  await page.keyboard.press('Control+V');
  const dialog = page.getByTestId('symbol-paste-dialog');
  await dialog.waitFor();
  await poll(() => dialog.getByTestId('symbol-paste-summary').textContent()).toBe(
    '6 rows under a header: 4 added, 1 renamed, 1 refused.',
  );
  const row = (i: number) => dialog.getByTestId(`symbol-paste-row-${i}`);
  expect(await row(0).getAttribute('data-action')).toBe('add');
  expect(await row(0).textContent()).toContain('%IX0.0'); // TIA's %I0.0 in IEC spelling
  expect(await row(3).getAttribute('data-action')).toBe('rename');
  expect(await row(3).getByRole('combobox').inputValue()).toBe('rename');
  expect(await row(3).textContent()).toContain('Level_2');
  expect(await row(4).getAttribute('data-action')).toBe('refuse');
  expect(await row(4).textContent()).toMatch(/"Fill pump" is not an IEC identifier/);
  // Nothing changed yet.
  expect(await globalNames()).toEqual(['Level']);

  await dialog.getByTestId('symbol-paste-confirm').click();
  await dialog.waitFor({ state: 'detached' });
  await poll(globalNames).toEqual([
    'Level',
    'StartButton',
    'StopButton',
    'FillValve',
    'Level_2',
    'BottleCount',
  ]);
  await editor.variableRow('FillValve').waitFor();
  expect(await editor.variableRow('FillValve').getByLabel('Address').inputValue()).toBe('%QX0.0');
  expect(await editor.variableRow('Level_2').getByLabel('Address').inputValue()).toBe('%IW64');
  expect(await editor.variableRow('BottleCount').getByLabel('Comment').inputValue()).toBe('bottles filled');

  // One undo step takes the whole paste back.
  await draw.canvas().focus();
  await page.keyboard.press('Control+Z');
  await poll(globalNames).toEqual(['Level']);
  await page.keyboard.press('Control+Y');
  await poll(globalNames).toEqual([
    'Level',
    'StartButton',
    'StopButton',
    'FillValve',
    'Level_2',
    'BottleCount',
  ]);
  expect(editor.errors).toEqual([]);
});

test('Enter on the last row adds a row with its name focused; the class is typed (in = VAR_INPUT) and stepped with the arrows', async () => {
  await editor.variables.getByRole('radio', { name: /^Main/ }).check();
  await editor.variables.getByRole('button', { name: 'Add variable' }).click();
  const focusedName = editor.variables.locator('input[aria-label="Name"]:focus');
  await focusedName.fill('Filling');
  await focusedName.press('Enter'); // commits the name
  await editor.variableRow('Filling').waitFor();
  await page.keyboard.press('Enter'); // nothing left to commit on the last row: a new row
  await poll(() => focusedName.inputValue()).toBe('Var1');
  await focusedName.fill('Done');
  await focusedName.press('Enter');
  const main = async () => (await project()).pous[0]!.variables.map((v) => [v.name, v.varClass]);
  await poll(main).toEqual([
    ['Filling', 'local'],
    ['Done', 'local'],
  ]);

  const cls = editor.variableRow('Done').getByLabel('Class');
  await cls.focus();
  await page.keyboard.type('in');
  await poll(main).toEqual([
    ['Filling', 'local'],
    ['Done', 'input'],
  ]);
  // The row moved up among the inputs and kept the keyboard.
  await poll(() => page.evaluate(() => document.activeElement?.getAttribute('aria-label'))).toBe('Class');
  await page.keyboard.press('ArrowDown');
  await poll(main).toEqual([
    ['Filling', 'local'],
    ['Done', 'output'],
  ]);
  // `c` switches CONSTANT (VAR_OUTPUT CONSTANT is refused by the row's check: it names why).
  await page.keyboard.press('c');
  await poll(async () => (await project()).pous[0]!.variables.find((v) => v.name === 'Done')?.constant).toBe(
    true,
  );
  await draw.canvas().focus();
  await page.keyboard.press('Control+Z');
  await poll(
    async () => (await project()).pous[0]!.variables.find((v) => v.name === 'Done')?.constant,
  ).toBeUndefined();
  expect(editor.errors).toEqual([]);
});

test('declare as global from the canvas and from the completion list; one undo step each', async () => {
  await draw.canvas().focus();
  await page.keyboard.press('c');
  const inline = page.getByTestId('inline-editor');
  await inline.waitFor();
  await inline.fill('EStop');
  const offer = page.getByRole('option', { name: /Declare EStop.*global at %IX0\.2/ });
  await offer.waitFor();
  await offer.click();
  await inline.waitFor({ state: 'detached' });
  await poll(globalNames).toContain('EStop');
  const estop = (await project()).globals.find((g) => g.name === 'EStop');
  expect(estop).toMatchObject({ type: 'BOOL', location: '%IX0.2' });
  expect((await project()).pous[0]!.variables.map((v) => v.name)).not.toContain('EStop');
  expect((await draw.networks())[0]!.elements.find((e) => e.kind === 'contact')).toMatchObject({
    variable: 'EStop',
  });

  // A coil, named in the inspector's field: the completion list offers the global too.
  await page.keyboard.press('o');
  await inline.waitFor();
  await page.keyboard.press('Escape');
  await inline.waitFor({ state: 'detached' });
  await editor.tab('Inspector');
  const field = editor.inspector.getByTestId('inspector-variable');
  await field.click();
  await field.fill('Horn');
  const options = editor.inspector.getByRole('listbox', { name: 'Suggestions' }).getByRole('option');
  await poll(() => options.allTextContents()).toContain('Declare HornBOOL global (VAR_GLOBAL)');
  const texts = await options.allTextContents();
  for (let i = 0; i < texts.indexOf('Declare HornBOOL global (VAR_GLOBAL)'); i++)
    await field.press('ArrowDown');
  await field.press('Enter');
  await poll(globalNames).toContain('Horn');
  const coil = async () => (await draw.networks())[0]!.elements.find((e) => e.kind === 'coil');
  expect(await coil()).toMatchObject({ variable: 'Horn' });
  // One undo: the global and the name on the coil go together.
  await draw.canvas().focus();
  await page.keyboard.press('Control+Z');
  await poll(globalNames).not.toContain('Horn');
  expect(await coil()).toMatchObject({ variable: '' });
  await page.keyboard.press('Control+Y');
  await poll(globalNames).toContain('Horn');
  expect(editor.errors).toEqual([]);
});

test('a POU variable with the name of a global is warned in Problems (LD-W05), and the problem shows the variable', async () => {
  await editor.tab('Variables');
  await editor.variables.getByRole('radio', { name: /^Main/ }).check();
  await editor.declare('StartButton');
  await editor.tab('Problems');
  const problem = editor.problems.getByTestId('problem').filter({ hasText: 'LD-W05' });
  await poll(() => problem.count()).toBe(1);
  expect(await problem.textContent()).toMatch(
    /the VAR variable "StartButton" of Main has the name of the global variable StartButton/,
  );
  await problem.click();
  await poll(() =>
    page.evaluate(() => document.activeElement?.closest('tr')?.getAttribute('data-testid')),
  ).toBe('variable-row-StartButton');
  expect(editor.errors).toEqual([]);
});

test('inside an FB of an OpenPLC project: the interface is offered first, and a global gets its VAR_EXTERNAL in the FB, one undo step', async () => {
  await page.evaluate(() => {
    const doc = window.rungsmith!.documentStore!.getState();
    doc.setProjectProfile('openplc');
    doc.addPou('FUNCTION_BLOCK', 'Conveyor');
  });
  await page.getByTestId('pou-tab-Conveyor').waitFor();
  await poll(() => page.evaluate(() => window.rungsmith!.documentStore!.getState().activePouId)).toBe(
    (await project()).pous.find((p) => p.name === 'Conveyor')!.id,
  );
  await draw.canvas().focus();
  await page.keyboard.press('c');
  const inline = page.getByTestId('inline-editor');
  await inline.waitFor();
  await inline.fill('Jam');
  const offers = page.locator('[role="listbox"] [role="option"].rs-declare .rs-completion-type');
  await poll(() => offers.allTextContents()).toEqual([
    'BOOL input (VAR_INPUT)',
    'BOOL in-out (VAR_IN_OUT)',
    'BOOL output (VAR_OUTPUT)',
    'BOOL local (VAR)',
    'BOOL global + VAR_EXTERNAL in Conveyor',
  ]);
  await page.getByRole('option', { name: /global \+ VAR_EXTERNAL in Conveyor/ }).click();
  await inline.waitFor({ state: 'detached' });
  await poll(globalNames).toContain('Jam');
  const conveyor = async () => (await project()).pous.find((p) => p.name === 'Conveyor')!.variables;
  expect(await conveyor()).toEqual([
    { name: 'Jam', type: 'BOOL', varClass: 'external', retain: false, comment: '' },
  ]);
  await draw.canvas().focus();
  await page.keyboard.press('Control+Z');
  await poll(globalNames).not.toContain('Jam');
  expect(await conveyor()).toEqual([]);
  expect(editor.errors).toEqual([]);
});

test('a box pin offers its own type; "Bottles : DINT" typed on the pin declares it with the type written (and its VAR_EXTERNAL: still OpenPLC)', async () => {
  await page.getByTestId('pou-tab-Main').click();
  await page.keyboard.press('n');
  await draw.canvas().focus();
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('CTU');
  await page.keyboard.press('Enter');
  await draw.typeName('Counter');
  await editor.tab('Inspector');
  const cv = editor.inspector.getByTestId('pin-CV');
  await cv.click();
  await cv.fill('Bottles');
  const options = editor.inspector.getByRole('listbox', { name: 'Suggestions' }).getByRole('option');
  await poll(() => options.allTextContents()).toContain('Declare BottlesINT global + VAR_EXTERNAL in Main');
  await cv.fill('Bottles : DINT');
  await poll(() => options.allTextContents()).toContain('Declare BottlesDINT global + VAR_EXTERNAL in Main');
  await options.filter({ hasText: 'BottlesDINT global + VAR_EXTERNAL in Main' }).click();
  await poll(async () => (await project()).globals.find((g) => g.name === 'Bottles')?.type).toBe('DINT');
  const box = (await project()).pous[0]!.networks.flatMap((n) => n.elements).find((e) => e.kind === 'box');
  expect(box).toMatchObject({ outputs: { CV: 'Bottles' } });
  expect((await project()).pous[0]!.variables.find((v) => v.name === 'Bottles')).toMatchObject({
    varClass: 'external',
    type: 'DINT',
  });
  expect(editor.errors).toEqual([]);
});
