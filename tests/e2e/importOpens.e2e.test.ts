// Issue 22, section 2 item 13: importing a file whose first POU is an ST function (as Beremiz's
// first_steps) opened that function, and the report said "7 LD POUs" for 3. The report counts POUs
// by their body language, offers the program the resource runs, and Open shows that program.
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { expect, test } from 'vitest';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();

test('the import report counts POUs by language and opens the program the resource runs', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  const text = await readFile(fileURLToPath(new URL('../fixtures/plcopen/open-resource-program.xml', import.meta.url)), 'utf8');
  await editor.chooseFile('File', 'Import PLCopen XML…', { name: 'open-resource-program.xml', mimeType: 'application/xml', text });
  const report = page.getByTestId('plcopen-report');
  await report.waitFor();
  expect(await report.getByTestId('plcopen-pou-count').textContent()).toBe('4 POUs (3 LD, 1 ST)');
  const choice = report.getByTestId('plcopen-pou-choice');
  // The choice starts on Plant, which task Main runs as MainInstance; the ST function says ST.
  expect(await choice.evaluate((s: HTMLSelectElement) => s.selectedOptions[0]?.textContent)).toBe('Plant (program, 1 network)');
  expect(await choice.locator('option').allTextContents()).toContain('Halve (function, ST)');
  await report.getByRole('button', { name: 'Open' }).click();
  await poll(async () => (await editor.project()).name).toBe('FirstProgram');
  const active = () =>
    page.evaluate(() => {
      const s = window.rungsmith!.documentStore!.getState();
      return s.project.pous.find((p) => p.id === s.activePouId)?.name;
    });
  await poll(active).toBe('Plant');
  // The canvas shows Plant's network (its coil Filling), not the function's text.
  await page.getByTestId('ladder-canvas').waitFor();
  expect(editor.errors).toEqual([]);
  await editor.close();
});
