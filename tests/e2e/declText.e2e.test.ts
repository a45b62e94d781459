// The variables panel's text view (Table | Text): declarations as IEC text, typed with the keyboard,
// applied as one undo step, shown in the table and back; a syntax error is located and changes
// nothing. One page for the whole file: each test starts from what the one before left.
import { afterAll, beforeAll, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project } from '../../src/model/project';
import { openApp, useChromium } from './appPage';

const browser = useChromium();
let page: Page;
let errors: string[];

const contact = (name: string): LdElement => ({ kind: 'contact', contact: 'NO', variable: name, id: 'c1' as ElementId, row: 0, col: 0 });
const coil = (name: string): LdElement => ({ kind: 'coil', coil: 'COIL', variable: name, id: 'q1' as ElementId, row: 0, col: 6 });

function station(): Project {
  return newProject('Filler', {
    pous: [
      newPou('Main', {
        networks: [newNetwork({ elements: [contact('Start'), coil('Motor')] })],
        variables: [
          variable('Start', 'BOOL', { varClass: 'input', location: '%IX0.0', comment: 'start button' }),
          variable('Motor', 'BOOL', { varClass: 'output', location: '%QX0.0' }),
        ],
      }),
    ],
  });
}

const panel = () => page.getByTestId('variables-panel');
const area = () => panel().getByRole('textbox', { name: /as IEC text/ });
const status = () => panel().getByTestId('declaration-status');
const variables = () =>
  page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    return s.project.pous.find((p) => p.id === s.activePouId)!.variables;
  });
const poll = <T>(fn: () => T | Promise<T>) => expect.poll(fn, { timeout: 15_000 });

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate(() => localStorage.removeItem('rungsmith.variablesView'));
  await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), station());
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
  await panel().getByTestId('variable-row-Start').waitFor();
});

afterAll(() => {
  expect(errors).toEqual([]);
});

test('Text shows the declarations as IEC text; a declaration typed with the keyboard appears in the table', async () => {
  await panel().getByText('Text', { exact: true }).click();
  await area().waitFor();
  expect(await area().inputValue()).toBe(
    'VAR_INPUT\n\tStart AT %IX0.0 : BOOL; (* start button *)\nEND_VAR\n\nVAR_OUTPUT\n\tMotor AT %QX0.0 : BOOL;\nEND_VAR\n',
  );
  // Keyboard only: to the end of line 2, a new line, Tab to indent, the declaration, Ctrl+Enter.
  await area().focus();
  await page.keyboard.press('Control+Home');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('End');
  await page.keyboard.press('Enter');
  await page.keyboard.press('Tab');
  await page.keyboard.type('Stop AT %IX0.1 : BOOL := TRUE; (* stop button, NC *)');
  await poll(() => status().textContent()).toContain('not applied yet');
  expect((await variables()).map((v) => v.name)).toEqual(['Start', 'Motor']);
  await page.keyboard.press('Control+Enter');
  await poll(() => status().textContent()).toContain('Applied');
  expect(await area().inputValue()).toContain('\tStop AT %IX0.1 : BOOL := TRUE; (* stop button, NC *)\nEND_VAR');
  const vars = await variables();
  expect(vars.map((v) => v.name)).toEqual(['Start', 'Stop', 'Motor']);
  expect(vars[1]).toMatchObject({ varClass: 'input', location: '%IX0.1', initial: 'TRUE', comment: 'stop button, NC' });
  // The choice is remembered for the next visit.
  expect(await page.evaluate(() => localStorage.getItem('rungsmith.variablesView'))).toBe('text');

  await panel().getByText('Table', { exact: true }).click();
  const row = panel().getByTestId('variable-row-Stop');
  await row.waitFor();
  expect(await row.getByLabel('Address').inputValue()).toBe('%IX0.1');
  expect(await row.getByLabel('Comment').inputValue()).toBe('stop button, NC');
});

test('keyboard only: Shift+Tab unindents, Escape then Tab leaves the editor', async () => {
  await panel().getByText('Text', { exact: true }).click();
  await area().focus();
  await page.keyboard.press('Control+Home');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('Shift+Tab');
  await poll(() => area().inputValue()).toContain('\nStart AT %IX0.0');
  await page.keyboard.press('Tab');
  await page.keyboard.press('Tab');
  await poll(() => area().inputValue()).toContain('\n\t\tStart AT %IX0.0');
  await page.keyboard.press('Shift+Tab');
  await poll(() => area().inputValue()).toContain('\n\tStart AT %IX0.0');
  await page.keyboard.press('Escape');
  await page.keyboard.press('Tab');
  await poll(() => page.evaluate(() => document.activeElement?.tagName)).not.toBe('TEXTAREA');
  await panel().getByText('Table', { exact: true }).click();
});

test('an edit in the table shows in the text', async () => {
  const comment = panel().getByTestId('variable-row-Motor').getByLabel('Comment');
  await comment.click();
  await comment.fill('contactor K1');
  await comment.press('Enter');
  await poll(async () => (await variables()).find((v) => v.name === 'Motor')?.comment).toBe('contactor K1');
  await panel().getByText('Text', { exact: true }).click();
  await poll(() => area().inputValue()).toContain('\tMotor AT %QX0.0 : BOOL; (* contactor K1 *)\n');
});

test('a syntax error is shown at its line, in the text view and the Problems list; the variables stay', async () => {
  const before = await variables();
  await area().focus();
  await page.keyboard.press('Control+End');
  await page.keyboard.type('VAR\n\tCount : INT := 0\n\tLimit : INT := 10;\nEND_VAR\n');
  // Line 10 is "\tCount : INT := 0": its ";" is missing.
  const mark = panel().locator('.rs-decl-gutter [data-line="10"]');
  await poll(() => mark.getAttribute('class')).toContain('rs-decl-error');
  const problem = panel().getByTestId('declaration-problem').first();
  expect(await problem.textContent()).toMatch(/^LD-E18 line 10, column 18: ";" missing/);
  expect(await area().getAttribute('aria-invalid')).toBe('true');
  // Leaving the editor does not apply it: the table is untouched, the text stays as typed.
  await panel().getByText('Table', { exact: true }).click();
  await panel().getByTestId('variable-row-Motor').waitFor();
  expect(await variables()).toEqual(before);
  expect(await panel().getByTestId('variable-row-Count').count()).toBe(0);
  await page.getByRole('tab', { name: 'Problems', exact: true }).click();
  const listed = page.getByTestId('problems-panel').locator('[data-rule="LD-E18"]');
  await poll(() => listed.count()).toBe(1);
  expect(await listed.textContent()).toContain('line 10, column 18');
  // The problem leads back to the text, caret at the place.
  await listed.click();
  await area().waitFor();
  expect(await area().inputValue()).toContain('\tCount : INT := 0\n\tLimit');
  await poll(() => area().evaluate((el: HTMLTextAreaElement) => el.value.slice(0, el.selectionStart).split('\n').length)).toBe(10);
  // Fixed: applies, and the problem is gone.
  await page.keyboard.press('End');
  await page.keyboard.type(';');
  await page.keyboard.press('Control+Enter');
  await poll(async () => (await variables()).map((v) => v.name)).toEqual(['Start', 'Stop', 'Motor', 'Count', 'Limit']);
  await page.getByRole('tab', { name: 'Problems', exact: true }).click();
  await poll(() => listed.count()).toBe(0);
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
});

test('one Ctrl+Z undoes a whole text edit; a rename in the text renames the uses', async () => {
  await area().waitFor();
  const before = await variables();
  const text = await area().inputValue();
  // Several changes in one edit: a rename in place (Motor → Pump), a type and an initial value changed.
  const edited = text.replace('Motor AT', 'Pump AT').replace('Count : INT := 0;', 'Count : DINT := 0;').replace('Limit : INT := 10;', 'Limit : INT := 20;');
  await area().fill(edited);
  await area().press('Control+Enter');
  await poll(async () => (await variables()).map((v) => `${v.name}:${v.type}`)).toEqual([
    'Start:BOOL',
    'Stop:BOOL',
    'Pump:BOOL',
    'Count:DINT',
    'Limit:INT',
  ]);
  expect((await variables())[4]!.initial).toBe('20');
  const coilName = () =>
    page.evaluate(() => {
      const el = window.rungsmith!.documentStore!.getState().project.pous[0]!.networks[0]!.elements.find((e) => e.kind === 'coil');
      return el?.kind === 'coil' ? el.variable : '';
    });
  expect(await coilName()).toBe('Pump');
  expect(await page.evaluate(() => window.rungsmith!.documentStore!.getState().undoName)).toBe('editDeclarations');
  await area().press('Control+z');
  await poll(() => variables()).toEqual(before);
  expect(await coilName()).toBe('Motor');
  await poll(() => area().inputValue()).toBe(text);
});

test("a variable's problem (not a syntax error) applies, is marked at its line, and the Problems list leads to it", async () => {
  await area().waitFor();
  const text = await area().inputValue();
  const line = text.split('\n').findIndex((l) => l.includes('Count :')) + 1;
  await area().fill(text.replace('Count : INT := 0;', 'Count : INT := abc;'));
  await area().press('Control+Enter');
  await poll(async () => (await variables()).find((v) => v.name === 'Count')?.initial).toBe('abc');
  await poll(() => panel().locator(`.rs-decl-gutter [data-line="${line}"]`).getAttribute('class')).toContain('rs-decl-warning');
  // Away from the line, then from the Problems list back to it.
  await area().press('Control+Home');
  await page.getByRole('tab', { name: 'Problems', exact: true }).click();
  const problem = page.getByTestId('problems-panel').locator('[data-rule="LD-E14"]');
  await poll(() => problem.count()).toBe(1);
  await problem.click();
  await poll(() =>
    area().evaluate((el: HTMLTextAreaElement) => (document.activeElement === el ? el.value.slice(0, el.selectionStart).split('\n').length : 0)),
  ).toBe(line);
  await area().press('Control+z');
  await poll(async () => (await variables()).find((v) => v.name === 'Count')?.initial).toBe('0');
});

test('the globals as VAR_GLOBAL text: a global typed there is declared, its // comment kept', async () => {
  await panel().getByText('Global', { exact: true }).click();
  await area().waitFor();
  expect(await area().inputValue()).toBe('VAR_GLOBAL\nEND_VAR\n');
  await area().focus();
  await page.keyboard.press('Control+Home');
  await page.keyboard.press('End');
  await page.keyboard.press('Enter');
  await page.keyboard.press('Tab');
  await page.keyboard.type('MaxLevel : INT := 900; // litres');
  await page.keyboard.press('Control+Enter');
  await poll(() => page.evaluate(() => window.rungsmith!.documentStore!.getState().project.globals)).toEqual([
    { name: 'MaxLevel', type: 'INT', varClass: 'local', initial: '900', retain: false, comment: 'litres' },
  ]);
  expect(await area().inputValue()).toBe('VAR_GLOBAL\n\tMaxLevel : INT := 900; (* litres *)\nEND_VAR\n');
});
