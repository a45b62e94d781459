// Exploratory QA of the box sorter, the garage door and the lift in the Plant panel (issue 26),
// in real Chromium against the real server: what a student or trainer hit using them. One page
// for the file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { LAMP_LIT, LAMP_UNLIT, PlantPage } from './plantPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let plants: PlantPage;
let errors: string[];

interface GarageNow {
  carIn: boolean;
  position: number;
}
const garage = async () => (await plants.plant<GarageNow>())!.now.state;

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  plants = new PlantPage(page, sim);
});

test('an exercise opened from File > Examples shows its machine: the Plant tab is chosen, the drawing in view', async () => {
  await sim.tab('Inspector');
  await expect.poll(() => page.getByTestId('plant-panel').isVisible()).toBe(false);
  await sim.openExample('Three-floor lift (machine: lift)');
  await expect.poll(() => page.getByRole('tab', { name: 'Plant' }).getAttribute('aria-selected')).toBe('true');
  await expect.poll(() => page.getByTestId('plant-panel').isVisible()).toBe(true);
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('lift');
  expect(await page.getByTestId('plant-op-Call1').isVisible()).toBe(true);
});

test('at a recorded scan the drawing\'s switch shows it as it was, and turning it acts on the live machine and goes back to Live', async () => {
  await plants.openExercise('Garage door (machine: garage)', 100);
  await plants.runHoldPause('KeyOpen', 'WarningLamp');
  await plants.fastForward(150);
  const doorway = page.getByTestId('plant-op-Doorway');
  await doorway.click();
  await expect.poll(async () => (await plants.plant())!.now.operator.Doorway).toBe(true);
  await plants.fastForward(20);
  expect((await garage()).carIn).toBe(true);
  await expect.poll(() => doorway.getAttribute('aria-pressed')).toBe('true');
  // Back to scan 100: the door opening, no car yet.
  await page.evaluate(() => (window.rungsmith as unknown as { simStore: { getState(): { seekHistory(s: number): void } } }).simStore.getState().seekHistory(100));
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toMatch(/^Recorded scan 100 \(/);
  await expect.poll(() => doorway.getAttribute('aria-pressed')).toBe('false');
  // The operator drives the car out: the live switch turns OFF (it was ON), and the panel shows it live.
  await doorway.click();
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toMatch(/^After scan /);
  await expect.poll(async () => (await plants.plant())!.now.operator.Doorway).toBe(false);
  await expect.poll(() => doorway.getAttribute('aria-pressed')).toBe('false');
  await plants.fastForward(1);
  expect((await garage()).carIn).toBe(false);
  expect(errors).toEqual([]);
});

test('"Why?" on the box sorter\'s PusherEye names the box in front of it and where it is, at the recorded scan', async () => {
  await plants.openExercise('Box sorter (machine: boxes)', 20);
  await plants.startAndFastForward(400);
  // The first recorded scan the photo-eye at the pusher read ON.
  await page.getByTestId('history-condition').fill('PusherEye');
  await page.getByTestId('history-find').click();
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toMatch(/^Recorded scan /);
  const status = (await page.getByTestId('plant-status').textContent())!;
  const scan = /^Recorded scan ([\d,]+)/.exec(status)![1]!;
  await sim.tab('Why?');
  await page.getByTestId('why-input').fill('PusherEye');
  await page.getByTestId('why-ask').click();
  const why = page.getByTestId('why-explanation');
  await expect.poll(() => why.textContent()).toContain(`PusherEye is TRUE after scan ${scan}`);
  expect(await why.textContent()).toMatch(
    /the photo-eye at the pusher at 2\.08 m is ON while a box breaks its beam; box 1 \(small\) is in front of it, its front edge at 2\.0[89] m, so it is ON/,
  );
  await sim.tab('Plant');
  expect(errors).toEqual([]);
});

test('a consequence opens its scan with the time it gave, as the History gives it; live, the panel gives the toolbar\'s time', async () => {
  await page.getByTestId('history-live').click();
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toMatch(/^After scan /);
  await page.getByTestId('plant-fault-size_stuck_off').check();
  await expect.poll(async () => (await plants.plant())!.now.faults).toEqual(['size_stuck_off']);
  await plants.fastForward(600);
  // Live: after scan N at 20 ms the toolbar gives the scan's time, (N - 1) x 20 ms; so does the panel.
  const live = await plants.simScan();
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toBe(
    `After scan ${live.toLocaleString('en-US')} (${(((live - 1) * 20) / 1000).toFixed(2)} s)`,
  );
  const event = page.getByTestId('plant-events').getByRole('button', { name: /\(large\) ran into the small-box bin at scan/ }).first();
  const [, scan, time] = /at scan ([\d,]+) \((\d+\.\d\d) s\)/.exec((await event.textContent())!)!;
  await event.click();
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toBe(`Recorded scan ${scan} (${time} s)`);
  await expect.poll(() => page.getByTestId('history-marker').textContent()).toBe(`HISTORY scan ${scan} · ${time}0 s`);
  const n = Number(scan!.replace(/,/g, ''));
  expect(Number(time)).toBeCloseTo(((n - 1) * 20) / 1000, 5);
  // The fault box at that recorded scan (checked: the fault was set then) clears the live fault and goes back to Live.
  await page.getByTestId('plant-fault-size_stuck_off').uncheck();
  await page.getByTestId('history-marker').filter({ hasText: 'Live' }).waitFor();
  await expect.poll(async () => (await plants.plant())!.now.faults).toEqual([]);
  expect(errors).toEqual([]);
});

test('paused at a breakpoint inside a scan, the panel shows the machine after the scan before, with that scan\'s time', async () => {
  const network = await page.evaluate(
    () =>
      window.rungsmith!.documentStore!.getState().project.pous[0]!.networks.find((n) => n.title === 'Pusher')!.id,
  );
  type Breakpoints = { simStore: { getState(): { toggleBreakpoint(id: string): void } } };
  await page.evaluate((id) => (window.rungsmith as unknown as Breakpoints).simStore.getState().toggleBreakpoint(id), network);
  await sim.button('run').click();
  await page.waitForFunction(() => (window.rungsmith as unknown as { simStore: { getState(): { breakpointHit?: number } } }).simStore.getState().breakpointHit !== undefined, null, { timeout: 30_000 });
  await sim.waitForMode('Paused');
  // Scan N stopped before its Pusher network: the machine is as scan N - 1 left it.
  const scan = await plants.simScan();
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toBe(
    `After scan ${(scan - 1).toLocaleString('en-US')} (${(((scan - 2) * 20) / 1000).toFixed(2)} s)`,
  );
  await page.evaluate((id) => (window.rungsmith as unknown as Breakpoints).simStore.getState().toggleBreakpoint(id), network);
  expect(errors).toEqual([]);
});

test('a stuck limit switch or floor sensor is drawn as the program reads it: dark at its stop, lit with no car, as before when cleared', async () => {
  // The garage door starts closed: its Closed limit lamp (left of the track, at the floor) is lit.
  await plants.openExercise('Garage door (machine: garage)', 100);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await expect.poll(() => plants.drawnColour(14, 216)).toBe(LAMP_LIT);
  await page.getByTestId('plant-fault-closed_stuck_off').check();
  await expect.poll(async () => (await plants.plant())?.now.faults).toEqual(['closed_stuck_off']);
  await expect.poll(() => plants.drawnColour(14, 216)).toBe(LAMP_UNLIT);
  await page.getByTestId('plant-fault-closed_stuck_off').uncheck();
  await expect.poll(() => plants.drawnColour(14, 216)).toBe(LAMP_LIT);
  // The lift's car waits at floor 1: its AtFloor1 lamp on the shaft wall is lit, AtFloor2's dark;
  // with the floor 2 sensor stuck ON, AtFloor2's lamp is lit with no car there.
  await plants.openExercise('Three-floor lift (machine: lift)', 20);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await expect.poll(() => plants.drawnColour(206, 280)).toBe(LAMP_LIT);
  await expect.poll(() => plants.drawnColour(206, 190)).toBe(LAMP_UNLIT);
  await page.getByTestId('plant-fault-floor2_stuck_on').check();
  await expect.poll(() => plants.drawnColour(206, 190)).toBe(LAMP_LIT);
  await page.getByTestId('plant-fault-floor2_stuck_on').uncheck();
  await expect.poll(() => plants.drawnColour(206, 190)).toBe(LAMP_UNLIT);
  expect(errors).toEqual([]);
});


test("the garage door's motor is drawn energised while its contactor drives it against a stop (stalled, speed 0), dark when both are off", async () => {
  // The door starts closed. MotorDown forced ON drives it against the closed stop: it stalls there.
  await plants.openExercise('Garage door (machine: garage)', 100);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  // The motor box over the doorway (its centre 150, 18 in the drawing, clear of the arrow).
  const motor = () => plants.drawnColour(150 - 16, 18);
  await expect.poll(motor).toBe('75,85,99');
  // A scan first: a force is made on a program loaded in the simulator.
  await sim.button('step-scan').click();
  await sim.waitForMode('Paused');
  type Forcing = { simStore: { getState(): { force(n: string, v: { text: string }): void; unforce(n: string): void } } };
  await page.evaluate(() => (window.rungsmith as unknown as Forcing).simStore.getState().force('MotorDown', { text: 'TRUE' }));
  await sim.button('step-scan').click();
  await expect.poll(async () => (await plants.plant<{ down: boolean; speed: number }>())!.now.state).toMatchObject({ down: true, speed: 0 });
  // Amber: the contactor is on although the door does not move (it drew dark, as a motor off).
  await expect.poll(motor).toBe('234,179,8');
  await page.evaluate(() => (window.rungsmith as unknown as Forcing).simStore.getState().unforce('MotorDown'));
  await sim.button('step-scan').click();
  await expect.poll(motor).toBe('75,85,99');
  expect(errors).toEqual([]);
});
