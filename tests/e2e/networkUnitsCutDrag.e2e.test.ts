// Whole networks moved as units in a real Chromium: three networks picked with Shift+click on their
// headers are cut and pasted after another network (one undo step each), and two selected networks
// dragged by a header's handle land below another network together.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { openApp, useChromium } from './appPage';

const browser = useChromium();
let page: Page;
let errors: string[];

const v = (name: string): Variable => ({ name, type: 'BOOL', varClass: 'local', retain: false, comment: '' });

function sixNetworks(): Project {
  const main = newPou('Main');
  const names = ['N1', 'N2', 'N3', 'N4', 'N5', 'N6'];
  return newProject('Units', {
    pous: [
      {
        ...main,
        variables: [v('In'), ...names.map((n) => v(`Out${n}`))],
        networks: names.map((title, i) =>
          newNetwork({
            title,
            rows: 1,
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'In', id: `c${i}` as ElementId, row: 0, col: 0 },
              { kind: 'coil', coil: 'COIL', variable: `Out${title}`, id: `o${i}` as ElementId, row: 0, col: 9 },
            ],
          }),
        ),
      },
    ],
  });
}

const networks = () =>
  page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    return s.project.pous[0]!.networks.map((n) => ({ id: n.id, title: n.title }));
  });
const titles = async () => (await networks()).map((n) => n.title);
const header = async (title: string) => {
  const n = (await networks()).find((x) => x.title === title)!;
  return page.getByTestId(`network-number-${n.id}`);
};
const undoSteps = () => page.evaluate(() => window.rungsmith!.documentStore!.getState().history.undo.length);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), sixNetworks());
});

test('three networks selected with Shift+click are cut and pasted after another network', async () => {
  await (await header('N1')).click();
  await (await header('N3')).click({ modifiers: ['Shift'] });
  expect(await page.locator('[data-selected="true"]').count()).toBe(3);
  const before = await undoSteps();
  await page.keyboard.press('Control+x');
  expect(await titles()).toEqual(['N4', 'N5', 'N6']);
  expect(await undoSteps()).toBe(before + 1);

  await (await header('N5')).click();
  await page.keyboard.press('Control+v');
  await expect.poll(titles).toEqual(['N4', 'N5', 'N1', 'N2', 'N3', 'N6']);
  // The pasted networks are the selection now, with their elements (new ids).
  expect(await page.locator('[data-selected="true"]').count()).toBe(3);
  const pasted = await page.evaluate(() =>
    window.rungsmith!.documentStore!.getState().project.pous[0]!.networks[2]!.elements.map((e) => e.id),
  );
  expect(pasted).toHaveLength(2);
  expect(pasted).not.toContain('c0');
  expect(await undoSteps()).toBe(before + 2);

  await page.keyboard.press('Control+z');
  expect(await titles()).toEqual(['N4', 'N5', 'N6']);
  await page.keyboard.press('Control+z');
  expect(await titles()).toEqual(['N1', 'N2', 'N3', 'N4', 'N5', 'N6']);
  await page.keyboard.press('Control+y');
  await page.keyboard.press('Control+y');
  expect(await titles()).toEqual(['N4', 'N5', 'N1', 'N2', 'N3', 'N6']);
  expect(errors).toEqual([]);
});

test('two selected networks dragged by a handle onto a later network land below it together', async () => {
  // Collapsed, every header is on screen: the handles and the drop target are all visible.
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().setCollapsed('all', true));
  await (await header('N4')).click();
  await (await header('N5')).click({ modifiers: ['Shift'] });
  expect(await page.locator('[data-selected="true"]').count()).toBe(2);
  const before = await undoSteps();
  // Drag network 1 (N4, selected with N5) onto network 5 (N3).
  await page.getByTestId('network-header-0').locator('.rs-drag-handle').dragTo(page.getByTestId('network-header-4'));
  await expect.poll(titles).toEqual(['N1', 'N2', 'N3', 'N4', 'N5', 'N6']);
  expect(await undoSteps()).toBe(before + 1);
  // And back up: dragged onto the first network, they go before it.
  await page.getByTestId('network-header-3').locator('.rs-drag-handle').dragTo(page.getByTestId('network-header-0'));
  await expect.poll(titles).toEqual(['N4', 'N5', 'N1', 'N2', 'N3', 'N6']);
  await page.keyboard.press('Control+z');
  expect(await titles()).toEqual(['N1', 'N2', 'N3', 'N4', 'N5', 'N6']);
  expect(errors).toEqual([]);
});
