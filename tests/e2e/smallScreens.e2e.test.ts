// At 1440×900 and at 1280×720 nothing overflows the window and each panel's main content is
// readable: the canvas keeps most of the height (the bottom panel is not a mostly empty 190 px),
// the scan history is one row whose controls do not overlap, the palette's names and the variable
// table's long names and types are whole, the Watch value of a timer is whole, the scenario editor
// shows several rows of its scenario, and the online-change dialog's text is inside the dialog. Screenshots of each
// size are written to $RS_SHOTS (default: the OS temp dir) to look at.
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import type { Locator, Page } from 'playwright-core';
import { afterEach, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page | undefined;
const SHOTS = process.env.RS_SHOTS ?? tmpdir();

afterEach(async () => {
  await page?.close();
  page = undefined;
});

/** Text inside an element fits it (nothing cut by an ellipsis or clipped). */
const whole = (l: Locator) => l.evaluate((el) => el.scrollWidth <= el.clientWidth + 1);
const pageFits = (p: Page) => p.evaluate(() => document.documentElement.scrollWidth <= innerWidth && document.documentElement.scrollHeight <= innerHeight);

for (const viewport of [{ width: 1440, height: 900 }, { width: 1280, height: 720 }]) {
  const size = `${viewport.width}x${viewport.height}`;

  test(`${size}: nothing overflows; canvas, history row, palette, variables, watch and scenario editor readable`, async () => {
    const app = await openApp(browser());
    page = app.page;
    await page.setViewportSize(viewport);
    const sim = new SimPage(page);
    await sim.openExample('Traffic light (TON chain)');
    // Names as long as a real plant's, declared in the program.
    await page.evaluate(() => {
      const s = window.rungsmith!.documentStore!.getState();
      s.addVariable({ name: 'BottleInPositionSensor', type: 'BOOL', varClass: 'local', retain: false, comment: 'Bottle under the filler' });
      s.addVariable({ name: 'FillValveOpenTimer', type: 'TON', varClass: 'local', retain: false, comment: '' });
    });
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await page.waitForTimeout(700);
    await sim.button('pause').click();
    await sim.waitForMode('Paused');
    expect(await pageFits(page)).toBe(true);

    // The canvas has most of the height; the bottom panel is a strip, not a third of the window.
    const canvas = (await page.getByTestId('ladder-canvas').boundingBox())!;
    const bottom = (await page.locator('.rs-bottom').boundingBox())!;
    expect(canvas.height).toBeGreaterThan(viewport.height * 0.45);
    expect(bottom.height).toBeLessThanOrEqual(170);

    // The scan history: one row, each control whole and none over another.
    const timeline = page.getByTestId('timeline');
    const row = (await timeline.boundingBox())!;
    expect(row.height).toBeLessThan(44);
    const parts = await timeline.locator('button, input').all();
    const boxes = [];
    for (const part of parts) boxes.push((await part.boundingBox())!);
    for (const b of boxes) {
      expect(b.x).toBeGreaterThanOrEqual(row.x - 1);
      expect(b.x + b.width).toBeLessThanOrEqual(row.x + row.width + 1);
    }
    boxes.sort((a, b) => a.x - b.x);
    for (let i = 1; i < boxes.length; i++) expect(boxes[i]!.x).toBeGreaterThanOrEqual(boxes[i - 1]!.x + boxes[i - 1]!.width - 1);

    // The palette's names are whole.
    await page.getByTestId('tab-palette').click();
    for (const label of await page.locator('.rs-palette-item > span:last-child').all()) {
      if (await label.isVisible()) expect(await whole(label), await label.textContent() ?? '').toBe(true);
    }

    // The variable table in the side panel: long names and types whole.
    await page.getByRole('tab', { name: 'Variables' }).click();
    for (const name of ['BottleInPositionSensor', 'FillValveOpenTimer']) {
      const field = page.locator(`input[value="${name}"]`).first();
      await field.waitFor();
      expect(await whole(field), name).toBe(true);
    }

    // The Watch tab: a timer's elapsed time whole.
    await page.getByRole('tab', { name: 'Watch' }).click();
    await page.getByTestId('watch-add-name').fill('RedTime.ET');
    await page.getByTestId('watch-add').click();
    const value = page.getByTestId('watch-row-RedTime.ET').getByTestId('watch-value');
    await expect.poll(() => value.textContent()).toMatch(/^T#/);
    expect(await whole(value)).toBe(true);
    expect(await value.isVisible()).toBe(true);

    // The scenario editor shows several rows of its CSV.
    await page.getByRole('tab', { name: 'Tests' }).click();
    await page.locator('.rs-bottom').getByRole('button', { name: 'Edit', exact: true }).first().click();
    const table = page.getByTestId('scenario-table');
    await table.waitFor();
    // What the user sees of it: rows of the scenario inside the bottom panel's visible part.
    const visibleRows = async () => {
      const panel = (await page!.locator('.rs-bottom').boundingBox())!;
      let n = 0;
      for (const r of await table.locator('tbody tr').all()) {
        const b = await r.boundingBox();
        if (b && b.y >= panel.y && b.y + b.height <= panel.y + panel.height) n++;
      }
      return n;
    };
    await expect.poll(visibleRows).toBeGreaterThanOrEqual(5);
    // The canvas keeps a readable part meanwhile.
    expect((await page.getByTestId('ladder-canvas').boundingBox())!.height).toBeGreaterThan(150);
    await page.screenshot({ path: join(SHOTS, `rungsmith-${size}-panels.png`) });
    expect(await pageFits(page)).toBe(true);
    expect(app.errors).toEqual([]);
  });

  test(`${size}: the online-change dialog's text is inside the dialog`, async () => {
    const app = await openApp(browser());
    page = app.page;
    await page.setViewportSize(viewport);
    const sim = new SimPage(page);
    await sim.runExample('Parts counter (CTU)');
    // What the Hardware tab's link does when it is open as controller (no gateway runs in this test).
    await page.evaluate(() => (window.rungsmith as unknown as { simStore: { getState(): { setOnlineConfirmRequired(r: boolean): void } } }).simStore.getState().setOnlineConfirmRequired(true));
    await sim.draw.canvas().focus();
    await page.keyboard.press('n');
    const dialog = page.getByTestId('online-change-dialog');
    await dialog.waitFor();
    const box = (await dialog.boundingBox())!;
    expect(box.x).toBeGreaterThanOrEqual(0);
    expect(box.y).toBeGreaterThanOrEqual(0);
    expect(box.x + box.width).toBeLessThanOrEqual(viewport.width);
    expect(box.y + box.height).toBeLessThanOrEqual(viewport.height);
    // Every paragraph and the buttons are inside the dialog's box and need no horizontal scrolling.
    expect(await dialog.evaluate((el) => el.scrollWidth <= el.clientWidth)).toBe(true);
    for (const part of await dialog.locator('p, li, button').all()) {
      const b = (await part.boundingBox())!;
      expect(b.x).toBeGreaterThanOrEqual(box.x);
      expect(b.x + b.width).toBeLessThanOrEqual(box.x + box.width + 0.5);
      expect(await whole(part)).toBe(true);
    }
    await page.screenshot({ path: join(SHOTS, `rungsmith-${size}-online-change.png`) });
    await page.getByTestId('online-change-cancel').click();
    await dialog.waitFor({ state: 'detached' });
    expect(await pageFits(page)).toBe(true);
    expect(app.errors).toEqual([]);
  });
}
