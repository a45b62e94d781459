// PLCopen XML in the browser: File > Export PLCopen XML downloads a valid TC6 v2.01 file; File >
// Import PLCopen XML… shows the import report, lets the user pick the POU to open, and leaves the
// open project untouched when the file is bad.
import { readFile } from 'node:fs/promises';
import { fileURLToPath } from 'node:url';
import { expect, test } from 'vitest';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';
import { EXAMPLES } from '../../src/model/examples';
import { schemaErrors } from '../plcopen/xsd';

const browser = useChromium();

function importXml(editor: EditorPage, name: string, text: string): Promise<void> {
  return editor.chooseFile('File', 'Import PLCopen XML…', { name, mimeType: 'application/xml', text });
}

test('export downloads valid PLCopen XML; importing it gives back the same program', async () => {
  const editor = await EditorPage.open(browser());
  const example = EXAMPLES.find((e) => e.id === 'traffic-light')!;
  await editor.menu('File', `Example: ${example.title}`);
  await poll(async () => (await editor.project()).name).toBe(example.build().name);
  const original = await editor.project();

  // The traffic light's timers reach only the rail: the export review lists that first (exportWarnings.e2e.test.ts).
  const file = await editor.download(async () => {
    await editor.menu('File', 'Export PLCopen XML');
    await editor.page.getByTestId('export-review').getByRole('button', { name: 'Export anyway' }).click();
  });
  expect(file.name).toBe('Traffic_light.xml');
  const xml = file.text;
  expect(await schemaErrors(xml)).toEqual([]);

  await editor.menu('File', 'New project');
  await importXml(editor, 'Traffic_light.xml', xml);
  const report = editor.page.getByTestId('plcopen-report');
  await report.waitFor();
  expect(await report.textContent()).toContain('Nothing was dropped or changed.');
  expect(await report.getByTestId('plcopen-profile').textContent()).toContain(
    `semantics profile ${original.profile}, as recorded by Rungsmith in the file`,
  );
  await report.getByRole('button', { name: 'Open' }).click();
  await poll(async () => (await editor.project()).name).toBe(original.name);
  const back = await editor.project();
  expect(back.pous[0]!.variables).toEqual(original.pous[0]!.variables);
  expect(back.pous[0]!.networks.map((n) => n.title)).toEqual(original.pous[0]!.networks.map((n) => n.title));
  expect(back.tasks).toEqual(original.tasks);
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('a file with several POUs shows the report and opens on the POU the user picks', async () => {
  const editor = await EditorPage.open(browser());
  const text = await readFile(
    fileURLToPath(new URL('../fixtures/plcopen/corpus/sakunamary__i2c_test.xml', import.meta.url)),
    'utf8',
  );
  await importXml(editor, 'i2c_test.xml', text);
  const report = editor.page.getByTestId('plcopen-report');
  await report.waitFor();
  expect(await report.getByTestId('plcopen-pou-count').textContent()).toBe('2 POUs (LD)');
  expect(await report.getByTestId('plcopen-warnings').textContent()).toContain('I2C_AHT20');
  // A TC6 v2.01 file from OpenPLC runs as OpenPLC runs it; the report says so and where to change it.
  expect(await report.getByTestId('plcopen-profile').textContent()).toMatch(
    /^Runs under the semantics profile openplc: PLCopen TC6 v2\.01 is written by Beremiz and OpenPLC.*Change it in the project inspector \(Semantics\)\.$/,
  );
  await report.getByTestId('plcopen-pou-choice').selectOption({ label: 'get_temp (program, 2 networks)' });
  await report.getByRole('button', { name: 'Open' }).click();
  await poll(async () => (await editor.project()).pous.map((p) => p.name).join(',')).toBe('main,get_temp');
  const active = await editor.page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    return s.project.pous.find((p) => p.id === s.activePouId)?.name;
  });
  expect(active).toBe('get_temp');
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('a file that is not PLCopen XML shows a located error and keeps the open project', async () => {
  const editor = await EditorPage.open(browser());
  await editor.tab('Variables');
  await editor.declare('Keep', { address: '%MX0.0' });
  const before = await editor.project();
  await importXml(
    editor,
    'broken.xml',
    '<?xml version="1.0"?>\n<project xmlns="http://www.plcopen.org/xml/tc6_0201">\n<types>\n',
  );
  const failure = editor.page.getByTestId('plcopen-failure');
  await failure.waitFor();
  expect(await failure.textContent()).toMatch(
    /Could not import broken\.xml.*line 4.*the file ends inside <types>/,
  );
  await failure.getByRole('button', { name: 'OK' }).click();
  await failure.waitFor({ state: 'detached' });
  expect(await editor.project()).toEqual(before);
  expect(editor.errors).toEqual([]);
  await editor.close();
});
