// Rough edges of the editor in a real Chromium: a real double-click on a contact opens its name
// editor; a box dragged or pasted onto the first column is wired like a box placed there (only its
// power-flow input from the rail).
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();
let editor: EditorPage;
let page: Page;
let draw: DrawPage;

beforeAll(async () => {
  editor = await EditorPage.open(browser());
  page = editor.page;
  draw = new DrawPage(page);
});

type Placed = [row: number, col: number, template: Record<string, unknown>];

/** A fresh project: its first network holds `first` (placed through the document store), then `more` empty networks. */
async function fresh(first: Placed[], more = 0) {
  await page.evaluate(
    ({ first, more }) => {
      const s = window.rungsmith!.documentStore!;
      s.getState().newProject('Edges');
      const net = s.getState().project.pous[0]!.networks[0]!.id;
      for (const [row, col, t] of first)
        s.getState().placeElement(net, { row, col }, t as Parameters<ReturnType<typeof s.getState>['placeElement']>[2]);
      for (let i = 0; i < more; i++) s.getState().addNetwork();
    },
    { first, more },
  );
}

const TON = { kind: 'box', blockType: 'TON', instance: 'T1', inputs: {}, outputs: {} };

test('a double-click on a contact opens its name editor, Enter renames it', async () => {
  await fresh([
    [0, 0, { kind: 'contact', contact: 'NO', variable: 'Start' }],
    [0, 1, { kind: 'coil', coil: 'COIL', variable: 'Lamp' }],
  ]);
  const p = await draw.cellPoint(0, 0, 0);
  await page.mouse.dblclick(p.x, p.y);
  const input = page.getByTestId('inline-editor');
  await input.waitFor();
  expect(await input.inputValue()).toBe('Start');
  await input.fill('Go');
  await page.keyboard.press('Enter');
  await input.waitFor({ state: 'detached' });
  expect((await draw.elements(0))[0]).toMatchObject({ kind: 'contact', name: 'Go' });

  // The coil too; a double-click on an empty cell opens nothing.
  const coil = await draw.cellPoint(0, 0, 1);
  await page.mouse.dblclick(coil.x, coil.y);
  await input.waitFor();
  expect(await input.inputValue()).toBe('Lamp');
  await page.keyboard.press('Escape');
  await input.waitFor({ state: 'detached' });
  const empty = await draw.cellPoint(0, 2, 3);
  await page.mouse.dblclick(empty.x, empty.y);
  await page.waitForTimeout(200);
  expect(await input.count()).toBe(0);
  expect(editor.errors).toEqual([]);
});

test('a TON dragged onto the first column goes right of the rail, fed from the rail on IN only', async () => {
  await fresh([[0, 3, TON]]);
  expect(await draw.elements(0)).toEqual([{ kind: 'box', row: 0, col: 3 }]);
  const from = await draw.cellPoint(0, 0, 3);
  const to = await draw.cellPoint(0, 0, 0);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move((from.x + to.x) / 2, from.y, { steps: 4 });
  await page.mouse.move(to.x, to.y, { steps: 4 });
  await page.mouse.up();
  await poll(() => draw.elements(0)).toEqual([
    { kind: 'link', row: 0, col: 0 },
    { kind: 'box', row: 0, col: 1 },
  ]);
  expect(editor.errors).toEqual([]);
});

test('a TON copied and pasted onto the first column of another network is wired the same way', async () => {
  await fresh([[0, 3, TON]], 1);
  await draw.clickCell(0, 0, 3);
  await page.keyboard.press('Control+c');
  await draw.clickCell(1, 0, 0);
  await page.keyboard.press('Control+v');
  await poll(() => draw.elements(1)).toEqual([
    { kind: 'link', row: 0, col: 0 },
    { kind: 'box', row: 0, col: 1 },
  ]);
  expect(editor.errors).toEqual([]);
});
