// Canvas gestures added on review of the editor issue: dragging elements into another network (one
// undo step), two-finger pinch zoom on a touch screen, and Enter on an unchanged name in the
// inline editor moving on like a commit.
import { afterAll, beforeAll, beforeEach, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import { APP_VIEWPORT, appUrl, openApp, useChromium, waitForApp } from './appPage';
import { collectPageErrors } from './browser';
import { DrawPage } from './drawPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  draw = new DrawPage(page);
});

beforeEach(async () => {
  await page.evaluate(() => {
    const doc = window.rungsmith!.documentStore!.getState();
    doc.newProject('Gaps');
    doc.addNetwork();
  });
});

afterAll(() => {
  expect(errors).toEqual([]);
});

/**
 * Drags with the mouse from one cell to another in small steps, like a hand would. Once a drag has
 * begun every network shows an empty row to drop on, so the target is aimed at as it is then shown.
 */
async function dragCell(from: [number, number, number], to: [number, number, number]) {
  const a = await draw.cellPoint(...from);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move(a.x + 12, a.y + 12, { steps: 3 });
  await page.waitForFunction(() => window.rungsmith!.uiStore!.getState().dragging);
  const b = await draw.cellPoint(...to);
  await page.mouse.move(a.x + (b.x - a.x) / 3, a.y + (b.y - a.y) / 3, { steps: 4 });
  await page.mouse.move(b.x, b.y, { steps: 6 });
  await page.mouse.up();
}

test('dragging a contact into the next network moves it there, and one undo brings it back', async () => {
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('Start');
  await dragCell([0, 0, 0], [1, 0, 2]);

  expect(await draw.elements(0)).toEqual([]);
  expect(await draw.elements(1)).toEqual([{ kind: 'contact', row: 0, col: 2, name: 'Start', type: 'NO' }]);
  // The moved contact stays selected, in its new network.
  const selection = await page.evaluate(() => {
    const ui = window.rungsmith!.uiStore!.getState();
    const doc = window.rungsmith!.documentStore!.getState();
    const nets = doc.project.pous[0]!.networks;
    return {
      network: nets.findIndex((n) => n.id === ui.selection.network),
      count: ui.selection.elements.length,
    };
  });
  expect(selection).toEqual({ network: 1, count: 1 });

  await page.keyboard.press('Control+z');
  expect(await draw.elements(0)).toEqual([{ kind: 'contact', row: 0, col: 0, name: 'Start', type: 'NO' }]);
  expect(await draw.elements(1)).toEqual([]);
  await page.keyboard.press('Control+y');
  expect(await draw.elements(1)).toEqual([{ kind: 'contact', row: 0, col: 2, name: 'Start', type: 'NO' }]);
});

test('holding a drag at the bottom edge scrolls the canvas to a network that was off screen', async () => {
  await page.evaluate(() => {
    const doc = window.rungsmith!.documentStore!.getState();
    for (let i = 0; i < 8; i++) doc.addNetwork({ rows: 3 });
  });
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('Start');
  const a = await draw.cellPoint(0, 0, 0);
  const box = (await draw.canvas().boundingBox())!;
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move(a.x + 10, a.y + 40, { steps: 3 });
  // Rest near the bottom edge until the canvas has scrolled well down.
  await page.mouse.move(a.x + 10, box.y + box.height - 6, { steps: 4 });
  await page.waitForFunction(
    () => document.querySelector<HTMLElement>('[data-testid="ladder-canvas"]')!.scrollTop > 900,
  );
  // Away from the edge (still dragging) the scrolling stops; wait until it has, so the drop point
  // measured below is where the pointer lands.
  await page.mouse.move(a.x + 10, box.y + box.height / 2, { steps: 2 });
  await draw.waitScrollStill();
  // Drop on the first network whose grid is now in view, far below where the drag began.
  const target = await page.evaluate(() => {
    const el = document.querySelector<HTMLElement>('[data-testid="ladder-canvas"]')!;
    const z = window.rungsmith!.uiStore!.getState().viewport.zoom;
    const headers = [...document.querySelectorAll<HTMLElement>('[data-testid^="network-header-"]')];
    const visible = headers
      .map((h) => ({ index: Number(h.dataset.testid!.split('-').pop()), top: h.offsetTop * z }))
      .filter((h) => h.top > el.scrollTop + 20 && h.top < el.scrollTop + el.clientHeight - 260)
      .sort((x, y) => x.index - y.index);
    return visible[0]!.index;
  });
  expect(target).toBeGreaterThanOrEqual(3);
  const b = await draw.cellPoint(target, 1, 1);
  await page.mouse.move(b.x, b.y, { steps: 4 });
  await page.mouse.up();
  expect(await draw.elements(0)).toEqual([]);
  expect(await draw.elements(target)).toEqual([
    { kind: 'contact', row: 1, col: 1, name: 'Start', type: 'NO' },
  ]);
});

test('a drag onto an occupied cell of another network is refused and changes nothing', async () => {
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('Start');
  await draw.clickCell(1, 0, 1);
  await page.keyboard.press('o');
  await draw.typeName('Motor');
  await dragCell([0, 0, 0], [1, 0, 1]);

  expect(await draw.elements(0)).toEqual([{ kind: 'contact', row: 0, col: 0, name: 'Start', type: 'NO' }]);
  expect(await draw.elements(1)).toEqual([{ kind: 'coil', row: 0, col: 1, name: 'Motor', type: 'COIL' }]);
  await expect.poll(() => page.getByTestId('status-bar').textContent()).toContain('in the way');
});

test('Enter on an unchanged name closes the name field and moves the cursor on', async () => {
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('Start');
  const history = () => page.evaluate(() => window.rungsmith!.documentStore!.getState().history.undo.length);
  const steps = await history();
  // Back onto the contact, open its name field and confirm it unchanged.
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('Enter');
  const input = page.getByTestId('inline-editor');
  await input.waitFor();
  expect(await input.inputValue()).toBe('Start');
  await page.keyboard.press('Enter');
  await input.waitFor({ state: 'detached' });
  const cursor = await page.evaluate(() => window.rungsmith!.uiStore!.getState().cursor);
  expect(cursor).toMatchObject({ row: 0, col: 1 });
  // Nothing entered the history for the unchanged name.
  expect(await history()).toBe(steps);
  // The canvas has the keyboard again: a letter places the next element at the cursor.
  await page.keyboard.press('o');
  await draw.typeName('Motor');
  expect((await draw.elements(0)).map((e) => e.kind)).toEqual(['contact', 'coil']);
});

test('two fingers spreading on a touch screen zoom the canvas in, pinching zooms out', async () => {
  const touchPage = await browser().newPage({ viewport: APP_VIEWPORT, hasTouch: true });
  const touchErrors = collectPageErrors(touchPage);
  await touchPage.goto(appUrl());
  await waitForApp(touchPage);
  const box = (await touchPage.getByTestId('ladder-canvas').boundingBox())!;
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  const cdp = await touchPage.context().newCDPSession(touchPage);
  const fingers = (spread: number) => [
    { x: cx - spread, y: cy, id: 1 },
    { x: cx + spread, y: cy, id: 2 },
  ];
  const zoom = () => touchPage.evaluate(() => window.rungsmith!.uiStore!.getState().viewport.zoom);
  const pinch = async (from: number, to: number) => {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: fingers(from) });
    for (let k = 1; k <= 8; k++)
      await cdp.send('Input.dispatchTouchEvent', {
        type: 'touchMove',
        touchPoints: fingers(from + ((to - from) * k) / 8),
      });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  };

  expect(await zoom()).toBe(1);
  await pinch(60, 120);
  await expect.poll(zoom).toBeGreaterThan(1.6);
  await pinch(120, 60);
  await expect.poll(zoom).toBeLessThan(1.2);
  // The page itself never zoomed: only the canvas did.
  expect(await touchPage.evaluate(() => window.visualViewport?.scale ?? 1)).toBe(1);
  expect(touchErrors).toEqual([]);
  await touchPage.close();
});
