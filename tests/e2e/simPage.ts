// Page object for the simulator in a real browser: the toolbar, panels and canvas pixels.
// The simulation state is read through window.rungsmith.simStore only to check what the user sees.
import type { Page } from 'playwright-core';
import { CELL_H, cellRect, columnsOf, WIRE_Y } from '../../src/editor/canvas/geometry';
import type { Project } from '../../src/model/project';
import { DrawPage } from './drawPage';

interface SimHandle {
  getState(): {
    mode: string;
    scan: number;
    values: unknown[];
    variableIndex: Map<string, number>;
  };
}

export class SimPage {
  readonly draw: DrawPage;
  constructor(readonly page: Page) {
    this.draw = new DrawPage(page);
  }

  async openExample(title: string) {
    await this.draw.menu('File', `Example: ${title}`);
    await this.page.getByTestId('project-name').filter({ hasText: title.split(' ')[0]! }).waitFor();
  }

  /** Opens an example from the File menu and runs it (Run, then waits until the mode reads Running). */
  async runExample(title: string) {
    await this.openExample(title);
    await this.button('run').click();
    await this.waitForMode('Running');
  }

  /** Loads a project through the scripting handle (for programs no example has, like a runaway loop). */
  async load(project: Project) {
    await this.page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), project);
  }

  button(id: 'run' | 'pause' | 'step-scan' | 'step-network' | 'reset' | 'warm' | 'step-n') {
    return this.page.getByTestId(`sim-${id}`);
  }

  async mode(): Promise<string> {
    return (await this.page.getByTestId('sim-mode').textContent()) ?? '';
  }

  async waitForMode(mode: string) {
    await this.page.getByTestId('sim-mode').filter({ hasText: mode }).waitFor({ timeout: 30_000 });
  }

  /** A variable's current value as the simulator holds it (BOOL true/false, TIME in ms). */
  async value(name: string): Promise<unknown> {
    return this.page.evaluate((n) => {
      const s = (window.rungsmith as unknown as { simStore: SimHandle }).simStore.getState();
      const i = s.variableIndex.get(n.toUpperCase());
      return i === undefined ? undefined : s.values[i];
    }, name);
  }

  async waitForValue(name: string, expected: unknown) {
    await this.page.waitForFunction(
      ([n, v]) => {
        const s = (window.rungsmith as unknown as { simStore: SimHandle }).simStore.getState();
        const i = s.variableIndex.get((n as string).toUpperCase());
        return i !== undefined && s.values[i] === v;
      },
      [name, expected] as const,
      { timeout: 30_000 },
    );
  }

  async tab(name: string) {
    await this.page.getByRole('tab', { name }).click();
  }

  /**
   * Whether the wire at the right end of a cell (or in its middle: a line's own wire, away from a
   * vertical link on its right) is drawn in the theme's energised colour (read from the canvas
   * pixels, as a user would see it).
   */
  async wireLit(network: number, row: number, col: number, at: 'end' | 'middle' = 'end'): Promise<boolean> {
    const { networks, layout } = await this.draw.layout();
    const n = networks[network]!;
    const point = await this.draw.cellPoint(network, row, col);
    const dx = at === 'middle' ? 0 : cellRect(columnsOf(layout, n), { row, col }).width / 2 - 5;
    const dy = WIRE_Y - CELL_H / 2;
    const zoom = await this.zoom();
    return this.litAt({ x: point.x + dx * zoom, y: point.y + dy * zoom });
  }

  /** Whether the vertical link on `boundary` from `row` to the next row is drawn energised. */
  async vlinkLit(network: number, row: number, boundary: number): Promise<boolean> {
    return this.litAt(await this.draw.vlinkPoint(network, row, boundary));
  }

  /** Whether the canvas pixels around a screen point show the theme's energised colour. */
  async litAt(point: { x: number; y: number }): Promise<boolean> {
    return this.page.evaluate(
      ({ x, y }) => {
        const canvas = document.querySelector<HTMLCanvasElement>('[data-testid="ladder-canvas"] canvas');
        if (!canvas) return false;
        const rect = canvas.getBoundingClientRect();
        const scale = canvas.width / rect.width;
        const px = Math.round((x - rect.left) * scale);
        const py = Math.round((y - rect.top) * scale);
        const data = canvas.getContext('2d')!.getImageData(px - 3, py - 3, 7, 7).data;
        const hex = getComputedStyle(document.documentElement).getPropertyValue('--canvas-energised').trim();
        const want = [1, 3, 5].map((i) => Number.parseInt(hex.slice(i, i + 2), 16));
        for (let i = 0; i < data.length; i += 4) {
          if (want.every((c, k) => Math.abs(data[i + k]! - c) < 40)) return true;
        }
        return false;
      },
      point,
    );
  }

  private async zoom(): Promise<number> {
    return this.page.evaluate(() => window.rungsmith!.uiStore!.getState().viewport.zoom);
  }

  /**
   * Switches the BOOL input a contact reads, as a user does while simulating: a double-click (a plain
   * click only selects, as when editing).
   */
  async switchCell(network: number, row: number, col: number) {
    const p = await this.draw.cellPoint(network, row, col);
    await this.page.mouse.dblclick(p.x, p.y);
  }

  /** Presses a contact like a push-button (Alt + press) and keeps it held until release() is called. */
  async holdCell(network: number, row: number, col: number): Promise<() => Promise<void>> {
    const p = await this.draw.cellPoint(network, row, col);
    await this.page.mouse.move(p.x, p.y);
    await this.page.keyboard.down('Alt');
    await this.page.mouse.down();
    return async () => {
      await this.page.mouse.up();
      await this.page.keyboard.up('Alt');
    };
  }
}

