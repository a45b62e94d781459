// The trend's trigger, freeze, cursors and CSV export, in real Chromium against the real server:
// a one-scan pulse (a P contact on Start driving Pulse) triggers a single capture that holds the
// chosen pre-trigger share of samples; two cursors read Δt; the CSV download holds the samples.
import type { Download, Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { openApp, settledBox, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

function pulseProject() {
  const id = (k: string) => `tp_${k}` as ElementId;
  const elements: LdElement[] = [
    { kind: 'contact', contact: 'P', variable: 'Start', id: id('p'), row: 0, col: 0 },
    ...[1, 2, 3, 4, 5, 6, 7, 8].map((col) => ({ kind: 'link' as const, id: id(`l${col}`), row: 0, col })),
    { kind: 'coil', coil: 'COIL', variable: 'Pulse', id: id('q'), row: 0, col: 9 },
  ];
  return newProject('Pulse trend', {
    pous: [
      newPou('Main', {
        networks: [newNetwork({ title: 'One scan on each rising edge of Start', rows: 1, elements })],
        variables: [variable('Start', 'BOOL', { location: '%IX0.0' }), variable('Pulse', 'BOOL')],
      }),
    ],
  });
}

interface TrendHandle {
  getState(): {
    scan: number;
    trendCapture?: { triggerIndex: number; samples: { names: string[]; scans: number[]; series: number[][] } };
  };
}
/** A download's bytes, read through playwright's connection (the browser is the run's shared one). */
async function bytes(file: Download): Promise<Buffer> {
  const chunks: Buffer[] = [];
  for await (const chunk of await file.createReadStream()) chunks.push(chunk as Buffer);
  return Buffer.concat(chunks);
}
const capture = () => page.evaluate(() => (window.rungsmith as unknown as { simStore: TrendHandle }).simStore.getState().trendCapture);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  await sim.load(pulseProject());
  await sim.tab('Trend');
  for (const name of ['Start', 'Pulse']) {
    await page.getByTestId('trend-add-name').fill(name);
    await page.getByTestId('trend-add').click();
  }
  await page.getByTestId('trend-capacity').fill('100');
  await page.getByTestId('trend-capacity').press('Enter');
});

test('a one-scan pulse triggers a single capture holding the pre-trigger share, held while the PLC runs on', async () => {
  await page.getByTestId('trend-trigger-name').fill('Pulse');
  await page.getByTestId('trend-trigger-direction').selectOption('rising');
  await page.getByTestId('trend-trigger-pre').fill('20');
  await page.getByTestId('trend-trigger-mode').selectOption('single');
  await page.getByTestId('trend-trigger-arm').click();
  const status = page.getByTestId('trend-trigger-status');
  await expect.poll(() => status.textContent()).toContain('Armed: waiting for Pulse ↑');
  await sim.button('run').click();
  await sim.waitForMode('Running');
  // Enough scans before the edge for a full pre-trigger share.
  await page.waitForFunction(() => (window.rungsmith as unknown as { simStore: TrendHandle }).simStore.getState().scan > 40, undefined, { timeout: 30_000 });
  await sim.tab('Inputs');
  await page.getByTestId('input-Start').getByTestId('input-switch').click();
  await sim.waitForValue('Start', true);
  await sim.tab('Trend');
  await expect.poll(() => status.textContent(), { timeout: 30_000 }).toMatch(/Triggered on Pulse ↑ at scan \d+ \(single/);
  const c = (await capture())!;
  expect(c.samples.scans).toHaveLength(100);
  expect(c.triggerIndex).toBe(20);
  const pulse = c.samples.series[c.samples.names.indexOf('Pulse')]!;
  // Pulse is TRUE for exactly the trigger's scan: a one-scan pulse, caught.
  expect(pulse.flatMap((v, i) => (v ? [i] : []))).toEqual([20]);
  // Consecutive scans: every scan's values, not the display's.
  expect(c.samples.scans[99]! - c.samples.scans[0]!).toBe(99);
  // The chart shows the capture and keeps it while the PLC scans on.
  const chart = page.getByTestId('trend-chart');
  const shown = `${c.samples.scans[0]}-${c.samples.scans[99]}`;
  await expect.poll(() => chart.getAttribute('data-scans')).toBe(shown);
  const scanNow = Number(await page.getByTestId('sim-scan').textContent());
  await expect.poll(async () => Number(await page.getByTestId('sim-scan').textContent())).toBeGreaterThan(scanNow + 20);
  expect(await chart.getAttribute('data-scans')).toBe(shown);
  expect(errors).toEqual([]);
});

test('two cursors read each signal and the time between them', async () => {
  const over = page.getByTestId('trend-chart').locator('.u-over');
  const box = await settledBox(over);
  await over.click({ position: { x: box.width * 0.1, y: box.height / 2 } });
  await over.click({ position: { x: box.width * 0.7, y: box.height / 2 } });
  const a = await page.getByTestId('trend-cursor-a').textContent();
  const b = await page.getByTestId('trend-cursor-b').textContent();
  const ta = Number(/A: (\d+) ms/.exec(a ?? '')![1]);
  const tb = Number(/B: (\d+) ms/.exec(b ?? '')![1]);
  expect(tb).toBeGreaterThan(ta);
  expect(await page.getByTestId('trend-cursor-dt').textContent()).toBe(`Δt = ${tb - ta} ms`);
  // Start was switched on within the window: FALSE at A (before the trigger), TRUE at B.
  await expect.poll(() => page.getByTestId('trend-cursor-row-Start').textContent()).toBe('StartFALSETRUE');
  expect(errors).toEqual([]);
});

test('the CSV download holds time, scan and a column per signal with every sample shown', async () => {
  const [download] = await Promise.all([page.waitForEvent('download'), page.getByTestId('trend-export-csv').click()]);
  const text = (await bytes(download)).toString('utf8');
  const lines = text.trim().split('\n');
  expect(lines[0]).toBe('time_ms,scan,Start,Pulse');
  expect(lines).toHaveLength(101);
  const c = (await capture())!;
  expect(lines.slice(1).map((l) => Number(l.split(',')[1]))).toEqual(c.samples.scans);
  expect(lines.filter((l) => l.endsWith(',1,1'))).toHaveLength(1);
  expect(lines[21]!.split(',').slice(2)).toEqual(['1', '1']);
  const [png] = await Promise.all([page.waitForEvent('download'), page.getByTestId('trend-export-png').click()]);
  expect(png.suggestedFilename()).toMatch(/\.png$/);
  const image = await bytes(png);
  expect(image.subarray(1, 4).toString()).toBe('PNG');
  expect(errors).toEqual([]);
});

test('freeze holds the live picture while the PLC runs; resume follows it again', async () => {
  await page.getByTestId('trend-trigger-off').click();
  const chart = page.getByTestId('trend-chart');
  const first = await chart.getAttribute('data-scans');
  await expect.poll(() => chart.getAttribute('data-scans')).not.toBe(first);
  await page.getByTestId('trend-freeze').click();
  const held = await chart.getAttribute('data-scans');
  const scanNow = Number(await page.getByTestId('sim-scan').textContent());
  await expect.poll(async () => Number(await page.getByTestId('sim-scan').textContent())).toBeGreaterThan(scanNow + 20);
  expect(await chart.getAttribute('data-scans')).toBe(held);
  await page.getByTestId('trend-freeze').click();
  await expect.poll(() => chart.getAttribute('data-scans')).not.toBe(held);
  expect(errors).toEqual([]);
});
