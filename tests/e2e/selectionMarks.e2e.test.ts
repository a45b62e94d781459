// The selection, the keyboard cursor and the cell under the pointer are drawn over the canvas by
// page elements (SelectionMarks.tsx, so a click redraws no network picture): checked on what the
// user sees, the page's screenshot: the clicked contact is framed in the selection colour and the
// one selected before is not any more; the arrow keys move the cursor's frame (cursor colour) from
// cell to cell; on a box the selection frames the whole box; the marks follow the canvas's zoom.
import { afterAll, beforeAll, expect, test } from 'vitest';
import { CELL_H, cellRect, columnsOf, headerHeight, RAIL_X } from '../../src/editor/canvas/geometry';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();
let editor: EditorPage;
let draw: DrawPage;

const v = (name: string, type = 'BOOL'): Variable => ({ name, type, varClass: 'local', retain: false, comment: '' });
const e = (s: string) => s as ElementId;

function machine(): Project {
  const main = newPou('Main');
  return newProject('Marks', {
    pous: [
      {
        ...main,
        variables: [v('Start'), v('Stop'), v('Motor'), v('Jog'), v('Lamp'), v('Delay', 'TON')],
        networks: [
          newNetwork({
            title: 'Motor',
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Start', id: e('a'), row: 0, col: 0 },
              { kind: 'contact', contact: 'NC', variable: 'Stop', id: e('b'), row: 0, col: 1 },
              { kind: 'coil', coil: 'COIL', variable: 'Motor', id: e('c'), row: 0, col: 9 },
            ],
          }),
          newNetwork({
            title: 'Lamp',
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Jog', id: e('d'), row: 0, col: 0 },
              { kind: 'box', blockType: 'TON', instance: 'Delay', id: e('t'), row: 0, col: 1, inputs: { PT: 'T#1s' }, outputs: {} },
              { kind: 'coil', coil: 'COIL', variable: 'Lamp', id: e('f'), row: 0, col: 9 },
            ],
          }),
        ],
      },
    ],
  });
}

type Box = { x: number; y: number; width: number; height: number };

/** Screen rectangle of an element's cells (network `index`, its row and column span). */
async function elementBox(index: number, row: number, col: number, cols = 1, rows = 1): Promise<Box> {
  const { networks, layout } = await draw.layout();
  const n = networks[index]!;
  const r = cellRect(columnsOf(layout, n), { row, col }, cols, rows, layout.pitches[index] ?? CELL_H);
  const topLeft = await draw.screenPoint({ x: RAIL_X + r.x, y: layout.tops[index]! + headerHeight(n) + r.y });
  const zoom = await editor.page.evaluate(() => window.rungsmith!.uiStore!.getState().viewport.zoom);
  return { x: topLeft.x, y: topLeft.y, width: r.width * zoom, height: r.height * zoom };
}

/** How many pixels of the screenshot of `box` have `colour` (a CSS colour of the theme), as the user sees them. */
async function pixelsOf(box: Box, cssVar: string): Promise<number> {
  const png = await editor.page.screenshot({
    clip: { x: Math.round(box.x), y: Math.round(box.y), width: Math.round(box.width), height: Math.round(box.height) },
  });
  return editor.page.evaluate(
    async ({ b64, cssVar }) => {
      const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
      const image = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
      const canvas = new OffscreenCanvas(image.width, image.height);
      const ctx = canvas.getContext('2d')!;
      ctx.drawImage(image, 0, 0);
      const data = ctx.getImageData(0, 0, image.width, image.height).data;
      // The theme's colour as the page computes it.
      const probe = document.createElement('div');
      probe.style.color = `var(${cssVar})`;
      document.body.append(probe);
      const [r, g, b] = getComputedStyle(probe).color.match(/\d+/g)!.map(Number);
      probe.remove();
      let count = 0;
      for (let i = 0; i < data.length; i += 4)
        if (Math.abs(data[i]! - r!) <= 12 && Math.abs(data[i + 1]! - g!) <= 12 && Math.abs(data[i + 2]! - b!) <= 12) count++;
      return count;
    },
    { b64: png.toString('base64'), cssVar },
  );
}

const selected = () => editor.page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements);
const selectionMarks = () => editor.page.getByTestId('canvas-selection-mark').count();

beforeAll(async () => {
  editor = await EditorPage.open(browser());
  draw = new DrawPage(editor.page);
  await editor.page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), machine());
  await editor.page.getByTestId('network-header-1').waitFor();
  // The pointer away from the grid: no cell under it.
  await editor.page.mouse.move(1, 1);
});

afterAll(async () => {
  await editor.close();
});

test('a click frames the clicked contact in the selection colour, and the one selected before no longer', async () => {
  const a = await elementBox(0, 0, 0);
  const b = await elementBox(0, 0, 1);
  expect(await pixelsOf(a, '--canvas-selection')).toBe(0);
  expect(await pixelsOf(b, '--canvas-selection')).toBe(0);

  await draw.clickCell(0, 0, 0);
  await poll(selected).toEqual(['a']);
  await poll(() => pixelsOf(a, '--canvas-selection')).toBeGreaterThan(40);
  expect(await pixelsOf(b, '--canvas-selection')).toBe(0);
  expect(await selectionMarks()).toBe(1);

  await draw.clickCell(0, 0, 1);
  await poll(selected).toEqual(['b']);
  await poll(() => pixelsOf(a, '--canvas-selection')).toBe(0);
  expect(await pixelsOf(b, '--canvas-selection')).toBeGreaterThan(40);
  expect(await selectionMarks()).toBe(1);

  // A click on an empty cell selects nothing and frames nothing.
  await draw.clickCell(0, 0, 5);
  await poll(selected).toEqual([]);
  await poll(() => pixelsOf(b, '--canvas-selection')).toBe(0);
  expect(await selectionMarks()).toBe(0);
});

test('the arrow keys move the cursor frame from cell to cell; on a box the selection frames the whole box', async () => {
  await draw.clickCell(1, 0, 0);
  await poll(selected).toEqual(['d']);
  const d = await elementBox(1, 0, 0);
  await poll(() => pixelsOf(d, '--canvas-cursor')).toBeGreaterThan(40);

  await editor.page.keyboard.press('ArrowRight');
  await poll(() => editor.page.evaluate(() => window.rungsmith!.uiStore!.getState().cursor?.col)).toBe(1);
  await poll(() => pixelsOf(d, '--canvas-cursor')).toBe(0);
  // The TON is two columns wide and several rows tall: the frames go round all of it.
  const ton = await editor.page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    return s.project.pous[0]!.networks[1]!.elements.find((el) => el.kind === 'box')!.id;
  });
  await poll(selected).toEqual([ton]);
  const mark = await editor.page.getByTestId('canvas-selection-mark').boundingBox();
  const cursorMark = await editor.page.getByTestId('canvas-cursor-mark').boundingBox();
  const cell = await elementBox(1, 0, 1);
  expect(mark!.width).toBeGreaterThan(cell.width * 1.5);
  expect(mark!.height).toBeGreaterThan(cell.height * 1.5);
  expect(cursorMark!.width).toBeGreaterThan(cell.width * 1.5);
  // Its right part, a cell away from where the cursor stands, shows the selection colour too.
  const right = await elementBox(1, 0, 2);
  expect(await pixelsOf(right, '--canvas-selection')).toBeGreaterThan(20);
});

test('the marks follow the zoom: after zooming in the clicked contact is still the one framed', async () => {
  await editor.page.evaluate(() => window.rungsmith!.uiStore!.getState().setZoom(1.5));
  await poll(() => editor.page.evaluate(() => window.rungsmith!.uiStore!.getState().viewport.zoom)).toBe(1.5);
  await draw.clickCell(0, 0, 0);
  await poll(selected).toEqual(['a']);
  const a = await elementBox(0, 0, 0);
  const b = await elementBox(0, 0, 1);
  await poll(() => pixelsOf(a, '--canvas-selection')).toBeGreaterThan(60);
  expect(await pixelsOf(b, '--canvas-selection')).toBe(0);
  const mark = (await editor.page.getByTestId('canvas-selection-mark').boundingBox())!;
  // The frame sits on the contact's cell (within the cell, scaled with it).
  expect(mark.x).toBeGreaterThanOrEqual(a.x - 3);
  expect(mark.x + mark.width).toBeLessThanOrEqual(a.x + a.width + 3);
  expect(mark.width).toBeGreaterThan(a.width * 0.8);
});
