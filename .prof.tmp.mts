import { chromium } from 'playwright-core';
import { preview } from 'vite';
import { CHROMIUM_ARGS, CHROMIUM_PATH } from './tests/e2e/browser';
import { newNetwork, newPou, newProject, variable } from './src/model/factory';
import type { LdElement } from './src/model/elements';
import type { ElementId } from './src/model/ids';
import type { Network, Variable } from './src/model/project';
const networks: Network[] = []; const variables: Variable[] = [];
for (let i = 0; i < 1000; i++) {
  const id = (k: string) => `b${i}_${k}` as ElementId;
  const names = [`Start${i}`, `Stop${i}`, `Guard${i}`, `Motor${i}`];
  for (const n of names) variables.push(variable(n, 'BOOL'));
  const elements: LdElement[] = [
    { kind: 'contact', contact: 'NO', variable: names[0]!, id: id('a'), row: 0, col: 0 },
    { kind: 'contact', contact: 'NC', variable: names[1]!, id: id('b'), row: 0, col: 1 },
    { kind: 'coil', coil: 'COIL', variable: names[3]!, id: id('q'), row: 0, col: 9 },
    ...[2,3,4,5,6,7,8].map((col) => ({ kind: 'link' as const, id: id(`l${col}`), row: 0, col })),
    { kind: 'contact', contact: 'NO', variable: names[3]!, id: id('m'), row: 1, col: 0 },
  ];
  networks.push(newNetwork({ rows: 2, elements, vlinks: [{ row: 0, boundary: 1 }], comment: i % 5 === 0 ? 'a comment' : '' }));
}
const project = newProject('Bench', { pous: [newPou('Main', { networks, variables })] });
const server = await preview({ preview: { port: 0, host: '127.0.0.1' }, logLevel: 'warn' });
const addr = server.httpServer.address() as { port: number };
const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, args: [...CHROMIUM_ARGS, '--disable-gpu-vsync', '--disable-frame-rate-limit'] });
const page = await browser.newPage({ viewport: { width: 1440, height: 900 } });
await page.goto(`http://127.0.0.1:${addr.port}/`);
await page.getByTestId('ladder-canvas').waitFor();
const cdp = await page.context().newCDPSession(page);
await cdp.send('Profiler.enable');
await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
const t = await page.evaluate((p) => { const t0 = performance.now(); window.rungsmith!.documentStore!.getState().loadProject(p as never); return new Promise<number>((r) => requestAnimationFrame(() => setTimeout(() => r(performance.now() - t0), 0))); }, project);
await page.waitForTimeout(2000);
await cdp.send('Profiler.start');
const deltas = await page.evaluate(async () => {
  const el = document.querySelector<HTMLElement>('[data-testid="ladder-canvas"]')!;
  const d: number[] = [];
  let last = await new Promise<number>((r) => requestAnimationFrame(r));
  for (let n = 0; n < 300; n++) { el.scrollTop += 40; const t = await new Promise<number>((r) => requestAnimationFrame(r)); d.push(Math.round(t - last)); last = t; }
  return d;
});
console.log(deltas.join(' '));
const { profile } = await cdp.send('Profiler.stop');
console.log('first', t);
const self = new Map<string, number>();
const dt = profile.timeDeltas!; const samples = profile.samples!;
const byId = new Map(profile.nodes.map((n) => [n.id, n]));
samples.forEach((s, i) => { const n = byId.get(s)!; const k = `${n.callFrame.functionName || '(anon)'} ${n.callFrame.url.split('/').pop()}:${n.callFrame.lineNumber}`; self.set(k, (self.get(k) ?? 0) + (dt[i] ?? 0) / 1000); });
console.log([...self.entries()].sort((a, b) => b[1] - a[1]).slice(0, 25).map(([k, v]) => `${v.toFixed(0)}ms ${k}`).join('\n'));
await browser.close(); server.httpServer.close();
