// Editing clicks never change the process: paused after a step, a click on an input contact selects
// it (Enter then edits that contact, in its own network) and leaves the input as it was. Switching
// the input is a deliberate gesture the tooltip and the status line name: a double-click (Alt+press
// holds it).
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
});

const selected = () =>
  page.evaluate(() => {
    const ui = window.rungsmith!.uiStore!.getState();
    const doc = window.rungsmith!.documentStore!.getState();
    const networks = doc.project.pous.find((p) => p.id === doc.activePouId)!.networks;
    const n = networks.findIndex((x) => x.id === ui.selection.network);
    const el = networks[n]?.elements.find((e) => e.id === ui.selection.elements[0]);
    return { network: n, variable: el && 'variable' in el ? el.variable : undefined, count: ui.selection.elements.length };
  });

test('paused after a step, a click on an input contact selects it and changes no input; a double-click switches it', async () => {
  await sim.openExample('Motor start/stop (seal-in)');
  await sim.button('step-scan').click();
  await sim.waitForMode('Paused');
  const scan = await page.getByTestId('sim-scan').textContent();

  // Select another element first (the Motor coil), then click the Start contact.
  await sim.draw.clickCell(0, 0, 9);
  await sim.draw.clickCell(0, 0, 0);
  expect(await selected()).toEqual({ network: 0, variable: 'Start', count: 1 });
  await page.waitForTimeout(300); // any toggle would have reached the simulator by now
  expect(await sim.value('Start')).toBe(false);
  expect(await page.getByTestId('sim-scan').textContent()).toBe(scan);

  // The status line and the tooltip name the gesture that does switch it.
  await expect.poll(() => page.getByTestId('sim-input-hint').textContent()).toBe(
    'Input Start: double-click to switch it, Alt+press to hold it on (a click only selects)',
  );
  const p = await sim.draw.cellPoint(0, 0, 0);
  await page.mouse.move(p.x + 1, p.y);
  await expect.poll(() => page.locator('.rs-canvas-sticky').getAttribute('title')).toContain('double-click to switch it');

  // Enter edits the clicked contact, not another network's element.
  await sim.draw.canvas().focus();
  await page.keyboard.press('Enter');
  const inline = page.getByTestId('inline-editor');
  await inline.waitFor();
  expect(await inline.inputValue()).toBe('Start');
  await page.keyboard.press('Escape');
  await inline.waitFor({ state: 'detached' });
  expect(await sim.value('Start')).toBe(false);

  // The deliberate gesture: a double-click switches it on, paused too (the next scan reads it); the
  // status line says so.
  await sim.switchCell(0, 0, 0);
  await expect.poll(() => page.getByTestId('status-bar').textContent()).toContain('Start switched ON (double-click)');
  await sim.button('step-scan').click();
  await sim.waitForValue('Start', true);
  await sim.waitForValue('Motor', true);
  await sim.switchCell(0, 0, 0);
  await sim.button('step-scan').click();
  await sim.waitForValue('Start', false);

  // Plain clicks on it again: nothing changes.
  await sim.draw.clickCell(0, 0, 0);
  await sim.draw.clickCell(0, 0, 1);
  await page.waitForTimeout(300);
  expect(await sim.value('Start')).toBe(false);
  expect(await sim.value('Stop')).toBe(false);
  expect(errors).toEqual([]);
});

test('at a breakpoint, a click on an input contact selects it and changes no input', async () => {
  await sim.openExample('Traffic light (TON chain)');
  await page.getByTestId('network-breakpoint-2').click();
  await sim.button('run').click();
  await sim.waitForMode('Paused');
  const inputs = await page.evaluate(() => {
    const s = (window.rungsmith as unknown as { simStore: { getState(): { layout?: { variables: { name: string; role: string; type: string }[] }; values: unknown[]; variableIndex: Map<string, number> } } }).simStore.getState();
    return (s.layout?.variables ?? []).filter((v) => v.role === 'input' && v.type === 'BOOL').map((v) => [v.name, s.values[s.variableIndex.get(v.name.toUpperCase())!]]);
  });
  const { networks } = await sim.draw.layout();
  // The canvas scrolls to the network paused at (and to a selection); a cell's point is measured
  // once the scrolling has stopped, or the click lands on another network on a busy machine.
  // Click every contact of every network: each click selects; no input changes.
  for (let i = 0; i < networks.length; i++) {
    for (const el of networks[i]!.elements.filter((e) => e.kind === 'contact')) {
      await sim.draw.waitScrollStill();
      await sim.draw.clickCell(i, el.row, el.col);
      expect((await selected()).network).toBe(i);
    }
  }
  await page.waitForTimeout(300);
  for (const [name, value] of inputs) expect(await sim.value(name as string)).toBe(value);
  expect(await sim.mode()).toBe('Paused');
  expect(errors).toEqual([]);
});
