// Where the editor's time goes: loads a generated project into the built app in Chromium, records
// Chromium's sampling profiler (CDP Profiler) around the first render and around a series of edits,
// and prints the functions with the most self time. For finding causes; the figures are bench:editor's.
// `npx vite build --outDir /tmp/x --minify false && RUNGSMITH_DIST=/tmp/x npx tsx bench/editorProfile.ts [load|edit|select|undo|all] [bottle]`
import { existsSync, writeFileSync } from 'node:fs';
import { chromium, type CDPSession } from 'playwright-core';
import { preview } from 'vite';
import { CHROMIUM_ARGS, CHROMIUM_PATH } from '../tests/e2e/browser';
import { sealInProject } from '../tests/e2e/sealInProject';
import type { Project } from '../src/model/project';
import { bottleFillerProject } from './bottleFiller';
import { cellOnScreen, interactionFigures, runningFrameP95, timed } from './editorInteractions';

interface ProfileNode {
  id: number;
  callFrame: { functionName: string; url: string; lineNumber: number; columnNumber: number };
  hitCount?: number;
  children?: number[];
}
interface Profile {
  nodes: ProfileNode[];
  samples: number[];
  timeDeltas: number[];
  startTime: number;
  endTime: number;
}

/** Self ms per function (name, file, line), and total ms per function on the stack. */
function summarize(p: Profile, top = Number(process.env.TOP ?? 35)): string {
  const byId = new Map(p.nodes.map((n) => [n.id, n]));
  const parent = new Map<number, number>();
  for (const n of p.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
  const self = new Map<string, number>();
  const total = new Map<string, number>();
  const key = (n: ProfileNode) =>
    `${n.callFrame.functionName || '(anon)'} ${n.callFrame.url.split('/').pop()}:${n.callFrame.lineNumber + 1}`;
  const focus = process.env.FOCUS;
  const under = (n: ProfileNode | undefined): boolean => {
    for (; n; n = byId.get(parent.get(n.id) ?? -1)) if (n.callFrame.functionName === focus) return true;
    return false;
  };
  for (let i = 0; i < p.samples.length; i++) {
    const dt = (p.timeDeltas[i + 1] ?? 0) / 1000;
    let n = byId.get(p.samples[i]!);
    if (!n) continue;
    if (focus && !under(n)) continue;
    self.set(key(n), (self.get(key(n)) ?? 0) + dt);
    const seen = new Set<string>();
    for (; n; n = byId.get(parent.get(n.id) ?? -1)) {
      const k = key(n);
      if (seen.has(k)) continue;
      seen.add(k);
      total.set(k, (total.get(k) ?? 0) + dt);
    }
  }
  const fmt = (m: Map<string, number>) =>
    [...m]
      .sort((a, b) => b[1] - a[1])
      .slice(0, top)
      .map(([k, v]) => `${v.toFixed(1).padStart(8)} ms  ${k}`)
      .join('\n');
  return `SELF\n${fmt(self)}\nTOTAL\n${fmt(total)}`;
}

interface TraceEvent { name: string; ph: string; dur?: number; tdur?: number; tid: number; pid: number; args?: { name?: string } }

/** With TRACE=1: Chromium's timeline instead of the JS profiler, ms per event name on the renderer's main thread. */
async function traced(cdp: CDPSession, name: string, fn: () => Promise<unknown>) {
  const events: TraceEvent[] = [];
  cdp.on('Tracing.dataCollected', (e) => {
    events.push(...(e.value as unknown as TraceEvent[]));
  });
  const done = new Promise<void>((r) => cdp.once('Tracing.tracingComplete', () => r()));
  await cdp.send('Tracing.start', { traceConfig: { includedCategories: ['devtools.timeline', 'disabled-by-default-devtools.timeline'] } } as never);
  const r = await fn();
  await cdp.send('Tracing.end');
  await done;
  const main = events.find((e) => e.name === 'thread_name' && e.args?.name === 'CrRendererMain');
  // Wall time and the thread's own CPU time (tdur: what a busy machine does not inflate by waiting for a core).
  const sums = new Map<string, { dur: number; cpu: number }>();
  for (const e of events)
    if (main && e.tid === main.tid && e.pid === main.pid && e.ph === 'X' && e.dur) {
      const s = sums.get(e.name) ?? { dur: 0, cpu: 0 };
      s.dur += e.dur / 1000;
      s.cpu += (e.tdur ?? 0) / 1000;
      sums.set(e.name, s);
    }
  console.log(`==== ${name} (trace, wall ms / thread CPU ms): ${JSON.stringify(r)}`);
  for (const [k, v] of [...sums].sort((a, b) => b[1].dur - a[1].dur).slice(0, 30))
    console.log(`${v.dur.toFixed(1).padStart(8)} ${v.cpu.toFixed(1).padStart(8)} ms  ${k}`);
}

async function profiled(cdp: CDPSession, name: string, fn: () => Promise<unknown>) {
  if (process.env.TRACE) return traced(cdp, name, fn);
  await cdp.send('Profiler.enable');
  await cdp.send('Profiler.setSamplingInterval', { interval: Number(process.env.INTERVAL ?? 200) });
  await cdp.send('Profiler.start');
  const r = await fn();
  const { profile } = (await cdp.send('Profiler.stop')) as unknown as { profile: Profile };
  writeFileSync(`/tmp/prof/${name}.cpuprofile`, JSON.stringify(profile));
  console.log(`==== ${name}: ${JSON.stringify(r)}\n${summarize(profile)}`);
}

async function main() {
  const dist = process.env.RUNGSMITH_DIST ?? 'dist';
  const what = process.argv[2] ?? 'all';
  const project: Project = process.argv[3] === 'bottle' ? bottleFillerProject(50) : sealInProject(1000);
  if (!existsSync(`${dist}/index.html`)) throw new Error(`${dist}/ is missing`);
  const server = await preview({ build: { outDir: dist }, preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'warn' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('no port');
  const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, args: [...CHROMIUM_ARGS, '--disable-gpu-vsync', '--disable-frame-rate-limit'], headless: true });
  try {
    const context = await browser.newContext({ viewport: { width: 1440, height: 900 }, permissions: ['clipboard-read', 'clipboard-write'] });
    const page = await context.newPage();
    const cdp = await page.context().newCDPSession(page);
    await page.goto(`http://127.0.0.1:${address.port}/`);
    await page.getByTestId('ladder-canvas').waitFor();
    await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
    await page.evaluate((p) => ((window as unknown as { __p: Project }).__p = p), project);
    const load = () =>
      page.evaluate(() => {
        const store = window.rungsmith!.documentStore!.getState();
        const t0 = performance.now();
        store.loadProject((window as unknown as { __p: Project }).__p);
        return new Promise<number>((resolve) => requestAnimationFrame(() => setTimeout(() => resolve(performance.now() - t0), 0)));
      });
    if (what === 'load' || what === 'all') await profiled(cdp, 'load', load);
    else await load();
    await page.evaluate(() => new Promise((r) => setTimeout(r, 2000)));
    if (what === 'edit' || what === 'all')
      await profiled(cdp, 'edit', () =>
        page.evaluate(async () => {
          const doc = window.rungsmith!.documentStore!;
          const times: number[] = [];
          for (let k = 0; k < 10; k++) {
            const s = doc.getState();
            const target = s.project.pous[0]!.networks[1]!;
            const t0 = performance.now();
            s.insertInSeries(target.id, { row: 0, col: 1 }, { kind: 'contact', contact: 'NO', variable: `Extra${k}` });
            await new Promise<void>((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
            times.push(performance.now() - t0);
            await new Promise((r) => setTimeout(r, 30));
          }
          return times.map(Math.round);
        }),
      );
    if (what === 'select' || what === 'commit' || what === 'undo') {
      const count = project.pous[0]!.networks.length;
      const points = [];
      for (let k = 0; k < 6; k++) points.push(await cellOnScreen(page, Math.floor(((k + 0.5) * count) / 6), 0, 0));
      const p = points[3]!;
      if (what === 'select')
        await profiled(cdp, 'select', async () => {
          const out: number[] = [];
          // The same network in view: select its contact, then another cell, alternately.
          for (let k = 0; k < 8; k++) out.push(await timed(page, 'pointerdown', () => page.mouse.click(p.x + (k % 2) * 60, p.y)));
          return out.map(Math.round);
        });
      else if (what === 'undo') {
        const out: number[] = [];
        await cdp.send('Profiler.enable');
        await cdp.send('Profiler.setSamplingInterval', { interval: Number(process.env.INTERVAL ?? 200) });
        const profiles: Profile[] = [];
        for (let k = 0; k < 6; k++) {
          await page.mouse.click(points[k]!.x, points[k]!.y);
          await page.waitForTimeout(100);
          await timed(page, 'keydown', () => page.keyboard.press('Enter'), { editorOpen: true });
          await page.keyboard.press('Control+a');
          await page.keyboard.type(`Prof${k}`);
          await page.waitForTimeout(100);
          await timed(page, 'keydown', () => page.keyboard.press('Enter'), { declared: `Prof${k}` });
          await page.waitForTimeout(200);
          await cdp.send('Profiler.start');
          out.push(await timed(page, 'keydown', () => page.keyboard.press('Control+z'), { notDeclared: `Prof${k}` }));
          profiles.push(((await cdp.send('Profiler.stop')) as unknown as { profile: Profile }).profile);
          await page.waitForTimeout(100);
        }
        profiles.forEach((pr, i) => writeFileSync(`/tmp/prof/undo${i}.cpuprofile`, JSON.stringify(pr)));
        console.log(`==== undo: ${JSON.stringify(out.map(Math.round))}\n${summarize(profiles[profiles.length - 1]!)}`);
      } else {
        await page.mouse.click(p.x, p.y);
        await profiled(cdp, 'commit', async () => {
          const out: number[] = [];
          for (let k = 0; k < 4; k++) {
            await timed(page, 'keydown', () => page.keyboard.press('Enter'), { editorOpen: true });
            await page.keyboard.press('Control+a');
            await page.keyboard.type(`Prof${k}`);
            await page.waitForTimeout(100);
            out.push(await timed(page, 'keydown', () => page.keyboard.press('Enter'), { declared: `Prof${k}` }));
            await page.waitForTimeout(100);
            out.push(await timed(page, 'keydown', () => page.keyboard.press('Control+z'), { notDeclared: `Prof${k}` }));
            await page.waitForTimeout(100);
            await page.mouse.click(p.x, p.y);
          }
          return out.map(Math.round);
        });
      }
    }
    if (what === 'interact') await profiled(cdp, 'interact', () => interactionFigures(page, 3));
    if (what === 'running') await profiled(cdp, 'running', () => runningFrameP95(page));
  } finally {
    await browser.close();
    await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
  }
}

main().catch((e: unknown) => {
  console.error(e);
  process.exit(1);
});
