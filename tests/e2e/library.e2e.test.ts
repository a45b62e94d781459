// The library manager in Chromium (docs/libraries.md): a library added from a PLCopen file
// (tests/fixtures/libraries/conveyors.xml: a Conveyor FB and a Scale function, in ST) shows with
// its version in the manager and under its name in the palette; its FB placed in a network runs
// in the simulator; the library is saved with the project and is there after a reload; removing it
// is refused while Main calls its block, with the uses listed; its blocks can be viewed read-only.
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { afterAll, beforeAll, expect, test } from 'vitest';
import { saveProject } from '../../src/model/load';
import type { Project } from '../../src/model/project';
import { io, multiProject, pou } from '../engine/userBlocksHelpers';
import { ladder } from '../engine/ladder';
import { useChromium, waitForApp } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();
const FIXTURE = readFileSync(new URL('../fixtures/libraries/conveyors.xml', import.meta.url), 'utf8');
const HASH = createHash('sha256').update(FIXTURE).digest('hex');
const FIXTURE_V2 = readFileSync(new URL('../fixtures/libraries/conveyors-v2.xml', import.meta.url), 'utf8');
const HASH_V2 = createHash('sha256').update(FIXTURE_V2).digest('hex');

let editor: EditorPage;
let draw: DrawPage;
let sim: SimPage;

beforeAll(async () => {
  editor = await EditorPage.open(browser());
  draw = new DrawPage(editor.page);
  sim = new SimPage(editor.page);
  // Set-up, not under test: an empty project.
  await editor.page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Plant'));
});

afterAll(async () => {
  expect(editor.errors).toEqual([]);
  await editor.close();
});

const project = () => editor.project() as Promise<Project>;
const manager = () => editor.page.getByTestId('library-manager');

test('File > Libraries… adds the blocks of a PLCopen file as a library, with its version and contents', async () => {
  const { page } = editor;
  await editor.menu('File', 'Libraries…');
  await manager().getByTestId('library-none').waitFor();
  // The OpenPLC vendor libraries are listed as external blocks.
  expect(await manager().getByTestId('library-vendor-MQTT').textContent()).toMatch(/MQTT.*runs as external block/);
  const chooser = page.waitForEvent('filechooser');
  await manager().getByTestId('library-add').click();
  await (await chooser).setFiles({ name: 'conveyors.xml', mimeType: 'application/xml', buffer: Buffer.from(FIXTURE) });
  const pending = manager().getByTestId('library-pending');
  await pending.waitFor();
  expect(await pending.getByTestId('library-name').inputValue()).toBe('Conveyors');
  expect(await pending.getByTestId('library-contents').textContent()).toBe(
    `1 function block, 1 function, 1 data type: Conveyor, Scale, BeltSpeed. Version ${HASH.slice(0, 12)}.`,
  );
  expect(await pending.getByTestId('library-notes').textContent()).toMatch(/PROGRAM \(Demo\).*left out/);
  await pending.getByTestId('library-confirm').click();
  await pending.waitFor({ state: 'detached' });
  const row = manager().getByTestId('library-row-Conveyors');
  expect(await row.getByTestId('library-hash-Conveyors').textContent()).toBe(HASH.slice(0, 12));
  expect(await row.getByTestId('library-hash-Conveyors').getAttribute('title')).toBe(`sha256:${HASH}`);
  expect(await row.textContent()).toMatch(/conveyors\.xml \(PLCopen XML\)/);
  // A block is viewed read-only: its interface and its ST body.
  await row.getByTestId('library-view-Conveyor').click();
  const view = manager().getByTestId('library-block-view');
  expect(await view.getByTestId('library-block-interface').textContent()).toBe(
    'FUNCTION_BLOCK Conveyor (Start : BOOL; Stop : BOOL -> Running : BOOL; Starts : INT)',
  );
  expect(await view.getByTestId('library-block-source').textContent()).toMatch(/Running := \(Start OR Running\) AND NOT Stop;/);
  // Adding the same blocks again under another name is refused, with the reason.
  const again = page.waitForEvent('filechooser');
  await manager().getByTestId('library-add').click();
  await (await again).setFiles({ name: 'conveyors.xml', mimeType: 'application/xml', buffer: Buffer.from(FIXTURE) });
  await pending.getByTestId('library-name').fill('Belts');
  await pending.getByTestId('library-confirm').click();
  expect(await pending.getByTestId('library-errors').textContent()).toMatch(/function block Conveyor is already defined by the library Conveyors/);
  await pending.getByTestId('library-cancel').click();
  await manager().getByTestId('library-close').click();
  await manager().waitFor({ state: 'detached' });
  expect((await project()).libraries?.map((l) => [l.name, l.hash])).toEqual([['Conveyors', `sha256:${HASH}`]]);
  // The Project tree lists it.
  await page.getByTestId('tab-project').click();
  await page.getByTestId('tree-library-Conveyors').waitFor();
});

test('the palette lists its blocks under its name; its FB placed in a network runs in the simulator', async () => {
  const { page } = editor;
  await page.getByTestId('tab-palette').click();
  const group = page.getByTestId('palette-library-Conveyors');
  expect(await group.locator('h2').textContent()).toBe('Conveyors');
  expect(await group.getByRole('button').allTextContents()).toEqual(['ConveyorFB', 'Scalefn']);
  await editor.tab('Variables');
  await editor.declare('Go', { type: 'BOOL', address: '%IX0.0' }); // an input: a double-click switches it
  await editor.declare('Halt', { type: 'BOOL' });
  await page.getByTestId('tab-palette').click();
  await group.getByTestId('palette-block-Conveyor').click();
  await draw.clickCell(0, 0, 1);
  await page.getByTestId('inline-editor').waitFor();
  await poll(() => page.getByRole('option', { name: /Declare Conveyor1/ }).count()).toBe(1);
  await page.keyboard.press('Enter');
  await page.getByTestId('inline-editor').waitFor({ state: 'detached' });
  await draw.pickPalette('contact-NO');
  await draw.clickCell(0, 0, 0);
  await draw.typeName('Go');
  await page.keyboard.press('Escape');
  await draw.pickPalette('select');
  await draw.clickCell(0, 0, 1);
  await editor.tab('Inspector');
  const stop = editor.inspector.getByTestId('pin-Stop');
  await stop.click();
  await stop.fill('Halt');
  await stop.press('Enter');
  const main = (await project()).pous[0]!;
  expect(main.variables.find((v) => v.name === 'Conveyor1')?.type).toBe('Conveyor');
  await editor.tab('Problems');
  await poll(() => draw.problemsSummary()).toBe('No problems');

  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.waitForValue('Conveyor1.Running', false);
  await sim.switchCell(0, 0, 0); // Go on: the conveyor starts and counts the start
  await sim.waitForValue('Conveyor1.Running', true);
  await sim.waitForValue('Conveyor1.Starts', 1);
  await sim.switchCell(0, 0, 0); // Go off: it keeps running (sealed in by the library's ST body)
  await sim.waitForValue('GO', false);
  expect(await sim.value('Conveyor1.Running')).toBe(true);
  await sim.button('reset').click();
  await sim.waitForMode('Stopped');
});

test('the library is saved with the project and is there after a reload', async () => {
  const { page } = editor;
  const saved = await editor.download(() => editor.menu('File', 'Save'));
  const file = JSON.parse(saved.text) as Project;
  expect(file.libraries?.map((l) => [l.name, l.hash, l.sourceFile, l.pous.map((p) => p.name)])).toEqual([
    ['Conveyors', `sha256:${HASH}`, 'conveyors.xml', ['Conveyor', 'Scale']],
  ]);
  await editor.waitForAutosave();
  await page.reload();
  await waitForApp(page);
  await page.getByTestId('tab-palette').click();
  await page.getByTestId('palette-library-Conveyors').getByTestId('palette-block-Conveyor').waitFor();
  expect((await project()).libraries?.[0]?.hash).toBe(`sha256:${HASH}`);
});

test('an update from a newer file shows what changes and which uses need attention; Undo takes it back', async () => {
  const { page } = editor;
  await editor.menu('File', 'Libraries…');
  const chooser = page.waitForEvent('filechooser');
  await manager().getByTestId('library-update-Conveyors').click();
  await (await chooser).setFiles({ name: 'conveyors-v2.xml', mimeType: 'application/xml', buffer: Buffer.from(FIXTURE_V2) });
  const pending = manager().getByTestId('library-pending');
  await pending.waitFor();
  expect(await pending.locator('h3').textContent()).toBe('Update Conveyors from conveyors-v2.xml');
  expect(await pending.getByTestId('library-diff').locator('li').allTextContents()).toEqual([
    'added: Scale2',
    'removed: Scale',
    'interface changed: FUNCTION_BLOCK Conveyor (Start : BOOL; Stop : BOOL -> Running : BOOL; Starts : INT) → FUNCTION_BLOCK Conveyor (Start : BOOL; Stop : BOOL; Jog : BOOL -> Running : BOOL; Starts : INT)',
  ]);
  expect(await pending.getByTestId('library-affected').locator('li').allTextContents()).toEqual([
    'Main: variable Conveyor1 : Conveyor',
    'Main, network 1: box Conveyor',
  ]);
  await pending.getByTestId('library-confirm').click();
  await pending.waitFor({ state: 'detached' });
  await poll(() => manager().getByTestId('library-hash-Conveyors').textContent()).toBe(HASH_V2.slice(0, 12));
  expect((await project()).libraries?.[0]?.pous.map((p) => p.name)).toEqual(['Conveyor', 'Scale2']);
  // The palette follows; the call keeps working with the new interface (Jog left open).
  await manager().getByTestId('library-close').click();
  await page.getByTestId('tab-palette').click();
  await page.getByTestId('palette-library-Conveyors').getByTestId('palette-block-Scale2').waitFor();
  await editor.tab('Problems');
  await poll(() => draw.problemsSummary()).toBe('No problems');
  // One undo step brings version 1 back.
  await editor.menu('Edit', 'Undo');
  await poll(async () => (await project()).libraries?.[0]?.hash).toBe(`sha256:${HASH}`);
  await page.getByTestId('palette-library-Conveyors').getByTestId('palette-block-Scale').waitFor();
});

test('removing the library is refused while Main calls its block, with the uses listed', async () => {
  await editor.menu('File', 'Libraries…');
  expect(await manager().getByTestId('library-uses-Conveyors').textContent()).toBe('2');
  await manager().getByTestId('library-remove-Conveyors').click();
  const refused = manager().getByTestId('library-refused');
  await refused.waitFor();
  expect(await refused.locator('li').allTextContents()).toEqual(['Main: variable Conveyor1 : Conveyor', 'Main, network 1: box Conveyor']);
  expect((await project()).libraries?.map((l) => l.name)).toEqual(['Conveyors']);
  await manager().getByTestId('library-close').click();
});

test('a Rungsmith project file as a library: its LD block is drawn read-only; an unused library is removed at once', async () => {
  const { page } = editor;
  // Another project with an LD function block (and a program, which the library leaves out).
  const latch = pou('Latch', 'FUNCTION_BLOCK', [...io('input', 'SetIn BOOL', 'ResetIn BOOL'), ...io('output', 'Q BOOL')], [
    ladder(['+ [SetIn] + [/ResetIn] (Q)', '+ [Q] +']),
  ]);
  const other = { ...multiProject([pou('Main', 'PROGRAM', [], []), latch]), name: 'Latches' };
  await editor.menu('File', 'Libraries…');
  const chooser = page.waitForEvent('filechooser');
  await manager().getByTestId('library-add').click();
  await (await chooser).setFiles({ name: 'latches.json', mimeType: 'application/json', buffer: Buffer.from(saveProject(other)) });
  const pending = manager().getByTestId('library-pending');
  expect(await pending.getByTestId('library-name').inputValue()).toBe('Latches');
  await pending.getByTestId('library-confirm').click();
  const row = manager().getByTestId('library-row-Latches');
  expect(await row.textContent()).toMatch(/latches\.json \(Rungsmith project\)/);
  await row.getByTestId('library-view-Latch').click();
  const view = manager().getByTestId('library-block-view');
  expect(await view.getByRole('img', { name: 'Network 1 of Latch' }).locator('svg').count()).toBe(1);
  expect(await view.getByTestId('library-block-interface').textContent()).toBe('FUNCTION_BLOCK Latch (SetIn : BOOL; ResetIn : BOOL -> Q : BOOL)');
  expect(await manager().getByTestId('library-uses-Latches').textContent()).toBe('0');
  await manager().getByTestId('library-remove-Latches').click();
  await row.waitFor({ state: 'detached' });
  expect((await project()).libraries?.map((l) => l.name)).toEqual(['Conveyors']);
  await manager().getByTestId('library-close').click();
});
