// The inspector follows the selection: a contact or coil clicked after another one keeps the
// inspector's form (it is not built again on every click, docs/benchmarks.md) and shows the new
// element's kind, variable, place and comment; what was typed for the previous element goes to that
// element when the field is left (the click), never to the next one, and a selection that changes
// while a field keeps the keyboard drops the draft.
import { afterAll, beforeAll, expect, test } from 'vitest';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();
let editor: EditorPage;
let draw: DrawPage;

const v = (name: string): Variable => ({ name, type: 'BOOL', varClass: 'local', retain: false, comment: '' });
const e = (s: string) => s as ElementId;

function machine(): Project {
  const main = newPou('Main');
  return newProject('Inspector', {
    pous: [
      {
        ...main,
        variables: [v('Start'), v('Stop'), v('Motor'), v('Lamp'), v('Jog')],
        networks: [
          newNetwork({
            title: 'Motor',
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Start', id: e('a'), row: 0, col: 0 },
              { kind: 'contact', contact: 'NC', variable: 'Stop', id: e('b'), row: 0, col: 1, comment: 'Stop button' },
              { kind: 'coil', coil: 'COIL', variable: 'Motor', id: e('c'), row: 0, col: 9 },
            ],
          }),
          newNetwork({
            title: 'Lamp',
            elements: [
              { kind: 'contact', contact: 'P', variable: 'Jog', id: e('d'), row: 0, col: 0 },
              { kind: 'coil', coil: 'SET', variable: 'Lamp', id: e('f'), row: 0, col: 9 },
            ],
          }),
        ],
      },
    ],
  });
}

interface Shown {
  heading: string;
  where: string;
  kind: string;
  variable: string;
  comment: string;
}

/** What the inspector shows for the selected contact or coil. */
const shown = (): Promise<Shown> =>
  editor.inspector.evaluate((root) => {
    const field = (sel: string) => root.querySelector<HTMLInputElement | HTMLTextAreaElement | HTMLSelectElement>(sel)?.value ?? '';
    return {
      heading: root.querySelector('h2')?.textContent ?? '',
      where: root.querySelector('.rs-inspector-where')?.textContent ?? '',
      kind: field('select'),
      variable: field('[data-testid="inspector-variable"]'),
      comment: field('[data-testid="inspector-element-comment"]'),
    };
  });

/** The element's variable and comment in the document. */
const stored = (id: string) =>
  editor.page.evaluate((id) => {
    const s = window.rungsmith!.documentStore!.getState();
    for (const n of s.project.pous[0]!.networks)
      for (const el of n.elements)
        if (el.id === id && (el.kind === 'contact' || el.kind === 'coil')) return { variable: el.variable, comment: el.comment ?? '' };
    return undefined;
  }, id);

const listOpen = () => editor.inspector.getByRole('listbox', { name: 'Suggestions' }).count();

beforeAll(async () => {
  editor = await EditorPage.open(browser());
  draw = new DrawPage(editor.page);
  await editor.page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), machine());
  await editor.page.getByTestId('network-header-1').waitFor();
  await editor.tab('Inspector');
});

afterAll(async () => {
  await editor.close();
});

test('clicking one contact or coil after another shows each one: kind, variable, place and comment', async () => {
  await draw.clickCell(0, 0, 0);
  await poll(shown).toMatchObject({ where: 'Network 1 · row 1, column 1', kind: 'NO', variable: 'Start', comment: '' });
  expect((await shown()).heading).toMatch(/^Normally open contact/);
  await draw.clickCell(0, 0, 1);
  await poll(shown).toMatchObject({ where: 'Network 1 · row 1, column 2', kind: 'NC', variable: 'Stop', comment: 'Stop button' });
  expect((await shown()).heading).toMatch(/^Normally closed contact/);
  await draw.clickCell(1, 0, 0);
  await poll(shown).toMatchObject({ where: 'Network 2 · row 1, column 1', kind: 'P', variable: 'Jog', comment: '' });
  expect((await shown()).heading).toMatch(/^Positive transition contact/);
  await draw.clickCell(1, 0, 9);
  await poll(shown).toMatchObject({ where: 'Network 2 · row 1, column 10', kind: 'SET', variable: 'Lamp', comment: '' });
  expect((await shown()).heading).toMatch(/coil/i);
  expect((await shown()).heading).toMatch(/set/i);
  await draw.clickCell(0, 0, 9);
  await poll(shown).toMatchObject({ where: 'Network 1 · row 1, column 10', kind: 'COIL', variable: 'Motor', comment: '' });
  expect((await shown()).heading).toMatch(/coil/i);
  expect((await shown()).heading).not.toMatch(/set/i);
  expect(editor.errors).toEqual([]);
});

test('what was typed for one element goes to it when the next one is clicked, not to the next one', async () => {
  await draw.clickCell(0, 0, 0);
  await poll(shown).toMatchObject({ variable: 'Start' });
  // A new variable name typed, not confirmed: the click on the next contact leaves the field.
  await editor.inspector.getByTestId('inspector-variable').fill('Lamp');
  await draw.clickCell(0, 0, 1);
  await poll(shown).toMatchObject({ kind: 'NC', variable: 'Stop', comment: 'Stop button' });
  expect(await stored('a')).toEqual({ variable: 'Lamp', comment: '' });
  expect(await stored('b')).toEqual({ variable: 'Stop', comment: 'Stop button' });

  // The same for the element's own comment.
  await editor.inspector.getByTestId('inspector-element-comment').fill('Emergency stop chain');
  await draw.clickCell(1, 0, 0);
  await poll(shown).toMatchObject({ kind: 'P', variable: 'Jog', comment: '' });
  expect(await stored('b')).toEqual({ variable: 'Stop', comment: 'Emergency stop chain' });
  expect(await stored('d')).toEqual({ variable: 'Jog', comment: '' });

  // Undo brings the first contact's name back, and the inspector shows it when it is selected again.
  await editor.page.getByTestId('ladder-canvas').focus();
  await editor.page.keyboard.press('Control+z');
  await editor.page.keyboard.press('Control+z');
  await poll(() => stored('a')).toEqual({ variable: 'Start', comment: '' });
  await draw.clickCell(0, 0, 0);
  await poll(shown).toMatchObject({ kind: 'NO', variable: 'Start', comment: '' });
  expect(editor.errors).toEqual([]);
});

test('a selection that changes while the inspector field keeps the keyboard drops what was typed', async () => {
  await draw.clickCell(0, 0, 0);
  await poll(shown).toMatchObject({ variable: 'Start' });
  const field = editor.inspector.getByTestId('inspector-variable');
  await field.fill('Sto');
  await poll(listOpen).toBe(1);
  // Another contact selected without leaving the field (as a command from elsewhere would).
  await editor.page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    window.rungsmith!.uiStore!.getState().select(s.project.pous[0]!.networks[0]!.id, ['b' as never]);
  });
  await poll(shown).toMatchObject({ kind: 'NC', variable: 'Stop' });
  expect(await listOpen()).toBe(0);
  // Leaving the field now changes nothing: neither contact takes the dropped text.
  await editor.page.getByTestId('ladder-canvas').focus();
  await poll(shown).toMatchObject({ variable: 'Stop' });
  expect(await stored('a')).toEqual({ variable: 'Start', comment: '' });
  expect(await stored('b')).toMatchObject({ variable: 'Stop' });
  expect(editor.errors).toEqual([]);
});
