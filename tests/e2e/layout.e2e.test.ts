// The shell's layout: panels resized by dragging their handles or from the keyboard, collapsed and
// expanded (keys, buttons, dragging shut), remembered over a reload; one-line bars at 1280×720
// that do not move when Run starts or an inspector field gains a hint line; the variable table's
// wide view with every column in view.
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, beforeEach, expect, test } from 'vitest';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { DEFAULT_PANELS } from '../../src/store/uiStore';
import { openApp, useChromium } from './appPage';

const browser = useChromium();
let page: Page;
let errors: string[];

beforeAll(async () => {
  ({ page, errors } = await openApp(browser()));
  await page.evaluate(() => localStorage.removeItem('rungsmith.panels'));
  await page.reload();
  await page.getByTestId('ladder-canvas').waitFor();
});

beforeEach(async () => {
  // Each test starts from the default layout, whatever the one before left.
  await page.setViewportSize({ width: 1440, height: 900 });
  await page.evaluate((p) => window.rungsmith!.uiStore!.getState().setPanels(p), DEFAULT_PANELS);
});

afterAll(() => {
  expect(errors).toEqual([]);
});

const box = async (selector: string) => {
  const b = await page.locator(selector).first().boundingBox();
  if (!b) throw new Error(`${selector} is not shown`);
  return { x: Math.round(b.x), y: Math.round(b.y), width: Math.round(b.width), height: Math.round(b.height) };
};

/** Drags the handle's centre by (dx, dy) with the mouse. */
async function drag(handle: string, dx: number, dy: number) {
  const b = (await page.getByTestId(handle).boundingBox())!;
  const x = b.x + b.width / 2;
  const y = b.y + b.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + dx / 2, y + dy / 2);
  await page.mouse.move(x + dx, y + dy);
  await page.mouse.up();
}

test('dragging a handle resizes its panel, the keyboard does too, a double-click restores the default', async () => {
  expect((await box('.rs-left')).width).toBe(230);
  await drag('resize-left', 100, 0);
  expect((await box('.rs-left')).width).toBe(330);
  const right = (await box('.rs-right')).width;
  await drag('resize-right', -60, 0);
  expect((await box('.rs-right')).width).toBe(right + 60);
  const bottom = (await box('.rs-bottom')).height;
  await drag('resize-bottom', 0, -80);
  expect((await box('.rs-bottom')).height).toBe(bottom + 80);
  // The canvas takes what the panels leave.
  const centre = await box('.rs-center');
  expect(centre.x).toBe(330 + 5);

  await page.getByTestId('resize-left').dblclick();
  expect((await box('.rs-left')).width).toBe(230);
  const handle = page.getByTestId('resize-left');
  await handle.focus();
  await page.keyboard.press('ArrowRight');
  expect((await box('.rs-left')).width).toBe(240);
  expect(await handle.getAttribute('aria-valuenow')).toBe('240');
  await page.keyboard.press('Shift+ArrowLeft');
  expect((await box('.rs-left')).width).toBe(190);
  await page.keyboard.press('Home');
  expect((await box('.rs-left')).width).toBe(160);
  // Never smaller than its minimum by dragging: a little further collapses it instead.
  await drag('resize-left', -40, 0);
  expect((await box('.rs-left')).width).toBe(160);
  await page.getByTestId('resize-left').dblclick();
});

test('each panel collapses and expands from its key, its button, or dragging its handle shut', async () => {
  const canvasWidth = async () => (await box('[data-testid="ladder-canvas"]')).width;
  const wide = await canvasWidth();
  await page.locator('body').press('Control+b');
  expect(await page.locator('.rs-left').isHidden()).toBe(true);
  expect(await page.getByTestId('toggle-left').getAttribute('aria-pressed')).toBe('false');
  expect(await canvasWidth()).toBe(wide + 230);
  await page.locator('body').press('Control+b');
  expect(await page.locator('.rs-left').isVisible()).toBe(true);

  await page.locator('body').press('Control+j');
  expect(await page.locator('.rs-bottom').isHidden()).toBe(true);
  await page.getByTestId('toggle-bottom').click();
  expect(await page.locator('.rs-bottom').isVisible()).toBe(true);

  await page.getByTestId('toggle-right').click();
  expect(await page.locator('.rs-right').isHidden()).toBe(true);
  await page.locator('body').press('Control+Alt+b');
  expect(await page.locator('.rs-right').isVisible()).toBe(true);

  // Dragged nearly shut, the left panel collapses; Enter on its handle brings it back.
  await drag('resize-left', -200, 0);
  expect(await page.locator('.rs-left').isHidden()).toBe(true);
  await page.getByTestId('resize-left').focus();
  await page.keyboard.press('Enter');
  expect((await box('.rs-left')).width).toBe(230);
  // The View menu lists the commands with their keys.
  await page.getByTestId('menu-view').click();
  expect(await page.getByTestId('menuitem-view.toggleBottom').textContent()).toContain('Ctrl+J');
  await page.keyboard.press('Escape');
});

test('panel sizes and collapsed panels are remembered over a reload', async () => {
  await drag('resize-left', 70, 0);
  await drag('resize-bottom', 0, -50);
  const bottom = (await box('.rs-bottom')).height;
  await page.getByTestId('toggle-right').click();
  await page.reload();
  await page.getByTestId('ladder-canvas').waitFor();
  expect((await box('.rs-left')).width).toBe(300);
  expect((await box('.rs-bottom')).height).toBe(bottom);
  expect(await page.locator('.rs-right').isHidden()).toBe(true);
  // Back to the defaults for the next tests.
  await page.evaluate(() => localStorage.removeItem('rungsmith.panels'));
  await page.reload();
  await page.getByTestId('ladder-canvas').waitFor();
  expect((await box('.rs-left')).width).toBe(230);
  expect(await page.locator('.rs-right').isVisible()).toBe(true);
});

test('at 1280×720 the bars are one line each, a new network fits, and nothing moves when Run starts', async () => {
  await page.setViewportSize({ width: 1280, height: 720 });
  for (const bar of ['.rs-topbar', '[data-testid="toolbar"]', '[data-testid="status-bar"]'])
    expect((await box(bar)).height).toBeLessThanOrEqual(33);
  // Every button of the tool bar sits on the one line, inside the window.
  const buttons = await page.getByTestId('sim-toolbar').locator('button, input, .rs-sim-status').evaluateAll((els) =>
    els.map((e) => {
      const r = e.getBoundingClientRect();
      return { middle: Math.round(r.top + r.height / 2), right: r.right };
    }),
  );
  expect(new Set(buttons.map((b) => b.middle)).size).toBe(1);
  expect(Math.max(...buttons.map((b) => b.right))).toBeLessThanOrEqual(1280);
  // Every tab of the side panels is in sight, inside its panel (Outline and Plant were scrolled out of the right one).
  for (const panel of ['.rs-left', '.rs-right', '.rs-bottom']) {
    const area = await box(panel);
    const tabs = await page.locator(`${panel} [role="tab"]`).evaluateAll((els) =>
      els.map((e) => {
        const r = e.getBoundingClientRect();
        return { name: e.textContent, left: r.left, right: r.right, width: r.width };
      }),
    );
    expect(tabs.length).toBeGreaterThan(1);
    for (const t of tabs) {
      expect(t.width, `${panel} ${t.name}`).toBeGreaterThan(0);
      expect(t.left, `${panel} ${t.name}`).toBeGreaterThanOrEqual(area.x);
      expect(t.right, `${panel} ${t.name}`).toBeLessThanOrEqual(area.x + area.width);
    }
  }
  await expect.poll(() => page.locator('.rs-right [role="tab"]').allTextContents()).toContain('Plant');
  // The default network is drawn whole, without scrolling sideways.
  const canvas = page.getByTestId('ladder-canvas');
  expect(await canvas.evaluate((el) => el.scrollWidth <= el.clientWidth)).toBe(true);

  const layout = async () => ({
    left: await box('.rs-left'),
    right: await box('.rs-right'),
    bottom: await box('.rs-bottom'),
    toolbar: await box('[data-testid="toolbar"]'),
    canvasTop: (await box('[data-testid="ladder-canvas"]')).y,
    projectName: await box('[data-testid="project-name"]'),
    reset: await box('[data-testid="sim-toolbar"] button:has-text("Reset")'),
  });
  const before = await layout();
  await page.getByRole('button', { name: /Run/ }).first().click();
  await expect.poll(() => page.getByTestId('sim-mode').textContent()).toBe('Running');
  await expect.poll(() => page.getByTestId('sim-scan').textContent()).not.toBe('0');
  expect(await layout()).toEqual(before);
  await page.getByRole('button', { name: /Pause/ }).click();
  await page.setViewportSize({ width: 1440, height: 900 });
});

test('an inspector field gaining a hint line moves nothing else', async () => {
  const coil = 'q1' as ElementId;
  const net = newNetwork({
    rows: 1,
    cols: 4,
    elements: [{ kind: 'coil', coil: 'COIL', variable: '', id: coil, row: 0, col: 3 }],
  });
  await page.evaluate(
    (p) => window.rungsmith!.documentStore!.getState().loadProject(p),
    newProject('Hint', { pous: [newPou('Main', { networks: [net], variables: [variable('Lamp', 'BOOL', { location: '%QX0.0' })] })] }),
  );
  await page.evaluate(
    ({ id }) => {
      const s = window.rungsmith!;
      const network = s.documentStore!.getState().project.pous[0]!.networks[0]!.id;
      s.uiStore!.getState().select(network, [id as never]);
    },
    { id: coil },
  );
  await page.getByRole('tab', { name: 'Inspector', exact: true }).click();
  const field = page.getByTestId('inspector-variable');
  await field.waitFor();
  const before = { field: await box('[data-testid="inspector-variable"]'), right: await box('.rs-right'), centre: await box('.rs-center') };
  await field.fill('Lamp');
  await field.press('Enter');
  await page.locator('.rs-binding-info').first().waitFor();
  expect({ field: await box('[data-testid="inspector-variable"]'), right: await box('.rs-right'), centre: await box('.rs-center') }).toEqual(before);
});

test('the variable table’s wide view shows every column header inside the full-width bottom panel', async () => {
  await page.setViewportSize({ width: 1280, height: 720 });
  await page.getByRole('tab', { name: 'Variables', exact: true }).click();
  await page.getByTestId('variables-wide').click();
  await expect.poll(() => page.locator('.rs-bottom [data-testid="variables-panel"]').count()).toBe(1);
  expect(await page.locator('.rs-right [data-testid="variables-panel"]').count()).toBe(0);
  expect(await page.getByRole('tab', { name: 'Variables', exact: true }).getAttribute('aria-selected')).toBe('true');
  const panel = page.locator('.rs-bottom [data-testid="variables-panel"]');
  const scroller = (await panel.locator('.rs-var-scroll').boundingBox())!;
  const heads = await panel.locator('thead th').all();
  expect(heads.length).toBe(10);
  const rowTops = new Set<number>();
  for (const th of heads) {
    const b = (await th.boundingBox())!;
    const what = (await th.getAttribute('data-col')) ?? '';
    expect({ what, inside: b.x >= scroller.x - 0.5 && b.x + b.width <= scroller.x + scroller.width + 0.5 }).toEqual({ what, inside: true });
    expect({ what, cut: await th.evaluate((e) => e.scrollWidth > e.clientWidth + 1) }).toEqual({ what, cut: false });
    rowTops.add(Math.round(b.y));
  }
  // One line of headers: the wide table, not the side panel's three-line layout.
  expect(rowTops.size).toBe(1);
  await panel.getByTestId('variables-wide').click();
  await expect.poll(() => page.locator('.rs-right [data-testid="variables-panel"]').count()).toBe(1);
  await page.setViewportSize({ width: 1440, height: 900 });
});
