// The tank in the Plant panel (issue 26), in real Chromium against the real server: the exercise's
// reference solution, started with the Start button on the drawing, holds the tank between its
// switches for 5 minutes of PLC time (fast-forwarded with Step N); a fault set from the panel
// shows in the trace; a wrong program overflows the tank, shown on the drawing's panel as a
// located consequence that opens the recorded scan. One page for the whole file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { tankWrong } from '../../src/plant/exercises';
import { openApp, useChromium } from './appPage';
import { PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

let plants: PlantPage;
const plant = () => plants.plant();
const trace = (names: string[]) => plants.traceText(names);

const startAndFastForward = (scans: number) => plants.startAndFastForward(scans);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
  await plants.openExercise('Tank level control (machine: tank)', 100);
});

test('the reference solution holds the tank between the switches for 5 minutes of PLC time', async () => {
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('tank');
  await expect.poll(() => page.getByTestId('plant-io').locator('tbody tr').count()).toBe(9);
  await startAndFastForward(3000);
  const p = (await plant())!;
  expect(p.id).toBe('tank');
  expect(p.now.scan).toBeGreaterThanOrEqual(3000);
  expect(p.eventCount).toBe(0);
  await expect.poll(() => page.getByTestId('plant-events').textContent()).toContain('None so far.');
  // Every scan after the first fill: the level (the program's %IW0) between the switches, give or take the valves' travel.
  const rows = (await trace(['Level', 'LowLevel', 'HighLevel', 'Pump']))
    .trim()
    .split('\n')
    .slice(1)
    .map((r) => r.split(',').map(Number));
  expect(rows.length).toBeGreaterThanOrEqual(3000);
  const filled = rows.findIndex((r) => r[4] === 1);
  expect(filled).toBeGreaterThan(0);
  const after = rows.slice(filled);
  expect(Math.max(...after.map((r) => r[2]!))).toBeLessThanOrEqual(830);
  expect(Math.min(...after.map((r) => r[2]!))).toBeGreaterThanOrEqual(190);
  // The pump ran in at least two fills (filled, drained to the low switch, filled again).
  const starts = after.filter((r, i) => i > 0 && r[5] === 1 && after[i - 1]![5] === 0).length;
  expect(starts).toBeGreaterThanOrEqual(2);
  await expect.poll(() => page.getByTestId('plant-q-level').textContent()).toMatch(/^tank\.level\d+\.\d L$/);
});

test('a fault set from the panel shows in the trace: the high switch stuck OFF stays 0 above 800 L, and the tank overflows', async () => {
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await page.getByTestId('plant-fault-high_stuck_off').check();
  await expect.poll(async () => (await plant())?.now.faults).toEqual(['high_stuck_off']);
  await startAndFastForward(900);
  const rows = (await trace(['Level', 'HighLevel']))
    .trim()
    .split('\n')
    .slice(1)
    .map((r) => r.split(',').map(Number));
  const high = rows.filter((r) => r[2]! >= 800);
  expect(high.length).toBeGreaterThan(0);
  expect(high.every((r) => r[3] === 0)).toBe(true);
  await expect
    .poll(() => page.getByTestId('plant-events').textContent())
    .toMatch(/the tank overflowed at scan \d+ \(\d+\.\d\d s\)/);
  await page.getByTestId('plant-fault-high_stuck_off').uncheck();
  await expect.poll(async () => (await plant())?.now.faults).toEqual([]);
});

test('a wrong program overflows the tank: a located consequence that opens the recorded scan with the machine as it was', async () => {
  await sim.load(tankWrong());
  await expect.poll(() => page.getByTestId('project-name').textContent()).toContain('wrong');
  await startAndFastForward(900);
  const p = (await plant())!;
  expect(p.now.state.overflowing).toBe(true);
  const event = page.getByTestId('plant-events').getByRole('button', { name: /the tank overflowed at scan/ });
  const text = (await event.textContent())!;
  const scan = Number(/at scan ([\d,]+)/.exec(text)![1]!.replace(/,/g, ''));
  await event.click();
  await expect
    .poll(() => page.getByTestId('plant-status').textContent())
    .toMatch(new RegExp(`^Recorded scan ${scan.toLocaleString('en-US')} \\(`));
  // The drawing's readout shows that scan's machine: full to the rim.
  await expect.poll(() => page.getByTestId('plant-q-overflowing').textContent()).toContain('yes');
  expect(errors).toEqual([]);
});

interface DocHandle {
  getState(): {
    project: {
      plant?: { id: string; map?: Record<string, string> };
      pous: { variables: { name: string; location?: string }[] }[];
    };
    undoName?: string;
    undo(): void;
  };
}
const doc = () =>
  page.evaluate(() => {
    const s = (window.rungsmith as unknown as { documentStore: DocHandle }).documentStore.getState();
    return {
      plant: s.project.plant,
      variables: s.project.pous[0]!.variables.map((v) => `${v.name}@${v.location ?? ''}`),
      undoName: s.undoName,
    };
  });

test("choosing the tank for a new project, editing an address, and Declare the machine's I/O as one undo step", async () => {
  await page.evaluate(() =>
    (
      window.rungsmith as unknown as { documentStore: { getState(): { newProject(n: string): void } } }
    ).documentStore
      .getState()
      .newProject('Tank from scratch'),
  );
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('');
  await page.getByTestId('plant-choose').selectOption('tank');
  await expect.poll(async () => (await doc()).plant).toEqual({ id: 'tank' });
  // A sensor cannot be an output: refused, named, and nothing changes.
  const pump = page.getByTestId('plant-address-Pump');
  await pump.fill('%IX3.0');
  await pump.press('Enter');
  await expect
    .poll(() => page.getByTestId('plant-io-problem').textContent())
    .toBe('Pump: an actuator is a %Q output, not %IX3.0');
  await pump.fill('%QX1.0');
  await pump.press('Enter');
  await expect.poll(async () => (await doc()).plant).toEqual({ id: 'tank', map: { Pump: '%QX1.0' } });
  await page.getByTestId('plant-declare').click();
  await expect
    .poll(() => page.getByTestId('plant-declared').textContent())
    .toBe(
      'Declared 9 variables in Main: Start, Stop, LowLevel, HighLevel, Level, Pump, InletValve, DrainValve, RunLamp.',
    );
  const after = await doc();
  expect(after.variables).toContain('Pump@%QX1.0');
  expect(after.variables).toContain('Level@%IW0');
  expect(after.undoName).toBe("Declare the machine's I/O");
  await page.getByTestId('menu-edit').click();
  await page.getByRole('menuitem', { name: /^Undo/ }).click();
  await expect.poll(async () => (await doc()).variables).toEqual([]);
  expect(errors).toEqual([]);
});
