// A new user's first day, as one journey in Chromium at 1280×720 against the server `npm start`
// runs: draw the seal-in from the keyboard, add a TON and step scans, make a mistake and fix it,
// undo/redo, reload (the work is kept), scan history and Why?, a scenario with Run all, an FB used
// twice with step into, a rename through Find/Replace, print preview, PLCopen export and import,
// and the gateway driving the simulated device's coil (read back over Modbus TCP).
// At every stage nothing overflows the window and the page has logged no error.
import type { BrowserContext, Page } from 'playwright-core';
import ModbusRTU from 'modbus-serial';
import { expect, test } from 'vitest';
import { appUrl, simModbusPort, waitForApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
const VIEWPORT = { width: 1280, height: 720 } as const;
/** The live checks run shortly after the drawing stops changing. */
const CHECKS = { timeout: 15_000 };

let page: Page;
let errors: string[];

/** What a user would notice at every stage: nothing wider than the window, no error logged. */
async function stage(name: string) {
  const widths = await page.evaluate(() => ({ scroll: document.documentElement.scrollWidth, inner: window.innerWidth }));
  expect(widths.scroll, `${name}: the page is wider than the window`).toBeLessThanOrEqual(widths.inner);
  expect(errors, `${name}: console errors`).toEqual([]);
}

/** Types a name into the inline editor and takes the declare offer matching `offer` (↓ until it is active). */
async function nameAndDeclare(name: string, offer?: RegExp) {
  const input = page.getByTestId('inline-editor');
  await input.waitFor();
  await input.fill(name);
  if (offer) {
    await page.getByRole('option', { name: offer }).waitFor();
    for (let i = 0; i < 6; i++) {
      const active = await page.locator('li[role="option"][aria-selected="true"]').textContent().catch(() => '');
      if (offer.test(active ?? '')) break;
      await page.keyboard.press('ArrowDown');
    }
    expect(await page.locator('li[role="option"][aria-selected="true"]').textContent()).toMatch(offer);
  }
  await page.keyboard.press('Enter');
  await input.waitFor({ state: 'detached' });
}

const problems = async () => (await page.getByTestId('problem').allTextContents()).join('\n');

test('the first day: draw, run, fix, keep, explain, test, structure, rename, print, exchange, connect', async () => {
  const context: BrowserContext = await browser().newContext({ acceptDownloads: true, viewport: VIEWPORT });
  page = await context.newPage();
  const editor = new EditorPage(page);
  errors = editor.errors;
  const draw = new DrawPage(page);
  const sim = new SimPage(page);
  try {
    await page.goto(appUrl());
    await waitForApp(page);
    await stage('opened');

    // 1. Draw the seal-in from the keyboard (README tour step 2), Start on %IX0.0, Motor on %QX0.0.
    await draw.menu('File', 'New project');
    await poll(async () => (await draw.networks()).length).toBe(1);
    await draw.clickCell(0, 0, 0);
    await page.keyboard.press('c');
    await nameAndDeclare('Start', /input at %IX0\.0/);
    await page.keyboard.press('Shift+C');
    await nameAndDeclare('Stop', /input at %IX0\.1/);
    for (let i = 0; i < 7; i++) await page.keyboard.press('h');
    await page.keyboard.press('o');
    await nameAndDeclare('Motor', /output at %QX0\.0/);
    for (let i = 0; i < 9; i++) await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('Control+Shift+B');
    await page.keyboard.press('ArrowDown');
    await page.keyboard.press('c');
    await nameAndDeclare('Motor');
    expect(await draw.elements(0)).toEqual([
      { kind: 'contact', row: 0, col: 0, name: 'Start', type: 'NO' },
      { kind: 'contact', row: 0, col: 1, name: 'Stop', type: 'NC' },
      ...[2, 3, 4, 5, 6, 7, 8].map((col) => ({ kind: 'link', row: 0, col })),
      { kind: 'coil', row: 0, col: 9, name: 'Motor', type: 'COIL' },
      { kind: 'contact', row: 1, col: 0, name: 'Motor', type: 'NO' },
    ]);
    const declared = (await editor.project()).pous[0]!.variables.map((v) => `${v.name}:${v.type}@${v.location ?? ''}`);
    expect(declared.sort()).toEqual(['Motor:BOOL@%QX0.0', 'Start:BOOL@%IX0.0', 'Stop:BOOL@%IX0.1']);
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('seal-in drawn');

    // 2. A TON in a new network (tour step 3): Motor → T1 (PT T#20s) → Lamp. Step 3 pauses while T1
    // is timing: 20 s leaves room for the clicks from Start to Pause on a busy machine (with 2 s,
    // ET had reached PT before the pause at load 20, and stepping could not raise it).
    await page.keyboard.press('n');
    await poll(async () => (await draw.networks()).length).toBe(2);
    await page.keyboard.press('c');
    await nameAndDeclare('Motor');
    await page.keyboard.press('b');
    await page.getByRole('combobox', { name: 'Search blocks' }).fill('TON');
    await page.keyboard.press('Enter');
    await nameAndDeclare('T1');
    // Enter on the selected box opens its first open pin (PT); Tab goes on to Q.
    await page.keyboard.press('Enter');
    const pin = page.getByTestId('pin-editor');
    await pin.waitFor();
    await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('PT');
    await pin.fill('T#20s');
    await page.keyboard.press('Tab');
    await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).toBe('Q');
    await pin.fill('Lamp');
    await poll(() => page.getByRole('option', { name: /Declare Lamp/ }).count()).toBeGreaterThan(0);
    await page.keyboard.press('Enter');
    await page.keyboard.press('Escape');
    await pin.waitFor({ state: 'detached' });
    await poll(async () => {
      const box = (await draw.networks())[1]!.elements.find((e) => e.kind === 'box');
      return box && box.kind === 'box' ? { type: box.blockType, instance: box.instance, ...box.inputs, ...box.outputs } : undefined;
    }).toMatchObject({ type: 'TON', instance: 'T1', PT: 'T#20s', Q: 'Lamp' });
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('TON added');

    // 3. Run, press Start from the Inputs tab, pause and step: T1.ET goes up with each scan.
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.tab('Inputs');
    const startSwitch = page.getByTestId('input-Start').getByTestId('input-switch');
    await startSwitch.click();
    await sim.waitForValue('Motor', true);
    await startSwitch.click();
    await sim.waitForValue('Start', false);
    expect(await sim.value('Motor')).toBe(true);
    await sim.button('pause').click();
    await sim.waitForMode('Paused');
    const et0 = Number(await sim.value('T1.ET'));
    await sim.button('step-scan').click();
    await poll(async () => Number(await sim.value('T1.ET'))).toBeGreaterThan(et0);
    const et1 = Number(await sim.value('T1.ET'));
    await sim.button('step-scan').click();
    await poll(async () => Number(await sim.value('T1.ET'))).toBeGreaterThan(et1);
    await stage('stepped');
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');

    // 4. A mistake (tour step 5): Stop typed as Stopp, kept as typed; LD-R08 with network and element.
    await editor.tab('Problems');
    await draw.clickCell(0, 0, 1);
    await page.keyboard.press('Enter');
    await page.getByTestId('inline-editor').fill('Stopp');
    await page.keyboard.press('Shift+Enter');
    await expect.poll(problems, CHECKS).toMatch(/LD-R08/);
    const row = page.getByTestId('problem').filter({ hasText: 'LD-R08' }).first();
    const text = (await row.textContent()) ?? '';
    expect(text).toMatch(/Stopp/);
    expect(text).toMatch(/[Nn]etwork 1/);
    await stage('violation shown');
    // Clicking the row goes to the element.
    await draw.clickCell(1, 0, 0);
    await row.click();
    const stopId = (await draw.networks())[0]!.elements.find((e) => e.row === 0 && e.col === 1)!.id;
    await poll(async () => (await editor.selection()).elements).toEqual([stopId]);
    // Fixed by typing the right name.
    await draw.canvas().focus();
    await page.keyboard.press('Enter');
    await page.getByTestId('inline-editor').fill('Stop');
    await page.keyboard.press('Enter');
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');

    // 5. Undo brings the mistake back, redo the fix.
    await page.keyboard.press('Control+z');
    await poll(async () => (await draw.elements(0))[1]!.name).toBe('Stopp');
    await page.keyboard.press('Control+y');
    await poll(async () => (await draw.elements(0))[1]!.name).toBe('Stop');
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('undo/redo');

    // 6. Reload: the work is kept.
    const before = (await editor.project()).pous.map((p) => p.networks);
    await editor.waitForAutosave();
    await page.reload();
    await waitForApp(page);
    await poll(async () => (await editor.project()).pous.map((p) => p.networks)).toEqual(before);
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('reloaded');

    // 7. Scan history and Why? (tour step 7): run from a cold start, Start then Stop from the Inputs tab.
    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.tab('Inputs');
    const input = (name: string) => page.getByTestId(`input-${name}`).getByTestId('input-switch');
    await input('Start').click();
    await sim.waitForValue('Motor', true);
    await input('Start').click();
    await sim.waitForValue('Start', false);
    await input('Stop').click();
    await sim.waitForValue('Motor', false);
    await input('Stop').click();
    await sim.waitForValue('Stop', false);
    await page.getByTestId('history-condition').fill('Motor');
    await page.getByTestId('history-find').click();
    await page.getByTestId('history-marker').filter({ hasText: 'HISTORY' }).waitFor();
    await poll(() => sim.value('Motor')).toBe(true); // the view shows that scan as it was
    await poll(() => sim.wireLit(0, 0, 9)).toBe(true);
    await stage('history');
    await page.getByTestId('history-live').click();
    await page.getByTestId('history-marker').filter({ hasText: 'Live' }).waitFor();
    await poll(() => sim.value('Motor')).toBe(false);
    // Why? on the Motor coil from its context menu.
    const coil = await draw.cellPoint(0, 0, 9);
    await page.mouse.click(coil.x, coil.y, { button: 'right' });
    await page.getByRole('menuitem', { name: /Why is Motor/ }).click();
    const why = page.getByTestId('why-explanation');
    await why.filter({ hasText: /Motor is FALSE/ }).waitFor();
    expect(await why.textContent()).toMatch(/Start is open|Motor is open/);
    await stage('why');

    // 8. A scenario recorded from this cold-start run, then Run all: PASS.
    await sim.tab('Tests');
    await page.getByTestId('tests-record').click();
    await poll(() => page.getByTestId('tests-row').count()).toBe(1);
    await page.getByTestId('tests-run-all').click();
    await page.getByTestId('tests-summary').filter({ hasText: '1 passed, 0 failed' }).waitFor({ timeout: 30_000 });
    expect(await page.getByTestId('tests-row').first().textContent()).toContain('PASS');
    expect(await sim.mode()).toContain('Running'); // the live session carries on
    await stage('scenario');
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');

    // 9. An FB Conveyor (tour step 9) with its own seal-in, called twice from Main; step into the calls.
    await page.getByTestId('tab-project').click();
    await page.getByTestId('add-fb').click();
    await page.getByTestId('pou-rename').fill('Conveyor');
    await page.getByTestId('pou-rename').press('Enter');
    await page.getByTestId('pou-tab-Conveyor').waitFor();
    for (const [name, varClass] of [['Go', 'input'], ['Halt', 'input'], ['Run', 'output']] as const) {
      await editor.tab('Variables');
      await editor.declare(name, { type: 'BOOL' });
      await editor.variableRow(name).getByLabel('Class').selectOption(varClass);
    }
    await page.getByTestId('tab-palette').click();
    await draw.pickPalette('contact-NO');
    await draw.clickCell(0, 0, 0);
    await draw.typeName('Go');
    await draw.pickPalette('contact-NC');
    await draw.clickCell(0, 0, 1);
    await draw.typeName('Halt');
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
    await draw.pickPalette('select');
    await stage('FB drawn');

    await page.getByTestId('pou-tab-Main').click();
    await draw.clickCell(1, 0, 0);
    await page.keyboard.press('n');
    await poll(async () => (await draw.networks()).length).toBe(3);
    await draw.clickCell(2, 0, 1);
    await page.keyboard.press('b');
    await page.getByRole('combobox', { name: 'Search blocks' }).fill('Conveyor');
    await page.keyboard.press('Enter');
    await page.getByTestId('inline-editor').waitFor();
    await poll(() => page.getByRole('option', { name: /Declare Conveyor1/ }).count()).toBe(1);
    await page.keyboard.press('Enter');
    await page.getByTestId('inline-editor').waitFor({ state: 'detached' });
    await page.getByTestId('tab-palette').click();
    await page.getByRole('searchbox', { name: 'Search blocks' }).fill('Conveyor');
    await page.getByTestId('palette-block-Conveyor').click();
    await draw.clickCell(2, 2, 1);
    await page.getByTestId('inline-editor').waitFor();
    await poll(() => page.getByRole('option', { name: /Declare Conveyor2/ }).count()).toBe(1);
    await page.keyboard.press('Enter');
    await page.getByTestId('inline-editor').waitFor({ state: 'detached' });
    await draw.pickPalette('select');
    for (const [row, n] of [[0, 1], [2, 2]] as const) {
      await draw.clickCell(2, row, 1);
      await editor.tab('Inspector');
      for (const [pinName, operand] of [['Go', `Go${n}`], ['Halt', `Halt${n}`], ['Run', `Belt${n}`]] as const) {
        const field = editor.inspector.getByTestId(`pin-${pinName}`);
        await field.click();
        await field.fill(operand);
        await field.press('Enter');
      }
    }
    const calls = (await draw.networks())[2]!.elements.flatMap((e) => (e.kind === 'box' ? [`${e.blockType}:${e.instance}`] : []));
    expect(calls).toEqual(['Conveyor:Conveyor1', 'Conveyor:Conveyor2']);
    await editor.tab('Problems');
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('FB used twice');

    await sim.button('run').click();
    await sim.waitForMode('Running');
    await sim.button('pause').click();
    await sim.waitForMode('Paused');
    const position = page.getByTestId('sim-position');
    // Step into (F11) network by network until the first call: each step moves the position on.
    const where = async () => ((await position.count()) ? ((await position.textContent()) ?? '') : '');
    for (let i = 0; i < 8 && !(await where()).includes('Conveyor1 (Conveyor)'); i++) {
      const was = await where();
      await page.getByTestId('sim-step-into').click();
      await poll(where).not.toBe(was);
    }
    await poll(() => position.textContent()).toBe('▶ Main / network 3 → Conveyor1 (Conveyor) / network 1');
    await poll(() => page.getByTestId('pou-tab-Conveyor').getAttribute('aria-selected')).toBe('true');
    await poll(() => page.getByTestId('instance-picker').inputValue()).toBe('Conveyor1');
    await sim.button('step-network').click();
    await poll(() => position.textContent()).toBe('▶ Main / network 3 → Conveyor2 (Conveyor) / network 1');
    await poll(() => page.getByTestId('instance-picker').inputValue()).toBe('Conveyor2');
    await stage('stepped into the FB');
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');
    await page.getByTestId('pou-tab-Main').click();

    // 10. Rename Lamp to Alarm through Find/Replace: the declaration follows.
    await draw.canvas().focus();
    await page.keyboard.press('Control+f');
    await page.getByTestId('find-input').fill('Lamp');
    await page.getByTestId('find-mode').selectOption('word');
    await page.getByTestId('replace-input').fill('Alarm');
    await page.getByTestId('replace-preview').click();
    expect(await page.getByTestId('replace-rename').textContent()).toMatch(/^Renames the variable Lamp to Alarm: its declaration \(Main\)/);
    expect(await page.getByTestId('replace-undeclared').count()).toBe(0);
    await page.getByTestId('replace-all').click();
    await page.getByTestId('find-input').press('Escape');
    await page.getByTestId('find-panel').waitFor({ state: 'detached' });
    const main = (await editor.project()).pous.find((p) => p.name === 'Main')!;
    expect(main.variables.map((v) => v.name)).toContain('Alarm');
    expect(main.variables.map((v) => v.name)).not.toContain('Lamp');
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    expect(await problems()).not.toMatch(/LD-R08|LD-E02/);
    await stage('renamed');

    // 11. Print preview of the open POU.
    await page.locator('body').press('Control+p');
    const dialog = page.getByTestId('print-dialog');
    await dialog.waitFor();
    await dialog.getByRole('button', { name: 'Print preview' }).click();
    const view = page.locator('[data-testid="print-view"][data-ready="true"]');
    await view.waitFor();
    expect(await view.getByTestId('print-page').count()).toBeGreaterThan(0);
    expect(await view.textContent()).toContain('Motor');
    await stage('print preview');
    await page.getByTestId('print-close').click();
    await page.getByTestId('print-view').waitFor({ state: 'detached' });

    // 12. Export PLCopen XML and import it back.
    const original = await editor.project();
    const file = await editor.download(async () => {
      await editor.menu('File', 'Export PLCopen XML');
      // Only when Beremiz/OpenPLC would run something differently does a review come first.
      const review = page.getByTestId('export-review');
      await review.or(page.getByText(/^Exported .*\(PLCopen XML/)).first().waitFor();
      if (await review.isVisible()) await review.getByRole('button', { name: 'Export anyway' }).click();
    });
    expect(file.text).toContain('<project');
    await editor.menu('File', 'New project');
    // The project was never saved to a file: the editor asks first.
    await page.getByRole('button', { name: 'Discard and start new' }).click();
    await poll(async () => (await editor.project()).pous.length).toBe(1);
    await editor.chooseFile('File', 'Import PLCopen XML…', { name: file.name, mimeType: 'application/xml', text: file.text });
    const report = page.getByTestId('plcopen-report');
    await report.waitFor();
    expect(await report.textContent()).toContain('Nothing was dropped or changed.');
    // It opens on the program the task runs.
    expect(await report.getByTestId('plcopen-pou-choice').locator('option:checked').textContent()).toMatch(/^Main \(program/);
    await stage('import report');
    await report.getByRole('button', { name: 'Open' }).click();
    await poll(async () => (await editor.project()).pous.map((p) => p.name).sort()).toEqual(original.pous.map((p) => p.name).sort());
    const back = await editor.project();
    const mainBack = back.pous.find((p) => p.name === 'Main')!;
    expect(mainBack.variables).toEqual(original.pous.find((p) => p.name === 'Main')!.variables);
    // The same calls in the same order (the importer lays the networks out again, and splits the
    // two unconnected calls of network 3 into a network each).
    const callsOf = (networks: typeof mainBack.networks) =>
      networks.flatMap((n) => n.elements.flatMap((e) => (e.kind === 'box' ? [`${e.blockType}:${e.instance}:${JSON.stringify({ ...e.inputs, ...e.outputs })}`] : [])));
    expect(callsOf(mainBack.networks)).toEqual(callsOf(original.pous.find((p) => p.name === 'Main')!.networks));
    expect(back.pous.find((p) => p.name === 'Conveyor')!.variables).toEqual(original.pous.find((p) => p.name === 'Conveyor')!.variables);
    await poll(() => page.getByTestId('pou-tab-Main').getAttribute('aria-selected')).toBe('true');
    await expect.poll(() => draw.problemsSummary(), CHECKS).toBe('No problems');
    await stage('imported');

    // 13. Connect the gateway (Hardware tab, token from the page) and drive Motor, %QX0.0, on the
    // simulated device: its coil 0, read over Modbus TCP.
    await page.getByTestId('pou-tab-Main').click();
    await page.getByTestId('tab-hardware').click();
    const panel = page.getByTestId('hardware-panel');
    await panel.getByTestId('hw-connect').click();
    await poll(() => panel.getByTestId('hw-link').textContent()).toBe('Connected as controller');
    await stage('hardware connected');
    await sim.button('run').click();
    await sim.waitForMode('Running');
    const start = panel.getByTestId('hw-point-%IX0.0').getByTestId('hw-switch');
    await start.click();
    await sim.waitForValue('Motor', true);
    await start.click();
    await sim.waitForValue('Start', false);
    await poll(() => panel.getByTestId('hw-point-%QX0.0').getByTestId('hw-value').textContent()).toBe('TRUE');
    const modbus = new ModbusRTU();
    await modbus.connectTCP('127.0.0.1', { port: simModbusPort() });
    try {
      modbus.setTimeout(5_000);
      await expect.poll(async () => (await modbus.readCoils(0, 1)).data[0], { timeout: 15_000 }).toBe(true);
      await stage('output driven');
      // Pause: the gateway writes the safe state, the coil goes off.
      await sim.button('pause').click();
      await sim.waitForMode('Paused');
      await expect.poll(async () => (await modbus.readCoils(0, 1)).data[0], { timeout: 15_000 }).toBe(false);
    } finally {
      modbus.close(() => undefined);
    }
    await sim.button('reset').click();
    await sim.waitForMode('Stopped');
    await panel.getByTestId('hw-connect').click();
    await poll(() => panel.getByTestId('hw-link').textContent()).toBe('Not connected');
    await stage('done');
  } finally {
    await context.close();
  }
});

