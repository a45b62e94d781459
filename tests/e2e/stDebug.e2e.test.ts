// Debugging ST in the page (issue 25): an ST FB called from LD runs; its editor shows each value
// after the statement that last wrote it, following the scans, and dims the lines that did not run;
// a breakpoint set in the gutter pauses on its line with the path in the status line; step into
// from the LD call and out back to LD; a recorded scan shows its own values; a runaway WHILE loop
// faults naming its line.
import type { Locator, Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { ladder, vars } from '../engine/ladder';
import { box, HYST } from '../engine/stDebugProject';

/** Hyst's body with a count that keeps changing (line 7: modulo instead of doubling). */
const BODY = HYST.replace('Count := Count * 2;', 'Count := Count MOD 10000;');
import { io, stProject, textPou } from '../engine/stHelpers';
import { pou } from '../engine/userBlocksHelpers';
import { openApp, useChromium } from './appPage';
import { poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let errors: string[];
let sim: SimPage;

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
});

/** Main (LD) calls the ST FB Hyst as H1 (network 2, Level 12: above Hi) and H2 (network 3, Other 0: below Lo). */
function project(): Project {
  const lamp = pou('Lamp', 'FUNCTION_BLOCK', [...io('input', 'On BOOL'), ...io('output', 'Lit BOOL')], [ladder(['[On] (Lit)'])]);
  const hyst = textPou(
    'Hyst',
    'FUNCTION_BLOCK',
    [...io('input', 'X INT', 'Hi INT', 'Lo INT'), ...io('output', 'Q BOOL', 'Shown BOOL'), ...vars('Count INT', 'Twice INT', 'L Lamp')],
    BODY,
  );
  const main = pou('Main', 'PROGRAM', vars('Go BOOL := TRUE', 'Level INT := 12', 'Other INT', 'On1 BOOL', 'On2 BOOL', 'Before BOOL', 'After BOOL', 'H1 Hyst', 'H2 Hyst'), [
    ladder(['[Go] (Before)']),
    ladder(['[Go] # # (On1)', '. # # .', '. # # .', '. # # .'], { boxes: [box('Hyst', 0, 1, { instance: 'H1', executionControl: true, inputs: { X: 'Level', Hi: '10', Lo: '5' } })] }),
    ladder(['[Go] # # (On2)', '. # # .', '. # # .', '. # # .'], { boxes: [box('Hyst', 0, 1, { instance: 'H2', executionControl: true, inputs: { X: 'Other', Hi: '10', Lo: '5' } })] }),
    ladder(['[Go] (After)']),
  ]);
  return { ...stProject([main, hyst, lamp]), name: 'StDebug' };
}

async function openPou(name: string): Promise<void> {
  await page.getByTestId('tab-project').click();
  await page.getByTestId(`tree-pou-${name}`).getByRole('button', { name: new RegExp(name) }).first().click();
}

const editor = (): Locator => page.getByTestId('st-editor');
const line = (n: number): Locator => editor().locator('.cm-content .cm-line').nth(n - 1);
/** The inline values shown at the end of line n ('' when none). */
const valuesOn = async (n: number): Promise<string> => ((await line(n).locator('[data-testid="st-inline-values"]').count()) ? ((await line(n).locator('[data-testid="st-inline-values"]').textContent()) ?? '') : '');
const ran = (n: number) => line(n).getAttribute('data-st-run');
const position = () => page.getByTestId('sim-position').textContent();
const countShown = async () => Number(/Count = (\d+)/.exec(await valuesOn(7))?.[1] ?? NaN);

test('inline values follow the scans, lines that did not run are dim, per picked instance', async () => {
  await sim.load(project());
  await openPou('Hyst');
  await editor().locator('.cm-content').waitFor();
  await sim.button('run').click();
  await sim.waitForMode('Running');
  const picker = page.getByTestId('instance-picker');
  await poll(() => picker.inputValue()).toBe('H1');
  // H1: X = 12 > Hi: Q := TRUE on line 2; the ELSIF (3) and line 4 did not run.
  await poll(() => valuesOn(2)).toBe('Q = TRUE');
  await poll(() => ran(3)).toBe('no');
  expect(await ran(4)).toBe('no');
  expect(await ran(1)).toBe('yes');
  expect(await valuesOn(8)).toMatch(/^Twice = \d+$/);
  // The values follow: Count grows from scan to scan.
  const first = await countShown();
  await poll(async () => (await countShown()) !== first).toBe(true);
  // H2 (X = 0 < Lo): line 4 wrote Q FALSE, line 2 did not run.
  await picker.selectOption('H2');
  await poll(() => valuesOn(4)).toBe('Q = FALSE');
  await poll(() => ran(2)).toBe('no');
  expect(await valuesOn(2)).toBe('');
  await picker.selectOption('H1');
  await poll(() => valuesOn(2)).toBe('Q = TRUE');
  expect(errors).toEqual([]);
});

test('a breakpoint on a line pauses there with the path; step into from LD and out back; a recorded scan shows its values', async () => {
  // Click in the breakpoint gutter of line 7 (every instance).
  const gutterBox = (await editor().locator('.cm-st-breakpoint-gutter').boundingBox())!;
  const lineBox = (await line(7).boundingBox())!;
  await page.mouse.click(gutterBox.x + gutterBox.width / 2, lineBox.y + lineBox.height / 2);
  await editor().getByTestId('st-breakpoint').waitFor();
  await sim.waitForMode('Paused');
  await poll(position).toBe('▶ Main / network 2 → H1 (Hyst) / line 7');
  await poll(() => editor().getByTestId('st-pause-line').textContent()).toBe('Count := Count MOD 10000;');
  // Paused before line 7: the value shown for Count is line 6's.
  await poll(() => valuesOn(6)).toMatch(/^Count = \d+$/);
  expect(await valuesOn(7)).toBe('');
  // Remove the breakpoint (F9 on the cursor line), then step over line 7: its value appears.
  await line(7).click();
  await page.keyboard.press('F9');
  await editor().getByTestId('st-breakpoint').waitFor({ state: 'detached' });
  await sim.button('step-network').click();
  await poll(position).toBe('▶ Main / network 2 → H1 (Hyst) / line 8');
  await poll(() => valuesOn(7)).toMatch(/^Count = \d+$/);
  // Step out: back in the LD program, before network 3 (which calls H2).
  await page.getByTestId('sim-step-out').click();
  await poll(position).toBe('▶ Main / network 3');
  // Step into the call from LD: H2's first statement, shown with H2 picked.
  await page.getByTestId('sim-step-into').click();
  await poll(position).toBe('▶ Main / network 3 → H2 (Hyst) / line 1');
  await poll(() => page.getByTestId('instance-picker').inputValue()).toBe('H2');
  await poll(() => editor().getByTestId('st-pause-line').textContent()).toBe('IF X > Hi THEN');
  // Into L (the LD FB called on line 9) from the ST body, then out of it and out of H2.
  for (let k = 0; k < 6; k++) await sim.button('step-network').click();
  await poll(position).toBe('▶ Main / network 3 → H2 (Hyst) / line 9');
  await page.getByTestId('sim-step-into').click();
  await poll(position).toBe('▶ Main / network 3 → H2 (Hyst) / line 9 → H2.L (Lamp) / network 1');
  await page.getByTestId('sim-step-out').click();
  await poll(position).toBe('▶ Main / network 4');

  // The recorded scans: back to the previous scan, whose Count on line 7 is smaller than now's.
  await page.getByTestId('sim-step-out').click();
  await openPou('Hyst');
  await page.getByTestId('instance-picker').selectOption('H1');
  // H1 is observed from the next scan on (only the shown instance is): two whole scans, so the
  // scan before the live one has H1's values too. (The scan that step out finished may end before
  // or after H1 is picked: one step alone left the previous scan without them now and then.)
  const scanShown = async () => Number((await page.getByTestId('sim-scan').textContent())?.replace(/,/g, ''));
  for (let k = 0; k < 2; k++) {
    const before = await scanShown();
    await sim.button('step-scan').click();
    await poll(scanShown).toBeGreaterThan(before);
  }
  await poll(async () => Number.isFinite(await countShown())).toBe(true);
  const live = await countShown();
  await page.getByTestId('history-prev').click();
  await page.getByTestId('history-marker').filter({ hasText: 'HISTORY' }).waitFor();
  // The recorded scan's value, once shown (while the page asks the worker for it, line 7 shows none).
  await poll(async () => {
    const v = await countShown();
    return Number.isFinite(v) && v !== live;
  }).toBe(true);
  const older = await countShown();
  // Count goes up by one each scan: the recorded scan's value leads to the live one.
  expect((older + 1) % 10000).toBe(live);
  await page.getByTestId('history-live').click();
  await poll(countShown).toBe(live);
  expect(errors).toEqual([]);
});

test('a runaway WHILE loop in an ST FB faults naming the line, shown in the editor', async () => {
  const spin = textPou('Spin', 'FUNCTION_BLOCK', [...io('input', 'Run BOOL'), ...vars('N DINT')], 'N := 0;\nWHILE Run DO\n  N := N + 1;\nEND_WHILE;');
  const main = pou('Main', 'PROGRAM', vars('Go BOOL := TRUE', 'S1 Spin'), [ladder(['[Go] # # .', '. # # .'], { boxes: [box('Spin', 0, 1, { instance: 'S1' })] })]);
  await page.getByTestId('sim-reset').click();
  await sim.load({ ...stProject([main, spin]), name: 'Runaway' });
  await openPou('Spin');
  await editor().locator('.cm-content').waitFor();
  await sim.button('run').click();
  await sim.waitForMode('Faulted');
  await poll(() => page.getByTestId('sim-fault').textContent()).toMatch(/Watchdog fault in S1 \(Spin\) line 2: .*looping in the loop at line 2 of S1 \(Spin\)/);
  await poll(() => editor().getByTestId('st-fault-line').textContent()).toBe('WHILE Run DO');
  expect(errors).toEqual([]);
});
