// The variable table on a very large project: it renders only the rows in view, yet every row
// can be reached by scrolling, filtering or adding; and the problems list follows an edit.
import { afterAll, beforeAll, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { Project, Variable } from '../../src/model/project';
import { openApp, useChromium } from './appPage';

const browser = useChromium();
let page: Page;
let errors: string[];

const COUNT = 3000;

function bigProject(): Project {
  const variables: Variable[] = [];
  for (let i = 0; i < COUNT; i++) variables.push(variable(`Sensor${i}`, i % 3 === 0 ? 'INT' : 'BOOL'));
  return newProject('Big table', { pous: [newPou('Main', { networks: [newNetwork()], variables })] });
}

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), bigProject());
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
});

afterAll(() => {
  expect(errors).toEqual([]);
});

const panel = () => page.getByTestId('variables-panel');
const renderedRows = () => panel().locator('.rs-var-row').count();

test('a table of thousands of variables shows its first rows and renders only a window of them', async () => {
  await panel().getByTestId('variable-row-Sensor0').waitFor();
  await expect.poll(() => panel().locator('.rs-var-summary').textContent()).toContain(`${COUNT} variables`);
  const rendered = await renderedRows();
  expect(rendered).toBeGreaterThan(5);
  expect(rendered).toBeLessThan(200);
});

test('scrolling to the end reaches the last variable, and scrolling back the first', async () => {
  await panel()
    .locator('.rs-var-scroll')
    .evaluate((el) => {
      el.scrollTop = el.scrollHeight;
    });
  const last = panel().getByTestId(`variable-row-Sensor${COUNT - 1}`);
  await last.waitFor();
  expect(await last.isVisible()).toBe(true);
  expect(await panel().getByTestId('variable-row-Sensor0').count()).toBe(0);
  await panel()
    .locator('.rs-var-scroll')
    .evaluate((el) => {
      el.scrollTop = 0;
    });
  await panel().getByTestId('variable-row-Sensor0').waitFor();
});

test('filtering finds a row far down the table, and editing it works', async () => {
  await panel().getByRole('searchbox', { name: 'Filter variables' }).fill('Sensor2718');
  const row = panel().getByTestId('variable-row-Sensor2718');
  await row.waitFor();
  expect(await renderedRows()).toBe(1);
  await row.getByRole('textbox', { name: 'Comment' }).fill('Gate closed');
  await page.keyboard.press('Enter');
  await expect
    .poll(() =>
      page.evaluate(
        () =>
          window
            .rungsmith!.documentStore!.getState()
            .project.pous[0]!.variables.find((v) => v.name === 'Sensor2718')?.comment,
      ),
    )
    .toBe('Gate closed');
  await panel().getByRole('searchbox', { name: 'Filter variables' }).fill('');
});

test('adding a variable scrolls the table to the new row and puts the cursor in its name', async () => {
  await panel().getByTestId('add-variable').click();
  const row = panel().getByTestId('variable-row-Var1');
  await row.waitFor();
  expect(await row.isVisible()).toBe(true);
  await expect
    .poll(() => page.evaluate(() => (document.activeElement as HTMLInputElement | null)?.value))
    .toBe('Var1');
});

test('the problems list follows an edit that breaks a rule and the undo that repairs it', async () => {
  const summary = page.getByTestId('problems-summary');
  await expect.poll(() => summary.textContent()).toMatch(/^(No problems|0 errors)/);
  const before = await summary.textContent();
  await page.evaluate(() => {
    const doc = window.rungsmith!.documentStore!.getState();
    const net = doc.project.pous[0]!.networks[0]!;
    doc.placeElement(net.id, { row: 0, col: 0 }, { kind: 'contact', contact: 'NO', variable: 'Nowhere' });
  });
  await expect.poll(() => summary.textContent()).toMatch(/[1-9] errors?/);
  expect(await page.getByTestId('problem').first().textContent()).toContain('LD-R');
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  await expect.poll(() => summary.textContent()).toBe(before);
});
