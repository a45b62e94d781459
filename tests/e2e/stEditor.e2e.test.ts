// The ST editor (issue 25): an ST POU opens editable in a code editor with IEC highlighting,
// block keyword and bracket matching, folding and smart indentation; what is typed is one named undo
// step per burst in the project's history, and Ctrl+Z / Ctrl+Y in the editor are the project's
// undo and redo. A Scale FUNCTION and a hysteresis FB written in ST through the UI are called
// from an LD network and run.
import type { Locator, Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newPou, newProject } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
});

const project = (): Promise<Project> =>
  page.evaluate(
    () => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project,
  );
const source = async (name: string) => (await project()).pous.find((p) => p.name === name)?.source;
const undoName = () => page.evaluate(() => window.rungsmith!.documentStore!.getState().undoName);

/** Opens a POU from the project tree. */
async function openPou(name: string): Promise<void> {
  await page.getByTestId('tab-project').click();
  await page
    .getByTestId(`tree-pou-${name}`)
    .getByRole('button', { name: new RegExp(name) })
    .first()
    .click();
}

const content = (): Locator => page.getByTestId('st-editor').locator('.cm-content');
/** The editor's text, line by line as shown. */
const shownText = () =>
  content().evaluate((e) => [...e.querySelectorAll('.cm-line')].map((l) => l.textContent).join('\n'));

const BODY = [
  '(* Scale a raw value',
  '   to engineering units *)',
  'IF Raw > 16#7FFF THEN',
  '    Out := 100.0; // clamp',
  'ELSIF Raw < 0 THEN',
  '    Out := 0.0;',
  'ELSE',
  '    Out := INT_TO_REAL(Raw) * 1.5E-2 + Bias; {pragma}',
  'END_IF;',
  "Msg := 'ok';",
  'Delay := T#5s; Slow := TIME#1h2m; Addr := %IX0.0; Count := INT#5; Mask := 2#1010;',
].join('\n');

test('an ST POU opens editable, highlighted, with block matching, folding and indentation', async () => {
  await page.evaluate(({ p }) => window.rungsmith!.documentStore!.getState().loadProject(p), {
    p: newProject('StEdit', {
      pous: [
        newPou('Main'),
        newPou('Filter', { kind: 'FUNCTION_BLOCK', language: 'ST', networks: [], source: BODY }),
      ],
    }),
  });
  await openPou('Filter');
  await content().waitFor();
  expect(await content().getAttribute('aria-label')).toBe('ST body of Filter');
  expect(await content().getAttribute('contenteditable')).toBe('true');
  expect(await shownText()).toBe(BODY);

  // Highlighting: each kind of token has its class.
  const tokens = (cls: string) => content().locator(`.${cls}`).allTextContents();
  expect(await tokens('cm-st-keyword')).toEqual(
    expect.arrayContaining(['IF', 'THEN', 'ELSIF', 'ELSE', 'END_IF']),
  );
  expect(await tokens('cm-st-number')).toEqual(
    expect.arrayContaining(['16#7FFF', '100.0', '1.5E-2', 'INT#5', '2#1010']),
  );
  expect(await tokens('cm-st-time')).toEqual(['T#5s', 'TIME#1h2m']);
  expect(await tokens('cm-st-address')).toEqual(['%IX0.0']);
  expect(await tokens('cm-st-string')).toEqual(["'ok'"]);
  expect(await tokens('cm-st-pragma')).toEqual(['{pragma}']);
  // (Bracket matching may split a comment's "(" into a span of its own: compare the text.)
  expect((await tokens('cm-st-comment')).join('')).toBe(
    '(* Scale a raw value   to engineering units *)// clamp',
  );
  expect(await tokens('cm-st-call')).toEqual(['INT_TO_REAL']);

  // Keyword matching: the cursor on ELSIF marks IF, THEN, ELSIF, THEN, ELSE and END_IF.
  await content().locator('.cm-line', { hasText: 'ELSIF' }).click();
  await page.keyboard.press('Home');
  await poll(() => content().locator('.cm-st-blockMatch').allTextContents()).toEqual([
    'IF',
    'THEN',
    'ELSIF',
    'THEN',
    'ELSE',
    'END_IF',
  ]);
  // Bracket matching: the cursor after "INT_TO_REAL(" marks its ")".
  await content().locator('.cm-line', { hasText: 'INT_TO_REAL' }).click();
  await page.keyboard.press('Home');
  for (let i = 0; i < '    Out := INT_TO_REAL'.length; i++) await page.keyboard.press('ArrowRight');
  await poll(() => content().locator('.cm-matchingBracket').allTextContents()).toEqual(['(', ')']);

  // Folding: the IF block folds to its first line, and unfolds.
  const gutter = page.getByTestId('st-editor').locator('.cm-foldGutter .cm-gutterElement');
  await poll(() => gutter.filter({ hasText: '⌄' }).count()).toBe(2);
  await gutter.filter({ hasText: '⌄' }).nth(1).click();
  await poll(() => content().locator('.cm-line').count()).toBe(BODY.split('\n').length - 5);
  await content().locator('.cm-foldPlaceholder').click();
  await poll(() => content().locator('.cm-line').count()).toBe(BODY.split('\n').length);
  expect(errors).toEqual([]);
});

test('typing is one named undo step per burst; Ctrl+Z and Ctrl+Y in the editor are the project undo and redo', async () => {
  await page.evaluate(({ p }) => window.rungsmith!.documentStore!.getState().loadProject(p), {
    // Main, the program the task runs, written in ST.
    p: newProject('Undo', { pous: [newPou('Main', { language: 'ST', networks: [], source: '' })] }),
  });
  await openPou('Main');
  await content().click();
  // Smart indentation: after THEN the next line is indented; END_IF dedents as it is typed.
  await page.keyboard.type('IF Start THEN');
  await page.keyboard.press('Enter');
  await page.keyboard.type('Run := TRUE;');
  await page.keyboard.press('Enter');
  await page.keyboard.type('END_IF;');
  const typed = 'IF Start THEN\n    Run := TRUE;\nEND_IF;';
  expect(await shownText()).toBe(typed);
  await poll(() => source('Main')).toBe(typed);
  expect(await undoName()).toBe('Edit ST body of Main');

  // A second burst, ended by the pause.
  await page.keyboard.press('Enter');
  await page.keyboard.type('Count := Count + 1;');
  const second = `${typed}\nCount := Count + 1;`;
  await poll(() => source('Main')).toBe(second);

  await page.keyboard.press('Control+z');
  await poll(shownText).toBe(typed);
  expect(await source('Main')).toBe(typed);
  await page.keyboard.press('Control+z');
  await poll(shownText).toBe('');
  await page.keyboard.press('Control+y');
  await poll(shownText).toBe(typed);
  await page.keyboard.press('Control+Shift+Z');
  await poll(shownText).toBe(second);
  // The cursor is where the redo happened: typing goes on at the end.
  await page.keyboard.type(' // more');
  await poll(() => source('Main')).toBe(`${second} // more`);
  // An edit not committed yet goes to the model before Undo undoes it.
  await page.keyboard.type('!');
  await page.keyboard.press('Control+z');
  await poll(shownText).toBe(`${second} // more`);
  expect(await source('Main')).toBe(`${second} // more`);

  // A syntax error, then F5 in the editor: the burst goes in first, and Run is refused with the
  // rule id, the POU and the line and column.
  await content().press('Control+End');
  await page.keyboard.press('Enter');
  await page.keyboard.type('Count := ;');
  await page.keyboard.press('F5');
  const refusal = () =>
    page.evaluate(() =>
      (
        window.rungsmith as unknown as {
          simStore: { getState(): { refusal?: { diagnostics: { rule: string; message: string }[] } } };
        }
      ).simStore
        .getState()
        .refusal?.diagnostics.map((d) => `${d.rule} ${d.message}`),
    );
  await poll(refusal).toEqual(
    expect.arrayContaining([
      expect.stringMatching(/^LD-E50 the ST body of Main does not compile: line 5 col 10/),
    ]),
  );
  expect(await page.getByTestId('sim-mode').textContent()).not.toMatch(/Running/);
  expect(await source('Main')).toBe(`${second} // more\nCount := ;`);
  expect(errors).toEqual([]);
});

/** Adds a POU in ST from the project tree and names it in the field that opens. */
async function addStPou(button: 'add-fb' | 'add-function' | 'add-program', name: string) {
  await page.getByTestId('tab-project').click();
  await page.getByTestId('add-pou-language').selectOption('ST');
  await page.getByTestId(button).click();
  const field = page.getByTestId('pou-rename');
  await field.fill(name);
  await field.press('Enter');
  await page.getByTestId(`pou-tab-${name}`).waitFor();
  await content().waitFor();
}

/** Types lines into the ST editor (Enter between them; the editor indents). */
async function typeLines(lines: readonly string[]) {
  await content().click();
  for (const [i, line] of lines.entries()) {
    if (i > 0) await page.keyboard.press('Enter');
    await page.keyboard.type(line);
  }
}

test('text typed just before another project is opened never goes into that project', async () => {
  await page.evaluate(({ p }) => window.rungsmith!.documentStore!.getState().loadProject(p), {
    p: newProject('First', { pous: [newPou('Main', { language: 'ST', networks: [], source: 'A := 1;' })] }),
  });
  await openPou('Main');
  await content().click();
  await page.keyboard.press('Control+End');
  await page.keyboard.type(' B := 2;');
  // At once (the burst is not committed yet): a project whose Main has the same POU id is opened.
  await page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    const other = JSON.parse(JSON.stringify(s.project)) as Project;
    const main = other.pous.find((p) => p.name === 'Main')!;
    s.loadProject({ ...other, name: 'Second', pous: [{ ...main, source: 'C := 3;' }] });
  });
  await poll(shownText).toBe('C := 3;');
  // Past the burst's pause (ST_BURST_PAUSE_MS, 700 ms), and with the editor left: nothing was committed.
  await page.getByTestId('tab-project').click();
  await page.waitForTimeout(1500);
  expect(await source('Main')).toBe('C := 3;');
  expect(await page.evaluate(() => window.rungsmith!.documentStore!.getState().dirty)).toBe(false);
  expect(await undoName()).toBeUndefined();
});

test('a Scale FUNCTION and a hysteresis FB written in ST through the UI, called from LD, run', async () => {
  const editor = new EditorPage(page);
  const draw = new DrawPage(page);
  const declare = async (name: string, type: string, varClass: string) => {
    await editor.tab('Variables');
    await editor.declare(name, { type });
    await editor.variableRow(name).getByLabel('Class').selectOption(varClass);
  };
  const setPin = async (pin: string, operand: string) => {
    const field = editor.inspector.getByTestId(`pin-${pin}`);
    await field.click();
    await field.fill(operand);
    await field.press('Enter');
  };
  /** Where the call of `type` is in network `index` of Main. */
  const boxCell = async (index: number, type: string): Promise<[number, number]> => {
    const main = (await project()).pous.find((p) => p.name === 'Main')!;
    const box = main.networks[index]!.elements.find((e) => e.kind === 'box' && e.blockType === type)!;
    return [box.row, box.col];
  };
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Tank'));

  await addStPou('add-function', 'Scale');
  expect((await project()).pous.find((p) => p.name === 'Scale')).toMatchObject({
    language: 'ST',
    kind: 'FUNCTION',
    source: '',
  });
  await page.getByTestId('pou-return-type').selectOption('REAL');
  await declare('Raw', 'INT', 'input');
  await typeLines(['(* raw counts to % *)', 'Scale := INT_TO_REAL(Raw) * 0.1;']);
  await poll(() => source('Scale')).toBe('(* raw counts to % *)\nScale := INT_TO_REAL(Raw) * 0.1;');

  // "Hysteresis" is the standard block HYSTERESIS: the tree says so and keeps the field open.
  await page.getByTestId('tab-project').click();
  await page.getByTestId('add-fb').click();
  const field = page.getByTestId('pou-rename');
  await field.fill('Hysteresis');
  await field.press('Enter');
  expect(await page.getByTestId('project-tree').getByRole('alert').textContent()).toContain(
    'standard block HYSTERESIS',
  );
  await field.fill('TankHysteresis');
  await field.press('Enter');
  await page.getByTestId('pou-tab-TankHysteresis').waitFor();
  await content().waitFor();
  for (const [name, type, cls] of [
    ['In', 'REAL', 'input'],
    ['Low', 'REAL', 'input'],
    ['High', 'REAL', 'input'],
    ['Q', 'BOOL', 'output'],
  ] as const)
    await declare(name, type, cls);
  await typeLines(['IF In > High THEN', 'Q := TRUE;', 'ELSIF In < Low THEN', 'Q := FALSE;', 'END_IF;']);
  const body = 'IF In > High THEN\n    Q := TRUE;\nELSIF In < Low THEN\n    Q := FALSE;\nEND_IF;';
  await poll(() => source('TankHysteresis')).toBe(body);

  // Main (LD) calls both: Scale from the block search, the FB in a second network.
  await page.getByTestId('pou-tab-Main').click();
  await page.getByTestId('tab-palette').click();
  await draw.pickPalette('select');
  await draw.clickCell(0, 0, 0);
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('Scale');
  expect(await page.getByRole('option', { name: /Scale/ }).first().textContent()).toContain(
    'Raw : INT → OUT : REAL',
  );
  await page.keyboard.press('Enter');
  await draw.clickCell(0, ...(await boxCell(0, 'Scale')));
  await editor.tab('Inspector');
  await setPin('Raw', 'RawIn');
  await setPin('OUT', 'Level');
  await draw.menu('Network', 'Add network at the end');
  await draw.clickCell(1, 0, 0);
  await page.keyboard.press('b');
  await page.getByRole('combobox', { name: 'Search blocks' }).fill('TankHysteresis');
  expect(
    await page
      .getByRole('option', { name: /TankHysteresis/ })
      .first()
      .textContent(),
  ).toContain('In : REAL, Low : REAL, High : REAL → Q : BOOL');
  await page.keyboard.press('Enter');
  const inline = page.getByTestId('inline-editor');
  await inline.waitFor();
  await poll(() => page.getByRole('option', { name: /Declare TankHysteresis1/ }).count()).toBe(1);
  await page.keyboard.press('Enter');
  await inline.waitFor({ state: 'detached' });
  await draw.clickCell(1, ...(await boxCell(1, 'TankHysteresis')));
  await editor.tab('Inspector');
  await setPin('In', 'Level');
  await setPin('Low', '20.0');
  await setPin('High', '80.0');
  await setPin('Q', 'Pump');
  await poll(() => draw.problemsSummary()).toBe('No problems');

  // Run: the LD result follows the raw value through both ST blocks.
  const sim = new SimPage(page);
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.tab('Watch');
  await page.getByTestId('watch-add-name').fill('RawIn');
  await page.getByTestId('watch-add').click();
  const raw = page.getByTestId('watch-row-RawIn');
  const writeRaw = async (v: number) => {
    await raw.getByTestId('watch-input').fill(String(v));
    await raw.getByTestId('watch-write').click();
  };
  await writeRaw(900);
  await sim.waitForValue('Level', 90);
  await sim.waitForValue('Pump', true);
  await writeRaw(500);
  await sim.waitForValue('Level', 50);
  expect(await sim.value('Pump')).toBe(true);
  await writeRaw(100);
  await sim.waitForValue('Pump', false);
  expect(await sim.value('TankHysteresis1.Q')).toBe(false);
  expect(errors).toEqual([]);
});
