// Connectors and continuations in a real Chromium: a user draws `[A] >C>` on one row and `>C> (X)`
// on the next, runs it, toggles A and sees X follow and the pair lit; renames the connector in the
// inspector and its continuation follows (one undo step); G goes from one to its partner. Then the
// view following execution: stepping through a 30-network program keeps the network that runs
// next on screen, without moving the view while it already is.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let sim: SimPage;
let errors: string[];

const v = (name: string, location: string): Variable => ({
  name,
  type: 'BOOL',
  varClass: 'local',
  location,
  retain: false,
  comment: '',
});

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  sim = new SimPage(page);
});

/** The connectors and continuations of network 0 as `>C>|` / `|>C>` at their cells. */
async function pairs(): Promise<string[]> {
  return (await sim.draw.networks())[0]!.elements
    .flatMap((e) =>
      e.kind === 'connector' ? [`R${e.row}C${e.col} >${e.name}>|`] : e.kind === 'continuation' ? [`R${e.row}C${e.col} |>${e.name}>`] : [],
    )
    .sort();
}

const selected = () => page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements);
const idAt = async (row: number, col: number) =>
  (await sim.draw.networks())[0]!.elements.find((e) => e.row === row && e.col === col)!.id;

test('draw [A] >C> and >C> (X), run: X follows A through the pair, lit; renaming the connector renames its continuation', async () => {
  const main = newPou('Main');
  await sim.load(newProject('Pair', { pous: [{ ...main, variables: [v('A', '%IX0.0'), v('X', '%QX0.0')] }] }));
  const draw = sim.draw;

  await draw.pickPalette('contact-NO');
  await draw.clickCell(0, 0, 0);
  await draw.typeName('A');
  // A new connector offers C1; the user types C.
  await draw.pickPalette('connector');
  await draw.clickCell(0, 0, 1);
  expect(await page.getByTestId('inline-editor').inputValue()).toBe('C1');
  await draw.typeName('C');
  // The continuation takes the name of the only connector nobody reads yet: Enter keeps it.
  await draw.pickPalette('continuation');
  await draw.clickCell(0, 1, 0);
  expect(await page.getByTestId('inline-editor').inputValue()).toBe('C');
  await page.keyboard.press('Enter');
  await page.getByTestId('inline-editor').waitFor({ state: 'detached' });
  await draw.pickPalette('coil-COIL');
  await draw.clickCell(0, 1, 1);
  await draw.typeName('X');
  await draw.pickPalette('select');
  expect(await pairs()).toEqual(['R0C1 >C>|', 'R1C0 |>C>']);

  // Resting the pointer on the connector names its continuation and where it is.
  const at = await draw.cellPoint(0, 0, 1);
  await page.mouse.move(at.x, at.y);
  await expect
    .poll(() => page.locator('.rs-canvas-sticky').getAttribute('title'))
    .toContain('Connector >C> → 1 continuation (R2C1)');

  await sim.button('run').click();
  await sim.waitForMode('Running');
  expect(await sim.value('X')).toBe(false);
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('A', true);
  await sim.waitForValue('X', true);
  // The connector (its tag) and the continuation's wire are drawn energised.
  await expect.poll(() => sim.wireLit(0, 0, 1)).toBe(true);
  await expect.poll(() => sim.wireLit(0, 1, 0)).toBe(true);
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('X', false);
  await expect.poll(() => sim.wireLit(0, 1, 0)).toBe(false);

  // Rename the connector in the inspector: the continuation follows, one undo step.
  await draw.clickCell(0, 0, 1);
  await page.getByTestId('inspector-connection-name').waitFor();
  expect(await page.getByTestId('inspector-rename-pair').isChecked()).toBe(true);
  expect(await page.getByTestId('inspector-partners').textContent()).toContain('continuation at R2C1');
  await page.getByTestId('inspector-connection-name').fill('Permit');
  await page.keyboard.press('Enter');
  expect(await pairs()).toEqual(['R0C1 >Permit>|', 'R1C0 |>Permit>']);
  // The renamed program is swapped in while running: X still follows A.
  await sim.switchCell(0, 0, 0);
  await sim.waitForValue('X', true);
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  expect(await pairs()).toEqual(['R0C1 >C>|', 'R1C0 |>C>']);

  // G goes from the connector to its continuation and back.
  await draw.clickCell(0, 0, 1);
  await draw.canvas().focus();
  await page.keyboard.press('g');
  expect(await selected()).toEqual([await idAt(1, 0)]);
  await page.keyboard.press('g');
  expect(await selected()).toEqual([await idAt(0, 1)]);
  expect(errors).toEqual([]);
});

/** 30 one-row networks: `Run` to `Out<i>` each. */
function longProgram(): Project {
  const main = newPou('Main');
  const outs = Array.from({ length: 30 }, (_, i) => v(`Out${i + 1}`, `%QX${Math.floor(i / 8)}.${i % 8}`));
  return newProject('Long', {
    pous: [
      {
        ...main,
        variables: [v('Run', '%IX0.0'), ...outs],
        networks: outs.map((o, i) =>
          newNetwork({
            title: `Step ${i + 1}`,
            rows: 1,
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Run', id: `r${i}` as ElementId, row: 0, col: 0 },
              { kind: 'coil', coil: 'COIL', variable: o.name, id: `o${i}` as ElementId, row: 0, col: 9 },
            ],
          }),
        ),
      },
    ],
  });
}

/** Where execution stands (0-based network), the canvas's scroll position, and whether that network's header is on screen. */
async function stepView(): Promise<{ next: number; scrollTop: number; visible: boolean }> {
  return page.evaluate(() => {
    const sim = (window.rungsmith as unknown as { simStore: { getState(): { position: { network: number }[] } } }).simStore;
    const next = sim.getState().position.at(-1)?.network ?? -1;
    const canvas = document.querySelector<HTMLElement>('[data-testid="ladder-canvas"]')!;
    const box = canvas.getBoundingClientRect();
    const header = document.querySelector(`[data-testid="network-header-${next}"]`)?.getBoundingClientRect();
    const visible = Boolean(header && header.top >= box.top && header.bottom <= box.bottom);
    return { next, scrollTop: canvas.scrollTop, visible };
  });
}

test('stepping through 30 networks scrolls the canvas to the network that runs next, only when it is off screen', async () => {
  await sim.load(longProgram());
  const step = async (expected: number) => {
    await sim.button('step-network').click();
    await expect.poll(async () => (await stepView()).next).toBe(expected);
    await expect.poll(async () => (await stepView()).visible).toBe(true);
    return stepView();
  };
  await sim.button('step-network').click();
  await expect.poll(async () => (await stepView()).next).toBeGreaterThanOrEqual(0);
  const first = (await stepView()).next;
  const start = await stepView();
  // The next network is on screen already: the view stays where it is.
  const second = await step(first + 1);
  expect(second.scrollTop).toBe(start.scrollTop);
  const tops: number[] = [second.scrollTop];
  for (let n = first + 2; n < 30; n++) tops.push((await step(n)).scrollTop);
  // The view moved down as execution did, in a few jumps (not on every step), never back up.
  expect(tops.at(-1)!).toBeGreaterThan(tops[0]!);
  const moves = tops.filter((t, i) => i > 0 && t !== tops[i - 1]).length;
  expect(moves).toBeGreaterThan(1);
  expect(moves).toBeLessThan(tops.length / 2);
  expect(tops.every((t, i) => i === 0 || t >= tops[i - 1]!)).toBe(true);
  // F10 steps over the last network too; the view then follows back to the top of the next scan.
  await page.keyboard.press('F10');
  await expect.poll(async () => (await stepView()).next).not.toBe(29);
  expect(errors).toEqual([]);
});
