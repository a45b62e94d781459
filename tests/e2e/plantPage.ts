// The Plant panel as the machines' browser tests use it (issue 26): the machine's frame and the
// recorded trace read through the page's scripting handle, operator controls held on the drawing,
// and fast-forward with Step N on the virtual clock (never waiting in real time).
import type { Page } from 'playwright-core';
import { expect } from 'vitest';
import type { SimPage } from './simPage';

/** The machine's live frame as the simulator store holds it. */
export interface PlantFrame<S> {
  id: string;
  now: { scan: number; timeMs: number; state: S; faults: string[]; operator: Record<string, boolean> };
  events: { text: string }[];
  eventCount: number;
}

interface SimHandle {
  getState(): {
    scan: number;
    timeMs: number;
    plant?: PlantFrame<unknown>;
    exportHistory(r: { format: 'trace'; names: string[] }): Promise<string>;
  };
}

export class PlantPage {
  constructor(
    readonly page: Page,
    readonly sim: SimPage,
  ) {}

  /** The colour of the drawing's pixel at (x, y) in the drawing's own coordinates, as "r,g,b". */
  drawnColour(x: number, y: number): Promise<string> {
    return this.page.evaluate(
      ([px, py]) => {
        const box = document.querySelector<HTMLElement>('.rs-plant-drawing')!;
        const scale = Number(box.dataset.scale);
        const canvas = box.querySelector('canvas')!;
        const ratio = canvas.width / canvas.getBoundingClientRect().width;
        const d = canvas.getContext('2d')!.getImageData(Math.round(px! * scale * ratio), Math.round(py! * scale * ratio), 1, 1).data;
        return `${d[0]},${d[1]},${d[2]}`;
      },
      [x, y],
    );
  }

  /** The machine's live frame (state, faults, operator controls, consequences). */
  async plant<S = Record<string, number | boolean>>(): Promise<PlantFrame<S> | undefined> {
    return (await this.page.evaluate(
      () => (window.rungsmith as unknown as { simStore: SimHandle }).simStore.getState().plant,
    )) as PlantFrame<S> | undefined;
  }

  simTime(): Promise<number> {
    return this.page.evaluate(() => (window.rungsmith as unknown as { simStore: SimHandle }).simStore.getState().timeMs);
  }

  simScan(): Promise<number> {
    return this.page.evaluate(() => (window.rungsmith as unknown as { simStore: SimHandle }).simStore.getState().scan);
  }

  /** The recorded scans' trace of `names` as the History's Export writes it (CSV with a header). */
  traceText(names: string[]): Promise<string> {
    return this.page.evaluate(
      (n) =>
        (window.rungsmith as unknown as { simStore: SimHandle }).simStore
          .getState()
          .exportHistory({ format: 'trace', names: n }),
      names,
    );
  }

  /** The recorded scans' values of `names`, one row of numbers a scan (scan, time, then the names). */
  async trace(names: string[]): Promise<number[][]> {
    return (await this.traceText(names))
      .trim()
      .split('\n')
      .slice(1)
      .map((r) => r.split(',').map(Number));
  }

  /**
   * While running: holds an operator button on the drawing (mouse down) until the program's
   * `variable` is TRUE, then lets it go and waits until the button is released.
   */
  async holdUntil(control: string, variable: string): Promise<void> {
    const button = this.page.getByTestId(`plant-op-${control}`);
    await button.scrollIntoViewIfNeeded();
    const box = (await button.boundingBox())!;
    await this.page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await this.page.mouse.down();
    await expect.poll(() => button.getAttribute('aria-pressed'), { timeout: 10_000 }).toBe('true');
    await this.sim.waitForValue(variable, true);
    await this.page.mouse.up();
    await expect.poll(() => button.getAttribute('aria-pressed'), { timeout: 10_000 }).toBe('false');
  }

  /** Opens the machine's exercise from File > Examples, shows the Plant tab and sets the scan cycle. */
  async openExercise(title: string, cycleMs: number): Promise<void> {
    await this.sim.openExample(title);
    await this.sim.tab('Plant');
    await this.page.getByTestId('sim-cycle').fill(String(cycleMs));
    await this.page.getByTestId('sim-cycle').press('Enter');
  }

  /** Runs, holds Start on the drawing until the program runs, releases it, pauses; then Step N of `scans` scans. */
  async startAndFastForward(scans: number): Promise<void> {
    await this.runHoldPause('Start', 'Running');
    await this.fastForward(scans);
  }

  /** Run, hold `control` until `variable` is TRUE, pause. */
  async runHoldPause(control: string, variable: string): Promise<void> {
    await this.sim.button('run').click();
    await this.sim.waitForMode('Running');
    await this.holdUntil(control, variable);
    await this.sim.button('pause').click();
    await this.sim.waitForMode('Paused');
  }

  /** Step N of `scans` scans (fast-forward on the virtual clock) from a paused simulation, waiting until they are done. */
  async fastForward(scans: number): Promise<void> {
    const from = await this.simScan();
    await this.page.getByTestId('sim-step-count').fill(String(scans));
    await this.sim.button('step-n').click();
    await expect.poll(() => this.simScan(), { timeout: 120_000 }).toBeGreaterThanOrEqual(from + scans);
    await this.sim.waitForMode('Paused');
  }
}

/** A sensor's lamp on the drawings, lit and unlit ("r,g,b"). */
export const LAMP_LIT = '34,197,94';
export const LAMP_UNLIT = '229,231,235';

