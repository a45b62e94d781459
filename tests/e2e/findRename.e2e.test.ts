// Find/Replace of a declared variable's whole name is a rename: its declaration, every use, the
// watch list, the trend and the test scenarios follow, in one undo step, and the program stays
// free of errors. A text replace that would leave names undeclared says so first (issue 22, 2.4).
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { sealInProject } from './sealInProject';

const browser = useChromium();
let page: Page;
let errors: string[];

const project = (): Promise<Project> =>
  page.evaluate(() => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project);
const uses = (p: Project) =>
  p.pous[0]!.networks.flatMap((n) => n.elements.flatMap((el) => ('variable' in el ? [el.variable] : [])));
const summary = () => page.getByTestId('problems-summary').textContent();
const sim = () =>
  page.evaluate(() => {
    const s = (window.rungsmith!.simStore as { getState(): { watch: string[]; trendNames: string[] } }).getState();
    return { watch: s.watch, trend: s.trendNames };
  });

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  const p: Project = {
    ...sealInProject(2, 'Rename'),
    scenarios: [{ name: 'seal-in', csv: 'scan,Start0,Guard0,expect Motor0\n1,1,1,1\n2,0,,1\n' }],
  };
  await page.evaluate((x) => window.rungsmith!.documentStore!.getState().loadProject(x), p);
  // Watched and trended, as a user does from the variable's context menu.
  await page.evaluate(() => {
    const s = (window.rungsmith!.simStore as { getState(): { addWatch(n: string): void; toggleTrend(n: string): void } }).getState();
    s.addWatch('Motor0');
    s.toggleTrend('Motor0');
  });
});

test("replacing a declared variable's whole name renames it everywhere, in one undo step", async () => {
  await expect.poll(summary, { timeout: 15_000 }).toBe('No problems');
  await page.keyboard.press('Control+f');
  await page.getByTestId('find-input').fill('Motor0');
  await page.getByTestId('find-mode').selectOption('word');
  await page.getByTestId('replace-input').fill('Pump0');
  await page.getByTestId('replace-preview').click();
  expect(await page.getByTestId('replace-rename').textContent()).toBe(
    'Renames the variable Motor0 to Pump0: its declaration (Main), 2 uses, and the watch list, trend and test scenarios naming it.',
  );
  expect(await page.getByTestId('replace-undeclared').count()).toBe(0);
  await page.getByTestId('replace-all').click();

  const after = await project();
  expect(after.pous[0]!.variables.map((v) => v.name)).toEqual(['Start0', 'Stop0', 'Guard0', 'Pump0', 'Start1', 'Stop1', 'Guard1', 'Motor1']);
  expect(uses(after).filter((n) => /Motor0|Pump0/.test(n))).toEqual(['Pump0', 'Pump0']);
  expect(after.scenarios![0]!.csv).toBe('scan,Start0,Guard0,expect Pump0\n1,1,1,1\n2,0,,1\n');
  expect(await sim()).toEqual({ watch: ['Pump0'], trend: ['Pump0'] });
  expect(await page.getByTestId('status-bar').getByRole('status').textContent()).toBe(
    'Renamed Motor0 to Pump0 (one undo step).',
  );
  // The program still compiles: no LD-R08 (coil/contact naming nothing) or LD-E02.
  await expect.poll(summary, { timeout: 15_000 }).toBe('No problems');

  await page.keyboard.press('Escape');
  await page.keyboard.press('Control+z');
  const undone = await project();
  expect(undone.pous[0]!.variables.map((v) => v.name)).toContain('Motor0');
  expect(uses(undone).filter((n) => /Motor0|Pump0/.test(n))).toEqual(['Motor0', 'Motor0']);
  expect(undone.scenarios![0]!.csv).toContain('expect Motor0');
  await expect.poll(summary, { timeout: 15_000 }).toBe('No problems');
  expect(errors).toEqual([]);
});

test('a text replace that would leave names undeclared lists them first; Cancel keeps the program', async () => {
  const before = await project();
  await page.keyboard.press('Control+f');
  await page.getByTestId('find-mode').selectOption('text');
  await page.getByTestId('find-input').fill('Guard');
  await page.getByTestId('replace-input').fill('Gate');
  await page.getByTestId('replace-preview').click();
  expect(await page.getByTestId('replace-rename').count()).toBe(0);
  expect(await page.getByTestId('replace-undeclared').textContent()).toBe(
    'After this replace, these names would not be declared: Gate0 (Main · Network 1, contact: LD-R08), ' +
      'Gate1 (Main · Network 2, contact: LD-R08). Declare them afterwards, replace anyway, or cancel.',
  );
  expect(await page.getByTestId('replace-all').textContent()).toBe('Replace anyway');
  await page.getByTestId('replace-cancel').click();
  expect(await page.getByTestId('replace-list').count()).toBe(0);
  expect(await project()).toEqual(before);

  // Replace anyway: done, and the checks report what the warning said.
  await page.getByTestId('replace-preview').click();
  await page.getByTestId('replace-all').click();
  expect(uses(await project())).toContain('Gate0');
  await expect.poll(summary, { timeout: 15_000 }).toMatch(/error/);
  await page.keyboard.press('Escape');
  await page.keyboard.press('Control+z');
  expect(await project()).toEqual(before);
  expect(errors).toEqual([]);
});
