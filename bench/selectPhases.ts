// Probe (not a bench): the phases of bench:editor's select clicks on the bottle filler, measured
// in the page: input delay (event timeStamp to dispatch), the pointerdown's handlers, the wait
// for the frame (rAF), the frame's own work (rAF to the timer after it).
import { chromium } from 'playwright-core';
import { preview } from 'vite';
import { CHROMIUM_ARGS, CHROMIUM_PATH } from '../tests/e2e/browser';
import { sealInProject } from '../tests/e2e/sealInProject';
import type { Project } from '../src/model/project';
import { bottleFillerProject } from './bottleFiller';
import { interactionFigures } from './editorInteractions';

async function main() {
  const dist = process.env.RUNGSMITH_DIST ?? 'dist';
  const project: Project = process.argv[2] === 'seal' ? sealInProject(1000) : bottleFillerProject(50);
  const server = await preview({ build: { outDir: dist }, preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'warn' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('no port');
  const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, args: [...CHROMIUM_ARGS, '--disable-gpu-vsync', '--disable-frame-rate-limit'], headless: true });
  try {
    const context = await browser.newContext({ viewport: { width: 1440, height: 900 }, permissions: ['clipboard-read', 'clipboard-write'] });
    const page = await context.newPage();
    await page.goto(`http://127.0.0.1:${address.port}/`);
    await page.getByTestId('ladder-canvas').waitFor();
    await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
    if (process.env.PRE_PRINT) {
      // What bench:editor does first: the 1,000-network project, its print preview opened and closed.
      await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), sealInProject(1000));
      await page.evaluate(() => new Promise((r) => setTimeout(r, 1500)));
      await page.keyboard.press('Control+p');
      await page.getByTestId('print-dialog').waitFor();
      await page.getByTestId('print-preview').click();
      await page.locator('[data-testid="print-view"][data-ready="true"]').waitFor({ timeout: 60000 });
      await page.getByTestId('print-close').click();
      await page.evaluate(() => new Promise((r) => setTimeout(r, 500)));
    }
    await page.evaluate((p) => {
      window.rungsmith!.documentStore!.getState().loadProject(p);
    }, project);
    await page.evaluate(() => new Promise((r) => setTimeout(r, 1500)));
    if (process.env.PROBE_CSS) await page.addStyleTag({ content: process.env.PROBE_CSS });
    await page.evaluate('window.__name ??= (f) => f');
    const rows: string[] = [];
    const phases: number[][] = [];
    for (let run = 0; run < Number(process.env.RUNS ?? 1); run++)
      await interactionFigures(page, Number(process.env.REPEAT ?? 7), async (click) => {
        await page.evaluate(() => {
          const w = window as unknown as { __ph: Record<string, number> };
          w.__ph = {};
          const down = (e: Event) => {
            window.removeEventListener('pointerdown', down, true);
            w.__ph = { ts: e.timeStamp, dispatch: performance.now(), anim: document.getAnimations().filter((a) => a.playState === 'running').length };
            const after = () => {
              window.removeEventListener('pointerdown', after);
              w.__ph.handled = performance.now();
            };
            window.addEventListener('pointerdown', after);
            requestAnimationFrame(() => {
              w.__ph.raf = performance.now();
              setTimeout(() => (w.__ph.timer = performance.now()), 0);
            });
          };
          window.addEventListener('pointerdown', down, true);
        });
        const ms = await click();
        const ph = await page.evaluate(() => (window as unknown as { __ph: Record<string, number> }).__ph);
        const p = [ph.dispatch! - ph.ts!, ph.handled! - ph.dispatch!, ph.raf! - ph.handled!, ph.timer! - ph.raf!, ms, ph.anim!];
        phases.push(p);
        rows.push(p.map((x) => x.toFixed(1).padStart(6)).join(''));
        return ms;
      });
    console.log(' delay handlr  toRAF  frame  total  animations running at the click');
    console.log(rows.join('\n'));
    const med = (i: number) => [...phases.map((p) => p[i]!)].sort((a, b) => a - b)[Math.floor((phases.length - 1) / 2)]!;
    console.log('median ' + [0, 1, 2, 3, 4].map((i) => med(i).toFixed(1)).join(' '));
  } finally {
    await browser.close();
    await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
  }
}
main().catch((e: unknown) => {
  console.error(e);
  process.exit(1);
});
