// Rows and tasks (issue 24): a network is as tall as the rows its rung uses, with room to place into
// shown while placing (the keyboard cursor below the rung, an armed palette tool, a drag).
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, expect, test } from 'vitest';
import { CELL_H, GRID_PAD_BOTTOM } from '../../src/editor/canvas/geometry';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { poll } from './panelsPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  draw = new DrawPage(page);
});

afterAll(() => {
  expect(errors).toEqual([]);
});

/** Pixels from network i's header to network i + 1's (the network's whole height on the canvas). */
const step = (i: number) =>
  page.evaluate((i) => {
    const top = (k: number) => document.querySelector<HTMLElement>(`[data-testid="network-header-${k}"]`)!.offsetTop;
    return top(i + 1) - top(i);
  }, i);

const modelRows = () =>
  page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    return s.project.pous.find((p) => p.id === s.activePouId)!.networks.map((n) => n.rows);
  });

test('a one-row rung takes one row; ↓ below it shows an empty row, a contact placed there grows the network, deleting it shrinks it', async () => {
  await page.evaluate(() => {
    const doc = window.rungsmith!.documentStore!.getState();
    doc.newProject('Rows');
    doc.addNetwork({ rows: 3 });
  });
  // Both networks have three rows in the model; empty, each shows one row to draw in.
  expect(await modelRows()).toEqual([3, 3]);
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('Start');
  await page.keyboard.press('o');
  await draw.typeName('Motor');
  await draw.clickCell(0, 0, 0);
  const oneRow = await step(0);
  // The cursor is on row 0; network 0 is one row high: header + one row + its padding + gap.
  expect(await draw.elements(0)).toHaveLength(2);
  const header = await page.getByTestId('network-header-0').evaluate((h) => (h as HTMLElement).offsetHeight);
  expect(oneRow).toBeLessThan(header + 2 * CELL_H + GRID_PAD_BOTTOM);

  // ↓ onto the empty row under the rung: the network shows it (room for a branch).
  await page.keyboard.press('ArrowDown');
  await poll(() => page.evaluate(() => window.rungsmith!.uiStore!.getState().cursor?.row)).toBe(1);
  await poll(() => step(0)).toBe(oneRow + CELL_H);
  await page.keyboard.press('c');
  await draw.typeName('Jog');
  expect((await draw.elements(0)).map((e) => `${e.name}@${e.row},${e.col}`)).toContain('Jog@1,0');
  // Back up on the rung: the branch's row stays, it is used now.
  await page.keyboard.press('ArrowUp');
  await poll(() => step(0)).toBe(oneRow + CELL_H);

  // Deleting the branch's contact: once the cursor leaves that row the network is one row again.
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowLeft');
  await poll(() => page.evaluate(() => window.rungsmith!.uiStore!.getState().cursor)).toMatchObject({ row: 1, col: 0 });
  await page.keyboard.press('Delete');
  await poll(async () => (await draw.elements(0)).length).toBe(2);
  await page.keyboard.press('ArrowUp');
  await poll(() => step(0)).toBe(oneRow);
  // Positions of the model stay: the rung is on row 0, the model still has its three rows.
  expect((await modelRows())[0]).toBe(3);

  // ↓ twice from the rung goes through the empty row into the next network.
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowDown');
  const cursor = await page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    const c = window.rungsmith!.uiStore!.getState().cursor!;
    return { network: s.project.pous[0]!.networks.findIndex((n) => n.id === c.network), row: c.row };
  });
  expect(cursor).toEqual({ network: 1, row: 0 });
  await poll(() => step(0)).toBe(oneRow);
});

test('an armed palette tool shows an empty row under every rung; a click there places the element and the network grows', async () => {
  const oneRow = await step(0);
  await draw.pickPalette('contact-NC');
  await poll(() => step(0)).toBe(oneRow + CELL_H);
  await draw.clickCell(0, 1, 1);
  await draw.typeName('Lock');
  expect((await draw.elements(0)).map((e) => `${e.name}@${e.row},${e.col}`)).toContain('Lock@1,1');
  await draw.canvas().focus();
  await page.keyboard.press('Escape');
  await poll(() => page.evaluate(() => window.rungsmith!.uiStore!.getState().tool.kind)).toBe('select');
  // The placed contact uses row 1: two rows high now, without any room shown.
  await poll(() => step(0)).toBe(oneRow + CELL_H);
  await page.keyboard.press('Control+z');
  await poll(async () => (await draw.elements(0)).some((e) => e.row === 1)).toBe(false);
  await draw.clickCell(0, 0, 0);
  await poll(() => step(0)).toBe(oneRow);
});

test('dragging a coil onto the empty row under another rung drops it there; the view does not jump under the pointer', async () => {
  await draw.clickCell(1, 0, 0);
  await page.keyboard.press('c');
  await draw.typeName('Stop');
  const oneRow = await step(0);
  const a = await draw.cellPoint(0, 0, 1);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move(a.x + 10, a.y + 10, { steps: 3 });
  await page.waitForFunction(() => window.rungsmith!.uiStore!.getState().dragging);
  // While dragging, every network shows a row to drop on; the grabbed network stayed in place.
  await poll(() => step(0)).toBe(oneRow + CELL_H);
  const again = await draw.cellPoint(0, 0, 1);
  expect(Math.abs(again.y - a.y)).toBeLessThan(2);
  const b = await draw.cellPoint(1, 1, 2);
  await page.mouse.move(b.x, b.y, { steps: 8 });
  await page.mouse.up();
  await poll(() => page.evaluate(() => window.rungsmith!.uiStore!.getState().dragging)).toBe(false);
  expect((await draw.elements(1)).map((e) => `${e.name}@${e.row},${e.col}`)).toContain('Motor@1,2');
  expect((await draw.elements(0)).map((e) => e.name)).not.toContain('Motor');
  // The drop grew network 1 by one row; network 0 is one row again.
  await poll(() => step(0)).toBe(oneRow);
  await page.keyboard.press('Control+z');
  expect((await draw.elements(0)).map((e) => e.name)).toContain('Motor');
});

const focused = (p: Page = page) =>
  p.evaluate(() => {
    const a = document.activeElement as HTMLElement | null;
    return a?.dataset.testid ?? a?.getAttribute('aria-label') ?? a?.tagName ?? '';
  });

test('the tasks dialog keeps the keyboard in the field or row just edited (Enter, Tab, moving an instance)', async () => {
  await page.evaluate(() => {
    const doc = window.rungsmith!.documentStore!.getState();
    doc.newProject('Tasks');
  });
  await page.getByTestId('tab-project').click();
  await page.getByTestId('tree-tasks-edit').click();
  await page.getByTestId('tasks-dialog').waitFor();
  const tasks = () =>
    page.evaluate(() => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project.tasks)) as {
      name: string;
      cycleMs: number;
      priority: number;
      programs: { instance: string }[];
    }[]);
  const name = page.getByTestId('task-name-0');
  await name.fill('Fast');
  await name.press('Enter');
  await poll(async () => (await tasks())[0]!.name).toBe('Fast');
  // Still in the name field, ready for the next key.
  expect(await focused()).toBe('task-name-0');
  await page.keyboard.press('Tab');
  expect(await focused()).toBe('task-cycle-0');
  await page.keyboard.press('Control+a');
  await page.keyboard.type('20');
  await page.keyboard.press('Tab');
  await poll(async () => (await tasks())[0]!.cycleMs).toBe(20);
  // Tab committed the interval and the focus went on to the next control, not to the page.
  expect(await focused()).toBe('task-single-0');
  await page.keyboard.press('Tab');
  expect(await focused()).toBe('task-priority-0');
  await page.keyboard.type('5');
  await page.keyboard.press('Enter');
  await poll(async () => (await tasks())[0]!.priority).toBe(5);
  expect(await focused()).toBe('task-priority-0');

  // A second instance; renaming it with Enter keeps its field; ↓ on the first moves it and the keyboard follows.
  await page.getByTestId('task-add-program-0').focus();
  await page.getByTestId('task-add-program-0').selectOption('Main');
  await poll(async () => (await tasks())[0]!.programs.length).toBe(2);
  expect(await focused()).toBe('task-add-program-0');
  const second = page.getByTestId('task-0-program-1').getByRole('textbox');
  await second.fill('Second');
  await second.press('Enter');
  await poll(async () => (await tasks())[0]!.programs[1]!.instance).toBe('Second');
  expect(await page.evaluate(() => document.activeElement?.closest('[data-testid]')?.getAttribute('data-testid'))).toBe(
    'task-0-program-1',
  );
  const first = (await tasks())[0]!.programs[0]!.instance;
  await page.getByTestId('task-0-program-0').getByTitle('Run later').focus();
  await page.keyboard.press('Enter');
  await poll(async () => (await tasks())[0]!.programs.map((p) => p.instance)).toEqual(['Second', first]);
  // The moved instance is last now: the keyboard is on its "Run earlier" button.
  expect(
    await page.evaluate(() => {
      const a = document.activeElement!;
      return `${a.closest('tr')?.dataset.testid} ${a.getAttribute('title')}`;
    }),
  ).toBe('task-0-program-1 Run earlier');
  // Undo shows in the open dialog's fields.
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  await poll(() => page.getByTestId('task-0-program-0').getByRole('textbox').inputValue()).toBe(first);
  await page.getByTestId('tasks-close').click();
});

test('the canvas has the keyboard when the app opens and after New project; an open dialog keeps it', async () => {
  const fresh = await openApp(browser());
  const p = fresh.page;
  await poll(() => focused(p)).toBe('ladder-canvas');
  // Arrows and letters work at once.
  await p.keyboard.press('ArrowRight');
  await poll(() => p.evaluate(() => window.rungsmith!.uiStore!.getState().cursor !== undefined)).toBe(true);
  await p.keyboard.press('c');
  await p.getByTestId('inline-editor').waitFor();
  await p.keyboard.press('Escape');
  await p.getByTestId('inline-editor').waitFor({ state: 'detached' });

  // File > New project (after the question about the unsaved change): the new project's canvas has it.
  await p.getByTestId('tab-project').click();
  await p.getByTestId('menu-file').click();
  await p.getByRole('menuitem', { name: 'New project' }).click();
  const discard = p.getByRole('button', { name: /Discard/ });
  if (await discard.isVisible()) await discard.click();
  await poll(() => p.evaluate(() => window.rungsmith!.documentStore!.getState().project.pous[0]!.networks[0]!.elements.length)).toBe(0);
  await poll(() => focused(p)).toBe('ladder-canvas');

  // A project opened while a dialog is open leaves the keyboard in the dialog.
  await p.getByTestId('tree-tasks-edit').click();
  await p.getByTestId('tasks-dialog').waitFor();
  await p.getByTestId('task-name-0').focus();
  await p.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Other'));
  await p.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  expect(await focused(p)).toBe('task-name-0');
  await p.getByTestId('tasks-close').click();
  expect(fresh.errors).toEqual([]);
  await p.close();
});

test('+ Program runs the new program in a task of its own in one step (named with it), or in a task chosen', async () => {
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Plant'));
  const tasks = () =>
    page.evaluate(() =>
      window.rungsmith!.documentStore!
        .getState()
        .project.tasks.map((t) => `${t.name} ${t.cycleMs} ms: ${t.programs.map((p) => p.pou).join(', ')}`),
    );
  await page.getByTestId('tab-project').click();
  const [main] = await tasks();
  expect(main).toMatch(/^MainTask \d+ ms: Main$/);
  const runsIn = page.getByTestId('new-program-runs-in');
  expect(await runsIn.inputValue()).toBe('own');
  const steps = await page.evaluate(() => window.rungsmith!.documentStore!.getState().history.undo.length);
  await page.getByTestId('add-program').click();
  const field = page.getByTestId('pou-rename');
  await field.fill('Filler');
  await field.press('Enter');
  await page.getByTestId('pou-tab-Filler').waitFor();
  expect(await tasks()).toEqual([main, 'T_Filler 10 ms: Filler']);
  // The tree lists it; adding it was one undo step (the name another).
  await poll(() => page.getByTestId('tree-task-T_Filler').textContent()).toMatch(/every 10 ms/);
  expect(await page.evaluate(() => window.rungsmith!.documentStore!.getState().history.undo.length)).toBe(steps + 2);
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  expect(await tasks()).toEqual([main, 'T_Program 10 ms: Program']);
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  expect(await tasks()).toEqual([main]);

  // Or in an existing task, chosen in the same place.
  await runsIn.selectOption({ label: 'task MainTask' });
  await page.getByTestId('add-program').click();
  await page.getByTestId('pou-rename').fill('Signals');
  await page.getByTestId('pou-rename').press('Enter');
  await page.getByTestId('pou-tab-Signals').waitFor();
  expect(await tasks()).toEqual([`${main}, Signals`]);
});
