// A PLC programmer builds a project from several POUs: an FB Motor with its own seal-in rung,
// used twice from the program (block search and palette), renamed (calls and instance types
// follow), deleted (the editor says where it is used) and brought back with Undo; a FUNCTION with
// a return type; the variable table fully visible at 1280×720; an ST POU opens in the ST editor.
// Run: the values inside one instance picked on the Motor tab, then the other; step into the call
// and over the body's network back out to Main.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newPou, newProject } from '../../src/model/factory';
import type { BoxElement } from '../../src/model/elements';
import type { Project } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let draw: DrawPage;
let editor: EditorPage;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Plant'));
  draw = new DrawPage(page);
  editor = new EditorPage(page);
});

const project = (): Promise<Project> =>
  page.evaluate(
    () => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project,
  );
const pou = async (name: string) => (await project()).pous.find((p) => p.name === name);
const calls = async (): Promise<BoxElement[]> =>
  ((await pou('Main'))?.networks ?? []).flatMap((n) =>
    n.elements.filter((e): e is BoxElement => e.kind === 'box'),
  );

/** Opens a POU from the project tree. */
async function openPou(name: string) {
  await page.getByTestId('tab-project').click();
  await page.getByTestId(`tree-pou-${name}`).getByRole('button').first().click();
  await page.getByTestId(`pou-tab-${name}`).waitFor();
}

/** Adds a POU from the project tree and names it in the field that opens. */
async function addPou(button: 'add-fb' | 'add-function' | 'add-program', name: string) {
  await page.getByTestId('tab-project').click();
  await page.getByTestId(button).click();
  const field = page.getByTestId('pou-rename');
  await field.fill(name);
  await field.press('Enter');
  await page.getByTestId(`pou-tab-${name}`).waitFor();
}

/** Declares a variable in the open POU's table and sets its class. */
async function declare(name: string, type: string, varClass: string) {
  await editor.tab('Variables');
  await editor.declare(name, { type });
  await editor.variableRow(name).getByLabel('Class').selectOption(varClass);
}

/** Types an operand into a pin field of the box inspector and takes the first offer (declare or pick). */
async function setPin(pin: string, operand: string) {
  const field = editor.inspector.getByTestId(`pin-${pin}`);
  await field.click();
  await field.fill(operand);
  await field.press('Enter');
}

test('an FB Motor with inputs Start/Stop, output Run and its own seal-in rung', async () => {
  await addPou('add-fb', 'Motor');
  expect(await page.getByTestId('pou-tab-Motor').getAttribute('aria-selected')).toBe('true');
  await declare('Start', 'BOOL', 'input');
  await declare('Stop', 'BOOL', 'input');
  await declare('Run', 'BOOL', 'output');
  // The seal-in rung, drawn inside the FB with the palette.
  await page.getByTestId('tab-palette').click();
  await draw.pickPalette('contact-NO');
  await draw.clickCell(0, 0, 0);
  await draw.typeName('Start');
  await draw.pickPalette('contact-NC');
  await draw.clickCell(0, 0, 1);
  await draw.typeName('Stop');
  await draw.pickPalette('coil-COIL');
  await draw.clickCell(0, 0, 9);
  await draw.typeName('Run');
  await draw.pickPalette('link');
  for (let col = 2; col <= 8; col++) await draw.clickCell(0, 0, col);
  await draw.pickPalette('select');
  await draw.clickCell(0, 0, 0);
  await draw.menu('Edit', 'Parallel branch around selection');
  await draw.pickPalette('contact-NO');
  await draw.clickCell(0, 1, 0);
  await draw.typeName('Run');
  await page.keyboard.press('Escape');
  const motor = (await pou('Motor'))!;
  expect(motor.kind).toBe('FUNCTION_BLOCK');
  expect(motor.variables.map((v) => `${v.name}:${v.varClass}`)).toEqual([
    'Start:input',
    'Stop:input',
    'Run:output',
  ]);
  expect(motor.networks[0]!.elements).toHaveLength(11);
});

test('the FB is called twice from the program: from the block search and from the palette', async () => {
  await page.getByTestId('pou-tab-Main').click();
  await draw.pickPalette('select');
  // Block search (B) at the cursor: the project's own FB is offered with its pins.
  await draw.clickCell(0, 0, 1);
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('Motor');
  const option = page.getByRole('option', { name: /Motor/ }).first();
  expect(await option.textContent()).toContain('Start : BOOL, Stop : BOOL → Run : BOOL');
  await page.keyboard.press('Enter');
  // The instance name is offered: Motor1, declared with type Motor by Enter.
  const inline = page.getByTestId('inline-editor');
  await inline.waitFor();
  await expect.poll(() => page.getByRole('option', { name: /Declare Motor1/ }).count()).toBe(1);
  await page.keyboard.press('Enter');
  await inline.waitFor({ state: 'detached' });
  // The palette lists the FB among the blocks.
  await page.getByTestId('tab-palette').click();
  await page.getByRole('searchbox', { name: 'Search blocks' }).fill('Motor');
  await page.getByTestId('palette-block-Motor').click();
  await draw.clickCell(0, 2, 1);
  await inline.waitFor();
  await expect.poll(() => page.getByRole('option', { name: /Declare Motor2/ }).count()).toBe(1);
  await page.keyboard.press('Enter');
  await inline.waitFor({ state: 'detached' });
  await draw.pickPalette('select');
  expect((await calls()).map((b) => `${b.blockType}:${b.instance}@${b.row},${b.col}`)).toEqual([
    'Motor:Motor1@0,1',
    'Motor:Motor2@2,1',
  ]);
  const main = (await pou('Main'))!;
  expect(main.variables.map((v) => `${v.name}:${v.type}`)).toEqual(['Motor1:Motor', 'Motor2:Motor']);

  // Operands on the pins, from the inspector (each new name declared from the offer).
  for (const [row, n] of [
    [0, 1],
    [2, 2],
  ] as const) {
    await draw.clickCell(0, row, 1);
    await editor.tab('Inspector');
    await setPin('Start', `Start${n}`);
    await setPin('Stop', `Stop${n}`);
    await setPin('Run', `Lamp${n}`);
  }
  expect((await calls()).map((b) => ({ ...b.inputs, ...b.outputs }))).toEqual([
    { Start: 'Start1', Stop: 'Stop1', Run: 'Lamp1' },
    { Start: 'Start2', Stop: 'Stop2', Run: 'Lamp2' },
  ]);
  await poll(() => draw.problemsSummary()).toBe('No problems');
});

test('run: the values inside one instance, the other instance, step into the call', async () => {
  const sim = new SimPage(page);
  await sim.button('run').click();
  await sim.waitForMode('Running');
  // Press Start of Motor1 (its Start1 operand) from the watch table, then let go.
  await sim.tab('Watch');
  await page.getByTestId('watch-add-name').fill('Start1');
  await page.getByTestId('watch-add').click();
  const start = page.getByTestId('watch-row-Start1');
  await start.getByTestId('watch-input').fill('TRUE');
  await start.getByTestId('watch-write').click();
  await sim.waitForValue('Motor1.Run', true);
  await start.getByTestId('watch-input').fill('FALSE');
  await start.getByTestId('watch-write').click();
  await sim.waitForValue('Start1', false);
  // The Motor tab monitors one instance: Motor1 first, sealed in (power through Run's branch).
  await page.getByTestId('pou-tab-Motor').click();
  const picker = page.getByTestId('instance-picker');
  await poll(() => picker.inputValue()).toBe('Motor1');
  expect(await picker.locator('option').allTextContents()).toEqual(['Motor1', 'Motor2']);
  await poll(() => sim.wireLit(0, 0, 5)).toBe(true);
  await poll(() => sim.wireLit(0, 1, 0)).toBe(true);
  expect(await canvasValue('Run')).toBe('TRUE');
  // Motor2 was never started: its body shows no power, Run FALSE.
  await picker.selectOption('Motor2');
  await poll(() => sim.wireLit(0, 0, 5)).toBe(false);
  expect(await canvasValue('Run')).toBe('FALSE');
  // Pause, step into the call of Motor1: its body with Motor1 picked, network 1 next.
  await sim.button('pause').click();
  await sim.waitForMode('Paused');
  await page.getByTestId('sim-step-into').click();
  await poll(() => page.getByTestId('sim-position').textContent()).toBe('▶ Main / network 1 → Motor1 (Motor) / network 1');
  expect(await page.getByTestId('pou-tab-Motor').getAttribute('aria-selected')).toBe('true');
  await poll(() => picker.inputValue()).toBe('Motor1');
  await page.getByTestId('network-next-0').waitFor();
  // Step over: the body's network runs; the next stop is the call of Motor2 in the same network of Main.
  await sim.button('step-network').click();
  await poll(() => page.getByTestId('sim-position').textContent()).toBe('▶ Main / network 1 → Motor2 (Motor) / network 1');
  await poll(() => picker.inputValue()).toBe('Motor2');
  await page.getByTestId('network-next-0').waitFor();
  // Over the end of the scan: no position left, paused.
  await sim.button('step-network').click();
  await page.getByTestId('sim-position').waitFor({ state: 'detached' });
  expect(await sim.mode()).toBe('Paused');
  // From a call box in Main: "Open instance" (right-click), or a double-click.
  await page.getByTestId('pou-tab-Main').click();
  const call1 = await draw.cellPoint(0, 0, 1);
  await page.mouse.click(call1.x, call1.y, { button: 'right' });
  await page.getByTestId('sim-open-instance').click();
  await poll(() => page.getByTestId('pou-tab-Motor').getAttribute('aria-selected')).toBe('true');
  await poll(() => picker.inputValue()).toBe('Motor1');
  await page.getByTestId('pou-tab-Main').click();
  const call2 = await draw.cellPoint(0, 2, 2);
  await page.mouse.dblclick(call2.x, call2.y);
  await poll(() => page.getByTestId('pou-tab-Motor').getAttribute('aria-selected')).toBe('true');
  await poll(() => picker.inputValue()).toBe('Motor2');
  await page.getByTestId('pou-tab-Main').click();
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
  await editor.tab('Problems');
});

/** The value the canvas shows for an operand of the shown body (read in the picked instance). */
const canvasValue = (operand: string) =>
  page.evaluate((name) => {
    const store = window.rungsmith!.simStore as { getState(): unknown };
    const s = store.getState() as {
      canvasScope?: { prefix?: string };
      variableIndex: Map<string, number>;
      values: unknown[];
    };
    const path = s.canvasScope?.prefix ? `${s.canvasScope.prefix}.${name}` : name;
    const v = s.values[s.variableIndex.get(path.toUpperCase()) ?? -1];
    return v === undefined ? undefined : v ? 'TRUE' : 'FALSE';
  }, operand);

test('renaming the FB to FB_Motor renames the calls and the instance types', async () => {
  await page.getByTestId('tab-project').click();
  await page.getByRole('button', { name: 'Rename Motor' }).click();
  const field = page.getByTestId('pou-rename');
  await field.fill('FB_Motor');
  await field.press('Enter');
  expect((await calls()).map((b) => b.blockType)).toEqual(['FB_Motor', 'FB_Motor']);
  const main = (await pou('Main'))!;
  expect(main.variables.filter((v) => v.name.startsWith('Motor')).map((v) => v.type)).toEqual([
    'FB_Motor',
    'FB_Motor',
  ]);
  await page.getByTestId('pou-tab-FB_Motor').waitFor();
  await poll(() => draw.problemsSummary()).toBe('No problems');
});

test('deleting the FB says where it is used; Undo brings it back', async () => {
  await page.getByRole('button', { name: 'Delete FB_Motor' }).click();
  const dialog = page.getByTestId('delete-pou-dialog');
  await dialog.waitFor();
  const uses = await dialog.getByTestId('pou-uses').locator('li').allTextContents();
  expect(uses).toEqual([
    'Main, network 1 (Motor1)',
    'Main, network 1 (Motor2)',
    'Main: instance Motor1',
    'Main: instance Motor2',
  ]);
  await dialog.getByTestId('confirm-delete-pou').click();
  await poll(async () => (await project()).pous.map((p) => p.name)).toEqual(['Main']);
  expect(await page.getByTestId('pou-tab-FB_Motor').count()).toBe(0);
  // The calls now name an unknown block: the checks say so.
  await poll(() => draw.problemsSummary()).not.toBe('No problems');
  await draw.menu('Edit', 'Undo');
  await poll(async () => (await project()).pous.map((p) => p.name)).toEqual(['Main', 'FB_Motor']);
  await poll(() => draw.problemsSummary()).toBe('No problems');
});

test('a FUNCTION with a return type: its box has EN/ENO and the result pin OUT of that type', async () => {
  await addPou('add-function', 'Scale');
  await page.getByTestId('pou-return-type').selectOption('INT');
  await declare('Raw', 'INT', 'input');
  await page.getByTestId('pou-tab-Main').click();
  await page.getByTestId('tab-palette').click();
  await draw.pickPalette('select');
  await draw.clickCell(0, 0, 0);
  await draw.pickPalette('network');
  await draw.clickCell(1, 0, 1);
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('Scale');
  expect(await page.getByRole('option', { name: /Scale/ }).first().textContent()).toContain(
    'Raw : INT → OUT : INT',
  );
  await page.keyboard.press('Enter');
  const box = (await calls()).find((b) => b.blockType === 'Scale');
  expect(box).toMatchObject({ row: 0, col: 1 });
  expect(box).not.toHaveProperty('instance');
  await draw.clickCell(1, 0, 1);
  await editor.tab('Inspector');
  // Each pin's field is named by the pin and its type (the type written under the pin's name).
  await editor.inspector.getByLabel('OUT : INT').waitFor();
  await editor.inspector.getByLabel('Raw : INT').waitFor();
  // A function's box is EN, Raw / ENO, OUT: two rows.
  await draw.clickCell(1, 1, 1);
  expect((await page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements)).length).toBe(
    1,
  );
  // Its Raw input has no operand yet: the problem, clicked from another POU, opens Main at the box.
  await openPou('Scale');
  await editor.tab('Problems');
  const problem = editor.problems.getByTestId('problem').filter({ hasText: 'Main' }).first();
  await problem.waitFor();
  await problem.click();
  await poll(async () => page.getByTestId('pou-tab-Main').getAttribute('aria-selected')).toBe('true');
  expect(await page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements)).toEqual([
    box!.id,
  ]);
});

test('the variable table shows every column inside the side panel at 1280×720', async () => {
  await page.setViewportSize({ width: 1280, height: 720 });
  await openPou('FB_Motor');
  await editor.tab('Variables');
  // A local variable declared before an output still sorts after the interface.
  await editor.declare('Latch', { type: 'BOOL' });
  const names = await editor.variables
    .locator('tr.rs-var-row input[aria-label="Name"]')
    .evaluateAll((els) => els.map((e) => (e as HTMLInputElement).value));
  expect(names).toEqual(['Start', 'Stop', 'Run', 'Latch']);
  const panel = await editor.variables.locator('.rs-var-scroll').boundingBox();
  const side = await page.locator('.rs-right').boundingBox();
  expect(panel).not.toBeNull();
  const visible = {
    left: Math.max(panel!.x, side!.x),
    right: Math.min(panel!.x + panel!.width, side!.x + side!.width),
    top: panel!.y,
  };
  const boxes = [
    ...(await editor.variables.locator('thead th').all()),
    ...(await editor.variables.locator('tr.rs-var-row').first().locator('td').all()),
  ];
  expect(boxes.length).toBe(20);
  for (const cell of boxes) {
    const b = (await cell.boundingBox())!;
    const what = (await cell.getAttribute('data-col')) ?? '';
    expect({ what, left: b.x >= visible.left - 0.5, right: b.x + b.width <= visible.right + 0.5 }).toEqual({
      what,
      left: true,
      right: true,
    });
    expect(b.width).toBeGreaterThan(10);
  }
  // Headers read in full (not cut to an ellipsis).
  for (const th of await editor.variables.locator('thead th').all()) {
    const cut = await th.evaluate((e) => e.scrollWidth > e.clientWidth + 1);
    expect({ th: await th.textContent(), cut }).toMatchObject({ cut: false });
  }
});

test('a POU written in ST is listed and opens in the ST editor with its source', async () => {
  await page.evaluate(({ p }) => window.rungsmith!.documentStore!.getState().loadProject(p), {
    p: newProject('Mixed', {
      pous: [
        newPou('Main'),
        newPou('Filter', { kind: 'FUNCTION_BLOCK', language: 'ST', networks: [], source: 'OUT := IN * 2;' }),
      ],
    }),
  });
  await page.getByTestId('tab-project').click();
  await page
    .getByTestId('tree-pou-Filter')
    .getByRole('button', { name: /Filter/ })
    .first()
    .click();
  const view = page.getByTestId('st-body-view');
  await view.waitFor();
  const content = view.getByRole('textbox', { name: 'ST body of Filter' });
  expect(await content.getAttribute('contenteditable')).toBe('true');
  expect(await content.textContent()).toBe('OUT := IN * 2;');
  expect(errors).toEqual([]);
});
