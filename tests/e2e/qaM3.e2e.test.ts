// A student's first day with the machines (issue 26), third round of exploratory QA, in real
// Chromium against the real server: what a newcomer met that the rounds before did not cover.
// One page for the whole file; each test says what it starts from.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { appUrl, openApp, useChromium, waitForApp } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
});

/** Opens an example from File > Examples, discarding the project before if the app asks. */
async function openExample(title: string): Promise<void> {
  await sim.draw.menu('File', `Example: ${title}`);
  const discard = page.getByRole('button', { name: 'Discard and open' });
  const opened = page.getByTestId('project-name').filter({ hasText: title.split(' ')[0]! });
  await Promise.race([discard.waitFor().then(() => discard.click()), opened.waitFor()]);
  await opened.waitFor();
}

const rows = () => page.getByTestId('tests-row');

/** Runs the Tests tab's scenario in row `i` and gives what its run says (PASS in … / FAIL at …). */
async function runScenario(i: number): Promise<string> {
  const close = page.getByTestId('scenario-run').getByRole('button', { name: 'Close' });
  if (await close.isVisible().catch(() => false)) await close.click();
  await rows().nth(i).getByTestId('tests-open').click();
  const result = page.getByTestId('scenario-run-result');
  await result.waitFor({ timeout: 60_000 });
  return (await result.textContent()) ?? '';
}

test("a scenario run from the Tests tab starts with no fault set: a troubleshooting scenario's fault does not stay for the next run", async () => {
  await openExample('Tank level control (machine: tank)');
  await sim.tab('Tests');
  expect(await runScenario(0)).toBe('PASS in 3000 scans');
  // A troubleshooting scenario: the pump motor does not start, so the pump never runs.
  await page.getByTestId('tests-new').click();
  const editor = page.getByTestId('scenario-editor');
  await editor.getByRole('textbox', { name: 'Name' }).fill('Dead pump');
  await editor
    .getByLabel('Scenario CSV')
    .fill(
      '# plant: tank\n# cycle: 100ms\nscan,tank.Start,fault pump_dead,expect tank.pump\n1,1,1,\n50,,,0\n',
    );
  await editor.getByRole('button', { name: 'Save scenario' }).click();
  expect(await runScenario(1)).toBe('PASS in 50 scans');
  // The reference solution still holds the tank: the dead pump was that scenario's, not this one's.
  expect(await runScenario(0)).toBe('PASS in 3000 scans');
  expect(errors).toEqual([]);
});

test("a scenario run from the Tests tab uses the project's I/O map, as `rungsmith test` does: the pump rewired with its variable still fills the tank", async () => {
  await openExample('Tank level control (machine: tank)');
  await sim.tab('Plant');
  const address = page.getByTestId('plant-address-Pump');
  await address.fill('%QX1.0');
  await address.press('Enter');
  await page.getByTestId('plant-declare').click();
  await expect
    .poll(() => page.getByTestId('plant-declared').textContent())
    .toBe('Moved Pump from %QX0.0 to %QX1.0.');
  await expect.poll(() => page.getByTestId('plant-wired-Pump').textContent()).toBe('Pump');
  await sim.tab('Tests');
  // It failed at scan 600 with the level still at 100 L: the replay's tank had its pump at %QX0.0.
  expect(await runScenario(0)).toBe('PASS in 3000 scans');
  expect(errors).toEqual([]);
});

test("a refused address keeps its problem and its mark while another point is rewired; Esc gives the point's address back", async () => {
  await openExample('Tank level control (machine: tank)');
  await sim.tab('Plant');
  const pump = page.getByTestId('plant-address-Pump');
  await pump.fill('hello');
  await pump.press('Tab');
  const problems = page.getByTestId('plant-io-problem');
  await expect
    .poll(() => problems.allTextContents())
    .toEqual(['Pump: "hello" is not an IEC address (%IX0.0, %IW2, %QX1.3)']);
  // Another point rewired: the field still says "hello", so its problem stays said (it vanished,
  // leaving Pump's field showing an address the pump does not have and no error).
  const lamp = page.getByTestId('plant-address-RunLamp');
  await lamp.fill('%QX1.3');
  await lamp.press('Enter');
  await expect
    .poll(() => page.getByTestId('plant-wired-RunLamp').textContent())
    .toBe('not wired: RunLamp is at %QX0.3');
  expect(await problems.allTextContents()).toEqual([
    'Pump: "hello" is not an IEC address (%IX0.0, %IW2, %QX1.3)',
  ]);
  expect(await pump.inputValue()).toBe('hello');
  expect(await pump.getAttribute('aria-invalid')).toBe('true');
  expect(await lamp.getAttribute('aria-invalid')).toBe('false');
  // Esc: the pump's address back in its field, nothing left to say.
  await pump.press('Escape');
  await expect.poll(() => pump.inputValue()).toBe('%QX0.0');
  await expect.poll(() => problems.count()).toBe(0);
  expect(await pump.getAttribute('aria-invalid')).toBe('false');
  expect(errors).toEqual([]);
});

test('the app open in a second tab of the same browser: both tabs say they share one autosave (a reload keeps only the tab changed last); closing one, the other stops saying it', async () => {
  // Two tabs of one browser profile (one context: one IndexedDB and localStorage).
  const context = await browser().newContext();
  try {
    const first = await context.newPage();
    await first.goto(appUrl());
    await waitForApp(first);
    expect(await first.getByTestId('other-tab-notice').count()).toBe(0);
    const second = await context.newPage();
    await second.goto(appUrl());
    await waitForApp(second);
    for (const tab of [first, second])
      await expect
        .poll(() => tab.getByTestId('other-tab-notice').textContent(), { timeout: 30_000 })
        .toContain('Rungsmith is also open in another tab of this browser. The tabs share one autosave');
    // A reload is not another tab.
    await second.reload();
    await waitForApp(second);
    await expect.poll(() => second.getByTestId('other-tab-notice').count(), { timeout: 30_000 }).toBe(1);
    await second.close();
    await expect.poll(() => first.getByTestId('other-tab-notice').count(), { timeout: 30_000 }).toBe(0);
  } finally {
    await context.close();
  }
  expect(errors).toEqual([]);
});

test('a reload in the middle of a machine exercise brings the work back with the machine in view: the Plant tab, the machine and its rewired point', async () => {
  await openExample('Garage door (machine: garage)');
  await sim.tab('Plant');
  const address = page.getByTestId('plant-address-WarningLamp');
  await address.fill('%QX1.7');
  await address.press('Enter');
  await expect
    .poll(() => page.getByTestId('plant-wired-WarningLamp').textContent())
    .toBe('not wired: WarningLamp is at %QX0.2');
  // The change is autosaved (the status says when), then the page is reloaded.
  await expect
    .poll(() => page.getByTestId('autosave-status').getAttribute('data-pending'), { timeout: 30_000 })
    .toBe('false');
  await page.reload();
  await page
    .getByTestId('file-notice')
    .filter({ hasText: 'Restored "Garage door"' })
    .waitFor({ timeout: 30_000 });
  await expect
    .poll(() => page.getByRole('tab', { name: 'Plant' }).getAttribute('aria-selected'))
    .toBe('true');
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('garage');
  expect(await page.getByTestId('plant-address-WarningLamp').inputValue()).toBe('%QX1.7');
  expect(await page.locator('.rs-plant-drawing canvas').isVisible()).toBe(true);
  expect(errors).toEqual([]);
});

test('a wrong solution that overflows the tank fails its scenario at the scan of the overflow: the run says FAIL, not "did not run", and Why? shows the machine there', async () => {
  await openExample('Tank level control (machine: tank)');
  // The classic mistake: nothing stops filling at the high switch.
  await page.getByRole('button', { name: 'Delete network 4' }).click();
  await expect
    .poll(async () => (await sim.draw.networks()).map((n) => n.title))
    .not.toContain('Stop filling');
  await sim.tab('Tests');
  expect(await runScenario(0)).toMatch(/^FAIL: the tank overflowed at scan [\d,]+ \([\d.]+ s\)$/);
  expect(await rows().nth(0).getByTestId('tests-failure').textContent()).toMatch(
    /^the tank overflowed at scan [\d,]+ /,
  );
  // "Why it failed" explains the machine at that scan, as it does a divergence: the pump and the
  // inlet still driven with the tank full, and ◀ steps back through the run.
  const scan = Number(
    (await page.getByTestId('scenario-run-result').textContent())!
      .match(/scan ([\d,]+)/)![1]!
      .replace(/,/g, ''),
  );
  const title = page.getByTestId('scenario-why-title');
  await expect
    .poll(() => title.textContent(), { timeout: 30_000 })
    .toBe(`tank.overflows is 1 after scan ${scan.toLocaleString('en-US')}`);
  expect(await page.getByTestId('scenario-why').textContent()).toMatch(/pump 100\.0 %, inlet 100\.0 %/);
  await page.getByTestId('scenario-why').getByRole('button', { name: 'Previous scan' }).click();
  await expect
    .poll(() => title.textContent())
    .toBe(`tank.overflows is 0 after scan ${(scan - 1).toLocaleString('en-US')}`);
  expect(errors).toEqual([]);
});

test("an exercise's task is the first thing under the machine: its goal in one line above the drawing, the whole text and I/O table a click away", async () => {
  await openExample('Three-floor lift (machine: lift)');
  await sim.tab('Plant');
  const goal = page.getByTestId('plant-task-goal');
  await expect.poll(() => goal.textContent()).toBe('Task: Answer the calls of a three-floor lift.');
  // Above the drawing, in view without scrolling the panel (it was last, under the I/O map).
  const [summary, drawing, panel] = await Promise.all([
    goal.boundingBox(),
    page.locator('.rs-plant-drawing').boundingBox(),
    page.getByTestId('plant-panel').boundingBox(),
  ]);
  expect(summary!.y + summary!.height).toBeLessThanOrEqual(drawing!.y);
  expect(summary!.y).toBeGreaterThanOrEqual(panel!.y);
  const text = page.getByTestId('plant-task');
  expect(await text.isVisible()).toBe(false);
  await goal.click();
  await expect.poll(() => text.isVisible()).toBe(true);
  expect(await text.textContent()).toMatch(/I\/O:\n%IX0\.0 +Call1 /);
  expect(errors).toEqual([]);
});

test("a machine's point named on a contact in a new project is declared at the machine's address by Enter; a name of the program's own gets no machine wire; part of a point's name offers the point", async () => {
  await sim.draw.menu('File', 'New project');
  const discard = page.getByRole('button', { name: 'Discard and start new' });
  if (await discard.isVisible().catch(() => false)) await discard.click();
  await expect.poll(async () => (await sim.draw.networks()).length).toBe(1);
  await sim.tab('Plant');
  await page.getByTestId('plant-choose').selectOption('tank');
  await expect.poll(() => page.getByTestId('plant-wired-LowLevel').textContent()).toBe('not wired');
  // Drawn from the keyboard, without "Declare the machine's I/O": the offer under the name says
  // where the machine has it, and Enter takes it (it declared LowLevel with no address: not wired).
  await sim.draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  const input = page.getByTestId('inline-editor');
  await input.waitFor();
  await input.fill('LowLevel');
  await expect
    .poll(() => page.locator('li[role="option"][aria-selected="true"]').textContent())
    .toBe("Declare LowLevelBOOL input at %IX0.2, the machine's LowLevel");
  await page.keyboard.press('Enter');
  await input.waitFor({ state: 'detached' });
  await expect.poll(() => page.getByTestId('plant-wired-LowLevel').textContent()).toBe('LowLevel');
  // A name of the program's own offered as an input is not put on the machine's Start button (%IX0.0).
  await page.keyboard.press('c');
  await input.waitFor();
  await input.fill('Reset');
  const offers = await page.locator('li[role="option"]').allTextContents();
  expect(offers).toContain('Declare ResetBOOL input at %IX0.4');
  expect(offers.join('\n')).not.toContain('%IX0.0');
  // Part of a point's name: the machine's point is offered too, below the name typed (Enter keeps "High").
  await input.fill('High');
  await expect
    .poll(() => page.locator('li[role="option"]').allTextContents())
    .toContain("Declare HighLevelBOOL input at %IX0.3, the machine's HighLevel");
  expect(await page.locator('li[role="option"][aria-selected="true"]').textContent()).toBe(
    'Declare HighBOOL',
  );
  await page.keyboard.press('Escape');
  expect(errors).toEqual([]);
});

test('a reload keeps the faults set on purpose and a switch turned ON, as Reset does (the machine starts over); push buttons spring back', async () => {
  await openExample('Garage door (machine: garage)');
  await sim.tab('Plant');
  const plant = () =>
    page.evaluate(
      () =>
        (
          window.rungsmith as unknown as {
            simStore: {
              getState(): { plant?: { now: { faults: string[]; operator: Record<string, boolean> } } };
            };
          }
        ).simStore.getState().plant?.now,
    );
  const fault = page.getByTestId('plant-fault-open_stuck_off');
  await fault.check();
  await page.getByTestId('plant-op-Doorway').click();
  await expect.poll(async () => (await plant())?.faults).toEqual(['open_stuck_off']);
  await expect.poll(async () => (await plant())?.operator.Doorway).toBe(true);
  await expect
    .poll(() => page.getByTestId('autosave-status').getAttribute('data-pending'), { timeout: 30_000 })
    .toBe('false');
  await page.reload();
  await page
    .getByTestId('file-notice')
    .filter({ hasText: 'Restored "Garage door"' })
    .waitFor({ timeout: 30_000 });
  await expect.poll(async () => (await plant())?.faults, { timeout: 30_000 }).toEqual(['open_stuck_off']);
  await expect.poll(async () => (await plant())?.operator.Doorway).toBe(true);
  expect(await page.getByTestId('plant-fault-open_stuck_off').isChecked()).toBe(true);
  expect(await page.getByTestId('plant-op-Doorway').getAttribute('aria-pressed')).toBe('true');
  expect(await page.getByTestId('plant-op-KeyOpen').getAttribute('aria-pressed')).toBe('false');
  // Cleared, and reloaded again: nothing comes back.
  await page.getByTestId('plant-fault-open_stuck_off').uncheck();
  await page.getByTestId('plant-op-Doorway').click();
  await expect.poll(async () => (await plant())?.faults).toEqual([]);
  await expect.poll(async () => (await plant())?.operator.Doorway).toBe(false);
  await page.reload();
  await page
    .getByTestId('file-notice')
    .filter({ hasText: 'Restored "Garage door"' })
    .waitFor({ timeout: 30_000 });
  await expect.poll(() => page.getByTestId('plant-choose').inputValue()).toBe('garage');
  await expect.poll(async () => (await plant())?.operator.Doorway).toBe(false);
  expect((await plant())?.faults).toEqual([]);
  expect(errors).toEqual([]);
});

test("New scenario in a machine exercise runs against the machine: # plant: tank, the operator's tank.Start and tank.Stop as columns, not the inputs the machine writes", async () => {
  await openExample('Tank level control (machine: tank)');
  await sim.tab('Tests');
  await page.getByTestId('tests-new').click();
  const editor = page.getByTestId('scenario-editor');
  const csv = editor.getByLabel('Scenario CSV');
  await expect.poll(() => csv.inputValue()).toContain('# plant: tank\n');
  expect(await editor.getByTestId('scenario-table').locator('th').allTextContents()).toEqual([
    'scan',
    'tank.Start',
    'tank.Stop',
    'expect Pump',
    'expect InletValve',
    'expect DrainValve',
    'expect RunLamp',
  ]);
  // Filled in from the grid as a newcomer would: Start pressed at scan 1, the lamp lit at scan 3.
  await csv.fill(`${(await csv.inputValue()).replace(/\n1,.*\n$/, '\n1,1,,*,*,*,*\n3,0,,*,*,*,1\n')}`);
  await editor.getByRole('button', { name: 'Save scenario' }).click();
  expect(await runScenario(1)).toBe('PASS in 3 scans');
  expect(errors).toEqual([]);
});

test('a watched or trended machine name whose machine is no longer chosen says so, with nothing to write or force; it reads again when the machine is chosen back', async () => {
  await openExample('Tank level control (machine: tank)');
  await sim.tab('Watch');
  await page.getByTestId('watch-add-name').fill('tank.level');
  await page.getByTestId('watch-add').click();
  const row = page.getByTestId('watch-row-tank.level');
  await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('100.0 L');
  await row.getByRole('checkbox', { name: 'Trend' }).check();
  await sim.tab('Plant');
  await page.getByTestId('plant-choose').selectOption('garage');
  await sim.tab('Watch');
  // It offered Write and Force, and Force said: unknown variable "tank.level".
  await expect.poll(() => row.getByTestId('watch-detached').textContent()).toBe('tank not chosen');
  expect(await row.getByTestId('watch-detached').getAttribute('title')).toBe(
    "The machine tank (Tank level control) is not chosen: the project's machine is garage; choose it in the Plant panel to read tank.level.",
  );
  expect(await row.locator('td').nth(1).textContent()).toBe('REAL');
  expect(await row.getByRole('button').allTextContents()).toEqual(['×']);
  // The trend says it too: no samples come for it (it drew a frozen line).
  await sim.tab('Trend');
  await expect
    .poll(() => page.getByTestId('trend-chip-tank.level').textContent())
    .toBe('tank.level (tank not chosen) ×');
  await sim.tab('Watch');
  await sim.tab('Plant');
  await page.getByTestId('plant-choose').selectOption('tank');
  await sim.tab('Watch');
  await expect.poll(() => row.getByTestId('watch-value').textContent()).toBe('100.0 L');
  await sim.tab('Trend');
  await expect.poll(() => page.getByTestId('trend-chip-tank.level').textContent()).toBe('tank.level ×');
  await page.getByTestId('trend-chip-tank.level').click();
  await sim.tab('Watch');
  await row.getByRole('button', { name: 'Stop watching tank.level' }).click();
  expect(errors).toEqual([]);
});

test("with the side panel at its narrowest, every operator button of every machine stays whole on its drawing (the garage's Doorway ran off its right edge)", async () => {
  const panels = (right: number) =>
    page.evaluate((r) => {
      const p = JSON.parse(localStorage.getItem('rungsmith.panels') ?? '{}') as Record<string, unknown>;
      localStorage.setItem('rungsmith.panels', JSON.stringify({ ...p, right: r }));
    }, right);
  await panels(240);
  try {
    await page.reload();
    await page
      .getByRole('heading', { name: /Rungsmith/ })
      .first()
      .waitFor();
    await sim.tab('Plant');
    await expect
      .poll(async () => (await page.getByTestId('plant-panel').boundingBox())?.width)
      .toBeLessThanOrEqual(240);
    for (const id of ['tank', 'lift', 'garage', 'mixer', 'boxes', 'intersection']) {
      await page.getByTestId('plant-choose').selectOption(id);
      await expect.poll(() => page.locator('.rs-plant-op').count()).toBeGreaterThan(0);
      const drawing = (await page.locator('.rs-plant-drawing').boundingBox())!;
      for (const button of await page.locator('.rs-plant-op').all()) {
        const box = (await button.boundingBox())!;
        const name = await button.textContent();
        expect(box.x, `${id} ${name}`).toBeGreaterThanOrEqual(drawing.x);
        expect(box.x + box.width, `${id} ${name}`).toBeLessThanOrEqual(drawing.x + drawing.width);
        expect(box.y + box.height, `${id} ${name}`).toBeLessThanOrEqual(drawing.y + drawing.height);
        // Whole: its name not cut (the text fits the button).
        expect(await button.evaluate((b) => b.scrollWidth <= b.clientWidth + 1), `${id} ${name}`).toBe(true);
      }
    }
  } finally {
    await panels(340);
  }
  expect(errors).toEqual([]);
});

test('stepping through a start-up: Start clicked on the drawing while paused (or stopped) stays pressed until Step scan has read it, then springs back', async () => {
  await openExample('Tank level control (machine: tank)');
  await sim.tab('Plant');
  const start = page.getByTestId('plant-op-Start');
  // Paused after a step: a click, then Step scan. The click was let go at once, and no step saw it.
  await sim.button('step-scan').click();
  await sim.waitForMode('Paused');
  await start.click();
  await expect.poll(() => start.getAttribute('aria-pressed')).toBe('true');
  expect(await sim.value('Running')).toBe(false);
  await sim.button('step-scan').click();
  await sim.waitForValue('Running', true);
  await expect.poll(() => start.getAttribute('aria-pressed')).toBe('false');
  // Stopped (after Reset) alike: the first step reads it. Reset lets an unread click go.
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await start.click();
  await expect.poll(() => start.getAttribute('aria-pressed')).toBe('true');
  await sim.button('reset').click();
  await expect.poll(() => start.getAttribute('aria-pressed')).toBe('false');
  await start.click();
  await sim.button('step-scan').click();
  await sim.waitForValue('Running', true);
  await expect.poll(() => start.getAttribute('aria-pressed')).toBe('false');
  // The next step does not see it again: Stop then stops the system.
  await page.getByTestId('plant-op-Stop').click();
  await sim.button('step-scan').click();
  await sim.waitForValue('Running', false);
  expect(errors).toEqual([]);
});
