// A CODESYS/TIA programmer makes 3 variants of a 3-network program (a timer call, a jump back to
// a label, a motor coil) by copying the whole networks and pasting them with new instances. The
// test counts the user actions (clicks and key presses) and checks the result: 12 networks,
// Timer1..Timer4 declared, labels unique with each jump following its own label, no errors.
// Then: Ctrl+G goes to a network, Alt+↑ moves a selected network, collapse all / expand all.
import type { Page } from 'playwright-core';
import { beforeAll, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { openApp, useChromium } from './appPage';

const browser = useChromium();
let page: Page;
let errors: string[];

const v = (name: string, type: string): Variable => ({ name, type, varClass: 'local', retain: false, comment: '' });
const e = (s: string) => s as ElementId;

function program(): Project {
  const main = newPou('Main');
  return newProject('Machine', {
    pous: [
      {
        ...main,
        variables: [v('Start', 'BOOL'), v('Run', 'BOOL'), v('Lamp', 'BOOL'), v('Motor', 'BOOL'), v('Timer1', 'TON')],
        networks: [
          newNetwork({
            title: 'Start delay',
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Start', id: e('a'), row: 0, col: 0 },
              { kind: 'box', blockType: 'TON', instance: 'Timer1', id: e('b'), row: 0, col: 1, inputs: { PT: 'T#2s' }, outputs: { Q: 'Lamp' } },
            ],
          }),
          newNetwork({
            title: 'Skip when idle',
            label: 'Idle',
            elements: [
              { kind: 'contact', contact: 'NC', variable: 'Run', id: e('c'), row: 0, col: 0 },
              { kind: 'jump', target: 'Idle', id: e('d'), row: 0, col: 1 },
            ],
          }),
          newNetwork({
            title: 'Motor',
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Lamp', id: e('f'), row: 0, col: 0 },
              { kind: 'coil', coil: 'COIL', variable: 'Motor', id: e('g'), row: 0, col: 6 },
            ],
          }),
        ],
      },
    ],
  });
}

const project = (): Promise<Project> =>
  page.evaluate(() => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project);
const titles = async () => (await project()).pous[0]!.networks.map((n) => n.title);
const header = (id: string) => page.getByTestId(`network-number-${id}`);

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), program());
});

test('3 variants of a 3-network program by copy/paste of whole networks with new instances: 9 actions', async () => {
  const ids = (await project()).pous[0]!.networks.map((n) => n.id);
  let actions = 0;
  const act = async (fn: () => Promise<void>) => {
    await fn();
    actions++;
  };
  await act(() => header(ids[0]!).click());
  await act(() => header(ids[2]!).click({ modifiers: ['Shift'] }));
  expect(await page.locator('[data-selected="true"]').count()).toBe(3);
  await act(() => page.keyboard.press('Control+c'));
  for (let variant = 0; variant < 3; variant++) {
    await act(() => page.keyboard.press('Control+v'));
    await page.getByTestId('paste-prompt').waitFor();
    expect(await page.getByTestId('paste-prompt').textContent()).toContain('Timer1');
    await act(() => page.getByTestId('paste-new-instances').click());
    await page.getByTestId('paste-prompt').waitFor({ state: 'detached' });
  }
  expect(actions).toBe(9);

  const p = await project();
  const pou = p.pous[0]!;
  expect(pou.networks).toHaveLength(12);
  expect(await titles()).toEqual(Array.from({ length: 4 }, () => ['Start delay', 'Skip when idle', 'Motor']).flat());
  const instances = pou.networks.flatMap((n) => n.elements.flatMap((x) => (x.kind === 'box' ? [x.instance] : [])));
  expect(instances).toEqual(['Timer1', 'Timer2', 'Timer3', 'Timer4']);
  expect(pou.variables.filter((x) => x.type === 'TON').map((x) => x.name)).toEqual(['Timer1', 'Timer2', 'Timer3', 'Timer4']);
  const labels = pou.networks.flatMap((n) => (n.label ? [n.label] : []));
  expect(labels).toEqual(['Idle', 'Idle2', 'Idle3', 'Idle4']);
  // Each jump points at the label of its own copy.
  for (const n of pou.networks.filter((x) => x.label))
    expect(n.elements.find((x) => x.kind === 'jump')).toMatchObject({ target: n.label });
  expect(checkProject(p).filter((d) => d.severity === 'error')).toEqual([]);

  // One undo step per paste.
  await page.keyboard.press('Control+z');
  expect((await project()).pous[0]!.networks).toHaveLength(9);
  expect(errors).toEqual([]);
});

test('Ctrl+G goes to a network, Alt+↑ moves the selection, collapse all and expand all', async () => {
  await page.getByRole('heading', { name: /Rungsmith/ }).first().click();
  await page.keyboard.press('Control+g');
  await page.getByTestId('goto-input').fill('5');
  await page.keyboard.press('Enter');
  const nets = (await project()).pous[0]!.networks;
  expect(await page.locator('[data-selected="true"]').getAttribute('data-testid')).toBe('network-header-4');
  await page.keyboard.press('Alt+ArrowUp');
  expect((await project()).pous[0]!.networks[3]!.id).toBe(nets[4]!.id);
  // Keep the keyboard on the selected header: Shift+↓ extends the selection to two networks.
  await header(nets[4]!.id).focus();
  await page.keyboard.press('Shift+ArrowDown');
  expect(await page.locator('[data-selected="true"]').count()).toBe(2);
  await page.keyboard.press('Control+Shift+ArrowUp');
  expect((await project()).pous[0]!.networks.every((n) => n.collapsed)).toBe(true);
  await page.keyboard.press('Control+Shift+ArrowDown');
  expect((await project()).pous[0]!.networks.some((n) => n.collapsed)).toBe(false);
  // The outline lists every network; a click goes there.
  await page.getByTestId('tab-outline').click();
  await page.getByTestId('outline-item-7').click();
  expect(await page.locator('[data-selected="true"]').getAttribute('data-testid')).toBe('network-header-7');
  expect(errors).toEqual([]);
});
