// STRING in the browser: the variable table offers STRING and WSTRING, the watch table shows a
// string as its literal and writes plain text or a literal into a STRING variable.
import { beforeEach, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

beforeEach(async () => {
  await page?.close();
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
});

function greeting() {
  const net = newNetwork({
    rows: 4,
    cols: 4,
    elements: [
      { id: 'l1' as ElementId, kind: 'link', row: 0, col: 0 },
      { id: 'b1' as ElementId, kind: 'box', row: 0, col: 1, blockType: 'CONCAT', inputs: { IN1: 'Name', IN2: "' is on'" }, outputs: { OUT: 'Msg' } },
    ],
    vlinks: [],
  });
  const main = newPou('Main', { variables: [variable('Name', 'STRING', { initial: "'Motor'" }), variable('Msg', 'STRING')], networks: [net] });
  return newProject('Strings', { pous: [main] });
}

test('the watch table shows STRING values as literals and writes text into them', async () => {
  await sim.load(greeting());
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
  const row = page.getByTestId('variables-panel').getByTestId('variable-row-Msg');
  await row.waitFor();
  expect(await row.getByLabel('Type').inputValue()).toBe('STRING');
  const types = await row.getByLabel('Type').locator('option').allTextContents();
  expect(types).toEqual(expect.arrayContaining(['STRING', 'WSTRING', 'DATE', 'TOD', 'DT']));
  await sim.tab('Watch');
  for (const name of ['Name', 'Msg']) {
    await page.getByTestId('watch-add-name').fill(name);
    await page.getByTestId('watch-add').click();
  }
  await sim.button('run').click();
  await sim.waitForMode('Running');
  const msg = page.getByTestId('watch-row-Msg').getByTestId('watch-value');
  await expect.poll(() => msg.textContent()).toBe("'Motor is on'");
  const name = page.getByTestId('watch-row-Name');
  await name.getByTestId('watch-input').fill('Pump 2');
  await name.getByTestId('watch-write').click();
  await expect.poll(() => msg.textContent()).toBe("'Pump 2 is on'");
  await name.getByTestId('watch-input').fill("'it$'s$N'");
  await name.getByTestId('watch-write').click();
  await sim.waitForValue('Msg', "it's\n is on");
  await expect.poll(() => msg.textContent()).toBe("'it$'s$N is on'");
  expect(errors).toEqual([]);
});
