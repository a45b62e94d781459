// Probe (not a bench): which composited layers bench:editor's scroll-then-click on the bottle filler
// repaints (CDP LayerTree paintCount before and after), then every layer of the page with its size
// and element. `npx vite build && npx tsx bench/layerProbe.ts` (RUNGSMITH_DIST for another build).
import { chromium } from 'playwright-core';
import { preview } from 'vite';
import { CHROMIUM_ARGS, CHROMIUM_PATH } from '../tests/e2e/browser';
import { bottleFillerProject } from './bottleFiller';
import { cellOnScreen, timed } from './editorInteractions';

interface Layer { layerId: string; parentLayerId?: string; backendNodeId?: number; width: number; height: number; paintCount: number; drawsContent: boolean; offsetX: number; offsetY: number }

async function main() {
  const project = bottleFillerProject(50);
  const server = await preview({ build: { outDir: process.env.RUNGSMITH_DIST ?? 'dist' }, preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'warn' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('no port');
  const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, args: [...CHROMIUM_ARGS, '--disable-gpu-vsync', '--disable-frame-rate-limit'], headless: true });
  try {
    const context = await browser.newContext({ viewport: { width: 1440, height: 900 } });
    const page = await context.newPage();
    await page.goto(`http://127.0.0.1:${address.port}/`);
    await page.getByTestId('ladder-canvas').waitFor();
    await page.evaluate((p) => window.rungsmith!.documentStore!.getState().loadProject(p), project);
    await page.evaluate(() => new Promise((r) => setTimeout(r, 1500)));
    const cdp = await context.newCDPSession(page);
    let layers: Layer[] = [];
    cdp.on('LayerTree.layerTreeDidChange', (e: { layers?: Layer[] }) => { if (e.layers) layers = e.layers; });
    await cdp.send('LayerTree.enable');
    await cdp.send('DOM.getDocument', { depth: -1 });
    const describe = async (l: Layer) => {
      if (!l.backendNodeId) return '(no node)';
      try {
        const { node } = (await cdp.send('DOM.describeNode', { backendNodeId: l.backendNodeId })) as { node: { nodeName: string; attributes?: string[] } };
        const a = node.attributes ?? [];
        const cls = a[a.indexOf('class') + 1] ?? '';
        const tid = a.includes('data-testid') ? a[a.indexOf('data-testid') + 1] : '';
        return `${node.nodeName} ${a.indexOf('class') >= 0 ? cls : ''} ${tid ?? ''}`;
      } catch { return '?'; }
    };
    const count = project.pous[0]!.networks.length;
    for (let k = 0; k < 4; k++) {
      const b0 = new Map(layers.map((l) => [l.layerId, l.paintCount]));
      const p = await cellOnScreen(page, Math.floor(((k + 0.5) * count) / 4), 0, 0);
      await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
      console.log(`scroll ${k}: ${layers.length} layers`);
      for (const l of layers) {
        const d = l.paintCount - (b0.get(l.layerId) ?? 0);
        if (d > 0) console.log(`  +${d} ${l.width}x${l.height} ${await describe(l)}`);
      }
      const before = new Map(layers.map((l) => [l.layerId, l.paintCount]));
      const ms = await timed(page, 'pointerdown', () => page.mouse.click(p.x, p.y));
      await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
      console.log(`click ${k}: ${ms.toFixed(1)} ms, ${layers.length} layers`);
      for (const l of layers) {
        const d = l.paintCount - (before.get(l.layerId) ?? 0);
        if (d > 0) console.log(`  +${d} ${l.width}x${l.height} at ${l.offsetX},${l.offsetY} ${await describe(l)}`);
      }
    }
    console.log('all layers (why composited):');
    for (const l of layers) {
      let why = '';
      try {
        why = ((await cdp.send('LayerTree.compositingReasons', { layerId: l.layerId })) as { compositingReasonIds?: string[] }).compositingReasonIds?.join(',') ?? '';
      } catch { why = '?'; }
      console.log(`  ${l.width}x${l.height} at ${l.offsetX},${l.offsetY} ${await describe(l)} [${why}]`);
    }
  } finally {
    await browser.close();
    await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
  }
}
main().catch((e: unknown) => { console.error(e); process.exit(1); });
