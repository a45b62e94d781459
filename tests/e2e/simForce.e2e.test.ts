// Forced variables are marked distinctly on the canvas (issue 4): an outline and an "F" tag in
// the theme's --forced colour on every element showing a forced variable, gone when unforced.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { CELL_H, cellRect, columnsOf } from '../../src/editor/canvas/geometry';
import { openApp, useChromium } from './appPage';
import { collectPageErrors } from './browser';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;

beforeAll(async () => {
  ({ page } = await openApp(browser()));
  sim = new SimPage(page);
});

/** Whether the cell's top-left corner shows the forced tag, read from the canvas pixels. */
async function forcedMark(network: number, row: number, col: number): Promise<boolean> {
  const centre = await sim.draw.cellPoint(network, row, col);
  const zoom = await page.evaluate(() => window.rungsmith!.uiStore!.getState().viewport.zoom);
  const { networks, layout } = await sim.draw.layout();
  const width = cellRect(columnsOf(layout, networks[network]!), { row, col }).width;
  // The tag covers content pixels 2..16 from the cell's corner; sample around (6, 6).
  const x = centre.x + (6 - width / 2) * zoom;
  const y = centre.y + (6 - CELL_H / 2) * zoom;
  return page.evaluate(
    ({ x, y }) => {
      const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="ladder-canvas"] canvas');
      if (!canvas) return false;
      const rect = canvas.getBoundingClientRect();
      const scale = canvas.width / rect.width;
      const data = canvas.getContext('2d')!.getImageData(Math.round((x - rect.left) * scale) - 2, Math.round((y - rect.top) * scale) - 2, 5, 5).data;
      const hex = getComputedStyle(document.documentElement).getPropertyValue('--forced').trim();
      const want = [1, 3, 5].map((i) => Number.parseInt(hex.slice(i, i + 2), 16));
      let hits = 0;
      for (let i = 0; i < data.length; i += 4) if (want.every((c, k) => Math.abs(data[i + k]! - c) < 30)) hits++;
      return hits >= 5;
    },
    { x, y },
  );
}

test('forcing the Motor coil marks the coil and the Motor contact on the canvas until it is unforced', async () => {
  const errors = collectPageErrors(page);
  await sim.runExample('Motor start/stop (seal-in)');
  // Coil Motor at (0, 9); its seal-in contact at (1, 0); Start at (0, 0) is not forced.
  expect(await forcedMark(0, 0, 9)).toBe(false);

  const coil = await sim.draw.cellPoint(0, 0, 9);
  await page.mouse.click(coil.x, coil.y, { button: 'right' });
  await page.getByTestId('sim-context-menu').getByRole('menuitem', { name: 'Force TRUE' }).click();
  await sim.waitForValue('Motor', true);
  await expect.poll(() => forcedMark(0, 0, 9)).toBe(true);
  expect(await forcedMark(0, 1, 0)).toBe(true);
  expect(await forcedMark(0, 0, 0)).toBe(false);
  expect(await forcedMark(0, 0, 1)).toBe(false);
  // Exactly that one variable is forced in the simulation.
  const forced = await page.evaluate(() => {
    const s = (window.rungsmith as unknown as { simStore: { getState(): { forced: Map<string, unknown> } } }).simStore.getState();
    return [...s.forced.keys()];
  });
  expect(forced).toEqual(['MOTOR']);

  await page.mouse.click(coil.x, coil.y, { button: 'right' });
  await page.getByTestId('sim-context-menu').getByRole('menuitem', { name: 'Unforce' }).click();
  await expect.poll(() => forcedMark(0, 0, 9)).toBe(false);
  expect(await forcedMark(0, 1, 0)).toBe(false);
  expect(errors).toEqual([]);
});

test('the forced colour is a theme colour, distinct from power flow, in light and dark themes', async () => {
  const colours = await page.evaluate(() => {
    const root = document.documentElement;
    const before = root.getAttribute('data-theme');
    const read = (theme: string) => {
      root.setAttribute('data-theme', theme);
      const s = getComputedStyle(root);
      return { forced: s.getPropertyValue('--forced').trim(), energised: s.getPropertyValue('--canvas-energised').trim(), error: s.getPropertyValue('--canvas-error').trim() };
    };
    const out = { light: read('light'), dark: read('dark') };
    if (before === null) root.removeAttribute('data-theme');
    else root.setAttribute('data-theme', before);
    return out;
  });
  for (const theme of [colours.light, colours.dark]) {
    expect(theme.forced).toMatch(/^#[0-9a-f]{6}$/i);
    expect(theme.forced).not.toBe(theme.energised);
    expect(theme.forced).not.toBe(theme.error);
  }
  expect(colours.light.forced).not.toBe(colours.dark.forced);
});
