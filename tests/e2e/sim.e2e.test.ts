// The simulator in a real Chromium: run the motor example with push-buttons on the canvas, step the
// traffic light scan by scan, stop at a breakpoint, and survive a runaway program.
import { beforeEach, expect, test } from 'vitest';
import type { Page } from 'playwright-core';
import { newNetwork, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { openApp, useChromium } from './appPage';
import { runawayProgram } from '../sim/programs';
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

test('motor start/stop: Start (held) energises Motor, which seals in, and Stop drops it', async () => {
  await sim.runExample('Motor start/stop (seal-in)');
  expect(await sim.value('Motor')).toBe(false);
  expect(await sim.wireLit(0, 0, 9)).toBe(false);

  // Start is cell (0,0), Stop (0,1), the Motor coil (0,9).
  const releaseStart = await sim.holdCell(0, 0, 0);
  await sim.waitForValue('Start', true);
  await sim.waitForValue('Motor', true);
  await releaseStart();
  await sim.waitForValue('Start', false);
  await page.waitForTimeout(200);
  expect(await sim.value('Motor')).toBe(true); // sealed in through its own contact
  await expect.poll(() => sim.wireLit(0, 0, 9)).toBe(true);

  const releaseStop = await sim.holdCell(0, 0, 1);
  await sim.waitForValue('Motor', false);
  await releaseStop();
  await page.waitForTimeout(200);
  expect(await sim.value('Motor')).toBe(false);
  await expect.poll(() => sim.wireLit(0, 0, 9)).toBe(false);
  expect(errors).toEqual([]);
});

test('a plain click on an input contact only selects it; a double-click switches it like a switch', async () => {
  await sim.runExample('Motor start/stop (seal-in)');
  await sim.draw.clickCell(0, 0, 0);
  await expect.poll(() => page.getByTestId('sim-input-hint').textContent()).toContain('double-click to switch it');
  expect(await sim.value('Start')).toBe(false);
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('Start', true);
  await sim.waitForValue('Motor', true);
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('Start', false);
  await sim.tab('Inputs');
  await expect.poll(() => page.getByTestId('input-Start').getByTestId('input-switch').textContent()).toBe('OFF');
});

test("traffic light stepped scan by scan: RedTime's ET advances by the 10 ms cycle", async () => {
  await sim.openExample('Traffic light (TON chain)');
  await sim.tab('Watch');
  await page.getByTestId('watch-add-name').fill('RedTime.ET');
  await page.getByTestId('watch-add').click();
  const et = page.getByTestId('watch-row-RedTime.ET').getByTestId('watch-value');
  await sim.button('step-scan').click();
  await expect.poll(() => et.textContent()).toBe('T#0ms');
  expect(await page.getByTestId('sim-scan').textContent()).toBe('1');
  await sim.button('step-scan').click();
  await expect.poll(() => et.textContent()).toBe('T#10ms');
  await sim.button('step-scan').click();
  await expect.poll(() => et.textContent()).toBe('T#20ms');
  expect(await page.getByTestId('sim-time').textContent()).toBe('20 ms');
  await page.getByTestId('sim-step-count').fill('48');
  await sim.button('step-n').click();
  await expect.poll(() => et.textContent()).toBe('T#500ms');
  expect(await sim.mode()).toBe('Paused');
  expect(errors).toEqual([]);
});

test('a breakpoint stops execution before its network, and stepping shows the next network', async () => {
  await sim.openExample('Traffic light (TON chain)');
  await page.getByTestId('network-breakpoint-2').click();
  await sim.button('run').click();
  await page.getByTestId('sim-breakpoint-hit').filter({ hasText: 'before network 3' }).waitFor();
  expect(await sim.mode()).toBe('Paused');
  await page.getByTestId('network-next-2').waitFor();
  const scan = Number(await page.getByTestId('sim-scan').textContent());
  await sim.button('step-network').click();
  await page.getByTestId('network-next-3').waitFor();
  expect(await page.getByTestId('network-next-2').count()).toBe(0);
  await sim.button('run').click();
  // Once past it, Run stops at the same breakpoint in the next scan.
  await expect.poll(async () => Number(await page.getByTestId('sim-scan').textContent())).toBe(scan + 1);
  await sim.waitForMode('Paused');
  await page.getByTestId('network-next-2').waitFor();
  // The breakpoints list shows it too, and clearing it lets the program run on.
  await sim.tab('Breakpoints & forces');
  await page.getByLabel('Breakpoint before network 3', { exact: true }).uncheck();
  await sim.button('run').click();
  await sim.waitForMode('Running');
  expect(errors).toEqual([]);
});

test('a runaway backward jump faults with the network named, and the page stays responsive', async () => {
  const project = runawayProgram();
  await sim.load(project);
  await sim.button('run').click();
  const fault = page.getByTestId('sim-fault');
  await fault.waitFor();
  expect(await fault.textContent()).toMatch(/network 2 \(LOOP\)/);
  expect(await sim.mode()).toBe('Faulted');
  // The page still answers: frames keep coming and the controls work.
  const frames = await page.evaluate(
    () => new Promise<number>((resolve) => {
      let n = 0;
      const end = performance.now() + 300;
      const tick = () => (++n, performance.now() < end ? requestAnimationFrame(tick) : resolve(n));
      requestAnimationFrame(tick);
    }),
  );
  expect(frames).toBeGreaterThan(5);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  expect(await fault.count()).toBe(0);
});

test('Run is refused for a program with errors, naming the rule and network', async () => {
  const base = newProject('Broken');
  const coil = { id: 'c' as ElementId, kind: 'coil' as const, coil: 'COIL' as const, variable: 'Nowhere', row: 0, col: 0 };
  await sim.load({ ...base, pous: [{ ...base.pous[0]!, networks: [newNetwork({ rows: 1, cols: 1, elements: [coil] })] }] });
  await sim.button('run').click();
  const refusal = page.getByTestId('sim-refusal');
  await refusal.waitFor();
  expect(await refusal.textContent()).toMatch(/Run refused/);
  expect(await refusal.textContent()).toMatch(/LD-R08 Main network 1/);
  expect(await sim.mode()).toBe('Stopped');
});
