// One-way vertical links in a real Chromium (LD-SEMANTICS section 1). A user draws, with the
// palette and the vertical link tool, a line that fans out and then runs into an OR:
//   |--[A]--+-------( X )
//   |       +--+----( Y )
//   |--[B]-----+
// The page accepts it (before, LD-R01), and running it with B TRUE and A FALSE gives Y TRUE and X
// FALSE, the line from A's junction to the OR bar drawn dark and the OR bar and Y's line lit; with
// A TRUE, that line, A's junction and the bar are lit.
// A U-turn (a line fed only from its right) is still refused with LD-R01 naming the coil.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let sim: SimPage;
let errors: string[];
/** The live checks run shortly after the drawing stops changing. */
const CHECKS = { timeout: 10_000 };

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
  draw = sim.draw;
});

const newProject = (name: string) =>
  page.evaluate((n) => window.rungsmith!.documentStore!.getState().newProject(n), name);

/** Places a palette element at a cell of network 0 and names it (each new name is declared BOOL). */
async function place(tool: string, row: number, col: number, name?: string) {
  // The tool stays armed after a placement (picking it again would put it down).
  if ((await page.getByTestId(`palette-${tool}`).getAttribute('aria-pressed')) !== 'true') await draw.pickPalette(tool);
  await draw.clickCell(0, row, col);
  if (name) await draw.typeName(name);
}

const problems = async () => (await page.getByTestId('problem').allTextContents()).join('\n');

/** Adds a variable to the watch table and returns its row. */
async function watch(name: string) {
  await page.getByTestId('watch-add-name').fill(name);
  await page.getByTestId('watch-add').click();
  return page.getByTestId(`watch-row-${name}`);
}

test('a fan-out into an OR is drawn, accepted and runs one way: B lights Y, not X nor the line from A', async () => {
  await newProject('Fan-out');
  // The checks have seen the empty network first, so "No problems" later is about the drawing.
  await expect.poll(() => draw.problemsSummary(), CHECKS).not.toBe('No problems');
  await place('contact-NO', 0, 0, 'A');
  await place('link', 0, 1);
  await place('coil-COIL', 0, 2, 'X');
  await place('link', 1, 1);
  await place('coil-COIL', 1, 2, 'Y');
  await place('contact-NO', 2, 0, 'B');
  await place('link', 2, 1);
  // A's junction (boundary 1, rows 1-2) and the OR bar where B joins Y's line (boundary 2, rows 2-3).
  await draw.clickVLink(0, 0, 1);
  await draw.clickVLink(0, 1, 2);
  await page.keyboard.press('Escape');
  // The keyboard cursor's frame goes to an empty cell, away from the wires looked at below.
  await draw.clickCell(0, 2, 6);

  const n = (await draw.networks())[0]!;
  expect(n.vlinks).toEqual([
    { row: 0, boundary: 1 },
    { row: 1, boundary: 2 },
  ]);
  expect(await draw.elements(0)).toEqual([
    { kind: 'contact', row: 0, col: 0, name: 'A', type: 'NO' },
    { kind: 'link', row: 0, col: 1 },
    { kind: 'coil', row: 0, col: 2, name: 'X', type: 'COIL' },
    { kind: 'link', row: 1, col: 1 },
    { kind: 'coil', row: 1, col: 2, name: 'Y', type: 'COIL' },
    { kind: 'contact', row: 2, col: 0, name: 'B', type: 'NO' },
    { kind: 'link', row: 2, col: 1 },
  ]);
  const declared = await page.evaluate(() =>
    window.rungsmith!.documentStore!.getState().project.pous[0]!.variables.map((v) => `${v.name}:${v.type}`),
  );
  expect(declared.sort()).toEqual(['A:BOOL', 'B:BOOL', 'X:BOOL', 'Y:BOOL']);
  // Accepted: no LD-R01 (nor any other problem; a failure shows the problems listed).
  await expect.poll(async () => `${await draw.problemsSummary()} ${await problems()}`.trim(), CHECKS).toBe('No problems');

  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.tab('Watch');
  const x = await watch('X');
  const y = await watch('Y');
  const b = await watch('B');
  await expect.poll(() => y.getByTestId('watch-value').textContent()).toBe('FALSE');
  // Write B TRUE once from the watch table (A stays FALSE).
  await b.getByTestId('watch-input').fill('TRUE');
  await b.getByTestId('watch-write').click();
  await sim.waitForValue('B', true);
  await expect.poll(() => y.getByTestId('watch-value').textContent()).toBe('TRUE');
  expect(await x.getByTestId('watch-value').textContent()).toBe('FALSE');
  expect(await sim.value('A')).toBe(false);

  // B's line and the OR bar are lit, and Y's line after it; the line from A's junction to the bar,
  // A's junction and X's line are dark.
  await expect.poll(() => sim.wireLit(0, 2, 1)).toBe(true);
  await expect.poll(() => sim.vlinkLit(0, 1, 2)).toBe(true);
  await expect.poll(() => sim.wireLit(0, 1, 2)).toBe(true);
  expect(await sim.wireLit(0, 1, 1, 'middle')).toBe(false);
  expect(await sim.vlinkLit(0, 0, 1)).toBe(false);
  expect(await sim.wireLit(0, 0, 1, 'middle')).toBe(false);
  expect(await sim.wireLit(0, 0, 2)).toBe(false);

  // Now A TRUE and B FALSE: X and Y both on, and the same probes see A's junction, its line to the
  // bar and the bar lit (so the dark readings above are the drawing's, not the probe's).
  const a = await watch('A');
  await a.getByTestId('watch-input').fill('TRUE');
  await a.getByTestId('watch-write').click();
  await b.getByTestId('watch-input').fill('FALSE');
  await b.getByTestId('watch-write').click();
  await sim.waitForValue('B', false);
  await expect.poll(() => x.getByTestId('watch-value').textContent()).toBe('TRUE');
  expect(await y.getByTestId('watch-value').textContent()).toBe('TRUE');
  await expect.poll(() => sim.wireLit(0, 1, 1, 'middle')).toBe(true);
  expect(await sim.vlinkLit(0, 0, 1)).toBe(true);
  expect(await sim.wireLit(0, 0, 1, 'middle')).toBe(true);
  expect(await sim.vlinkLit(0, 1, 2)).toBe(true);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  expect(errors).toEqual([]);
});

test('a U-turn (a line fed only from its right) is still refused: LD-R01 names the coil', async () => {
  await newProject('U-turn');
  await sim.tab('Problems');
  await expect.poll(() => draw.problemsSummary(), CHECKS).not.toBe('No problems');
  // |--[A]--[B]--+
  // |     +--+---+
  // |     +--+----------( Z )
  await place('contact-NO', 0, 0, 'A');
  await place('contact-NO', 0, 1, 'B');
  await place('link', 1, 1);
  await place('link', 2, 1);
  await place('coil-COIL', 2, 2, 'Z');
  await draw.clickVLink(0, 0, 2);
  await draw.clickVLink(0, 1, 1);
  await page.keyboard.press('Escape');
  expect((await draw.networks())[0]!.vlinks).toEqual([
    { row: 0, boundary: 2 },
    { row: 1, boundary: 1 },
  ]);

  await expect.poll(problems, CHECKS).toMatch(/LD-R01/);
  const r01 = page.locator('[data-testid="problem"][data-rule="LD-R01"]').first();
  expect(await r01.textContent()).toMatch(/network 1/i);
  expect(await r01.textContent()).toMatch(/coil "?Z"? is fed from its right/i);
  expect(await draw.problemsSummary()).toMatch(/^[1-9]\d* errors?/);
  expect(errors).toEqual([]);
});
