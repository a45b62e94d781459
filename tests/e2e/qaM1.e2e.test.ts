// Exploratory QA of the tank, the batch mixer and the road intersection in the Plant panel
// (issue 26), as a student or trainer uses them, in real Chromium against the real server: what
// was found wrong, each test failing before its fix. One page for the whole file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { coil, contact, rung } from '../../src/model/examples';
import { intersectionReference } from '../../src/plant/intersectionExercise';
import { tankReference, tankWrong } from '../../src/plant/exercises';
import { openApp, useChromium } from './appPage';
import { LAMP_LIT, LAMP_UNLIT, PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let plants: PlantPage;
let errors: string[];

interface HistoryHandle {
  getState(): { history?: { first: number; last: number }; historyScan?: number };
}
const historyRange = () =>
  page.evaluate(() => (window.rungsmith as unknown as { simStore: HistoryHandle }).simStore.getState().history);
const historyScan = () =>
  page.evaluate(() => (window.rungsmith as unknown as { simStore: HistoryHandle }).simStore.getState().historyScan);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
  await plants.openExercise('Tank level control (machine: tank)', 100);
});

test('a consequence whose scan the history no longer keeps says so when clicked, instead of showing another scan as that one', async () => {
  await sim.load(tankWrong());
  await expect.poll(() => page.getByTestId('project-name').textContent()).toContain('wrong');
  await plants.startAndFastForward(900);
  const event = page.getByTestId('plant-events').getByRole('button', { name: /the tank overflowed at scan/ });
  const scan = Number(/at scan ([\d,]+)/.exec((await event.textContent())!)![1]!.replace(/,/g, ''));
  // Many minutes of PLC time later (fast-forward): the history keeps the newest scans only.
  await plants.fastForward(101_000);
  const range = (await historyRange())!;
  expect(range.first).toBeGreaterThan(scan);
  await event.click();
  await expect
    .poll(() => page.getByTestId('plant-events-gone').textContent())
    .toBe(
      `Scan ${scan.toLocaleString('en-US')} is no longer in the history (it keeps scans ${range.first.toLocaleString('en-US')} to ${range.last.toLocaleString('en-US')}).`,
    );
  // The drawing stays live: no recorded scan is shown as if it were the overflow's.
  expect(await historyScan()).toBeUndefined();
  expect(await page.getByTestId('plant-status').textContent()).toMatch(/^After scan /);
  expect(errors).toEqual([]);
});

test('"Why?" on the mixer\'s Temperature with the transmitter frozen from the panel explains it by the machine: frozen at what it shows, the batch hotter', async () => {
  await plants.openExercise('Batch mixer (machine: mixer)', 100);
  // Dosed (about 40 s) and heating: then the transmitter freezes while the heater goes on.
  await plants.startAndFastForward(450);
  await page.getByTestId('plant-fault-temp_frozen').check();
  await expect.poll(async () => (await plants.plant())?.now.faults).toEqual(['temp_frozen']);
  await plants.fastForward(100);
  const shown = Number(await sim.value('Temperature'));
  await sim.tab('Why?');
  await page.getByTestId('why-input').fill('Temperature');
  await page.getByTestId('why-ask').click();
  const why = page.getByTestId('why-explanation');
  await expect.poll(() => why.textContent()).toContain('the transmitter is frozen (fault temp_frozen): it keeps showing ');
  const text = (await why.textContent())!;
  const m = /it keeps showing (\d+\.\d) °C \((\d+)\) whatever the batch; the batch is (\d+\.\d) °C/.exec(text)!;
  expect(Number(m[2])).toBe(shown);
  expect(Number(m[3])).toBeGreaterThan(Number(m[1]));
  // A switch: the level against it.
  await page.getByTestId('why-input').fill('HighLevel');
  await page.getByTestId('why-ask').click();
  await expect.poll(() => why.textContent()).toMatch(/the high level switch is ON at 800 L and above; the level is \d+\.\d L, so it is ON/);
  await page.getByTestId('plant-fault-temp_frozen').uncheck();
  await expect.poll(async () => (await plants.plant())?.now.faults).toEqual([]);
  expect(errors).toEqual([]);
});

test('a program that leaves the main road red lit under its green: the signal shows both, a located conflict, CONFLICT on the drawing', async () => {
  // A classic mistake: red whenever the main road is not yellow (forgetting its green).
  const reference = intersectionReference();
  const main = reference.pous[0]!;
  const project = {
    ...reference,
    name: 'Road intersection (wrong: red under the green)',
    pous: [
      {
        ...main,
        networks: main.networks.map((n) =>
          n.title === 'Main road red'
            ? { ...n, elements: rung([contact(0, 0, 'MainYellow', 'NC')], coil(0, 'MainRed')) }
            : n,
        ),
      },
    ],
  };
  await sim.load(project);
  await expect.poll(() => page.getByTestId('project-name').textContent()).toContain('red under the green');
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('intersection');
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await plants.fastForward(50);
  const event = page.getByTestId('plant-events').getByRole('button', {
    name: 'conflicting signals: the main road signal shows red and green together at scan 1 (0.00 s)',
  });
  await expect.poll(() => event.count()).toBe(1);
  const p = (await plants.plant<{ lamps: number; conflict: number }>())!;
  // Both lamps lit on the head, the monitor's conflict still on (drawn as CONFLICT).
  expect(p.now.state.lamps & 5).toBe(5);
  expect(p.now.state.conflict).not.toBe(0);
  await expect.poll(() => page.getByTestId('plant-q-conflicts').textContent()).toBe('intersection.conflicts1');
  expect(errors).toEqual([]);
});

const drawnColour = (x: number, y: number) => plants.drawnColour(x, y);
const LIT = LAMP_LIT;
const UNLIT = LAMP_UNLIT;

test('a level switch stuck OFF is drawn as it reads: under water its lamp stays dark, as the program sees it', async () => {
  await plants.openExercise('Tank level control (machine: tank)', 100);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await page.getByTestId('plant-fault-high_stuck_off').check();
  await expect.poll(async () => (await plants.plant())?.now.faults).toEqual(['high_stuck_off']);
  // The reference never sees the high switch: it fills on past 800 L.
  await plants.startAndFastForward(500);
  const level = (await plants.plant<{ level: number }>())!.now.state.level;
  expect(level).toBeGreaterThan(850);
  expect(await sim.value('HighLevel')).toBe(false);
  // The tank's switch lamps sit right of the vessel (x 230) at 800 L (y 76) and 200 L (y 184).
  await expect.poll(() => drawnColour(230, 76)).toBe(UNLIT);
  expect(await drawnColour(230, 184)).toBe(LIT);
  // Cleared, the switch reads ON under water and its lamp lights.
  await page.getByTestId('plant-fault-high_stuck_off').uncheck();
  await expect.poll(async () => (await plants.plant())?.now.faults).toEqual([]);
  await plants.fastForward(1);
  await expect.poll(() => drawnColour(230, 76)).toBe(LIT);
  expect(errors).toEqual([]);
});

test('a quick click on Start on the drawing at a slow scan cycle starts the tank: the press is held until a scan has read it', async () => {
  await plants.openExercise('Tank level control (machine: tank)', 1000);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await sim.button('run').click();
  await sim.waitForMode('Running');
  const start = page.getByTestId('plant-op-Start');
  await start.click();
  await sim.waitForValue('Running', true);
  await expect.poll(() => start.getAttribute('aria-pressed'), { timeout: 10_000 }).toBe('false');
  // The program saw the press for exactly one scan.
  const rows = await plants.trace(['Start']);
  expect(rows.filter((r) => r[2] === 1)).toHaveLength(1);
  await sim.button('pause').click();
  await sim.waitForMode('Paused');
  expect(errors).toEqual([]);
});

test("the Inputs tab shows the machine's inputs as coming from the machine: no switch or value to set that the next scan would overwrite", async () => {
  await plants.openExercise('Tank level control (machine: tank)', 100);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await sim.button('step-scan').click();
  await sim.waitForMode('Paused');
  await sim.tab('Inputs');
  const low = page.getByTestId('input-LowLevel');
  await expect.poll(() => low.getByTestId('input-from-machine').textContent()).toBe('from the machine');
  expect(await low.getByTestId('input-switch').isDisabled()).toBe(true);
  expect(await low.getByTestId('input-hold').isDisabled()).toBe(true);
  expect(await low.getByTestId('input-switch').getAttribute('title')).toBe(
    'Written by the machine tank every scan (its sensor LowLevel); a value set here would be overwritten. Only a force overrides it.',
  );
  const start = page.getByTestId('input-Start');
  expect(await start.getByTestId('input-from-machine').getAttribute('title')).toContain(
    'its operator control Start: press it on the drawing in the Plant panel',
  );
  const level = page.getByTestId('input-Level');
  expect(await level.getByRole('button', { name: 'Set' }).isDisabled()).toBe(true);
  await expect.poll(() => level.getByTestId('input-from-machine').textContent()).toBe('from the machine');
  // Rewired elsewhere in the map, LowLevel's input is no longer the machine's: it can be set again.
  const address = page.getByTestId('plant-address-LowLevel');
  await sim.tab('Plant');
  await address.fill('%IX1.0');
  await address.press('Enter');
  await sim.tab('Inputs');
  await expect.poll(() => low.getByTestId('input-from-machine').count()).toBe(0);
  expect(await low.getByTestId('input-switch').isDisabled()).toBe(false);
  await page.keyboard.press('Control+z');
  await expect.poll(() => low.getByTestId('input-from-machine').count()).toBe(1);
  expect(errors).toEqual([]);
});

test("double-clicking a contact on one of the machine's inputs does not switch it (the next scan would undo it): it offers the force menu and says why", async () => {
  // The exercise as loaded (the test before left edits that File > Examples would ask about).
  await sim.load(tankReference());
  await expect.poll(() => page.getByTestId('project-name').textContent()).toBe('Tank level control');
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await sim.button('step-scan').click();
  await sim.waitForMode('Paused');
  expect(await sim.value('LowLevel')).toBe(false);
  // Network 3, "Start filling": Running, then LowLevel (NC) at row 0, column 1.
  await sim.switchCell(2, 0, 1);
  await expect.poll(() => page.getByTestId('sim-context-menu').isVisible()).toBe(true);
  await expect
    .poll(() => page.getByTestId('status-bar').textContent())
    .toContain('LowLevel comes from the machine tank (its sensor LowLevel): it writes it every scan; force it to override');
  await page.keyboard.press('Escape');
  expect(await sim.value('LowLevel')).toBe(false);
  expect(errors).toEqual([]);
});
