// Issue 22, section 2 item 11: while a configuration runs, its variables are named by program
// instance (MainInst.Clear). A short name typed into the watch (Clear) showed type "?" and "—"; now
// it resolves to its instance path when one instance has it, the instance paths are offered while
// typing, and a name two instances have is added only once the user picks a path.
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();

test('a short name in a configuration watches its instance path; ambiguous names offer the paths', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  const sim = new SimPage(page);
  // Two program instances in one task (MainInst of Main, TallyInst of Tally): a configuration.
  const text = await readFile(fileURLToPath(new URL('../fixtures/plcopen/names-globals.xml', import.meta.url)), 'utf8');
  await editor.chooseFile('File', 'Import PLCopen XML…', { name: 'names-globals.xml', mimeType: 'application/xml', text });
  await page.getByTestId('plcopen-report').getByRole('button', { name: 'Open' }).click();
  await poll(async () => (await editor.project()).name).toBe('names');
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.tab('Watch');

  const field = page.getByTestId('watch-add-name');
  // Typing the start of a name lists the instance path it may mean.
  await field.fill('Cle');
  const choices = page.getByTestId('watch-choices');
  await poll(() => choices.getByTestId('watch-choice').allTextContents()).toEqual(['MainInst.Clear']);
  // The whole short name, Enter: the instance path is watched, with its type and value.
  await field.fill('Clear');
  await field.press('Enter');
  const row = page.getByTestId('watch-row-MainInst.Clear');
  await row.waitFor();
  expect(await row.locator('td').nth(1).textContent()).toBe('BOOL');
  await poll(() => row.getByTestId('watch-value').textContent()).toBe('FALSE');
  expect(await page.getByTestId('watch-row-Clear').count()).toBe(0);
  // A pick from the list while typing.
  await field.fill('Pul');
  await choices.getByRole('option', { name: 'MainInst.Pulse' }).click();
  await page.getByTestId('watch-row-MainInst.Pulse').waitFor();

  // A second instance of Main: Clear is in two instances; nothing is guessed, both are offered.
  await sim.button('reset').click();
  const project = await editor.project();
  const twice: Project = {
    ...project,
    tasks: project.tasks.map((t, i) => (i === 0 ? { ...t, programs: [...t.programs, { instance: 'Spare', pou: 'Main' }] } : t)),
  };
  await sim.load(twice);
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await field.fill('Clear');
  await poll(() => choices.getByTestId('watch-choice').allTextContents()).toEqual(['MainInst.Clear', 'Spare.Clear']);
  expect(await page.getByTestId('watch-add').isDisabled()).toBe(true);
  await field.press('Enter');
  expect(await page.getByTestId('watch-row-Clear').count()).toBe(0);
  await choices.getByRole('option', { name: 'Spare.Clear' }).click();
  const spare = page.getByTestId('watch-row-Spare.Clear');
  await spare.waitFor();
  expect(await spare.locator('td').nth(1).textContent()).toBe('BOOL');
  await poll(() => spare.getByTestId('watch-value').textContent()).toBe('FALSE');
  expect(editor.errors).toEqual([]);
  await editor.close();
});
