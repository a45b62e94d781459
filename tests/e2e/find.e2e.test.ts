// Ctrl+F finds a name across every POU (the canvas is not searchable by the browser): results
// listed with POU and network, Enter goes to the next one; a whole-name replace with preview is
// one undo step. The cross-reference lists every use with read/write, clickable, and the unused
// variables.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { openApp, useChromium } from './appPage';

const browser = useChromium();
let page: Page;
let errors: string[];

const v = (name: string, type: string): Variable => ({ name, type, varClass: 'local', retain: false, comment: '' });
const e = (s: string) => s as ElementId;

function plant(): Project {
  const main = newPou('Main');
  const aux = newPou('Aux');
  return newProject('Plant', {
    globals: [v('Pump', 'BOOL')],
    pous: [
      {
        ...main,
        variables: [v('Start', 'BOOL'), v('Spare', 'INT')],
        networks: [
          newNetwork({
            title: 'Pump on',
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Start', id: e('a'), row: 0, col: 0 },
              { kind: 'coil', coil: 'SET', variable: 'Pump', id: e('b'), row: 0, col: 6 },
            ],
          }),
        ],
      },
      {
        ...aux,
        networks: [
          newNetwork({ title: 'Idle' }),
          newNetwork({
            title: 'Pump lamp',
            comment: 'shows Pump',
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Pump', id: e('c'), row: 0, col: 0 },
              { kind: 'coil', coil: 'RESET', variable: 'Pump', id: e('d'), row: 0, col: 6 },
            ],
          }),
        ],
      },
    ],
  });
}

const project = (): Promise<Project> =>
  page.evaluate(() => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project);
const activePou = () => page.evaluate(() => window.rungsmith!.documentStore!.getState().activePouId);
const selection = () => page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), plant());
});

test('find across POUs, next goes to the element in its POU; replace a whole name in one undo step', async () => {
  const p = await project();
  await page.keyboard.press('Control+f');
  await page.getByTestId('find-input').fill('pump');
  await expect.poll(() => page.getByTestId('find-count').textContent()).toBe('6 matches');
  const rows = await page.getByTestId('find-results').locator('li').allTextContents();
  expect(rows[0]).toContain('Main · Network 1');
  expect(rows.some((r) => r.includes('Aux · Network 2 · comment'))).toBe(true);
  // Enter five times: the fifth match is the contact in Aux, network 2 (after its title and comment).
  for (let i = 0; i < 5; i++) await page.keyboard.press('Enter');
  await expect.poll(() => page.getByTestId('find-count').textContent()).toBe('5 of 6 matches');
  expect(await activePou()).toBe(p.pous[1]!.id);
  await expect.poll(selection).toEqual(['c']);

  await page.getByTestId('find-mode').selectOption('word');
  await page.getByTestId('find-input').fill('Pump');
  await page.getByTestId('replace-input').fill('Pump1');
  await page.getByTestId('replace-preview').click();
  const preview = await page.getByTestId('replace-list').locator('li').allTextContents();
  expect(preview).toHaveLength(6);
  await page.getByTestId('replace-all').click();
  const after = await project();
  const names = after.pous.flatMap((x) => x.networks.flatMap((n) => n.elements.flatMap((el) => ('variable' in el ? [el.variable] : []))));
  expect(names.filter((n) => n === 'Pump1')).toHaveLength(3);
  expect(after.pous[1]!.networks[1]!.comment).toBe('shows Pump1');
  await page.keyboard.press('Escape');
  await page.keyboard.press('Control+z');
  expect((await project()).pous[1]!.networks[1]!.comment).toBe('shows Pump');
  expect(errors).toEqual([]);
});

test('cross-reference: every use of a global with POU, network and access; click goes there; unused variables', async () => {
  await page.getByTestId('tab-xref').click();
  await page.getByTestId('xref-input').fill('Pump');
  const rows = await page.getByTestId('xref-uses').locator('tbody tr').allTextContents();
  expect(rows).toEqual([
    expect.stringMatching(/Main · Network 1.*coil SET.*Pump.*write/),
    expect.stringMatching(/Aux · Network 2.*contact NO.*Pump.*read/),
    expect.stringMatching(/Aux · Network 2.*coil RESET.*Pump.*write/),
  ]);
  await page.getByTestId('xref-uses').getByRole('button', { name: 'Main · Network 1' }).click();
  expect(await activePou()).toBe((await project()).pous[0]!.id);
  await expect.poll(selection).toEqual(['b']);
  await page.getByTestId('xref-unused').click();
  expect(await page.getByTestId('xref-summary').textContent()).toContain('Spare');
  await page.getByTestId('xref-multi').click();
  expect(await page.getByTestId('xref-summary').textContent()).toMatch(/Pump.*2 writers/);
  expect(errors).toEqual([]);
});
