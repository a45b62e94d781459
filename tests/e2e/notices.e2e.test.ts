// Notices have one place, in the layout flow under the tool bar: an import notice with a very long
// file name, "Edit not applied" raised again and again, a breakpoint, a runaway fault never cover
// the POU tabs, the Palette/Project tabs, the menus or the tool bar (each is still clickable, no
// "intercepts pointer events"), never widen the page, collapse their repeats (×N) and are dismissed
// with their × button. At 1440×900 and at 1280×720.
import type { Page } from 'playwright-core';
import { beforeEach, expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { saveProject } from '../../src/model/load';
import { runawayProgram } from '../sim/programs';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

beforeEach(async () => {
  await page?.close();
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
});

type Box = { x: number; y: number; width: number; height: number };
const overlap = (a: Box, b: Box) => a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;

/** Every notice shown is clear of every control, each control still takes a click, and the page is no wider than the window. */
async function noticesCoverNothing(): Promise<number> {
  const notices = await page.locator('[data-testid="notices"] > *').all();
  const controls = [
    page.getByTestId('menu-file'),
    page.getByTestId('tab-palette'),
    page.getByTestId('tab-project'),
    page.getByTestId('pou-tab-Main'),
    sim.button('run'),
    sim.button('reset'),
    sim.button('step-scan'),
    page.getByRole('tab', { name: 'Problems' }),
    page.getByRole('tab', { name: 'Inspector' }),
  ];
  for (const control of controls) {
    if (!(await control.count())) continue;
    const c = (await control.first().boundingBox())!;
    for (const notice of notices) {
      const n = await notice.boundingBox();
      if (n) expect(overlap(n, c), `a notice covers ${await control.first().getAttribute('data-testid')}`).toBe(false);
    }
    // Playwright's actionability check: fails with "intercepts pointer events" when something covers it.
    if (await control.first().isEnabled()) await control.first().click({ trial: true, timeout: 5000 });
  }
  const widths = await page.evaluate(() => ({ scroll: document.documentElement.scrollWidth, inner: innerWidth }));
  expect(widths.scroll).toBeLessThanOrEqual(widths.inner);
  return notices.length;
}

async function dropProjectFile(name: string, text: string) {
  await page.evaluate(
    ([n, t]) => {
      const data = new DataTransfer();
      data.items.add(new File([t], n, { type: 'application/json' }));
      const target = document.querySelector('main') ?? document.body;
      target.dispatchEvent(new DragEvent('dragover', { dataTransfer: data, bubbles: true, cancelable: true }));
      target.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
    },
    [name, text] as const,
  );
}

for (const viewport of [{ width: 1440, height: 900 }, { width: 1280, height: 720 }]) {
  test(`at ${viewport.width}×${viewport.height}: import, edit-not-applied (×N), breakpoint and fault notices cover no control and are dismissed`, async () => {
    await page.setViewportSize(viewport);
    // An import notice naming a file with a very long name wraps inside the window.
    const example = EXAMPLES.find((x) => x.id === 'motor-start-stop')!.build();
    const longName = `${'Motor_start_stop_with_a_very_long_file_name_'.repeat(12)}.json`;
    await dropProjectFile(longName, saveProject(example));
    const fileNotice = page.getByTestId('file-notice');
    await expect.poll(() => fileNotice.textContent()).toContain('Opened Motor_start_stop');
    expect(await noticesCoverNothing()).toBeGreaterThanOrEqual(1);
    await fileNotice.getByRole('button', { name: /^Dismiss/ }).click();
    await fileNotice.waitFor({ state: 'detached' });

    // Running, an edit with an error is not applied; raised again, the notice counts instead of stacking.
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.draw.canvas().focus();
    await page.keyboard.press('n');
    await expect.poll(async () => (await sim.draw.networks()).length).toBe(2);
    await page.keyboard.press('j');
    await sim.draw.typeName('NOWHERE');
    const refusal = page.getByTestId('sim-refusal');
    await expect.poll(() => refusal.textContent(), { timeout: 30_000 }).toMatch(/^Edit not applied: 1 error/);
    expect(await refusal.textContent()).toContain('LD-R07');
    // Two more edits, each refused for the same error: one notice, ×2, then ×3.
    await page.keyboard.press('ArrowDown');
    for (const n of [2, 3]) {
      await page.keyboard.press('h');
      await expect.poll(() => refusal.getAttribute('data-count'), { timeout: 30_000 }).toBe(String(n));
    }
    expect(await page.getByTestId('sim-refusal').count()).toBe(1);
    expect(await refusal.getByTestId('notice-count').textContent()).toBe('×3');
    await noticesCoverNothing();
    await refusal.getByRole('button', { name: /^Dismiss/ }).click();
    await refusal.waitFor({ state: 'detached' });
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');

    // A breakpoint hit.
    await sim.load(EXAMPLES.find((x) => x.id === 'traffic-light')!.build());
    await page.getByTestId('network-breakpoint-2').click();
    await sim.button('run').click();
    await sim.waitForMode('Paused');
    const hit = page.getByTestId('sim-breakpoint-hit');
    await hit.waitFor();
    await noticesCoverNothing();
    await hit.getByRole('button', { name: /^Dismiss/ }).click();
    await hit.waitFor({ state: 'detached' });
    await page.getByTestId('network-breakpoint-2').click();
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');

    // A runaway program's watchdog fault.
    await sim.load(runawayProgram());
    await sim.button('run').click();
    const fault = page.getByTestId('sim-fault');
    await fault.waitFor();
    await noticesCoverNothing();
    await fault.getByRole('button', { name: /^Dismiss/ }).click();
    await fault.waitFor({ state: 'detached' });
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');
    expect(errors).toEqual([]);
  });
}
