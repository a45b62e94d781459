// Issue 23 class 8: a CODESYS V3 export (a CFC PLC_PRG and an LD program in one task, Util's BLINK
// and LIMITALARM) imported through the File menu: the report names the CFC body and the library
// blocks, Open shows the LD program the task runs, and the CFC and BLINK POUs say what they are.
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { expect, test } from 'vitest';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();

test('a CODESYS export opens on its LD program; the CFC PLC_PRG and the Util blocks are named', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  const text = await readFile(fileURLToPath(new URL('../fixtures/plcopen/codesys-v3-application.xml', import.meta.url)), 'utf8');
  await editor.chooseFile('File', 'Import PLCopen XML…', { name: 'codesys-v3-application.xml', mimeType: 'application/xml', text });
  const report = page.getByTestId('plcopen-report');
  await report.waitFor();
  expect(await report.getByTestId('plcopen-pou-count').textContent()).toBe('4 POUs (1 LD, 1 CFC, 2 library)');
  const choice = report.getByTestId('plcopen-pou-choice');
  expect(await choice.evaluate((s: HTMLSelectElement) => s.selectedOptions[0]?.textContent)).toBe('LampLogic (program, 5 networks)');
  expect(await choice.locator('option').allTextContents()).toEqual([
    'PLC_PRG (program, CFC)',
    'LampLogic (program, 5 networks)',
    'BLINK (function block, ST, CODESYS Util library)',
    'LIMITALARM (function block, ST, CODESYS Util library)',
  ]);
  expect(await report.textContent()).toContain('POU "PLC_PRG" is written in CFC (CODESYS)');
  await report.getByRole('button', { name: 'Open' }).click();
  const active = () =>
    page.evaluate(() => {
      const s = window.rungsmith!.documentStore!.getState();
      return s.project.pous.find((p) => p.id === s.activePouId)?.name;
    });
  await poll(active).toBe('LampLogic');
  await page.getByTestId('ladder-canvas').waitFor();

  await page.getByTestId('tab-project').click();
  await page.getByTestId('tree-pou-PLC_PRG').getByRole('button', { name: /PLC_PRG/ }).first().click();
  const view = page.getByTestId('source-view');
  await view.waitFor();
  await poll(async () => await view.textContent()).toContain('PLC_PRG is written in CFC. CFC bodies are not run (LD-E51)');
  expect(await view.locator('pre').textContent()).toMatch(/^<CFC>/);

  await page.getByTestId('tree-pou-BLINK').getByRole('button', { name: /BLINK/ }).first().click();
  await poll(async () => await view.textContent()).toContain("BLINK is a block of the CODESYS Util library, which the file calls without declaring it");
  expect(await view.locator('pre').textContent()).toContain('CLOCK(IN := TRUE, PT := TIMEHIGH);');
  expect(editor.errors).toEqual([]);
  await editor.close();
});
