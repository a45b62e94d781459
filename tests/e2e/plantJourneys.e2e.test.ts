// The machines as a user meets them (issue 26), in real Chromium against the real server: a new
// project built from scratch against a machine (choose it, declare its I/O, draw a rung, run it
// fast-forwarded with Step N, rewire a point, the I/O map saying what the program has at each
// address, undo it; export it as PLCopen XML and import it back with its machine), and the
// drawing's operator buttons readable in the dark theme. One page for the whole file.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let draw: DrawPage;
let errors: string[];

const plantState = () =>
  page.evaluate(
    () =>
      (
        window.rungsmith as unknown as {
          simStore: {
            getState(): {
              plant?: { id: string; now: { scan: number; state: Record<string, unknown>; faults: string[] } };
            };
          };
        }
      ).simStore.getState().plant,
  );
const docPlant = () =>
  page.evaluate(
    () =>
      (window.rungsmith as unknown as { documentStore: { getState(): { project: { plant?: unknown } } } }).documentStore.getState()
        .project.plant,
  );
const faults = async () => (await plantState())?.now.faults;
const scan = () =>
  page.evaluate(() => (window.rungsmith as unknown as { simStore: { getState(): { scan: number } } }).simStore.getState().scan);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  draw = new DrawPage(page);
});

/** WCAG contrast ratio of two computed CSS colours (rgb()/rgba()). */
function contrast(a: string, b: string): number {
  const lum = (c: string) => {
    const [r, g, bl] = c.match(/[\d.]+/g)!.slice(0, 3).map((x) => {
      const v = Number(x) / 255;
      return v <= 0.03928 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4;
    });
    return 0.2126 * r! + 0.7152 * g! + 0.0722 * bl!;
  };
  const [hi, lo] = [lum(a), lum(b)].sort((x, y) => y - x);
  return (hi! + 0.05) / (lo! + 0.05);
}

test("the drawing's operator buttons and the panel's status stay readable in the dark theme; a held button springs back; stuck ON clears stuck OFF; the I/O map fits the panel", async () => {
  await sim.openExample('Tank level control (machine: tank)');
  await sim.tab('Plant');
  await page.getByTestId('theme-toggle').click();
  await expect.poll(() => page.evaluate(() => document.documentElement.dataset.theme)).toBe('dark');
  for (const id of ['plant-op-Start', 'plant-op-Stop', 'plant-status']) {
    const colours = await page.getByTestId(id).evaluate((el) => {
      let bg = 'rgba(0, 0, 0, 0)';
      for (let e: Element | null = el; e && /rgba\(0, 0, 0, 0\)|transparent/.test(bg); e = e.parentElement)
        bg = getComputedStyle(e).backgroundColor;
      return { fg: getComputedStyle(el).color, bg };
    });
    expect(contrast(colours.fg, colours.bg), `${id}: ${colours.fg} on ${colours.bg}`).toBeGreaterThanOrEqual(4.5);
  }
  await page.getByTestId('theme-toggle').click();
  // A push button held from the keyboard springs back when the focus leaves it (Tab while held),
  // once a scan has read it (stopped, the next step; qaM3: a click is never lost when stepping).
  const start = page.getByTestId('plant-op-Start');
  await start.focus();
  await page.keyboard.down(' ');
  await expect.poll(() => start.getAttribute('aria-pressed')).toBe('true');
  await page.keyboard.press('Tab');
  await page.keyboard.up(' ');
  await sim.button('step-scan').click();
  await expect.poll(() => start.getAttribute('aria-pressed')).toBe('false');
  // A switch is stuck ON or OFF, not both: setting one fault of the pair clears the other.
  await page.getByTestId('plant-fault-high_stuck_off').check();
  await expect.poll(faults).toEqual(['high_stuck_off']);
  await page.getByTestId('plant-fault-high_stuck_on').check();
  await expect.poll(faults).toEqual(['high_stuck_on']);
  await expect.poll(() => page.getByTestId('plant-fault-high_stuck_off').isChecked()).toBe(false);
  await page.getByTestId('plant-fault-high_stuck_on').uncheck();
  await expect.poll(faults).toEqual([]);
  // The I/O map fits the panel: nothing cut off at its right edge.
  const fit = await page.getByTestId('plant-panel').evaluate((panel) => ({
    table: panel.querySelector('[data-testid="plant-io"]')!.getBoundingClientRect().right,
    panel: panel.getBoundingClientRect().right,
  }));
  expect(fit.table).toBeLessThanOrEqual(fit.panel);
  expect(errors).toEqual([]);
});

test('a new project against the garage door: choose it, declare its I/O, draw a rung, step it; rewiring a point is undone by Undo', async () => {
  await draw.menu('File', 'New project');
  await sim.tab('Plant');
  await page.getByTestId('plant-choose').selectOption('garage');
  await expect.poll(docPlant).toEqual({ id: 'garage' });
  await expect.poll(() => page.getByTestId('plant-wired-MotorUp').textContent()).toBe('not wired');
  await page.getByTestId('plant-declare').click();
  await expect.poll(() => page.getByTestId('plant-declared').textContent()).toMatch(/^Declared 10 variables in Main: KeyOpen, /);
  await expect.poll(() => page.getByTestId('plant-wired-MotorUp').textContent()).toBe('MotorUp');
  // The door runs up until its open limit: OpenLimit (NC) -> MotorUp.
  await page.getByTestId('tab-palette').click();
  await draw.pickPalette('contact-NC');
  await draw.clickCell(0, 0, 0);
  await draw.typeName('OpenLimit');
  await draw.pickPalette('coil-COIL');
  await draw.clickCell(0, 0, 9);
  await draw.typeName('MotorUp');
  await draw.pickPalette('link');
  for (let col = 1; col <= 8; col++) await draw.clickCell(0, 0, col);
  await draw.pickPalette('select');
  await expect.poll(() => draw.problemsSummary()).toBe('No problems');
  await page.getByTestId('sim-cycle').fill('100');
  await page.getByTestId('sim-cycle').press('Enter');
  await page.getByTestId('sim-step-count').fill('200');
  await sim.button('step-n').click();
  await expect.poll(scan, { timeout: 60_000 }).toBeGreaterThanOrEqual(200);
  // 12 s end to end: open in 20 s of PLC time, stopped at the limit.
  await expect.poll(async () => (await plantState())?.now.state.position, { timeout: 30_000 }).toBeGreaterThanOrEqual(99);
  expect((await plantState())!.now.state.up).toBe(false);
  await expect.poll(() => page.getByTestId('plant-q-position').textContent()).toMatch(/^garage\.position(99|100)\.\d %$/);
  // Taken away and chosen again while paused at scan 200: the door starts over, and says it moves
  // from the next scan (not "After scan 0"); one step later it is the next scan's.
  const paused = await scan();
  await page.getByTestId('plant-choose').selectOption('');
  await page.getByTestId('plant-choose').selectOption('garage');
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toBe('Initial state: it moves from the next scan on');
  // The status is one line whatever it says: the drawing's buttons below it do not move under the pointer.
  const statusHeight = async () => (await page.getByTestId('plant-status').boundingBox())!.height;
  const startTop = async () => (await page.getByTestId('plant-op-KeyOpen').boundingBox())!.y;
  const [height, top] = [await statusHeight(), await startTop()];
  await sim.button('step-scan').click();
  await expect.poll(() => page.getByTestId('plant-status').textContent()).toMatch(new RegExp(`^After scan ${paused + 1} \\(`));
  expect(await statusHeight()).toBe(height);
  expect(await startTop()).toBe(top);

  // Rewire the motor's up contactor, then Undo: the address comes back (not the rung drawn before).
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  const address = page.getByTestId('plant-address-MotorUp');
  await address.fill('%QX1.5');
  await address.press('Enter');
  await expect.poll(docPlant).toEqual({ id: 'garage', map: { MotorUp: '%QX1.5' } });
  // The program still drives %QX0.0: the map says the motor is no longer connected to it.
  await expect
    .poll(() => page.getByTestId('plant-wired-MotorUp').textContent())
    .toBe('not wired: MotorUp is at %QX0.0');
  await draw.menu('Edit', 'Undo');
  await expect.poll(docPlant).toEqual({ id: 'garage' });
  await expect.poll(() => page.getByTestId('plant-address-MotorUp').inputValue()).toBe('%QX0.0');
  expect((await draw.elements(0)).length).toBeGreaterThanOrEqual(10);
  await draw.menu('Edit', 'Redo');
  await expect.poll(() => page.getByTestId('plant-address-MotorUp').inputValue()).toBe('%QX1.5');
  // None, then Undo: the garage and its map again.
  await page.getByTestId('plant-choose').selectOption('');
  await expect.poll(docPlant).toBe(undefined);
  await draw.menu('Edit', 'Undo');
  await expect.poll(docPlant).toEqual({ id: 'garage', map: { MotorUp: '%QX1.5' } });
  expect(errors).toEqual([]);
});

test('the machine and its rewired point survive File > Export PLCopen XML and Import PLCopen XML…; Declare the machine\'s I/O then moves the variable to the new address', async () => {
  // The project of the test before: the garage, MotorUp rewired to %QX1.5.
  await expect.poll(docPlant).toEqual({ id: 'garage', map: { MotorUp: '%QX1.5' } });
  const editor = new EditorPage(page);
  const file = await editor.download(async () => {
    await draw.menu('File', 'Export PLCopen XML');
    const anyway = page.getByTestId('export-review').getByRole('button', { name: 'Export anyway' });
    if (await anyway.isVisible().catch(() => false)) await anyway.click();
  });
  expect(file.text).toContain('<point name="MotorUp" address="%QX1.5"/>');
  await draw.menu('File', 'New project');
  await page.getByRole('button', { name: 'Discard and start new' }).click();
  await expect.poll(docPlant).toBe(undefined);
  await editor.chooseFile('File', 'Import PLCopen XML…', { name: file.name, mimeType: 'application/xml', text: file.text });
  const report = page.getByTestId('plcopen-report');
  await expect.poll(() => report.getByTestId('plcopen-extras').textContent()).toContain('Machine: garage.');
  await report.getByRole('button', { name: 'Open' }).click();
  await expect.poll(docPlant).toEqual({ id: 'garage', map: { MotorUp: '%QX1.5' } });
  await sim.tab('Plant');
  await expect.poll(() => page.getByTestId('plant-address-MotorUp').inputValue()).toBe('%QX1.5');
  // Declare the machine's I/O moves the variable to the rewired address, as one undo step.
  await expect.poll(() => page.getByTestId('plant-wired-MotorUp').textContent()).toBe('not wired: MotorUp is at %QX0.0');
  await page.getByTestId('plant-declare').click();
  await expect.poll(() => page.getByTestId('plant-declared').textContent()).toBe('Moved MotorUp from %QX0.0 to %QX1.5.');
  await expect.poll(() => page.getByTestId('plant-wired-MotorUp').textContent()).toBe('MotorUp');
  await draw.menu('Edit', 'Undo');
  await expect.poll(() => page.getByTestId('plant-wired-MotorUp').textContent()).toBe('not wired: MotorUp is at %QX0.0');
  expect(errors).toEqual([]);
});
