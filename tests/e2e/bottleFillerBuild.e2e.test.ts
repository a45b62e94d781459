// The bottle-filling station of issue 24 (bench/bottleFiller.ts) built through the UI by a script
// that drives only the keyboard and the mouse, counting what a user does: every key press or
// chord (Ctrl+Enter is one), every click, every name or line typed (one action per field, its
// characters counted as keystrokes too), and a copy from a spreadsheet (the clipboard filled as
// the stand-in for the user's Ctrl+C there) as one action. The station: 15 globals pasted as a
// symbol table, a user FB Conveyor (LD, its interface declared from the canvas) called twice, a
// CTU, a TON, a maintenance jump with labels, 13 networks in Main, a program Signals in a second
// task. At the end the checks find no error, F5 runs it and Start lights the run lamp.
import type { Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, expect, test } from 'vitest';
import type { Project } from '../../src/model/project';
import { appUrl, openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let errors: string[];
let draw: DrawPage;
let sim: SimPage;

/** What the user did: actions (keys, clicks, fields typed, copies) and keystrokes (every key). */
const count = { actions: 0, keystrokes: 0, arrowsToDeclare: 0 };
/** The new names whose offer to declare was listed under names that contain them. */
const detours: string[] = [];
const poll = <T>(fn: () => T | Promise<T>) => expect.poll(fn, { timeout: 30_000, interval: 50 });

/** One key or chord. */
async function key(k: string) {
  count.actions++;
  count.keystrokes++;
  await page.keyboard.press(k);
}
/** Text typed into one field: one action, one keystroke per character. */
async function type(text: string) {
  count.actions++;
  count.keystrokes += text.length;
  await page.keyboard.type(text);
}
/** A mouse click at a point. */
async function click(p: { x: number; y: number }) {
  count.actions++;
  await page.mouse.click(p.x, p.y);
}
/** A mouse click in the middle of what a locator shows. */
async function clickOn(testIdOrLocator: string | ReturnType<Page['locator']>) {
  const loc = typeof testIdOrLocator === 'string' ? page.getByTestId(testIdOrLocator) : testIdOrLocator;
  await loc.waitFor();
  const box = (await loc.boundingBox())!;
  await click({ x: box.x + box.width / 2, y: box.y + box.height / 2 });
}
/** The user's copy in a spreadsheet or a text editor: one action. */
async function copyFromElsewhere(text: string) {
  count.actions++;
  await page.evaluate((t) => navigator.clipboard.writeText(t), text);
}

const inline = () => page.getByTestId('inline-editor');
const project = (): Promise<Project> =>
  page.evaluate(() => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project);
const networkCount = async () => (await draw.networks()).length;

/**
 * Takes the offer for a typed name with `end` (Enter, or Tab in a pin): the name itself when it is
 * declared (listed first), else the first offer to declare it, reached with ↓ as a user must when
 * names that contain it (ConveyorJam for Jam) are listed above the offer.
 */
async function takeOffer(name: string, end: 'Enter' | 'Tab') {
  const options = page.locator('[role="listbox"] [role="option"]');
  await poll(() => options.count()).toBeGreaterThan(0);
  const list = await options.evaluateAll((els) =>
    els.map((e) => ({ declare: e.classList.contains('rs-declare'), text: e.querySelector('.rs-mono')?.textContent ?? '' })),
  );
  const first = list[0]!;
  if (first.declare || first.text.toUpperCase() !== name.toUpperCase()) {
    const at = list.findIndex((o) => o.declare);
    expect(at, `an offer to declare ${name}`).toBeGreaterThanOrEqual(0);
    for (let i = 0; i < at; i++) await key('ArrowDown');
    count.arrowsToDeclare += at;
    if (at > 0) detours.push(`${name} (${list.slice(0, at).map((o) => o.text).join(', ')})`);
  }
  await key(end);
}

/** Places an element with its key and names it: the name typed, Enter takes the offer (use or declare). */
async function element(k: string, name: string) {
  await key(k);
  await inline().waitFor();
  await type(name);
  await poll(() => inline().inputValue()).toBe(name);
  await takeOffer(name, 'Enter');
  await inline().waitFor({ state: 'detached' });
}

/** A block from the block search (B), its instance named (declared by Enter). */
async function block(blockType: string, instance: string) {
  await key('b');
  const search = page.getByRole('combobox', { name: 'Search blocks' });
  await search.waitFor();
  await type(blockType);
  await poll(() => page.getByRole('option', { name: new RegExp(`^${blockType}`) }).count()).toBeGreaterThan(0);
  await key('Enter');
  await inline().waitFor();
  await type(instance);
  await poll(() => page.locator('[role="listbox"] [role="option"]').count()).toBeGreaterThan(0);
  await key('Enter');
  await inline().waitFor({ state: 'detached' });
}

/**
 * Enter on the selected box, then its open pins in order, Tab between them ('' leaves a pin open:
 * Tab past it), Escape or Enter at the end.
 */
async function pins(...operands: string[]) {
  await key('Enter');
  const pin = page.getByTestId('pin-editor');
  await pin.waitFor();
  for (const [i, operand] of operands.entries()) {
    const before = await page.locator('[data-pin]').getAttribute('data-pin');
    const last = i === operands.length - 1;
    if (operand !== '') {
      await type(operand);
      await poll(() => pin.inputValue()).toBe(operand);
    }
    // A name takes its offer (use or declare); a literal or an empty pin has none.
    if (/^[A-Za-z_]\w*$/.test(operand)) await takeOffer(operand, last ? 'Enter' : 'Tab');
    else await key(last ? 'Enter' : 'Tab');
    if (!last) await poll(() => page.locator('[data-pin]').getAttribute('data-pin')).not.toBe(before);
  }
  if (await pin.isVisible()) await key('Escape');
  await pin.waitFor({ state: 'detached' });
}

/** N: a new network below, the cursor in it. */
async function newNetwork() {
  const before = await networkCount();
  await key('n');
  await poll(networkCount).toBe(before + 1);
}

/** L: the label of the cursor's network. */
async function label(name: string, network: number) {
  await key('l');
  await page.waitForFunction((n) => document.activeElement?.getAttribute('aria-label') === `Label of network ${n}`, network);
  await type(name);
  await key('Enter');
  await poll(async () => (await draw.networks())[network - 1]!.label).toBe(name);
  await poll(() => page.evaluate(() => document.activeElement?.getAttribute('data-testid'))).toBe('ladder-canvas');
}

/** A jump to a label (the label may not exist yet: Shift+Enter keeps the name as typed). */
async function jump(target: string) {
  await key('j');
  await inline().waitFor();
  await type(target);
  await key('Shift+Enter');
  await inline().waitFor({ state: 'detached' });
}

/** The project tree's button adding a POU, and its name typed. */
async function addPou(button: 'add-fb' | 'add-program', name: string) {
  await clickOn('tab-project');
  await clickOn(button);
  const field = page.getByTestId('pou-rename');
  await field.waitFor();
  await type(name);
  await key('Enter');
  await page.getByTestId(`pou-tab-${name}`).waitFor();
  await poll(() => page.getByTestId(`pou-tab-${name}`).getAttribute('aria-selected')).toBe('true');
}

/** A click on the first cell of the shown POU's first network: the keyboard goes to the canvas. */
async function clickFirstCell() {
  await draw.canvas().waitFor();
  await click(await draw.cellPoint(0, 0, 0));
  await poll(() => page.evaluate(() => document.activeElement?.getAttribute('data-testid'))).toBe('ladder-canvas');
}

// The I/O list as a spreadsheet holds it: name, type, address, initial value, comment.
const IO_LIST = [
  ['Start', 'BOOL', '%IX0.0', '', 'Start push button'],
  ['Stop', 'BOOL', '%IX0.1', '', 'Stop push button (TRUE while pressed)'],
  ['EStop', 'BOOL', '%IX0.2', '', 'Emergency stop chain open'],
  ['MaintKey', 'BOOL', '%IX0.3', '', 'Maintenance key switch'],
  ['BottleAtFill', 'BOOL', '%IX0.4', '', 'Photo eye: bottle under the fill nozzle'],
  ['BottleAtExit', 'BOOL', '%IX0.5', '', 'Photo eye: bottle at the outfeed'],
  ['LevelHigh', 'BOOL', '%IX0.6', '', 'Level probe: bottle full'],
  ['ConveyorJam', 'BOOL', '%IX0.7', '', 'Jam detector on the conveyors'],
  ['InfeedMotor', 'BOOL', '%QX0.0', '', 'Infeed conveyor motor contactor'],
  ['OutfeedMotor', 'BOOL', '%QX0.1', '', 'Outfeed conveyor motor contactor'],
  ['FillValve', 'BOOL', '%QX0.2', '', 'Fill valve solenoid'],
  ['RunLamp', 'BOOL', '%QX0.3', '', 'Line running lamp'],
  ['BatchLamp', 'BOOL', '%QX0.4', '', 'Batch complete lamp'],
  ['Running', 'BOOL', '%MX0.0', '', 'Line running (sealed in)'],
  ['BatchSize', 'INT', '%MW10', '24', 'Bottles per batch'],
];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page
    .context()
    .grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(appUrl()).origin });
  draw = new DrawPage(page);
  sim = new SimPage(page);
});

/** Actions per test (phase of the build), for the closing note. */
const phases: string[] = [];
let phaseStart = 0;
afterEach((ctx) => {
  phases.push(`${ctx.task.name.split(':')[0]}: ${count.actions - phaseStart}`);
  phaseStart = count.actions;
});

afterAll(() => {
  console.log(phases.join('\n'));
  console.log(`declare offers under other names: ${detours.join('; ')}`);
  console.log(
    `bottle-filler-build actions=${count.actions} keystrokes=${count.keystrokes} (of which ↓ to reach a declare offer: ${count.arrowsToDeclare})`,
  );
  expect(errors).toEqual([]);
  // A new name typed whole is offered for declaration before names that only contain it: Enter
  // never binds another variable (Jam is not ConveyorJam).
  expect(detours).toEqual([]);
});

test('a new project; the 15 globals pasted from the I/O list as a symbol table', async () => {
  await clickFirstCell();
  await key('Control+Alt+n');
  await poll(async () => (await project()).globals.length).toBe(0);
  await poll(async () => (await project()).pous.map((p) => p.name)).toEqual(['Main']);

  await clickOn(page.getByRole('tab', { name: 'Variables', exact: true }));
  const panel = page.getByTestId('variables-panel');
  await clickOn(panel.getByRole('radio', { name: 'Global' }));
  await copyFromElsewhere(IO_LIST.map((r) => r.join('\t')).join('\r\n'));
  await key('Control+v');
  const dialog = page.getByTestId('symbol-paste-dialog');
  await poll(() => dialog.getByTestId('symbol-paste-summary').textContent()).toMatch(/15 added/);
  await poll(() => page.evaluate(() => document.activeElement?.getAttribute('data-testid'))).toBe('symbol-paste-confirm');
  await key('Enter');
  await dialog.waitFor({ state: 'detached' });
  const globals = (await project()).globals;
  expect(globals.map((g) => g.name)).toEqual(IO_LIST.map((r) => r[0]));
  expect(globals.find((g) => g.name === 'BatchSize')).toMatchObject({ type: 'INT', location: '%MW10', initial: '24' });
});

test('FB Conveyor: two networks drawn from the keyboard, its interface declared from the canvas', async () => {
  await addPou('add-fb', 'Conveyor');
  await clickFirstCell();
  // Fault := Jam
  await element('c', 'Jam');
  await element('o', 'Fault');
  // Motor := Enable AND NOT Fault
  await newNetwork();
  await element('c', 'Enable');
  await element('Shift+C', 'Fault');
  await element('o', 'Motor');
  const fb = (await project()).pous.find((p) => p.name === 'Conveyor')!;
  expect(fb.kind).toBe('FUNCTION_BLOCK');
  expect(fb.variables.map((v) => `${v.name}:${v.varClass}`)).toEqual(['Jam:input', 'Fault:output', 'Enable:input', 'Motor:output']);
  expect(fb.networks).toHaveLength(2);
});

test('Main: the 13 networks, keyboard placement, blocks with pins, jump and labels', async () => {
  await clickOn('pou-tab-Main');
  await clickFirstCell();
  // 1 Line running: (Start OR Running) AND NOT Stop AND NOT EStop -> Running
  await element('c', 'Start');
  await element('Shift+C', 'Stop');
  await element('Shift+C', 'EStop');
  await element('o', 'Running');
  await click(await draw.cellPoint(0, 0, 0));
  await key('Control+Shift+B');
  await key('ArrowDown');
  await element('c', 'Running');
  // 2 Maintenance: MaintKey -> jump MAINT
  await newNetwork();
  await element('c', 'MaintKey');
  await jump('MAINT');
  // 3 Infeed conveyor
  await newNetwork();
  await element('c', 'Running');
  await element('Shift+C', 'BottleAtFill');
  await block('Conveyor', 'InfeedConv');
  await pins('ConveyorJam');
  await element('o', 'InfeedMotor');
  // 4 Filling
  await newNetwork();
  await element('c', 'Running');
  await element('c', 'BottleAtFill');
  await element('Shift+C', 'FillDone');
  await element('o', 'Filling');
  // 5 Fill time
  await newNetwork();
  await element('c', 'Filling');
  await block('TON', 'FillTimer');
  await pins('T#2s');
  await element('o', 'FillDone');
  // 6 Fill valve
  await newNetwork();
  await element('c', 'Filling');
  await element('Shift+C', 'LevelHigh');
  await element('o', 'FillValve');
  // 7 Bottle count
  await newNetwork();
  await element('p', 'FillDone');
  await block('CTU', 'BottleCounter');
  await pins('Stop', 'BatchSize', '', 'Count');
  await element('o', 'BatchLamp');
  // 8 Outfeed conveyor
  await newNetwork();
  await element('c', 'Running');
  await element('c', 'FillDone');
  await block('Conveyor', 'OutfeedConv');
  await pins('ConveyorJam');
  await element('o', 'OutfeedMotor');
  // 9 Run lamp
  await newNetwork();
  await element('c', 'Running');
  await element('o', 'RunLamp');
  // 10 Skip maintenance
  await newNetwork();
  await element('Shift+C', 'MaintKey');
  await jump('DONE');
  // 11 Maintenance mode, label MAINT
  await newNetwork();
  await label('MAINT', 11);
  await element('c', 'MaintKey');
  await element('o', 'MaintActive');
  // 12 Maintenance jog
  await newNetwork();
  await element('c', 'MaintActive');
  await element('c', 'Start');
  await element('o', 'JogRequest');
  // 13 Bottle out, label DONE
  await newNetwork();
  await label('DONE', 13);
  await element('p', 'BottleAtExit');
  await element('o', 'ExitPulse');

  const main = (await project()).pous.find((p) => p.name === 'Main')!;
  expect(main.networks).toHaveLength(13);
  expect(main.networks.map((n) => n.label ?? '')).toEqual(['', '', '', '', '', '', '', '', '', '', 'MAINT', '', 'DONE']);
  const boxes = main.networks.flatMap((n) => n.elements.flatMap((e) => (e.kind === 'box' ? [`${e.instance}:${e.blockType}`] : [])));
  expect(boxes).toEqual(['InfeedConv:Conveyor', 'FillTimer:TON', 'BottleCounter:CTU', 'OutfeedConv:Conveyor']);
  expect(main.variables.map((v) => `${v.name}:${v.type}`).sort()).toEqual(
    [
      'BottleCounter:CTU',
      'Count:INT',
      'ExitPulse:BOOL',
      'FillDone:BOOL',
      'FillTimer:TON',
      'Filling:BOOL',
      'InfeedConv:Conveyor',
      'JogRequest:BOOL',
      'MaintActive:BOOL',
      'OutfeedConv:Conveyor',
    ].sort(),
  );
});

test('program Signals (a blinker) in a second task of 100 ms', async () => {
  await addPou('add-program', 'Signals');
  await clickFirstCell();
  await element('Shift+C', 'Blink');
  await block('TON', 'BlinkTimer');
  await pins('T#500ms');
  await element('o', 'Blink');

  await clickOn('tab-project');
  await clickOn('tree-tasks-edit');
  await page.getByTestId('tasks-dialog').waitFor();
  // A new PROGRAM gets a task of its own (+ Program's default "runs in: its own task"), named
  // after it: only its interval is left to set.
  expect((await project()).tasks.map((t) => [t.name, t.programs.map((p) => p.pou)])).toEqual([
    ['MainTask', ['Main']],
    ['T_Signals', ['Signals']],
  ]);
  await clickOn('task-cycle-1');
  await key('Control+a');
  await type('100');
  await key('Enter');
  await poll(async () => (await project()).tasks[1]?.cycleMs).toBe(100);
  await clickOn('tasks-close');
  await page.getByTestId('tasks-dialog').waitFor({ state: 'detached' });
  expect((await project()).tasks.map((t) => t.programs.map((p) => p.pou))).toEqual([['Main'], ['Signals']]);
});

test('no problems; F5 runs it and Start lights the run lamp', async () => {
  await clickOn('pou-tab-Main');
  await clickOn(page.getByRole('tab', { name: 'Problems', exact: true }));
  await poll(async () => {
    const summary = await draw.problemsSummary();
    return summary === 'No problems' ? summary : `${summary}: ${(await page.getByTestId('problem').allTextContents()).join(' | ')}`;
  }).toBe('No problems');
  await click(await draw.cellPoint(0, 0, 0));
  await key('F5');
  await sim.waitForMode('Running');
  // A double-click on the Start contact switches the input, as a user does while simulating.
  count.actions++;
  await sim.switchCell(0, 0, 0);
  await poll(() => sim.wireLit(8, 0, 0)).toBe(true);
  await sim.waitForValue('RunLamp', true);
  await key('Shift+F5');
});
