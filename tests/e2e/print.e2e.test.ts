// Printing: Ctrl+P opens the Print dialog, the print view lays the networks out on A4 pages with a
// title block on each ("Page n / N"), never splitting a network that fits on a page, and the PDF
// Chromium prints from it has exactly those pages.
import type { Page } from 'playwright-core';
import { afterAll, afterEach, beforeAll, expect, test } from 'vitest';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { LdElement } from '../../src/model/elements';
import type { ElementId } from '../../src/model/ids';
import type { Project } from '../../src/model/project';
import { openApp, useChromium } from './appPage';
import { sealInProject } from './sealInProject';

const browser = useChromium();
let page: Page;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
});

afterEach(async () => {
  // A failed test leaves no print view over the next one.
  if (await page.getByTestId('print-view').count()) await closePreview();
});

afterAll(() => {
  expect(errors).toEqual([]);
});

async function load(project: Project) {
  await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), project);
}

/** Ctrl+P, the dialog's choices, Print preview; waits until the pages are laid out. */
async function printPreview(choices: { whole?: boolean; variables: boolean; crossReference: boolean; portrait?: boolean }) {
  await page.locator('body').press('Control+p');
  const dialog = page.getByTestId('print-dialog');
  await dialog.waitFor();
  await dialog.getByRole('radio', { name: choices.whole ? /whole project/ : /open POU/ }).check();
  await dialog.getByRole('checkbox', { name: /Variable list/ }).setChecked(choices.variables);
  await dialog.getByRole('checkbox', { name: /Cross-reference/ }).setChecked(choices.crossReference);
  await dialog.getByLabel('Paper').selectOption(choices.portrait ? 'portrait' : 'landscape');
  await dialog.getByRole('button', { name: 'Print preview' }).click();
  await page.locator('[data-testid="print-view"][data-ready="true"]').waitFor();
  return page.getByTestId('print-view');
}

/** Nothing is cut off at the bottom of a page: what was measured is what the pages hold. */
async function expectNothingCut() {
  const cut = await page.evaluate(() =>
    [...document.querySelectorAll<HTMLElement>('[data-testid="print-page"] .rs-print-body')]
      .map((body, i) => ({ page: i + 1, over: body.scrollHeight - body.clientHeight }))
      .filter((p) => p.over > 0),
  );
  expect(cut).toEqual([]);
}

async function closePreview() {
  await page.getByTestId('print-close').click();
  await page.getByTestId('print-view').waitFor({ state: 'detached' });
}

/** Pages of the PDF Chromium prints (its page objects), with the page size the print view asks for. */
async function pdfPages(): Promise<number> {
  const pdf = await page.pdf({ preferCSSPageSize: true, printBackground: true });
  return (pdf.toString('latin1').match(/\/Type\s*\/Page(?!s)/g) ?? []).length;
}

test('a 100-network POU prints on the expected number of pages, no network split, and the PDF has those pages', async () => {
  await load(sealInProject(100, 'Conveyor line'));
  const view = await printPreview({ variables: false, crossReference: false });
  const pages = view.getByTestId('print-page');
  const count = await pages.count();

  // Every network once, whole: no slice of a split network anywhere.
  expect(await view.getByTestId('print-network').count()).toBe(100);
  expect(await view.locator('.rs-print-slice').count()).toBe(0);
  // The networks are all alike: the page body holds as many as fit, the POU heading taking the
  // first page's top; so the count follows from their measured heights.
  const m = await page.evaluate(() => {
    const first = document.querySelector<HTMLElement>('[data-testid="print-page"] .rs-print-body')!;
    const net = document.querySelectorAll<HTMLElement>('[data-testid="print-page"]')[1]!;
    const h = net.querySelector<HTMLElement>('.rs-print-network')!.getBoundingClientRect().height;
    const heading = first.querySelector<HTMLElement>('.rs-print-pou')!.getBoundingClientRect().height;
    return { body: first.clientHeight, h, heading };
  });
  const perPage = Math.floor((m.body - 2) / m.h);
  const onFirst = Math.floor((m.body - 2 - m.heading) / m.h);
  expect(perPage).toBeGreaterThan(1);
  expect(count).toBe(1 + Math.ceil((100 - onFirst) / perPage));
  for (let i = 0; i < count; i++) {
    const nets = await pages.nth(i).getByTestId('print-network').count();
    expect(nets).toBe(i === 0 ? onFirst : Math.min(perPage, 100 - onFirst - (i - 1) * perPage));
  }

  // A title block on every page: project, POU, date, page n / N.
  const title = pages.nth(2).locator('.rs-print-title');
  expect(await title.locator('.rs-print-project').textContent()).toBe('Conveyor line');
  expect(await title.locator('.rs-print-section').textContent()).toBe('Main');
  expect(await title.locator('.rs-print-date').textContent()).toMatch(/^\d{4}-\d\d-\d\d \d\d:\d\d$/);
  expect(await pages.last().getByTestId('print-page-number').textContent()).toBe(`Page ${count} / ${count}`);
  // The grid is the canvas's drawing, as vector graphics: the contacts' variable names are text.
  expect(await pages.first().locator('svg text').allTextContents()).toEqual(
    expect.arrayContaining(['Start0', 'Stop0', 'Guard0', 'Motor0']),
  );

  await expectNothingCut();
  expect(await pdfPages()).toBe(count);
  await closePreview();
});

test('with variable lists and the cross-reference, in portrait: every page prints, tables keep their headers', async () => {
  // A comment long enough to wrap over several lines in its row.
  const project = sealInProject(100, 'Conveyor line');
  const main = project.pous[0]!;
  const long = 'Motor of the infeed conveyor, belt 3; stops on the light curtain and on any emergency stop of zone B. '.repeat(3);
  await load({
    ...project,
    pous: [{ ...main, variables: main.variables.map((v) => (v.name === 'Motor0' ? { ...v, comment: long } : v)) }],
  });
  const view = await printPreview({ variables: true, crossReference: true, portrait: true });
  const pages = view.getByTestId('print-page');
  const count = await pages.count();
  expect(await view.getByTestId('print-network').count()).toBe(100);
  expect(await view.locator('.rs-print-slice').count()).toBe(0);
  // 400 variables in the list and in the cross-reference; the last page is the cross-reference's.
  expect(await view.locator('.rs-print-row.rs-print-var:not(.rs-print-head)').count()).toBe(400);
  expect(await view.locator('.rs-print-row.rs-print-xref:not(.rs-print-head)').count()).toBe(400);
  expect(await pages.last().locator('.rs-print-section').textContent()).toBe('Cross-reference');
  // Each page a table runs onto starts with the table's header.
  const headersOk = await page.evaluate(() =>
    [...document.querySelectorAll('[data-testid="print-page"] .rs-print-body')].every((body) => {
      const first = body.firstElementChild;
      return !first?.classList.contains('rs-print-block') || !first.querySelector('.rs-print-row') ||
        first.previousElementSibling?.classList.contains('rs-print-head');
    }),
  );
  expect(headersOk).toBe(true);
  const wrapped = view.locator('.rs-print-row.rs-print-var').filter({ hasText: 'Motor0' });
  const oneLine = view.locator('.rs-print-row.rs-print-var').filter({ hasText: 'Motor1' }).first();
  expect((await wrapped.boundingBox())!.height).toBeGreaterThan(2 * (await oneLine.boundingBox())!.height);
  const motor7 = view.locator('.rs-print-row.rs-print-xref').filter({ hasText: 'Motor7' }).first();
  expect(await motor7.locator('span').allTextContents()).toEqual(['Motor7', 'Main', 'BOOL', '', 'Main: N8 W, N8 R', '2']);
  await expectNothingCut();
  expect(await pdfPages()).toBe(count);
  await closePreview();
});

test('a network taller than a page is split between rows with continued marks', async () => {
  const rows = 30;
  const elements: LdElement[] = Array.from({ length: rows }, (_, r) => ({
    kind: 'coil',
    coil: 'COIL',
    variable: `Out${r}`,
    id: `q${r}` as ElementId,
    row: r,
    col: 3,
  }));
  const tall = newNetwork({ title: 'Thirty outputs', rows, cols: 4, elements });
  await load(
    newProject('Tall', {
      pous: [
        newPou('Main', {
          networks: [newNetwork({ title: 'Before' }), tall, newNetwork({ title: 'After' })],
          variables: elements.map((_, r) => variable(`Out${r}`, 'BOOL')),
        }),
      ],
    }),
  );
  const view = await printPreview({ variables: false, crossReference: false });
  const slices = view.locator('.rs-print-slice');
  expect(await slices.count()).toBeGreaterThan(1);
  expect(await view.locator('.rs-print-mark').filter({ hasText: 'Network 2 (continued)' }).count()).toBe(
    (await slices.count()) - 1,
  );
  expect(await view.locator('.rs-print-mark').filter({ hasText: 'continued on the next page' }).count()).toBe(
    (await slices.count()) - 1,
  );
  // Each cut falls between two rows of 64 px (scaled to the page width), not through a coil.
  const cuts = await slices.evaluateAll((els) =>
    els.slice(0, -1).map((el) => {
      const svg = el.querySelector('svg')!;
      const scale = svg.getBoundingClientRect().height / Number(svg.getAttribute('height'));
      return (el.getBoundingClientRect().bottom - svg.getBoundingClientRect().top) / (64 * scale);
    }),
  );
  for (const c of cuts) expect(Math.abs(c - Math.round(c))).toBeLessThan(0.01);
  await expectNothingCut();
  expect(await pdfPages()).toBe(await view.getByTestId('print-page').count());
  await closePreview();
});

test('printing the open POU leaves the others out; the whole project has them all', async () => {
  const project = newProject('Two', {
    pous: [newPou('Main', { networks: [newNetwork({ title: 'Main rung' })] }), newPou('Other', { networks: [newNetwork({ title: 'Other rung' }), newNetwork()] })],
  });
  await load(project);
  let view = await printPreview({ variables: false, crossReference: false });
  expect(await view.locator('.rs-print-pou h2').allTextContents()).toEqual(['PROGRAM Main']);
  expect(await view.getByTestId('print-network').count()).toBe(1);
  await closePreview();
  view = await printPreview({ whole: true, variables: false, crossReference: false });
  expect(await view.locator('.rs-print-pou h2').allTextContents()).toEqual(['PROGRAM Main', 'PROGRAM Other']);
  expect(await view.getByTestId('print-network').count()).toBe(3);
  // The print view covers the editor, which is left out of the printed page.
  expect(await page.evaluate(() => document.body.classList.contains('rs-printing'))).toBe(true);
  await page.keyboard.press('Escape');
  await page.getByTestId('print-view').waitFor({ state: 'detached' });
  expect(await page.evaluate(() => document.body.classList.contains('rs-printing'))).toBe(false);
});
