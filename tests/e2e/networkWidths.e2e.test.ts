// An imported POU whose networks have different widths, in a real Chromium: each network's right
// rail at its own width, comments and titles shown whole, and placing past a network's right rail
// widens only that network.
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
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
  const text = await readFile(
    fileURLToPath(new URL('../fixtures/plcopen/corpus/godardhi0__dancinglights.xml', import.meta.url)),
    'utf8',
  );
  await editor.chooseFile('File', 'Import PLCopen XML…', { name: 'dancinglights.xml', mimeType: 'application/xml', text });
  const report = page.getByTestId('plcopen-report');
  await report.waitFor();
  await report.getByRole('button', { name: 'Open' }).click();
  await report.waitFor({ state: 'detached' });
  await page.waitForFunction(
    () => window.rungsmith!.documentStore!.getState().project.pous[0]?.networks.length === 15,
  );
});

/** The drawn grids (Konva shapes, one per network on screen): left edge, top and width. */
const grids = () =>
  page.evaluate(() => {
    const k = (window as unknown as { Konva: { stages: { find(s: string): { x(): number; y(): number; width(): number }[] }[] } })
      .Konva;
    return k.stages[0]!.find('Shape')
      .map((s) => ({ x: s.x(), y: s.y(), width: s.width() }))
      .sort((a, b) => a.y - b.y);
  });

test('the narrow network’s right rail stands left of the wide one’s', async () => {
  const nets = await draw.networks();
  // Network 1 needs 3 columns, network 2 needs 9: each is drawn at its own width.
  expect(nets[0]!.cols).toBe(3);
  expect(nets[1]!.cols).toBe(9);
  const [first, second] = await grids();
  expect(first!.x).toBe(second!.x);
  expect(first!.x + first!.width).toBeLessThan(second!.x + second!.width - 200);
  expect(editor.errors).toEqual([]);
});

test('a comment of five lines is shown whole; a long title too, after the user types it', async () => {
  const nets = await draw.networks();
  const comment = page.getByTestId(`network-comment-${nets[1]!.id}`);
  expect((await comment.inputValue()).split('\n')).toHaveLength(5);
  const hidden = (testId: string) =>
    page.getByTestId(testId).evaluate((el: HTMLInputElement | HTMLTextAreaElement) => ({
      rows: el.scrollHeight - el.clientHeight,
      cols: el.scrollWidth - el.clientWidth,
    }));
  expect(await hidden(`network-comment-${nets[1]!.id}`)).toEqual({ rows: 0, cols: 0 });

  const title = page.getByTestId(`network-title-${nets[0]!.id}`);
  const long = 'Memorise the stop request until the cycle has finished its last step';
  await title.click();
  await title.fill(long);
  await page.keyboard.press('Enter');
  await poll(async () => (await draw.networks())[0]!.title).toBe(long);
  await poll(() => hidden(`network-title-${nets[0]!.id}`)).toEqual({ rows: 0, cols: 0 });
  // The header's buttons stay inside it.
  const inside = await page.getByTestId('network-header-0').evaluate((h) => {
    const r = h.getBoundingClientRect();
    return [...h.querySelectorAll('button')].every((b) => b.getBoundingClientRect().right <= r.right + 0.5);
  });
  expect(inside).toBe(true);

  // A long comment line typed into network 1 wraps; every line stays visible.
  const c1 = page.getByTestId(`network-comment-${nets[0]!.id}`);
  await c1.click();
  await c1.fill(`${'The stop button is remembered here so that the cycle can end cleanly. '.repeat(5)}\nSecond paragraph.`);
  await page.keyboard.press('Enter');
  await poll(async () => (await draw.networks())[0]!.comment).toContain('Second paragraph.');
  await poll(() => hidden(`network-comment-${nets[0]!.id}`)).toEqual({ rows: 0, cols: 0 });
  // The grid moved down below the taller header.
  const header = await page.getByTestId('network-header-0').boundingBox();
  const c1box = await c1.boundingBox();
  expect(c1box!.y + c1box!.height).toBeLessThanOrEqual(header!.y + header!.height + 1);
  expect(editor.errors).toEqual([]);
});

test('placing a contact just past the narrow network’s right rail widens that network only', async () => {
  const before = (await draw.networks()).map((n) => n.cols);
  await draw.pickPalette('contact-NO');
  await draw.clickCell(0, 0, before[0]!);
  await draw.typeName('Extra');
  await draw.pickPalette('select');
  const after = (await draw.networks()).map((n) => n.cols);
  expect(after[0]).toBe(before[0]! + 1);
  expect(after.slice(1)).toEqual(before.slice(1));
  const [first, second] = await grids();
  expect(first!.x + first!.width).toBeLessThan(second!.x + second!.width);
  expect(editor.errors).toEqual([]);
});
