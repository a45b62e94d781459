// The ST editor (issue 25): an ST POU opens editable in a code editor with IEC highlighting,
// block keyword and bracket matching, folding and smart indentation; what is typed is one named undo
// step per burst in the project's history, and Ctrl+Z / Ctrl+Y in the editor are the project's
// undo and redo.
import type { Locator, Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { newPou, newProject } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { poll } from './panelsPage';

const browser = useChromium();
let page: Page;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
});

const project = (): Promise<Project> =>
  page.evaluate(() => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project);
const source = async (name: string) => (await project()).pous.find((p) => p.name === name)?.source;
const undoName = () => page.evaluate(() => window.rungsmith!.documentStore!.getState().undoName);

/** Opens a POU from the project tree. */
async function openPou(name: string): Promise<void> {
  await page.getByTestId('tab-project').click();
  await page.getByTestId(`tree-pou-${name}`).getByRole('button', { name: new RegExp(name) }).first().click();
}

const content = (): Locator => page.getByTestId('st-editor').locator('.cm-content');
/** The editor's text, line by line as shown. */
const shownText = () => content().evaluate((e) => [...e.querySelectorAll('.cm-line')].map((l) => l.textContent).join('\n'));

const BODY = [
  '(* Scale a raw value',
  '   to engineering units *)',
  'IF Raw > 16#7FFF THEN',
  '    Out := 100.0; // clamp',
  'ELSIF Raw < 0 THEN',
  '    Out := 0.0;',
  'ELSE',
  "    Out := INT_TO_REAL(Raw) * 1.5E-2 + Bias; {pragma}",
  'END_IF;',
  "Msg := 'ok';",
  'Delay := T#5s; Slow := TIME#1h2m; Addr := %IX0.0; Count := INT#5; Mask := 2#1010;',
].join('\n');

test('an ST POU opens editable, highlighted, with block matching, folding and indentation', async () => {
  await page.evaluate(
    ({ p }) => window.rungsmith!.documentStore!.getState().loadProject(p),
    {
      p: newProject('StEdit', {
        pous: [newPou('Main'), newPou('Filter', { kind: 'FUNCTION_BLOCK', language: 'ST', networks: [], source: BODY })],
      }),
    },
  );
  await openPou('Filter');
  await content().waitFor();
  expect(await content().getAttribute('aria-label')).toBe('ST body of Filter');
  expect(await content().getAttribute('contenteditable')).toBe('true');
  expect(await shownText()).toBe(BODY);

  // Highlighting: each kind of token has its class.
  const tokens = (cls: string) => content().locator(`.${cls}`).allTextContents();
  expect(await tokens('cm-st-keyword')).toEqual(expect.arrayContaining(['IF', 'THEN', 'ELSIF', 'ELSE', 'END_IF']));
  expect(await tokens('cm-st-number')).toEqual(expect.arrayContaining(['16#7FFF', '100.0', '1.5E-2', 'INT#5', '2#1010']));
  expect(await tokens('cm-st-time')).toEqual(['T#5s', 'TIME#1h2m']);
  expect(await tokens('cm-st-address')).toEqual(['%IX0.0']);
  expect(await tokens('cm-st-string')).toEqual(["'ok'"]);
  expect(await tokens('cm-st-pragma')).toEqual(['{pragma}']);
  // (Bracket matching may split a comment's "(" into a span of its own: compare the text.)
  expect((await tokens('cm-st-comment')).join('')).toBe('(* Scale a raw value   to engineering units *)// clamp');
  expect(await tokens('cm-st-call')).toEqual(['INT_TO_REAL']);

  // Keyword matching: the cursor on ELSIF marks IF, THEN, ELSIF, THEN, ELSE and END_IF.
  await content().locator('.cm-line', { hasText: 'ELSIF' }).click();
  await page.keyboard.press('Home');
  await poll(() => content().locator('.cm-st-blockMatch').allTextContents()).toEqual(['IF', 'THEN', 'ELSIF', 'THEN', 'ELSE', 'END_IF']);
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
  await page.evaluate(
    ({ p }) => window.rungsmith!.documentStore!.getState().loadProject(p),
    { p: newProject('Undo', { pous: [newPou('Main'), newPou('Calc', { kind: 'FUNCTION_BLOCK', language: 'ST', networks: [], source: '' })] }) },
  );
  await openPou('Calc');
  await content().click();
  // Smart indentation: after THEN the next line is indented; END_IF dedents as it is typed.
  await page.keyboard.type('IF Start THEN');
  await page.keyboard.press('Enter');
  await page.keyboard.type('Run := TRUE;');
  await page.keyboard.press('Enter');
  await page.keyboard.type('END_IF;');
  const typed = 'IF Start THEN\n    Run := TRUE;\nEND_IF;';
  expect(await shownText()).toBe(typed);
  await poll(() => source('Calc')).toBe(typed);
  expect(await undoName()).toBe('Edit ST body of Calc');

  // A second burst, ended by the pause.
  await page.keyboard.press('Enter');
  await page.keyboard.type('Count := Count + 1;');
  const second = `${typed}\nCount := Count + 1;`;
  await poll(() => source('Calc')).toBe(second);

  await page.keyboard.press('Control+z');
  await poll(shownText).toBe(typed);
  expect(await source('Calc')).toBe(typed);
  await page.keyboard.press('Control+z');
  await poll(shownText).toBe('');
  await page.keyboard.press('Control+y');
  await poll(shownText).toBe(typed);
  await page.keyboard.press('Control+Shift+Z');
  await poll(shownText).toBe(second);
  // The cursor is where the redo happened: typing goes on at the end.
  await page.keyboard.type(' // more');
  await poll(() => source('Calc')).toBe(`${second} // more`);
  // An edit not committed yet goes to the model before Undo undoes it.
  await page.keyboard.type('!');
  await page.keyboard.press('Control+z');
  await poll(shownText).toBe(`${second} // more`);
  expect(await source('Calc')).toBe(`${second} // more`);
  expect(errors).toEqual([]);
});
