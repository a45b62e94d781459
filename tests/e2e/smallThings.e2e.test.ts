// Issue 22, section 2 item 16: the small things a user meets in a day, each seen in the page as
// the real server serves it: the inspector's pin types whole, Problems rows naming their POU and a
// coil's place, "Checking…" before the first check, the cross-reference starting afresh in another
// project, Why? with one bullet per line and no tags left after Live, one unit for the execution
// time, the Inputs panel's forced mark, and the trend's lane names.
import type { Page } from 'playwright-core';
import { expect, test } from 'vitest';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { ladder } from '../engine/ladder';
import { useChromium } from './appPage';
import { EditorPage, poll } from './panelsPage';
import { SimPage } from './simPage';

const browser = useChromium();

const load = (page: Page, p: Project) => page.evaluate((x) => window.rungsmith!.documentStore!.getState().loadProject(x), p);

/** Main: a coil writing an input (LD-R13 on the coil); Other: an empty network (a warning there). */
function twoPous(): Project {
  const main = newPou('Main', {
    variables: [variable('Start', 'BOOL', { location: '%IX0.0' }), variable('Lamp', 'BOOL', { location: '%QX0.0' })],
    networks: [ladder(['[Lamp] - - (Start)'])],
  });
  const other = newPou('Other', { variables: [variable('A', 'BOOL'), variable('Y', 'BOOL')], networks: [ladder(['[A] - (Y)', '[A] . .'])] });
  return newProject('Two POUs', { pous: [main, other], tasks: [{ name: 'T', cycleMs: 10, priority: 1, programs: [{ instance: 'M', pou: 'Main' }] }] });
}

test('the ADD inspector shows ANY_MAGNITUDE whole; Problems rows name their POU and place a coil at the right rail', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  await load(page, twoPous());
  await editor.tab('Problems');
  // A problem in Other while Main is shown: the row names Other.
  const rows = editor.problems.getByTestId('problem');
  await poll(async () => (await rows.allTextContents()).some((t) => t.includes('Other · network 1'))).toBe(true);
  // LD-R13 on the coil Start: placed by its row, at the right rail where it is drawn.
  const r13 = editor.problems.locator('[data-rule="LD-R13"]');
  await poll(() => r13.count()).toBe(1);
  const text = (await r13.textContent())!;
  expect(text).toContain('Main · network 1 · row 1, at the right rail');
  expect(text).not.toMatch(/column 4|R\dC\d/);

  // An ADD box, selected: its pins' type reads whole inside the inspector.
  const adder = ladder(['- # # .', '. # # .', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'ADD', outputs: { OUT: 'Sum' } }] });
  await load(page, newProject('Adder', { pous: [newPou('Main', { variables: [variable('Sum', 'INT')], networks: [adder] })] }));
  await poll(async () => (await editor.project()).name).toBe('Adder');
  await editor.uiSelect(adder.id, [adder.elements.find((e) => e.kind === 'box')!.id]);
  await editor.tab('Inspector');
  const label = editor.inspector.locator('label', { hasText: 'IN1' });
  await label.waitFor();
  expect(await label.textContent()).toBe('IN1ANY_MAGNITUDE');
  expect(await label.evaluate((el) => el.scrollWidth <= el.clientWidth + 1)).toBe(true);
  expect(await editor.inspector.getByLabel('IN1 : ANY_MAGNITUDE').count()).toBe(1);
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('after a reload the Problems summary says Checking… until the checks ran, never "No problems" for a project with problems', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  await load(page, twoPous());
  await editor.waitForAutosave();
  // Every text the summary shows from the first moment of the reloaded page.
  await page.addInitScript(() => {
    const seen: string[] = [];
    (window as unknown as { summaries: string[] }).summaries = seen;
    const watch = () => {
      const el = document.querySelector('[data-testid="problems-summary"]');
      if (el && el.textContent !== seen[seen.length - 1]) seen.push(el.textContent ?? '');
    };
    new MutationObserver(watch).observe(document, { subtree: true, childList: true, characterData: true });
  });
  await page.reload();
  await editor.tab('Problems');
  await poll(() => editor.problems.getByTestId('problems-summary').textContent()).toBe('0 errors, 2 warnings');
  const seen = await page.evaluate(() => (window as unknown as { summaries: string[] }).summaries);
  expect(seen[0]).toBe('Checking…');
  expect(seen).not.toContain('No problems');
  await editor.close();
});

test('the cross-reference starts empty in another project', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  const sim = new SimPage(page);
  await sim.openExample('Motor start/stop (seal-in)');
  await page.getByTestId('tab-xref').click();
  await page.getByTestId('xref-input').fill('Motor');
  await page.getByTestId('xref-uses').waitFor();
  await sim.openExample('Parts counter (CTU)');
  await poll(() => page.getByTestId('xref-input').inputValue()).toBe('');
  expect(await page.getByTestId('xref-uses').count()).toBe(0);
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('running: one unit for the execution time, Why? with one bullet a line and no tags after Live, the forced input marked whole', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  const sim = new SimPage(page);
  await sim.runExample('Motor start/stop (seal-in)');
  const exec = page.getByTestId('sim-exec');
  const shapes = new Set<string>();
  for (let i = 0; i < 10; i++) {
    const t = (await exec.textContent()) ?? '';
    expect(t).toMatch(/^\d+\.\d{3} \/ \d+\.\d{3} \/ \d+\.\d{3} ms$/);
    shapes.add(t.replace(/\d/g, '9').replace(/9+/g, '9'));
    await page.waitForTimeout(50);
  }
  expect([...shapes]).toEqual(['9.9 / 9.9 / 9.9 ms']);

  // Force Stop from the Inputs panel's neighbour, the watch: the Inputs row shows the forced badge, nothing cut.
  await sim.tab('Watch');
  await page.getByTestId('watch-add-name').fill('Stop');
  await page.getByTestId('watch-add').click();
  const row = page.getByTestId('watch-row-Stop');
  await row.getByTestId('watch-input').fill('TRUE');
  await row.getByTestId('watch-force').click();
  await sim.waitForValue('Stop', true);
  await sim.tab('Inputs');
  const input = page.getByTestId('input-Stop');
  await input.getByTestId('forced-badge').waitFor();
  expect(await input.getByTestId('forced-badge').getAttribute('title')).toBe('forced to TRUE');
  expect(await page.getByTestId('inputs-panel').evaluate((el) => el.scrollWidth <= el.clientWidth + 1)).toBe(true);
  expect(await input.textContent()).not.toContain('…');

  // Why? at a recorded scan: sub-lines are list items without a second bullet; Live clears it.
  await page.getByTestId('history-prev').click();
  await page.getByTestId('history-marker').filter({ hasText: 'HISTORY' }).waitFor();
  await sim.tab('Why?');
  await page.getByTestId('why-input').fill('Motor');
  await page.getByTestId('why-ask').click();
  const why = page.getByTestId('why-explanation');
  await why.waitFor();
  const items = await why.locator('.rs-why-lines li').allTextContents();
  expect(items.length).toBeGreaterThan(1);
  for (const item of items) expect(item).not.toMatch(/^\s*[•\-*]\s/);
  await page.getByTestId('history-live').click();
  await why.waitFor({ state: 'detached' });
  expect(await page.evaluate(() => (window.rungsmith as unknown as { simStore: { getState(): { explanation: unknown } } }).simStore.getState().explanation)).toBeUndefined();
  expect(editor.errors).toEqual([]);
  await editor.close();
});

test('the trend writes a long lane name whole when it fits, and never two scale labels over each other', async () => {
  const editor = await EditorPage.open(browser());
  const page = editor.page;
  const sim = new SimPage(page);
  await sim.runExample('Traffic light (TON chain)');
  await sim.tab('Trend');
  const names = ['RedTime.ET', 'GreenTime.ET', 'YellowTime.ET', 'Red'];
  for (const name of names) {
    await page.getByTestId('trend-add-name').fill(name);
    await page.getByTestId('trend-add').click();
  }
  const chart = page.getByTestId('trend-chart');
  await poll(() => chart.getAttribute('data-lane-names')).toBe(names.join('|'));
  await poll(async () => ((await chart.getAttribute('data-scale-labels')) ?? '').length > 0).toBe(true);
  const labels = ((await chart.getAttribute('data-scale-labels')) ?? '').split('|').map((l) => Number(l.split('@')[1]));
  const height = await chart.evaluate((el) => el.querySelector('.u-over')?.clientHeight ?? 0);
  const total = 3 * 3 + 1;
  for (let i = 1; i < labels.length; i++) expect((labels[i - 1]! - labels[i]!) * (height / total)).toBeGreaterThanOrEqual(13.5);
  expect(editor.errors).toEqual([]);
  await editor.close();
});
