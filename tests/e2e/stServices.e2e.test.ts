// Language services of the ST editor (issue 25) in Chromium against the real server: an error
// typed shows at its line (underline, gutter mark) and in the Problems list, blocks Run with its
// rule id, and the problem leads back to the line; completion of `Motor1.` lists the TON's pins;
// hover shows a variable's type and comment; F2 renames an FB input in its body, in an ST caller
// and on an LD caller's box, as one undo step.
import type { Locator, Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import type { ElementId } from '../../src/model/ids';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
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
  await sim.load(plant());
});

const v = variable;
const HYST = 'IF X > Limit THEN\n    Q := TRUE;\nELSIF X < Limit - 1.0 THEN\n    Q := FALSE;\nEND_IF;';
const MAIN = 'Motor1(IN := Start, PT := T#5s);\nH1(X := Level, Limit := 80.0);';

function plant(): Project {
  const ladder: LdElement[] = [
    { kind: 'contact', contact: 'NO', variable: 'H2.Q', id: 'c1' as ElementId, row: 0, col: 0 },
    {
      kind: 'box',
      blockType: 'Hyst',
      instance: 'H2',
      executionControl: true,
      id: 'b1' as ElementId,
      row: 0,
      col: 1,
      inputs: { X: 'Level2', Limit: '50.0' },
      outputs: {},
    },
    { kind: 'coil', coil: 'COIL', variable: 'Lamp', id: 'l1' as ElementId, row: 0, col: 6 },
  ];
  return newProject('StServices', {
    pous: [
      newPou('Main', {
        variables: [
          v('Motor1', 'TON', { comment: 'pump start delay' }),
          v('Start', 'BOOL'),
          v('Level', 'REAL', { comment: 'tank level in %' }),
          v('H1', 'Hyst'),
        ],
        networks: [],
        language: 'ST',
        source: MAIN,
      }),
      newPou('Hyst', {
        kind: 'FUNCTION_BLOCK',
        variables: [
          v('X', 'REAL', { varClass: 'input' }),
          v('Limit', 'REAL', { varClass: 'input', comment: 'switch-on level' }),
          v('Q', 'BOOL', { varClass: 'output' }),
        ],
        networks: [],
        language: 'ST',
        source: HYST,
      }),
      newPou('Ladder', {
        variables: [v('H2', 'Hyst'), v('Level2', 'REAL'), v('Lamp', 'BOOL')],
        networks: [newNetwork({ elements: ladder })],
      }),
    ],
  });
}

const project = (): Promise<Project> =>
  page.evaluate(
    () => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project,
  );
const pou = async (name: string) => (await project()).pous.find((p) => p.name === name)!;

async function openPou(name: string): Promise<void> {
  await page.getByTestId('tab-project').click();
  await page
    .getByTestId(`tree-pou-${name}`)
    .getByRole('button', { name: new RegExp(name) })
    .first()
    .click();
  await content().waitFor();
  await poll(() => page.getByTestId('st-editor').getAttribute('data-pou')).toBe(name);
}

const content = (): Locator => page.getByTestId('st-editor').locator('.cm-content');
const shownText = () =>
  content().evaluate((e) => [...e.querySelectorAll('.cm-line')].map((l) => l.textContent).join('\n'));

/** The centre of the `nth` occurrence of `word` in the editor's text, on screen. */
async function wordPoint(word: string, nth = 0): Promise<{ x: number; y: number }> {
  const p = await content().evaluate(
    (root, { word, nth }) => {
      let seen = 0;
      const walker = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
      for (let n = walker.nextNode(); n; n = walker.nextNode()) {
        const text = n.textContent ?? '';
        for (let i = text.indexOf(word); i >= 0; i = text.indexOf(word, i + 1)) {
          if (seen++ < nth) continue;
          const r = document.createRange();
          r.setStart(n, i);
          r.setEnd(n, i + word.length);
          const b = r.getBoundingClientRect();
          return { x: b.left + b.width / 2, y: b.top + b.height / 2 };
        }
      }
      return undefined;
    },
    { word, nth },
  );
  if (!p) throw new Error(`"${word}" is not shown in the editor`);
  return p;
}

/** Puts the cursor inside the word (a click on it). */
async function clickWord(word: string, nth = 0): Promise<void> {
  const p = await wordPoint(word, nth);
  await page.mouse.click(p.x, p.y);
}

test('an error typed shows at its line and in the Problems list, blocks Run with its rule id, and leads back to the line', async () => {
  await openPou('Main');
  await content().click();
  await page.keyboard.press('Control+End');
  await page.keyboard.press('Enter');
  await page.keyboard.type('Level := Start;');
  // Underlined where the compiler says, with a mark in the gutter of line 3.
  const underline = content().locator('.cm-lintRange-error');
  await poll(() => underline.allTextContents()).toEqual(['Start']);
  expect(await content().locator('.cm-line').nth(2).locator('.cm-lintRange-error').count()).toBe(1);
  const gutterMarks = page.getByTestId('st-editor').locator('.cm-gutter-lint .cm-lint-marker-error');
  await poll(() => gutterMarks.count()).toBe(1);

  // The Problems list locates it (once the burst is committed and the project checked).
  await page.getByRole('tab', { name: 'Problems', exact: true }).click();
  const listed = page.getByTestId('problems-panel').locator('[data-rule="LD-E50"]');
  await poll(() => listed.count()).toBe(1);
  expect(await listed.textContent()).toContain('line 3, column 10');
  expect(await listed.textContent()).toContain('REAL is needed and the value is BOOL');

  // Run is refused, naming the rule, the POU and the line.
  await sim.button('run').click();
  const refusal = page.getByTestId('sim-refusal');
  await poll(() => refusal.textContent()).toMatch(/Run refused/);
  expect(await refusal.textContent()).toContain('LD-E50 Main line 3, column 10');
  expect(await sim.mode()).toContain('Stopped');
  await refusal.getByRole('button', { name: /^Dismiss/ }).click();

  // The problem leads back to the line: the cursor is on it.
  await clickWord('Motor1');
  await listed.click();
  await poll(() => content().locator('.cm-activeLine').textContent()).toBe('Level := Start;');

  // Fixed: the underline and the problem go.
  await page.keyboard.press('End');
  for (let i = 0; i < 'Start;'.length; i++) await page.keyboard.press('Backspace');
  await page.keyboard.type('0.0;');
  await poll(() => underline.count()).toBe(0);
  await poll(() => listed.count()).toBe(0);
  await poll(async () => (await pou('Main')).source).toBe(`${MAIN}\nLevel := 0.0;`);
  expect(errors).toEqual([]);
});

test('completion of "Motor1." lists the TON pins with their types; hover shows type and comment', async () => {
  await openPou('Main');
  await content().click();
  await page.keyboard.press('Control+End');
  await page.keyboard.press('Enter');
  await page.keyboard.type('Start := Motor1.');
  const list = page.locator('.cm-tooltip-autocomplete');
  await poll(() => list.locator('.cm-completionLabel').allTextContents()).toEqual(['Q', 'ET', 'IN', 'PT']);
  expect(await list.locator('li', { hasText: 'ET' }).locator('.cm-completionDetail').textContent()).toBe(
    'TIME — output of TON',
  );
  // The list stays open while the typing burst is committed to the project (after its pause).
  await poll(async () => (await project()).pous[0]!.source).toContain('Start := Motor1.');
  await poll(() => list.locator('[aria-selected="true"] .cm-completionLabel').textContent()).toBe('Q');
  await page.keyboard.press('Enter');
  await page.keyboard.type(';');
  await poll(shownText).toContain('Start := Motor1.Q;');
  await page.keyboard.press('Escape');

  // Hover: the variable's declaration, class and comment; a pin's type.
  const level = await wordPoint('Level');
  await page.mouse.move(level.x, level.y);
  const hover = page.getByTestId('st-hover');
  await poll(() => hover.textContent()).toContain('Level : REAL');
  expect(await hover.textContent()).toContain('tank level in %');
  const pin = await wordPoint('Limit');
  await page.mouse.move(pin.x, pin.y);
  await poll(() => hover.textContent()).toContain('Limit : REAL');
  expect(await hover.textContent()).toContain('switch-on level');
  await page.mouse.move(5, 5);
  expect(errors).toEqual([]);
});

test('F2 renames an FB input in its body, an ST caller and an LD caller as one undo step; a clash is refused with the reason', async () => {
  await openPou('Main');
  // A name already declared is refused in the prompt, and nothing changes.
  await clickWord('Level');
  await page.keyboard.press('F2');
  const input = page.getByTestId('st-rename-input');
  await input.waitFor();
  expect(await input.inputValue()).toBe('Level');
  await input.fill('Start');
  await input.press('Enter');
  await poll(() => page.getByTestId('st-rename-error').textContent()).toBe(
    '"Start" is already declared in Main',
  );
  await input.press('Escape');
  await page.getByTestId('st-rename').waitFor({ state: 'detached' });

  // The input Limit of Hyst, renamed from its caller's named argument.
  await clickWord('Limit');
  await page.keyboard.press('F2');
  await input.waitFor();
  await input.fill('OnLevel');
  await input.press('Enter');
  await page.getByTestId('st-rename').waitFor({ state: 'detached' });
  await poll(shownText).toContain('H1(X := Level, OnLevel := 80.0);');
  const hyst = await pou('Hyst');
  expect(hyst.variables.map((x) => x.name)).toEqual(['X', 'OnLevel', 'Q']);
  expect(hyst.source).toBe(HYST.replaceAll('Limit', 'OnLevel'));
  const box = (await pou('Ladder')).networks[0]!.elements.find((e) => e.kind === 'box');
  expect(box?.kind === 'box' && box.inputs).toEqual({ X: 'Level2', OnLevel: '50.0' });
  expect(await page.evaluate(() => window.rungsmith!.documentStore!.getState().undoName)).toBe(
    'Rename Limit → OnLevel',
  );

  // One Ctrl+Z in the editor undoes all of it.
  await content().click();
  await page.keyboard.press('Control+z');
  await poll(shownText).toContain('H1(X := Level, Limit := 80.0);');
  expect((await pou('Hyst')).source).toBe(HYST);
  const back = (await pou('Ladder')).networks[0]!.elements.find((e) => e.kind === 'box');
  expect(back?.kind === 'box' && back.inputs).toEqual({ X: 'Level2', Limit: '50.0' });
  expect(errors).toEqual([]);
});
