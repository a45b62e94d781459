// Monitoring without hunting (issue 24), in a real Chromium against the real server: values beside
// every box pin while the program runs (a TON's PT given a variable, an ADD fed by the TON's ET over
// a wire), clear of the operand names, and an older value on a recorded scan; then the watch list:
// completion of an instance member as it is typed (picked with the keyboard), W on the canvas adds
// the cursor's variable, and the list is still there after a reload. The canvas is read through its
// drawing calls (recorded in the page), not screenshots.
import type { Page } from 'playwright-core';
import { expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { ladder, project, vars } from '../engine/ladder';
import { collectPageErrors } from './browser';
import { APP_VIEWPORT, appUrl, useChromium, waitForApp } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let errors: string[];
let sim: SimPage;

/** Records every fillText of every 2D context: the text and its box in the canvas's device pixels. */
function recordTexts() {
  interface Drawn {
    canvas: number;
    text: string;
    x1: number;
    x2: number;
    y1: number;
    y2: number;
  }
  const w = window as unknown as { __texts: Drawn[] };
  w.__texts = [];
  const ids = new WeakMap<object, number>();
  let next = 1;
  const P = CanvasRenderingContext2D.prototype;
  const fillText = P.fillText;
  P.fillText = function (this: CanvasRenderingContext2D, text: string, x: number, y: number, maxWidth?: number) {
    let id = ids.get(this.canvas);
    if (id === undefined) ids.set(this.canvas, (id = next++));
    const m = this.measureText(text);
    const t = this.getTransform();
    const scale = maxWidth !== undefined && m.width > maxWidth ? maxWidth / m.width : 1;
    const left = x - m.actualBoundingBoxLeft * scale;
    const right = x + m.actualBoundingBoxRight * scale;
    w.__texts.push({
      canvas: id,
      text,
      x1: t.a * left + t.e,
      x2: t.a * right + t.e,
      y1: t.d * (y - m.actualBoundingBoxAscent) + t.f,
      y2: t.d * (y + m.actualBoundingBoxDescent) + t.f,
    });
    if (w.__texts.length > 20_000) w.__texts.splice(0, 10_000);
    return maxWidth === undefined ? fillText.call(this, text, x, y) : fillText.call(this, text, x, y, maxWidth);
  };
}

interface Drawn {
  canvas: number;
  text: string;
  x1: number;
  x2: number;
  y1: number;
  y2: number;
}

/** The texts drawn since the last call (then forgotten). */
const drawnSince = (): Promise<Drawn[]> =>
  page.evaluate(() => {
    const w = window as unknown as { __texts: Drawn[] };
    const out = w.__texts;
    w.__texts = [];
    return out;
  });

/** T#1s230ms -> 1230 (the canvas's TIME values). */
function timeMs(text: string): number {
  const m = /^T#(?:(\d+)m)?(?:(\d+)s)?(?:(\d+)ms)?$/.exec(text);
  if (!m || text === 'T#') return NaN;
  return Number(m[1] ?? 0) * 60_000 + Number(m[2] ?? 0) * 1000 + Number(m[3] ?? 0);
}

/**
 * Network 1: Start (%IX0.0) -> TON T1 with PT the variable Preset; T1.ET over a wire into ADD.IN1,
 * ADD.IN2 the variable Offset, ADD.OUT to Total.
 */
function timerAdd(): Project {
  return {
    ...project(vars('Start BOOL %IX0.0', 'Preset TIME := T#10s', 'Offset TIME := T#1s', 'Total TIME', 'T1 TON'), [
      ladder(['- [Start] # # . # # .', '. . # # - # # .', '. . . . . # # .'], {
        boxes: [
          { row: 0, col: 2, type: 'TON', instance: 'T1', inputs: { PT: 'Preset' }, outputs: {} },
          { row: 0, col: 5, type: 'ADD', inputs: { IN2: 'Offset' }, outputs: { OUT: 'Total' } },
        ],
      }),
    ]),
    name: 'Monitoring',
  };
}

const overlaps = (a: Drawn, b: Drawn) => a.x1 < b.x2 && b.x1 < a.x2 && a.y1 < b.y2 && b.y1 < a.y2;

/** The latest drawing of the network (one canvas) that shows `want`, polled until it does. */
async function drawingWith(want: (texts: Drawn[]) => boolean): Promise<Drawn[]> {
  let found: Drawn[] = [];
  await expect
    .poll(
      async () => {
        const drawn = await drawnSince();
        const byCanvas = new Map<number, Drawn[]>();
        for (const d of drawn) byCanvas.set(d.canvas, [...(byCanvas.get(d.canvas) ?? []), d]);
        for (const list of byCanvas.values()) {
          // The last complete pass: from the last drawing of the block name TON on.
          const start = list.map((d) => d.text).lastIndexOf('TON');
          const pass = start >= 0 ? list.slice(start) : [];
          if (want(pass)) found = pass;
        }
        return found.length > 0;
      },
      { timeout: 30_000, interval: 100 },
    )
    .toBe(true);
  return found;
}

test('values beside the pins while running, clear of the names, and an older value on a recorded scan', async () => {
  page = await browser().newPage({ viewport: APP_VIEWPORT });
  errors = collectPageErrors(page);
  await page.addInitScript(recordTexts);
  await page.goto(appUrl());
  await waitForApp(page);
  sim = new SimPage(page);
  await sim.load(timerAdd());
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.switchCell(0, 0, 1); // Start ON: T1 times
  await expect.poll(async () => Number(await sim.value('T1.ET')), { timeout: 30_000 }).toBeGreaterThan(300);

  // PT shows Preset's value, IN2 Offset's, IN1 the time that flowed on the wire from T1.ET.
  const live = await drawingWith((texts) => texts.some((d) => d.text === 'T#10s') && texts.some((d) => d.text === 'T#1s') && texts.filter((d) => timeMs(d.text) > 0 && d.text !== 'T#10s' && d.text !== 'T#1s').length >= 2);
  const names = live.filter((d) => ['Preset', 'Offset', 'Total', 'T1', 'PT', 'IN1', 'IN2', 'ET', 'OUT'].includes(d.text));
  const values = live.filter((d) => d.text.startsWith('T#'));
  expect(names.map((d) => d.text)).toEqual(expect.arrayContaining(['Preset', 'Offset', 'Total']));
  for (const v of values) for (const n of names) expect(overlaps(v, n), `${v.text} over ${n.text}`).toBe(false);

  // Pause, then back through the history: the wire into ADD.IN1 shows that scan's (older) time.
  await sim.button('pause').click();
  await sim.waitForMode('Paused');
  const pausedEt = Number(await sim.value('T1.ET'));
  // One scan back at a time, each shown before the next (five quick clicks could leave the value read
  // below from a scan the view then moved on from).
  const marker = page.getByTestId('history-marker');
  for (let i = 0; i < 5; i++) {
    const before = await marker.getAttribute('title');
    await page.getByTestId('history-prev').click();
    await expect.poll(() => marker.getAttribute('title')).not.toBe(before);
  }
  await marker.filter({ hasText: 'HISTORY' }).waitFor();
  await expect.poll(async () => Number(await sim.value('T1.ET'))).toBeLessThan(pausedEt);
  const olderEt = Number(await sim.value('T1.ET'));
  // The wire's value at ADD.IN1 (ET's, left of the ADD box) and ET's own value are that scan's.
  const older = await drawingWith((texts) => texts.filter((d) => timeMs(d.text) === olderEt).length >= 1);
  expect(older.some((d) => timeMs(d.text) === olderEt)).toBe(true);
  expect(older.some((d) => timeMs(d.text) === pausedEt)).toBe(false);
  expect(errors).toEqual([]);
});

test('watch: an instance member completed as it is typed, W on the canvas, the list kept over a reload', async () => {
  await page.getByTestId('history-live').click();
  await sim.tab('Watch');
  const field = page.getByTestId('watch-add-name');
  await field.fill('T1.');
  const choices = page.getByTestId('watch-choices');
  await expect.poll(() => choices.getByTestId('watch-choice').allTextContents()).toEqual(['T1.ET', 'T1.IN', 'T1.PT', 'T1.Q']);
  // ↓ ↓ Enter: the second completion is watched.
  await field.press('ArrowDown');
  await field.press('ArrowDown');
  await expect.poll(() => choices.locator('[aria-selected="true"]').textContent()).toBe('T1.IN');
  await field.press('Enter');
  const row = page.getByTestId('watch-row-T1.IN');
  await row.waitFor();
  await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('TRUE');
  expect(await field.inputValue()).toBe('');

  // W on the canvas: the variable of the element under the cursor (the Start contact).
  await sim.draw.clickCell(0, 0, 1);
  await page.keyboard.press('w');
  const start = page.getByTestId('watch-row-Start');
  await start.waitFor();
  await expect.poll(() => start.getByTestId('watch-value').textContent()).toBe('TRUE');

  // The list is the project's: after a reload (the autosave brings the project back) it is there.
  await page.reload();
  await waitForApp(page);
  await page.getByTestId('project-name').filter({ hasText: 'Monitoring' }).waitFor({ timeout: 15_000 });
  await sim.tab('Watch');
  await page.getByTestId('watch-row-T1.IN').waitFor();
  await page.getByTestId('watch-row-Start').waitFor();
  expect(await page.locator('[data-testid^="watch-row-"]').count()).toBe(2);
  expect(errors).toEqual([]);
  await page.close();
});
