// Large programs: a collapsed network is one header line; the Outline follows the canvas's scroll,
// selects ranges of networks (Shift+click, Ctrl+click) and moves them by dragging (one undo step);
// Ctrl+Shift+G extends the network selection to the network entered.
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, expect, test } from 'vitest';
import { COLLAPSED_HEADER_H } from '../../src/editor/canvas/geometry';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { poll } from './panelsPage';

const browser = useChromium();
let page: Page;
let errors: string[];
const COUNT = 40;

const v = (name: string): Variable => ({ name, type: 'BOOL', varClass: 'local', retain: false, comment: '' });

function plant(): Project {
  const main = newPou('Main');
  return newProject('Plant', {
    pous: [
      {
        ...main,
        variables: Array.from({ length: COUNT }, (_, i) => [v(`In${i}`), v(`Out${i}`)]).flat(),
        networks: Array.from({ length: COUNT }, (_, i) =>
          newNetwork({
            title: `Rung ${i + 1}`,
            comment: `Drives output ${i}`,
            elements: [
              { kind: 'contact', contact: 'NO', variable: `In${i}`, id: `a${i}` as ElementId, row: 0, col: 0 },
              { kind: 'coil', coil: 'COIL', variable: `Out${i}`, id: `b${i}` as ElementId, row: 0, col: 9 },
            ],
          }),
        ),
      },
    ],
  });
}

const titles = () =>
  page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    return s.project.pous.find((p) => p.id === s.activePouId)!.networks.map((n) => n.title);
  });
const selectedNos = () =>
  page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    const sel = new Set(window.rungsmith!.uiStore!.getState().networkSelection);
    return s.project.pous
      .find((p) => p.id === s.activePouId)!
      .networks.flatMap((n, i) => (sel.has(n.id) ? [i + 1] : []));
  });
const item = (i: number) => page.getByTestId(`outline-item-${i}`);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), plant());
  await page.getByTestId('network-header-1').waitFor();
  await page.getByTestId('tab-outline').click();
  await item(COUNT - 1).waitFor();
});

afterAll(async () => {
  await page.close();
});

test('a collapsed network is one header line: its title bar, no comment field, the next network right below', async () => {
  const header = page.getByTestId('network-header-0');
  const expanded = (await header.boundingBox())!;
  await page.getByRole('button', { name: 'Collapse network 1', exact: true }).click();
  await poll(async () => (await header.boundingBox())!.height).toBeLessThanOrEqual(COLLAPSED_HEADER_H);
  const collapsed = (await header.boundingBox())!;
  expect(collapsed.height).toBeLessThan(expanded.height);
  expect(await header.getByRole('textbox', { name: 'Comment of network 1' }).count()).toBe(0);
  // The comment is still there, as the header's tooltip.
  expect(await header.getAttribute('title')).toBe('Drives output 0');
  const next = (await page.getByTestId('network-header-1').boundingBox())!;
  // Title bar and a small gap: 72 px before.
  expect(next.y - collapsed.y).toBeLessThanOrEqual(COLLAPSED_HEADER_H + 4);
  expect(next.y - collapsed.y).toBeLessThan(72);
  await page.getByRole('button', { name: 'Expand network 1', exact: true }).click();
  await poll(async () => (await header.boundingBox())!.height).toBe(expanded.height);
  expect(errors).toEqual([]);
});

test('the outline follows the scroll: the network at the top of the view is marked and kept visible', async () => {
  // Scroll the canvas as a user does (its own scrollbar) so network `index` starts at the view's top.
  const reach = async (index: number) => {
    const { layout } = await new DrawPage(page).layout();
    await page.evaluate((top) => {
      const el = document.querySelector<HTMLElement>('[data-testid="ladder-canvas"]')!;
      el.scrollTop = top * window.rungsmith!.uiStore!.getState().viewport.zoom;
    }, layout.tops[index]!);
  };
  await reach(30);
  await poll(() => item(30).getAttribute('data-inview')).toBe('true');
  // Only one line is marked, and it is inside the outline's visible area.
  expect(await page.locator('[data-inview="true"]').count()).toBe(1);
  const visible = () =>
    item(30).evaluate((el) => {
      let box = el.parentElement;
      while (box && box.scrollHeight <= box.clientHeight) box = box.parentElement;
      if (!box) return true;
      const r = el.getBoundingClientRect();
      const b = box.getBoundingClientRect();
      return r.top >= b.top - 1 && r.bottom <= b.bottom + 1;
    });
  await poll(visible).toBe(true);
  await reach(2);
  await poll(() => item(2).getAttribute('data-inview')).toBe('true');
  expect(await item(30).getAttribute('data-inview')).toBeNull();
  expect(errors).toEqual([]);
});

test('Shift+click selects a range in the outline, Ctrl+click toggles, a drag moves the selection in one undo step', async () => {
  const before = await titles();
  await item(2).click();
  await item(4).click({ modifiers: ['Shift'] });
  expect(await selectedNos()).toEqual([3, 4, 5]);
  await item(6).click({ modifiers: ['Control'] });
  expect(await selectedNos()).toEqual([3, 4, 5, 7]);
  await item(6).click({ modifiers: ['Control'] });
  expect(await selectedNos()).toEqual([3, 4, 5]);
  expect(await item(3).getAttribute('aria-pressed')).toBe('true');

  // Drag the middle of the selection below network 10 (the lower half of its line).
  const target = (await item(9).boundingBox())!;
  await item(3).dragTo(item(9), { targetPosition: { x: target.width / 2, y: target.height * 0.8 } });
  const moved = ['Rung 1', 'Rung 2', 'Rung 6', 'Rung 7', 'Rung 8', 'Rung 9', 'Rung 10', 'Rung 3', 'Rung 4', 'Rung 5'];
  await poll(async () => (await titles()).slice(0, 10)).toEqual(moved);
  expect((await titles()).slice(10)).toEqual(before.slice(10));
  // One undo step brings the order back.
  await page.getByTestId('ladder-canvas').focus();
  await page.keyboard.press('Control+z');
  await poll(titles).toEqual(before);
  expect(errors).toEqual([]);
});

test('Ctrl+Shift+G extends the selection of networks to the network entered', async () => {
  await page.getByTestId('ladder-canvas').focus();
  await page.keyboard.press('Control+g');
  await page.getByTestId('goto-input').fill('5');
  await page.keyboard.press('Enter');
  expect(await selectedNos()).toEqual([5]);
  await page.keyboard.press('Control+Shift+g');
  const box = page.getByTestId('goto-box');
  expect(await box.getAttribute('aria-label')).toBe('Extend selection to network');
  await page.getByTestId('goto-input').fill('9');
  await page.keyboard.press('Enter');
  await box.waitFor({ state: 'detached' });
  expect(await selectedNos()).toEqual([5, 6, 7, 8, 9]);
  // Again, backwards from the same anchor: 2 to 5.
  await page.getByTestId('ladder-canvas').focus();
  await page.keyboard.press('Control+Shift+g');
  await page.getByTestId('goto-input').fill('2');
  await page.keyboard.press('Enter');
  expect(await selectedNos()).toEqual([2, 3, 4, 5]);
  expect(errors).toEqual([]);
});
