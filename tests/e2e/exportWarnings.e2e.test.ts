// File > Export PLCopen XML first lists what Beremiz and OpenPLC would run differently (LD-X rules):
// a dropped jump, timers whose Q reaches only the right rail (with the coil fix, one undo step),
// a network name that goes to the network, and "Export anyway".
import { expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';
import { schemaErrors } from '../plcopen/xsd';

const browser = useChromium();

/** Opens an example in a new editor and chooses File > Export PLCopen XML; the review is shown. */
async function reviewExport(id: string) {
  const editor = await EditorPage.open(browser());
  const example = EXAMPLES.find((e) => e.id === id)!;
  await editor.menu('File', `Example: ${example.title}`);
  await poll(async () => (await editor.project()).name).toBe(example.build().name);
  await editor.menu('File', 'Export PLCopen XML');
  const review = editor.page.getByTestId('export-review');
  await review.waitFor();
  return { editor, review };
}

test('exporting a program with a jump lists the dropped jump; Export anyway downloads valid XML', async () => {
  const { editor, review } = await reviewExport('jump-label');
  const items = review.getByTestId('export-warning');
  expect(await items.count()).toBe(1);
  const text = (await items.first().textContent())!;
  expect(text).toContain('LD-X01');
  expect(text).toContain('drop the jump to "MAINT" without a word');
  expect(await review.getByRole('button', { name: 'Network 1' }).count()).toBe(1);
  expect(await review.getByRole('button', { name: /^Apply fix/ }).count()).toBe(0);
  const file = await editor.download(() => review.getByRole('button', { name: 'Export anyway' }).click());
  expect(file.name).toBe('Jump_over_a_network.xml');
  expect(await schemaErrors(file.text)).toEqual([]);
  expect(file.text).toContain('<jump ');
  await poll(() => review.count()).toBe(0);
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('the traffic light: apply the coil fixes (one undo step each), then export; a network name goes to it', async () => {
  const { editor, review } = await reviewExport('traffic-light');
  await poll(() => review.getByTestId('export-warning').count()).toBe(2);
  expect(await review.getByTestId('export-warning').first().textContent()).toContain(
    "what reads RedTime's outputs in networks 4 and 5 sees them one scan late",
  );

  await review.getByRole('button', { name: 'Apply fix: Add a coil "RedTime_Q" on output Q of TON "RedTime"' }).click();
  await poll(() => review.getByTestId('export-warning').count()).toBe(1);
  await review.getByRole('button', { name: /^Apply fix: Add a coil "GreenTime_Q"/ }).click();
  await review.getByTestId('export-review-clear').waitFor();
  const fixed = await editor.project();
  const main = fixed.pous[0]!;
  expect(main.variables.filter((v) => v.name.endsWith('_Q')).map((v) => `${v.name}:${v.type}`)).toEqual([
    'RedTime_Q:BOOL',
    'GreenTime_Q:BOOL',
  ]);
  expect(main.networks[0]!.elements.some((e) => e.kind === 'coil' && e.variable === 'RedTime_Q')).toBe(true);

  // Each fix is one undo step: the coil and its variable go together.
  const state = () => editor.page.evaluate(() => window.rungsmith!.documentStore!.getState().undoName);
  expect(await state()).toMatch(/GreenTime_Q/);
  await editor.page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  await poll(() => review.getByTestId('export-warning').count()).toBe(1);
  const undone = (await editor.project()).pous[0]!;
  expect(undone.variables.some((v) => v.name === 'GreenTime_Q')).toBe(false);
  expect(undone.networks[1]!.elements.some((e) => e.kind === 'coil' && e.variable === 'GreenTime_Q')).toBe(false);

  // The network name closes the review and puts the cursor on the timer.
  await review.getByRole('button', { name: 'Network 2' }).click();
  await poll(() => review.count()).toBe(0);
  const focus = await editor.page.evaluate(() => {
    const ui = window.rungsmith!.uiStore!.getState();
    return { network: ui.focusRequest?.network, cell: ui.focusRequest?.cell };
  });
  expect(focus).toEqual({ network: undone.networks[1]!.id, cell: { row: 0, col: 2 } });

  await editor.menu('File', 'Export PLCopen XML');
  await review.waitFor();
  await review.getByRole('button', { name: /^Apply fix/ }).click();
  await review.getByTestId('export-review-clear').waitFor();
  const file = await editor.download(() => review.getByRole('button', { name: 'Export', exact: true }).click());
  expect(await schemaErrors(file.text)).toEqual([]);
  expect(file.text).toContain('<variable>GreenTime_Q</variable>');
  expect(editor.errors).toEqual([]);
  await editor.close();
});
