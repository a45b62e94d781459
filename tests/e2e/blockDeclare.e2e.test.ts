// Declaring from the canvas inside a FUNCTION_BLOCK offers its interface, as CODESYS's "Auto
// declare" does: a contact's new name as VAR_INPUT first, then VAR_IN_OUT, VAR_OUTPUT and VAR; a
// coil's as VAR_OUTPUT first. No %IX/%QX/%MX address (a block's variables are wired by its callers).
// Inside a FUNCTION: VAR_INPUT, VAR_OUTPUT and VAR. In a PROGRAM the addresses are still offered.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import type { Project, Variable } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Plant'));
  draw = new DrawPage(page);
});

const variables = async (pouName: string): Promise<Variable[]> => {
  const project = await page.evaluate(
    () => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project,
  );
  return [...(project.pous.find((p) => p.name === pouName)?.variables ?? [])];
};

async function addPou(button: 'add-fb' | 'add-function', name: string) {
  await page.getByTestId('tab-project').click();
  await page.getByTestId(button).click();
  const field = page.getByTestId('pou-rename');
  await field.fill(name);
  await field.press('Enter');
  await page.getByTestId(`pou-tab-${name}`).waitFor();
}

/** Places an element from the keyboard, types a new name and returns the declarations offered for it. */
async function offersFor(key: string, name: string): Promise<string[]> {
  await draw.canvas().focus();
  await page.keyboard.press(key);
  const input = page.getByTestId('inline-editor');
  await input.waitFor();
  await input.fill(name);
  const offers = page.locator('[role="listbox"] [role="option"].rs-declare');
  await offers.first().waitFor();
  return (await offers.locator('.rs-completion-type').allTextContents()).map((s) => s.trim());
}

/** Picks the offer with this label (click, as a user does). */
async function pick(label: string) {
  await page.locator('[role="listbox"] [role="option"].rs-declare', { hasText: label }).click();
  await page.getByTestId('inline-editor').waitFor({ state: 'detached' });
}

test('inside a FUNCTION_BLOCK: a contact offers VAR_INPUT first, a coil VAR_OUTPUT first, with VAR_IN_OUT and VAR, and no address', async () => {
  await addPou('add-fb', 'Valve');
  const contact = await offersFor('c', 'OpenCmd');
  expect(contact).toEqual([
    'BOOL input (VAR_INPUT)',
    'BOOL in-out (VAR_IN_OUT)',
    'BOOL output (VAR_OUTPUT)',
    'BOOL local (VAR)',
    'BOOL global (VAR_GLOBAL)',
  ]);
  expect(contact.join(' ')).not.toMatch(/%[IQM]/);
  await pick('BOOL input (VAR_INPUT)');

  const coil = await offersFor('o', 'IsOpen');
  expect(coil[0]).toBe('BOOL output (VAR_OUTPUT)');
  expect(coil).toEqual(expect.arrayContaining(['BOOL in-out (VAR_IN_OUT)', 'BOOL input (VAR_INPUT)', 'BOOL local (VAR)']));
  await pick('BOOL output (VAR_OUTPUT)');

  // A second network: a contact declared VAR_IN_OUT.
  await page.keyboard.press('n');
  await expect.poll(async () => (await draw.networks()).length).toBe(2);
  await offersFor('c', 'Interlock');
  await pick('BOOL in-out (VAR_IN_OUT)');

  const vars = await variables('Valve');
  expect(vars.map((v) => [v.name, v.type, v.varClass, v.location])).toEqual([
    ['OpenCmd', 'BOOL', 'input', undefined],
    ['IsOpen', 'BOOL', 'output', undefined],
    ['Interlock', 'BOOL', 'inOut', undefined],
  ]);
  // The block's box shows them as its pins.
  await page.getByTestId('pou-tab-Main').click();
  await draw.canvas().focus();
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('Valve');
  expect(await page.getByRole('option', { name: /Valve/ }).first().textContent()).toMatch(/OpenCmd.*Interlock.*IsOpen|OpenCmd.*IsOpen/);
  await page.keyboard.press('Escape');
  expect(errors).toEqual([]);
});

test('inside a FUNCTION: VAR_INPUT, VAR_OUTPUT and VAR; in a PROGRAM the addresses are offered', async () => {
  await addPou('add-function', 'Permit');
  const contact = await offersFor('c', 'Ready');
  expect(contact).toEqual(['BOOL input (VAR_INPUT)', 'BOOL output (VAR_OUTPUT)', 'BOOL local (VAR)', 'BOOL global (VAR_GLOBAL)']);
  await pick('BOOL input (VAR_INPUT)');
  expect((await variables('Permit')).find((v) => v.name === 'Ready')).toMatchObject({ varClass: 'input', type: 'BOOL' });

  await page.getByTestId('pou-tab-Main').click();
  const inProgram = await offersFor('c', 'StartButton');
  expect(inProgram[0]).toBe('BOOL');
  expect(inProgram.join(' ')).toMatch(/input at %IX/);
  await page.keyboard.press('Escape');
  expect(errors).toEqual([]);
});
