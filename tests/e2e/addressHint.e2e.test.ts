// Issue 22, section 2 item 12: every unaddressed variable showed a grey "%QX0.0" or "%MW0" in its
// Address cell (FB inputs too), as if they all shared %QX0.0. An unaddressed variable now says
// "no address" (italic), an FB instance nothing, and a real address reads as itself.
import { expect, test } from 'vitest';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();

test('unaddressed variables say "no address", never a grey %QX0.0', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Addresses'));
  await poll(async () => (await editor.project()).name).toBe('Addresses');
  await editor.tab('Variables');
  await editor.declare('Lamp', { type: 'BOOL' });
  await editor.declare('Count', { type: 'INT' });
  await editor.declare('T1', { type: 'TON' });
  await editor.declare('Valve', { type: 'BOOL', address: '%QX0.3' });
  const address = (name: string) => editor.variableRow(name).getByLabel('Address');
  const shown = async (name: string) => ({
    value: await address(name).inputValue(),
    placeholder: await address(name).getAttribute('placeholder'),
  });
  expect(await shown('Lamp')).toEqual({ value: '', placeholder: 'no address' });
  expect(await shown('Count')).toEqual({ value: '', placeholder: 'no address' });
  expect(await shown('T1')).toEqual({ value: '', placeholder: '' });
  expect(await shown('Valve')).toEqual({ value: '%QX0.3', placeholder: 'no address' });
  // The hint is drawn as a hint (italic), not as an address.
  expect(await address('Lamp').evaluate((el) => getComputedStyle(el, '::placeholder').fontStyle)).toBe('italic');
  expect(await address('Lamp').getAttribute('title')).toMatch(/^No address: type one/);

  // Inside a function block, its inputs too.
  await page.getByTestId('tab-project').click();
  await page.getByTestId('add-fb').click();
  const field = page.getByTestId('pou-rename');
  await field.fill('Pump');
  await field.press('Enter');
  await page.getByTestId('pou-tab-Pump').waitFor();
  await editor.tab('Variables');
  await editor.declare('Go', { type: 'BOOL' });
  await editor.variableRow('Go').getByLabel('Class').selectOption('input');
  await editor.declare('Speed', { type: 'INT' });
  await editor.variableRow('Speed').getByLabel('Class').selectOption('input');
  for (const name of ['Go', 'Speed']) expect((await shown(name)).placeholder).toBe('no address');
  const placeholders = await editor.variables.locator('input[aria-label="Address"]').evaluateAll((els) => els.map((e) => e.getAttribute('placeholder') ?? ''));
  expect(placeholders.filter((p) => p.startsWith('%'))).toEqual([]);
  expect(editor.errors).toEqual([]);
  await editor.close();
});
