// A PLC programmer declares variables in the table, sees a rule violation in the problems list,
// jumps to it, fixes it from the inspector and sees it disappear.
import { expect, test } from 'vitest';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { LdElement } from '../../src/model/elements';
import type { ElementId } from '../../src/model/ids';
import { saveProject } from '../../src/model/load';

const browser = useChromium();

const id = (s: string) => s as ElementId;

/** Start -| |- Stop -|/- ... -( )- Motor, with Motor not declared yet. */
function sealInWithoutMotor(): string {
  const elements: LdElement[] = [
    { id: id('c1'), kind: 'contact', contact: 'NO', variable: 'Start', row: 0, col: 0 },
    { id: id('c2'), kind: 'contact', contact: 'NC', variable: 'Stop', row: 0, col: 1 },
    { id: id('l1'), kind: 'link', row: 0, col: 2 },
    { id: id('m1'), kind: 'coil', coil: 'COIL', variable: 'Motor', row: 0, col: 3 },
  ];
  const main = newPou('Main', {
    variables: [
      variable('Start', 'BOOL', { location: '%IX0.0' }),
      variable('Stop', 'BOOL', { location: '%IX0.1' }),
    ],
    networks: [newNetwork({ rows: 1, cols: 4, elements, title: 'Motor' })],
  });
  return saveProject(newProject('Conveyor', { pous: [main] }));
}

/** A fresh editor with the Conveyor project opened from a file. */
async function openConveyor(): Promise<EditorPage> {
  const editor = await EditorPage.open(browser());
  await editor.openFile('conveyor.json', sealInWithoutMotor());
  await poll(async () => (await editor.project()).name).toBe('Conveyor');
  return editor;
}

test('declaring variables in the table, with mistakes shown inline until fixed', async () => {
  const editor = await EditorPage.open(browser());
  await editor.tab('Variables');

  await editor.declare('Start', { address: '%IX0.0', comment: 'Start push button' });
  await editor.declare('Stop', { address: '%ix0.0' });
  // Same address twice (whatever the spelling): the second row says so.
  await poll(() =>
    editor.variableRow('Stop').locator('xpath=following-sibling::tr[1]').textContent(),
  ).toContain('Address: %IX0.0 is already used by "Start" in row 1');
  await editor.fill(editor.variableRow('Stop').getByLabel('Address'), '%IX0.1');
  await editor.declare('Motor', { address: '%QW0' });
  await poll(() => editor.variables.getByTestId('variable-issue').allTextContents()).toEqual([
    'Address: %QW0 holds a 16-bit word, which does not fit type BOOL',
  ]);
  await editor.fill(editor.variableRow('Motor').getByLabel('Address'), '%QX0.0');
  await editor.declare('Count', { type: 'INT', initial: '70000' });
  await poll(() => editor.variables.getByTestId('variable-issue').count()).toBe(1);
  expect(await editor.variables.getByTestId('variable-issue').textContent()).toMatch(
    /Initial value: .*70000/,
  );
  await editor.fill(editor.variableRow('Count').getByLabel('Initial value'), '10');
  await editor.declare('1st');
  await poll(() => editor.variables.getByTestId('variable-issue').textContent()).toMatch(
    /Name: "1st" is not an IEC identifier/,
  );
  // The engine reports it too; clicking that problem brings the row back into view and focus.
  await editor.tab('Problems');
  const nameProblem = editor.problems.getByTestId('problem').filter({ hasText: 'LD-E11' });
  expect(await nameProblem.textContent()).toMatch(/LD-E11.*variables.*"1st"/);
  await nameProblem.click();
  await poll(() =>
    editor.page.evaluate(() => (document.activeElement as HTMLInputElement | null)?.value),
  ).toBe('1st');
  expect(
    await editor.page.getByRole('tab', { name: 'Variables', exact: true }).getAttribute('aria-selected'),
  ).toBe('true');
  await editor.variables.getByRole('button', { name: 'Delete variable 1st' }).click();

  await poll(() => editor.variables.getByTestId('variable-issue').count()).toBe(0);
  let vars = (await editor.project()).pous[0]?.variables;
  expect(vars?.map((v) => [v.name, v.type, v.location ?? '', v.initial ?? '', v.comment])).toEqual([
    ['Start', 'BOOL', '%IX0.0', '', 'Start push button'],
    ['Stop', 'BOOL', '%IX0.1', '', ''],
    ['Motor', 'BOOL', '%QX0.0', '', ''],
    ['Count', 'INT', '', '10', ''],
  ]);

  // A name already taken is refused with the reason, and the row keeps its old name.
  await editor.fill(editor.variableRow('Count').getByLabel('Name'), 'MOTOR');
  expect(await editor.variables.getByRole('alert').first().textContent()).toContain(
    'Cannot rename "Count" to "MOTOR"',
  );
  vars = (await editor.project()).pous[0]?.variables;
  expect(vars?.map((v) => v.name)).toEqual(['Start', 'Stop', 'Motor', 'Count']);
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('a rule violation is listed with its rule id, jumps to the element, and disappears once fixed', async () => {
  const editor = await openConveyor();

  await editor.tab('Problems');
  const problem = editor.problems.getByTestId('problem').filter({ hasText: 'LD-R08' });
  await problem.waitFor();
  expect(await problem.textContent()).toMatch(/LD-R08.*network 1.*row 1, at the right rail.*Motor/);

  // The checks run in a worker, off the page's thread.
  expect(editor.page.workers().some((w) => w.url().includes('check.worker'))).toBe(true);

  await problem.click();
  const selection = await editor.selection();
  expect(selection.elements).toEqual(['m1']);
  const cursor = await editor.page.evaluate(() => window.rungsmith!.uiStore!.getState().cursor);
  expect(cursor).toMatchObject({ network: selection.network, row: 0, col: 3 });
  await editor.tab('Inspector');
  await poll(() => editor.inspector.getByRole('heading').first().textContent()).toMatch(/^Coil/);
  const offer = editor.inspector.getByTestId('declare-offer');
  expect(await offer.textContent()).toContain('Motor is not declared');
  await offer.getByRole('button', { name: 'BOOL output at %QX0.0' }).click();

  await editor.tab('Problems');
  await poll(() => editor.problems.getByTestId('problem').filter({ hasText: 'LD-R08' }).count()).toBe(0);
  expect(await editor.problems.getByTestId('problems-summary').textContent()).toBe('No problems');
  const motor = (await editor.project()).pous[0]?.variables.find((v) => v.name === 'Motor');
  expect(motor).toMatchObject({ type: 'BOOL', location: '%QX0.0' });

  // Renaming a variable in the table renames it on the canvas too.
  await editor.tab('Variables');
  await editor.fill(editor.variableRow('Motor').getByLabel('Name'), 'Conveyor');
  await poll(async () =>
    (await editor.project()).pous[0]?.networks[0]?.elements.find((e) => e.id === 'm1'),
  ).toMatchObject({ variable: 'Conveyor' });
  // The table shows where a variable is used and takes you there.
  await editor.uiSelect(undefined, []);
  await editor.variableRow('Start').getByRole('button', { name: 'Show uses of Start' }).click();
  expect((await editor.selection()).elements).toEqual(['c1']);
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('typing the variable of a coil completes from the table and offers to declare new names', async () => {
  const editor = await openConveyor();
  await editor.tab('Problems');
  await editor.problems.getByTestId('problem').filter({ hasText: 'LD-R08' }).click();
  await editor.tab('Inspector');

  const field = editor.inspector.getByTestId('inspector-variable');
  await field.click();
  await field.fill('St');
  const options = editor.inspector.getByRole('listbox', { name: 'Suggestions' }).getByRole('option');
  await poll(() => options.allTextContents()).toEqual([
    'StopBOOL%IX0.1',
    'StartBOOL%IX0.0',
    'Declare StBOOL',
    'Declare StBOOL output at %QX0.0',
    'Declare StBOOL memory at %MX0.0',
    'Declare StBOOL global (VAR_GLOBAL)',
    'Declare StBOOL global at %QX0.0 (VAR_GLOBAL)',
  ]);
  await field.fill('Pump');
  await poll(() => options.allTextContents()).toEqual([
    'Declare PumpBOOL',
    'Declare PumpBOOL output at %QX0.0',
    'Declare PumpBOOL memory at %MX0.0',
    'Declare PumpBOOL global (VAR_GLOBAL)',
    'Declare PumpBOOL global at %QX0.0 (VAR_GLOBAL)',
  ]);
  await field.press('ArrowDown');
  await field.press('Enter');
  const project = await editor.project();
  expect(project.pous[0]?.networks[0]?.elements.find((e) => e.id === 'm1')).toMatchObject({
    variable: 'Pump',
  });
  expect(project.pous[0]?.variables.find((v) => v.name === 'Pump')).toMatchObject({
    type: 'BOOL',
    location: '%QX0.0',
  });
  // Declaring and binding was one step: one undo takes both back.
  await editor.page.getByTestId('menu-edit').click();
  await editor.page.getByRole('menuitem', { name: 'Undo' }).click();
  const undone = await editor.project();
  expect(undone.pous[0]?.networks[0]?.elements.find((e) => e.id === 'm1')).toMatchObject({
    variable: 'Motor',
  });
  expect(undone.pous[0]?.variables.map((v) => v.name)).toEqual(['Start', 'Stop']);

  // The table offers to declare every name the program uses but nobody declared.
  await editor.tab('Variables');
  await editor.variables.getByRole('button', { name: 'Declare 1 used name' }).click();
  expect((await editor.project()).pous[0]?.variables.map((v) => `${v.name}:${v.type}`)).toEqual([
    'Start:BOOL',
    'Stop:BOOL',
    'Motor:BOOL',
  ]);
  await editor.tab('Problems');
  await poll(() => editor.problems.getByTestId('problems-summary').textContent()).toBe('No problems');
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('the inspector edits a timer preset as a literal and explains a wrong one', async () => {
  const editor = await EditorPage.open(browser());
  await editor.menu('File', 'Example: Traffic light (TON chain)');
  await poll(async () => (await editor.project()).name).toBe('Traffic light');
  // Find the RedTime timer from the variable table, then edit it in the inspector.
  await editor.tab('Variables');
  await editor.variableRow('RedTime').getByRole('button', { name: 'Show uses of RedTime' }).click();
  await editor.tab('Inspector');
  await poll(() => editor.inspector.getByRole('heading').first().textContent()).toBe('TON function block');
  expect(await editor.inspector.getByTestId('inspector-instance').inputValue()).toBe('RedTime');

  const preset = editor.inspector.getByTestId('pin-PT');
  await editor.fill(preset, '5');
  await poll(() => editor.inspector.getByText(/5 is an integer, not a TIME/).count()).toBe(1);
  await editor.fill(preset, 'T#7s');
  await poll(() => editor.inspector.getByText('literal TIME').count()).toBe(1);
  const box = async () => {
    const net = (await editor.project()).pous[0]!.networks.find((n) =>
      n.elements.some((e) => e.kind === 'box' && e.instance === 'RedTime'),
    );
    return net?.elements.find((e) => e.kind === 'box');
  };
  expect(await box()).toMatchObject({ blockType: 'TON', inputs: { PT: 'T#7s' } });
  // The problems list agrees: a valid preset, no problems.
  await editor.tab('Problems');
  await poll(() => editor.problems.getByTestId('problems-summary').textContent()).toBe('No problems');
  expect(editor.errors).toEqual([]);
  await editor.close();
});
