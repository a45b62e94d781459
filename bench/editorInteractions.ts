// What a user waits for in the editor, measured in the built app in Chromium from the user's input
// event (its `timeStamp`, taken in a capture listener on window) to the first painted frame that
// shows the result (a requestAnimationFrame after it, then a task: the frame has been painted).
// Driven through page.mouse / page.keyboard as a user would, on a network in view:
//   select     a click on a contact
//   keystroke  a character typed into the name field open over it (completion list updated)
//   commit     Enter on a new name: the offer "Declare <name>" taken, the contact renamed
//   undo       Ctrl+Z of that commit (name and declaration back in one step)
//   paste200   Ctrl+V of 200 copied networks (Enter on "New instances" when the paste asks)
// and the frame times while the program runs in the simulator and the canvas scrolls.
import type { Page } from 'playwright-core';
import { cellCentre, layoutNetworks } from '../src/editor/canvas/geometry';
import { blockLibrary } from '../src/model/library';
import type { Network, Project } from '../src/model/project';

/** What must hold in the painted frame that ends a measurement (checked each frame). */
interface Until {
  readonly networksAtLeast?: number;
  readonly declared?: string;
  readonly notDeclared?: string;
  readonly editorOpen?: boolean;
}

interface SimHandle {
  getState(): { scan: number; run(p: Project): void; pause(): void; reset(): void };
}
interface Probe {
  __frame?: Promise<number>;
}
declare const window: Window & Probe;

/** ms from the next `type` event on the page to the painted frame where `until` holds. */
export async function timed(page: Page, type: string, act: () => Promise<unknown>, until: Until = {}): Promise<number> {
  // tsx names the functions declared inside the callbacks through a helper the page lacks.
  await page.evaluate('window.__name ??= (f) => f');
  await page.evaluate(
    ({ type, until }) => {
      const holds = () => {
        const s = window.rungsmith!.documentStore!.getState();
        const pou = s.project.pous.find((p) => p.id === s.activePouId)!;
        const has = (name: string) => pou.variables.some((v) => v.name === name);
        if (until.networksAtLeast !== undefined && pou.networks.length < until.networksAtLeast) return false;
        if (until.declared !== undefined && !has(until.declared)) return false;
        if (until.notDeclared !== undefined && has(until.notDeclared)) return false;
        if (until.editorOpen && !document.querySelector('[data-testid="inline-editor"]')) return false;
        return true;
      };
      window.__frame = new Promise<number>((resolve) => {
        const on = (e: Event) => {
          // Ctrl+Z arrives as Control's keydown, then Z's: the input is the Z.
          if (e instanceof KeyboardEvent && ['Control', 'Shift', 'Alt', 'Meta'].includes(e.key)) return;
          window.removeEventListener(type, on, true);
          const t0 = e.timeStamp;
          const frame = () =>
            requestAnimationFrame(() =>
              setTimeout(() => (holds() ? resolve(performance.now() - t0) : frame()), 0),
            );
          frame();
        };
        window.addEventListener(type, on, true);
      });
    },
    { type, until },
  );
  await act();
  return page.evaluate(() => window.__frame!);
}

const medianOf = (xs: readonly number[]) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length === 0 ? NaN : s[Math.floor((s.length - 1) / 2)]!;
};

async function shownProject(page: Page): Promise<{ project: Project; networks: Network[] }> {
  const project = await page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    return JSON.stringify({ project: s.project, active: s.activePouId });
  });
  const parsed = JSON.parse(project) as { project: Project; active: string };
  return { project: parsed.project, networks: parsed.project.pous.find((p) => p.id === parsed.active)!.networks as Network[] };
}

/** Screen point of a cell of network `index`, the canvas scrolled (like a user) to show it. */
export async function cellOnScreen(page: Page, index: number, row: number, col: number): Promise<{ x: number; y: number }> {
  const { project, networks } = await shownProject(page);
  const layout = layoutNetworks(networks, blockLibrary(project));
  const c = cellCentre(layout, networks, index, { row, col });
  const at = await page.getByTestId('ladder-canvas').evaluate((el, p) => {
    const z = window.rungsmith!.uiStore!.getState().viewport.zoom;
    el.scrollTop = Math.max(0, p.y * z - el.clientHeight / 3);
    el.scrollLeft = 0;
    const r = el.getBoundingClientRect();
    return { z, left: el.scrollLeft, top: el.scrollTop, x: r.left, y: r.top };
  }, c);
  // Two frames: the scrolled band drawn before the click.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return { x: at.x + c.x * at.z - at.left, y: at.y + c.y * at.z - at.top };
}

export interface InteractionFigures {
  /** The project's first click on an element after it was loaded (the page's first, for the first project measured). */
  readonly firstSelectMs: number;
  /** Median of `repeats` clicks, after the project's first two. */
  readonly selectMs: number;
  /**
   * The same click again on the contact it selected (nothing changes): the measure's own floor at
   * this load (input delivery, the app's pointer handling, the wait for the next frame).
   */
  readonly reclickMs: number;
  readonly keystrokeMs: number;
  readonly commitMs: number;
  readonly undoMs: number;
  readonly paste200Ms: number;
}

const settle = (page: Page) => page.evaluate(() => new Promise((r) => setTimeout(r, 150)));

/**
 * Select, type, commit with declaration and undo on `repeats` networks spread over the POU, then a
 * paste of 200 networks (undone after). The shown POU must have a contact at row 0, column 0 of
 * every network (both generated bench projects do).
 */
export async function interactionFigures(
  page: Page,
  repeats = 7,
  /** Runs each select click (bench/editorProfile.ts traces it); the click alone when absent. */
  aroundSelect: (click: () => Promise<number>) => Promise<number> = (click) => click(),
): Promise<InteractionFigures> {
  const select: number[] = [];
  const reclick: number[] = [];
  const keys: number[] = [];
  const commit: number[] = [];
  const undo: number[] = [];
  const count = (await shownProject(page)).networks.length;
  // The project's first clicks, timed as the others but not counted in select-ms: in a page that has
  // not clicked an element yet V8 still compiles what a click runs (the inspector's form, the
  // selection marks), so the first two take 20-35 ms and the next ones 8-18 (bench/selectPhases.ts).
  // Both projects are measured alike: the bottle filler's clicks were the page's first, the
  // 1,000-network project's came after them. The first click's own figure is select-first-ms.
  const first: number[] = [];
  for (const index of [1, count - 2]) {
    const p = await cellOnScreen(page, index, 0, 0);
    first.push(await timed(page, 'pointerdown', () => page.mouse.click(p.x, p.y)));
    await settle(page);
    await page.evaluate(() => new Promise((r) => setTimeout(r, 600)));
  }
  for (let k = 0; k < repeats; k++) {
    const index = Math.floor(((k + 0.5) * count) / repeats);
    const p = await cellOnScreen(page, index, 0, 0);
    select.push(await aroundSelect(() => timed(page, 'pointerdown', () => page.mouse.click(p.x, p.y))));
    await settle(page);
    const selected = await page.evaluate(() => window.rungsmith!.uiStore!.getState().selection.elements.length);
    if (selected !== 1) throw new Error(`the click on network ${index + 1} selected ${selected} elements, not its contact`);
    // Past any double-click interval: a second click, not a double click.
    await page.evaluate(() => new Promise((r) => setTimeout(r, 600)));
    reclick.push(await timed(page, 'pointerdown', () => page.mouse.click(p.x, p.y)));
    await settle(page);
    await timed(page, 'keydown', () => page.keyboard.press('Enter'), { editorOpen: true });
    await page.keyboard.press('Control+a');
    const name = `Bench${k}Fill`;
    for (const ch of name) {
      keys.push(await timed(page, 'keydown', () => page.keyboard.press(ch)));
      await page.evaluate(() => new Promise((r) => setTimeout(r, 30)));
    }
    await settle(page);
    commit.push(await timed(page, 'keydown', () => page.keyboard.press('Enter'), { declared: name }));
    await settle(page);
    undo.push(await timed(page, 'keydown', () => page.keyboard.press('Control+z'), { notDeclared: name }));
    await settle(page);
  }

  // Paste: 200 networks copied (selected by the outline's range, as Shift+click does), pasted after network 1.
  const ids = await page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    const pou = s.project.pous.find((p) => p.id === s.activePouId)!;
    return pou.networks.slice(0, 200).map((n) => n.id);
  });
  await page.evaluate((sel) => window.rungsmith!.uiStore!.getState().selectNetworks(sel as never), ids);
  await page.getByTestId('ladder-canvas').focus();
  await page.keyboard.press('Control+c');
  await page.evaluate((first) => window.rungsmith!.uiStore!.getState().selectNetworks([first] as never), ids[0]!);
  await page.getByTestId('ladder-canvas').focus();
  await settle(page);
  const asks = await page.evaluate(() => {
    const s = window.rungsmith!.documentStore!.getState();
    const pou = s.project.pous.find((p) => p.id === s.activePouId)!;
    return pou.networks.slice(0, 200).some((n) => n.elements.some((e) => e.kind === 'box' && e.instance));
  });
  let paste: number;
  if (asks) {
    await page.keyboard.press('Control+v');
    await page.getByTestId('paste-new-instances').waitFor();
    paste = await timed(page, 'keydown', () => page.keyboard.press('Enter'), { networksAtLeast: count + 200 });
  } else {
    paste = await timed(page, 'keydown', () => page.keyboard.press('Control+v'), { networksAtLeast: count + 200 });
  }
  await settle(page);
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().undo());
  await settle(page);
  return {
    firstSelectMs: first[0]!,
    selectMs: medianOf(select),
    reclickMs: medianOf(reclick),
    keystrokeMs: medianOf(keys),
    commitMs: medianOf(commit),
    undoMs: medianOf(undo),
    paste200Ms: paste,
  };
}

/** p95 of frame times (rAF deltas) while the shown program runs in the simulator and the canvas scrolls. */
export async function runningFrameP95(page: Page, frames = 300): Promise<number> {
  await page.evaluate(() => {
    const sim = (window.rungsmith!.simStore as SimHandle).getState();
    sim.run(window.rungsmith!.documentStore!.getState().project);
  });
  await page.waitForFunction(() => (window.rungsmith!.simStore as SimHandle).getState().scan > 10, undefined, { timeout: 60_000 });
  const deltas = await page.evaluate(async (n) => {
    const el = document.querySelector<HTMLElement>('[data-testid="ladder-canvas"]')!;
    el.scrollTop = 0;
    const out: number[] = [];
    let last = await new Promise<number>((r) => requestAnimationFrame(r));
    for (let i = 0; i < n; i++) {
      el.scrollTop += 20;
      const t = await new Promise<number>((r) => requestAnimationFrame(r));
      out.push(t - last);
      last = t;
    }
    return out;
  }, frames);
  await page.evaluate(() => {
    const sim = (window.rungsmith!.simStore as SimHandle).getState();
    sim.pause();
    sim.reset();
  });
  const s = [...deltas].sort((a, b) => a - b);
  return s[Math.min(s.length - 1, Math.floor((s.length - 1) * 0.95))]!;
}
