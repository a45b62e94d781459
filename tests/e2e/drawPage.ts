// Page object for drawing on the ladder canvas in a real browser: cell positions on screen from
// the editor's own geometry, and the document read through window.rungsmith.
import type { Page } from 'playwright-core';
import { expect } from 'vitest';
import {
  CELL_H,
  cellCentre,
  columnsOf,
  gridOrigin,
  layoutNetworks,
  WIRE_Y,
  type CanvasLayout,
} from '../../src/editor/canvas/geometry';
import { roomFor } from '../../src/editor/canvas/canvasLayout';
import { blockLibrary } from '../../src/model/library';
import type { Network, Project } from '../../src/model/project';
import { chooseMenuItem } from './appPage';

export interface ElementSummary {
  readonly kind: string;
  readonly row: number;
  readonly col: number;
  readonly name?: string;
  readonly type?: string;
}

export class DrawPage {
  constructor(readonly page: Page) {}

  /**
   * Waits until the canvas has stopped scrolling (an autoscroll while dragging, the scroll to a
   * breakpoint or a selection): a cell's point measured before then can land on another network.
   */
  async waitScrollStill(): Promise<void> {
    const scrollTop = () => this.page.evaluate(() => document.querySelector<HTMLElement>('[data-testid="ladder-canvas"]')!.scrollTop);
    let last = -1;
    await expect
      .poll(
        async () => {
          const now = await scrollTop();
          const still = now === last;
          last = now;
          return still;
        },
        { timeout: 30_000, interval: 200 },
      )
      .toBe(true);
  }

  canvas() {
    return this.page.getByTestId('ladder-canvas');
  }

  async networks(): Promise<Network[]> {
    return this.page.evaluate(() => {
      const s = window.rungsmith!.documentStore!.getState();
      return JSON.parse(
        JSON.stringify(s.project.pous.find((p) => p.id === s.activePouId)!.networks),
      ) as Network[];
    });
  }

  /** The shown POU's networks laid out as the canvas lays them out (columns sized with the project's blocks). */
  async layout(): Promise<{ networks: Network[]; layout: CanvasLayout }> {
    const project = await this.page.evaluate(() => {
      const s = window.rungsmith!.documentStore!.getState();
      const ui = window.rungsmith!.uiStore!.getState();
      return JSON.parse(
        JSON.stringify({
          project: s.project,
          active: s.activePouId,
          ui: { tool: ui.tool, cursor: ui.cursor, dragging: ui.dragging },
        }),
      ) as { project: Project; active: string; ui: Parameters<typeof roomFor>[0] };
    });
    const networks = project.project.pous.find((p) => p.id === project.active)!.networks as Network[];
    const library = blockLibrary(project.project);
    // As the canvas lays them out: used rows, and the room shown while placing (canvasLayout.ts).
    return { networks, layout: layoutNetworks(networks, library, undefined, roomFor(project.ui, networks, library)) };
  }

  /** Elements of network `index` as (kind, row, col, name, type), sorted by position. */
  async elements(index: number): Promise<ElementSummary[]> {
    const n = (await this.networks())[index]!;
    return n.elements
      .map((e) => {
        const name =
          e.kind === 'contact' || e.kind === 'coil' ? e.variable : e.kind === 'jump' ? e.target : undefined;
        const type = e.kind === 'contact' ? e.contact : e.kind === 'coil' ? e.coil : undefined;
        return {
          kind: e.kind,
          row: e.row,
          col: e.col,
          ...(name !== undefined ? { name } : {}),
          ...(type ? { type } : {}),
        };
      })
      .sort((a, b) => a.row - b.row || a.col - b.col);
  }

  /** Screen position of the middle of a cell (the canvas scrolled to show it first). */
  async cellPoint(index: number, row: number, col: number): Promise<{ x: number; y: number }> {
    const { networks, layout } = await this.layout();
    return this.screenPoint(cellCentre(layout, networks, index, { row, col }));
  }

  /** Screen position of a point in canvas content pixels (the canvas scrolled to show it first). */
  async screenPoint(content: { x: number; y: number }): Promise<{ x: number; y: number }> {
    const { x: contentX, y: contentY } = content;
    const { zoom, left, top, boxX, boxY } = await this.canvas().evaluate(
      (el, p) => {
        const z = window.rungsmith!.uiStore!.getState().viewport.zoom;
        // Bring the cell into view like a user scrolling to it.
        if (p.y * z < el.scrollTop || p.y * z > el.scrollTop + el.clientHeight - 40)
          el.scrollTop = p.y * z - el.clientHeight / 2;
        const r = el.getBoundingClientRect();
        return { zoom: z, left: el.scrollLeft, top: el.scrollTop, boxX: r.left, boxY: r.top };
      },
      { x: contentX, y: contentY },
    );
    await this.page.waitForTimeout(0);
    return { x: boxX + contentX * zoom - left, y: boxY + contentY * zoom - top };
  }

  /**
   * Screen position of the middle of the vertical link on column boundary `boundary` from row `row`
   * down to the next row (where it is drawn, and where the vertical link tool takes a click).
   */
  async vlinkPoint(index: number, row: number, boundary: number): Promise<{ x: number; y: number }> {
    const { networks, layout } = await this.layout();
    const n = networks[index]!;
    const origin = gridOrigin(n);
    return this.screenPoint({
      x: origin.x + columnsOf(layout, n).xs[boundary]!,
      y: layout.tops[index]! + origin.y + row * CELL_H + WIRE_Y + CELL_H / 2,
    });
  }

  /** Adds (or removes) a vertical link with the palette's vertical link tool, as a user clicks it. */
  async clickVLink(index: number, row: number, boundary: number) {
    await this.pickPalette('vlink');
    const p = await this.vlinkPoint(index, row, boundary);
    await this.page.mouse.click(p.x, p.y);
    await this.pickPalette('vlink');
  }

  async clickCell(index: number, row: number, col: number) {
    const p = await this.cellPoint(index, row, col);
    await this.page.mouse.click(p.x, p.y);
  }

  async pickPalette(id: string) {
    await this.page.getByTestId(`palette-${id}`).click();
  }

  /** Types a name into the inline editor that opened over a new element, and confirms it. */
  async typeName(name: string) {
    const input = this.page.getByTestId('inline-editor');
    await input.waitFor();
    await input.fill(name);
    await this.page.keyboard.press('Enter');
    await input.waitFor({ state: 'detached' });
  }

  menu(menu: string, item: string): Promise<void> {
    return chooseMenuItem(this.page, menu, item);
  }

  async problemsSummary(): Promise<string> {
    return (await this.page.getByTestId('problems-summary').textContent()) ?? '';
  }
}
