// Files: autosave and recovery after a reload, opening good and bad files, saving, "New" asking
// before discarding work, and the built-in examples.
import { expect, test } from 'vitest';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';
import { EXAMPLES } from '../../src/model/examples';
import { loadProject, saveProject } from '../../src/model/load';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';

const browser = useChromium();

test('after a reload the work is restored from the browser autosave', async () => {
  const editor = await EditorPage.open(browser());
  await editor.tab('Variables');
  await editor.declare('Start', { address: '%IX0.0' });
  await editor.declare('Motor', { address: '%QX0.0', comment: 'Conveyor motor' });
  await editor.waitForAutosave();

  await editor.page.reload();
  await editor.page.getByTestId('file-notice').waitFor();
  expect(await editor.page.getByTestId('file-notice').textContent()).toMatch(
    /Restored "Untitled" .*not yet saved to a file/,
  );
  const vars = (await editor.project()).pous[0]?.variables;
  expect(vars?.map((v) => `${v.name} ${v.location ?? ''} ${v.comment}`.trim())).toEqual([
    'Start %IX0.0',
    'Motor %QX0.0 Conveyor motor',
  ]);
  // Still unsaved to a file, so the project name shows the unsaved mark.
  expect(await editor.page.getByTestId('project-name').textContent()).toContain('•');
  await editor.tab('Variables');
  expect(await editor.variableRow('Motor').getByLabel('Comment').inputValue()).toBe('Conveyor motor');
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('opening a corrupt or invalid file shows located errors and keeps the open project', async () => {
  const editor = await EditorPage.open(browser());
  await editor.tab('Variables');
  await editor.declare('Keep', { address: '%MX0.0' });
  const before = await editor.project();

  await editor.openFile('broken.json', '{ "format": "rungsmith-project", ');
  const dialog = editor.page.getByTestId('open-failure');
  await dialog.waitFor();
  expect(await dialog.textContent()).toMatch(/Could not open broken\.json.*\(file\): not valid JSON/);
  await dialog.getByRole('button', { name: 'OK' }).click();
  expect(await editor.project()).toEqual(before);

  // Valid JSON, but an element lies outside its network: the error names where.
  const bad = newProject('Bad', {
    pous: [
      newPou('Main', {
        networks: [
          newNetwork({
            rows: 1,
            cols: 2,
            elements: [{ id: 'x' as ElementId, kind: 'link', row: 3, col: 0 }],
          }),
        ],
      }),
    ],
  });
  await editor.openFile('bad.json', saveProject(bad));
  await dialog.waitFor();
  expect(await dialog.textContent()).toMatch(
    /pous\[0\]\.networks\[0\]\.elements\[0\]: element at row 3, column 0 lies outside the 1x2 grid/,
  );
  await editor.page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'detached' });
  expect(await editor.project()).toEqual(before);
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('"New" asks before discarding unsaved work; Save downloads the project as .json', async () => {
  const editor = await EditorPage.open(browser());
  await editor.tab('Variables');
  await editor.declare('Pump', { address: '%QX0.1' });

  await editor.menu('File', 'New project');
  const ask = editor.page.getByRole('alertdialog', { name: 'Discard unsaved changes?' });
  await ask.waitFor();
  await ask.getByRole('button', { name: 'Cancel' }).click();
  expect((await editor.project()).pous[0]?.variables.map((v) => v.name)).toEqual(['Pump']);

  const file = await editor.download(() => editor.menu('File', 'Save'));
  expect(file.name).toBe('Untitled.json');
  const saved = loadProject(file.text);
  expect(saved.ok && saved.project).toEqual(await editor.project());
  expect(await editor.page.getByTestId('project-name').textContent()).not.toContain('•');

  // Saved: New no longer asks.
  await editor.menu('File', 'New project');
  await poll(async () => (await editor.project()).pous[0]?.variables.length).toBe(0);
  await editor.declare('Lamp');
  // Ctrl+S saves from anywhere outside a text field.
  await editor.page.getByRole('heading', { name: 'Rungsmith' }).click();
  const again = await editor.download(() => editor.page.keyboard.press('Control+s'));
  const second = loadProject(again.text);
  expect(second.ok && second.project.pous[0]?.variables.map((v) => v.name)).toEqual(['Lamp']);
  await editor.declare('Fan');
  await editor.menu('File', 'New project');
  await ask.getByRole('button', { name: 'Discard and start new' }).click();
  await poll(async () => (await editor.project()).pous[0]?.variables.length).toBe(0);
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('every built-in example loads from the File menu and shows no problems', async () => {
  const editor = await EditorPage.open(browser());
  await editor.tab('Problems');
  for (const example of EXAMPLES) {
    await editor.menu('File', `Example: ${example.title}`);
    await poll(async () => (await editor.project()).name).toBe(example.build().name);
    await poll(() => editor.problems.getByTestId('problems-summary').textContent()).toBe('No problems');
    expect(await editor.problems.getByTestId('problem').count()).toBe(0);
  }
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('a project file dropped on the page opens like File > Open', async () => {
  const editor = await EditorPage.open(browser());
  const example = EXAMPLES.find((x) => x.id === 'parts-counter')!.build();
  await editor.page.evaluate(
    ([name, text]) => {
      const data = new DataTransfer();
      data.items.add(new File([text], name, { type: 'application/json' }));
      const target = document.querySelector('main') ?? document.body;
      target.dispatchEvent(
        new DragEvent('dragover', { dataTransfer: data, bubbles: true, cancelable: true }),
      );
      target.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true, cancelable: true }));
    },
    ['counter.json', saveProject(example)] as const,
  );
  await poll(async () => (await editor.project()).name).toBe(example.name);
  expect(await editor.page.getByTestId('file-notice').textContent()).toContain('Opened counter.json');
  expect(await editor.project()).toEqual(example);
  expect(editor.errors).toEqual([]);
  await editor.close();
});
