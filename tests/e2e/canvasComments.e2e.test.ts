// Comments where people look: a variable's comment under its contact (View > Show symbol comments,
// or the top bar's switch; off by default as in CODESYS, remembered), on the canvas and in print; a
// comment of the element itself, edited in the inspector, shown whatever the option, kept through a
// reload and through PLCopen export and import.
import { expect, test, beforeAll, afterAll } from 'vitest';
import { cellRect, columnsOf, COMMENT_PITCH, CELL_H, headerHeight, layoutNetworks, RAIL_X, type SymbolComments } from '../../src/editor/canvas/geometry';
import { symbolCommentLookup } from '../../src/editor/canvas/symbolComments';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { blockLibrary } from '../../src/model/library';
import type { Network, Project, Variable } from '../../src/model/project';
import { schemaErrors } from '../plcopen/xsd';
import { useChromium } from './appPage';
import { DrawPage } from './drawPage';
import { EditorPage, poll } from './panelsPage';

const browser = useChromium();
let editor: EditorPage;
let draw: DrawPage;

const START_NOTE = 'Start push button, green, front panel';
const v = (name: string, comment = ''): Variable => ({ name, type: 'BOOL', varClass: 'local', retain: false, comment });
const e = (s: string) => s as ElementId;

function machine(): Project {
  const main = newPou('Main');
  return newProject('Commented', {
    pous: [
      {
        ...main,
        variables: [v('Start', START_NOTE), v('Stop'), v('Motor', 'Main drive contactor K1')],
        networks: [
          newNetwork({
            title: 'Motor',
            rows: 2,
            elements: [
              { kind: 'contact', contact: 'NO', variable: 'Start', id: e('a'), row: 0, col: 0 },
              { kind: 'contact', contact: 'NC', variable: 'Stop', id: e('b'), row: 0, col: 1 },
              { kind: 'coil', coil: 'COIL', variable: 'Motor', id: e('c'), row: 0, col: 9 },
              // Row 1 is used (far right), so the network shows two rows: under row 0 is an empty row.
              { kind: 'contact', contact: 'NO', variable: 'Stop', id: e('d'), row: 1, col: 8 },
            ],
          }),
          newNetwork({ title: 'Below' }),
        ],
      },
    ],
  });
}

const project = (): Promise<Project> =>
  editor.page.evaluate(() => JSON.parse(JSON.stringify(window.rungsmith!.documentStore!.getState().project)) as Project);

/** The symbol comments the canvas uses when the option is on (the same lookup, from the page's project). */
async function lookup(on: boolean): Promise<SymbolComments | undefined> {
  const p = await project();
  return on ? symbolCommentLookup(p.pous[0]!.variables, p.globals) : undefined;
}

/**
 * Pixels drawn in the comment band under cell (row 0, `col`) of network 0 that differ from the
 * network's background: text there is a comment (without the band the area is an empty row).
 */
async function inkUnder(col: number, symbolsOn: boolean): Promise<number> {
  const p = await project();
  const networks = p.pous[0]!.networks as Network[];
  const layout = layoutNetworks(networks, blockLibrary(p), await lookup(symbolsOn));
  const n = networks[0]!;
  const cell = cellRect(columnsOf(layout, n), { row: 0, col });
  const top = layout.tops[0]! + headerHeight(n) + CELL_H + 2;
  const box = { x: RAIL_X + cell.x + 3, y: top, width: cell.width - 6, height: COMMENT_PITCH - CELL_H - 6 };
  const origin = await draw.screenPoint({ x: box.x, y: box.y });
  return editor.page.evaluate(
    ({ o, w, h }) => {
      const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="ladder-canvas"] canvas')!;
      const rect = canvas.getBoundingClientRect();
      const scale = canvas.width / rect.width;
      const data = canvas
        .getContext('2d')!
        .getImageData(Math.round((o.x - rect.left) * scale), Math.round((o.y - rect.top) * scale), Math.round(w * scale), Math.round(h * scale)).data;
      const bg = [data[0]!, data[1]!, data[2]!];
      let ink = 0;
      for (let i = 0; i < data.length; i += 4)
        if (Math.abs(data[i]! - bg[0]!) + Math.abs(data[i + 1]! - bg[1]!) + Math.abs(data[i + 2]! - bg[2]!) > 90) ink++;
      return ink;
    },
    { o: origin, w: box.width, h: box.height },
  );
}

const headerTop = (i: number) =>
  editor.page.getByTestId(`network-header-${i}`).evaluate((el) => (el as HTMLElement).offsetTop);

async function printText(): Promise<string> {
  await editor.page.locator('body').press('Control+p');
  const dialog = editor.page.getByTestId('print-dialog');
  await dialog.waitFor();
  await dialog.getByRole('button', { name: 'Print preview' }).click();
  await editor.page.locator('[data-testid="print-view"][data-ready="true"]').waitFor();
  const text = (await editor.page.getByTestId('print-network').first().textContent()) ?? '';
  await editor.page.getByTestId('print-close').click();
  await editor.page.getByTestId('print-view').waitFor({ state: 'detached' });
  return text;
}

beforeAll(async () => {
  editor = await EditorPage.open(browser());
  draw = new DrawPage(editor.page);
  await editor.page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), machine());
  await editor.page.getByTestId('network-header-1').waitFor();
});

afterAll(async () => {
  await editor.close();
});

test('the symbol comment under a contact appears and disappears with the view option, is remembered, and prints', async () => {
  const toggle = editor.page.getByTestId('symbol-comments-toggle');
  // Off by default (CODESYS's default): no band, nothing under the contact.
  expect(await toggle.getAttribute('aria-pressed')).toBe('false');
  const before = await headerTop(1);
  expect(await inkUnder(0, false)).toBe(0);
  expect(await printText()).not.toContain('Start push');

  await toggle.click();
  expect(await toggle.getAttribute('aria-pressed')).toBe('true');
  // The rows of the network grow by the comment band: the network below moves down, nothing overlaps.
  await poll(() => headerTop(1)).toBe(before + 2 * (COMMENT_PITCH - CELL_H));
  await poll(() => inkUnder(0, true)).toBeGreaterThan(20);
  // Stop has no comment: nothing under it.
  expect(await inkUnder(1, true)).toBe(0);
  const printed = await printText();
  expect(printed).toContain('Start push');
  expect(printed).toContain('Main drive');

  // Remembered across a reload.
  await editor.page.reload();
  await editor.page.getByTestId('network-header-1').waitFor();
  expect(await editor.page.getByTestId('symbol-comments-toggle').getAttribute('aria-pressed')).toBe('true');
  await poll(() => inkUnder(0, true)).toBeGreaterThan(20);

  // View > Show symbol comments switches it off again (the menu shows its state).
  await editor.page.getByTestId('menu-view').click();
  expect(await editor.page.getByTestId('menuitem-view.symbolComments').getAttribute('data-checked')).toBe('true');
  await editor.page.getByTestId('menuitem-view.symbolComments').click();
  await poll(() => headerTop(1)).toBe(before);
  await poll(() => inkUnder(0, false)).toBe(0);
  expect(editor.errors).toEqual([]);
});

test('an element comment edited in the inspector shows on the canvas and in print, survives a reload and a PLCopen round trip', async () => {
  await draw.clickCell(0, 0, 1);
  await editor.tab('Inspector');
  const field = editor.inspector.getByTestId('inspector-element-comment');
  await field.click();
  await field.fill('Jog only from the panel');
  await field.press('Enter');
  await poll(async () => (await project()).pous[0]!.networks[0]!.elements.find((x) => x.id === 'b')?.comment).toBe(
    'Jog only from the panel',
  );
  // Shown without the symbol-comment option: the element's own comment.
  await poll(() => inkUnder(1, false)).toBeGreaterThan(20);
  // In print as on the canvas: wrapped in the contact's column, two lines, the rest cut with an ellipsis.
  const printed = await printText();
  expect(printed).toContain('Jog only');
  expect(printed).toContain('from the…');

  // Kept by the autosave through a reload.
  await editor.waitForAutosave();
  await editor.page.reload();
  await editor.page.getByTestId('network-header-1').waitFor();
  await poll(async () => (await project()).pous[0]!.networks[0]!.elements.find((x) => x.id === 'b')?.comment).toBe(
    'Jog only from the panel',
  );

  // PLCopen: the comment is the contact's <documentation>; importing the file brings it back.
  const file = await editor.download(async () => {
    await editor.menu('File', 'Export PLCopen XML');
    const review = editor.page.getByTestId('export-review');
    if (await review.isVisible().catch(() => false))
      await review.getByRole('button', { name: 'Export anyway' }).click();
  });
  expect(await schemaErrors(file.text)).toEqual([]);
  expect(file.text).toMatch(/<contact[^>]*negated="true"[^>]*>[\s\S]*?<documentation>[\s\S]*?Jog only from the panel[\s\S]*?<\/contact>/);
  // Clear the comment here, then import the file: the comment comes back from it.
  await draw.clickCell(0, 0, 1);
  const again = editor.inspector.getByTestId('inspector-element-comment');
  await again.click();
  await again.fill('');
  await again.press('Enter');
  await poll(async () => (await project()).pous[0]!.networks[0]!.elements.some((x) => x.comment)).toBe(false);
  await editor.chooseFile('File', 'Import PLCopen XML…', { name: file.name, mimeType: 'application/xml', text: file.text });
  const report = editor.page.getByTestId('plcopen-report');
  await report.waitFor();
  await report.getByRole('button', { name: 'Open' }).click();
  // The open project has unsaved changes: the editor asks first.
  await editor.page.getByRole('button', { name: 'Discard and import' }).click();
  await poll(async () => (await project()).pous[0]!.networks[0]!.elements.some((x) => x.comment)).toBe(true);
  const back = await project();
  const contacts = back.pous[0]!.networks.flatMap((n) => n.elements).filter((x) => x.kind === 'contact');
  expect(contacts.map((x) => x.comment ?? '')).toEqual(['', 'Jog only from the panel', '']);
  expect(editor.errors).toEqual([]);
});
