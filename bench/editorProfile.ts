// Where the editor's time goes: loads a generated project into the built app in Chromium, records
// Chromium's sampling profiler (CDP Profiler) around the first render and around a series of edits,
// and prints the functions with the most self time. For finding causes; the figures are bench:editor's.
// `npx vite build --outDir /tmp/x --minify false && RUNGSMITH_DIST=/tmp/x npx tsx bench/editorProfile.ts [load|edit|select|undo|clicks|interact|afterundo|benchselect|all] [bottle]`
// Switches: TRACE=1 (Chromium trace instead of the JS profiler; TIMELINE=1 prints each click's events
// per thread), TRACE_CATS=a,b (more trace categories, e.g. v8,disabled-by-default-v8.compile),
// TRACE_OUT=file (the events as JSON), JS_FLAGS="--trace-opt --trace-deopt" (V8 flags; with
// DEBUG=pw:browser its log shows), STYLE=css (added to the page). benchselect: RUNS, REPEAT; TAIL_MS=n
// traces n ms of the page after the scroll instead of the click (what the scroll leaves running),
// TAIL_DELAY=n waits n ms after the scroll first.
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
function summarize(p: Profile | readonly Profile[], top = Number(process.env.TOP ?? 35)): string {
  const self = new Map<string, number>();
  const total = new Map<string, number>();
  for (const one of Array.isArray(p) ? p : [p]) addUp(one as Profile, self, total);
  const fmt = (m: Map<string, number>) =>
    [...m]
      .sort((a, b) => b[1] - a[1])
      .slice(0, top)
      .map(([k, v]) => `${v.toFixed(1).padStart(8)} ms  ${k}`)
      .join('\n');
  return `SELF\n${fmt(self)}\nTOTAL\n${fmt(total)}`;
}

function addUp(p: Profile, self: Map<string, number>, total: Map<string, number>) {
  const byId = new Map(p.nodes.map((n) => [n.id, n]));
  const parent = new Map<number, number>();
  for (const n of p.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
  const key = (n: ProfileNode) =>
    `${n.callFrame.functionName || '(anon)'} ${n.callFrame.url.split('/').pop()}:${n.callFrame.lineNumber + 1}`;
  const focus = process.env.FOCUS;
  const under = (n: ProfileNode | undefined): boolean => {
    for (; n; n = byId.get(parent.get(n.id) ?? -1)) if (n.callFrame.functionName === focus) return true;
    return false;
  };
  for (let i = 0; i < p.samples.length; i++) {
    // COUNT=1: every sample counts its interval (a sampler starved of a core gives a few huge deltas).
    const dt = process.env.COUNT ? Number(process.env.INTERVAL ?? 200) / 1000 : (p.timeDeltas[i + 1] ?? 0) / 1000;
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
}

interface TraceEvent { name: string; ph: string; ts: number; dur?: number; tdur?: number; tid: number; pid: number; args?: { name?: string; data?: { type?: string; functionName?: string; lineNumber?: number } } }

/** Thread CPU per thread (the outermost events' tdur, so nested events count once), busiest first. */
function threadTotals(events: readonly TraceEvent[]): string {
  const names = new Map<string, string>();
  for (const e of events) if (e.name === 'thread_name' && e.args?.name) names.set(`${e.pid}:${e.tid}`, e.args.name);
  const byThread = new Map<string, TraceEvent[]>();
  for (const e of events)
    if (e.ph === 'X' && e.dur !== undefined) {
      const k = `${e.pid}:${e.tid}`;
      const list = byThread.get(k) ?? [];
      list.push(e);
      byThread.set(k, list);
    }
  const out: [string, number, number][] = [];
  for (const [k, list] of byThread) {
    list.sort((a, b) => a.ts - b.ts);
    let end = -Infinity;
    let wall = 0;
    let cpu = 0;
    for (const e of list) {
      if (e.ts < end) continue;
      end = e.ts + e.dur!;
      wall += e.dur! / 1000;
      cpu += (e.tdur ?? 0) / 1000;
    }
    out.push([names.get(k) ?? k, wall, cpu]);
  }
  return out
    .sort((a, b) => b[2] - a[2])
    .filter((t) => t[2] >= 0.5)
    .map(([n, w, c]) => `${w.toFixed(1).padStart(8)} ${c.toFixed(1).padStart(8)} ms  thread ${n}`)
    .join('\n');
}

/** Chromium's timeline events recorded while `fn` runs. */
async function recordTrace<T>(cdp: CDPSession, fn: () => Promise<T>): Promise<{ r: T; events: TraceEvent[] }> {
  const events: TraceEvent[] = [];
  const collect = (e: { value: unknown }) => {
    events.push(...(e.value as TraceEvent[]));
  };
  cdp.on('Tracing.dataCollected', collect);
  const done = new Promise<void>((r) => cdp.once('Tracing.tracingComplete', () => r()));
  await cdp.send('Tracing.start', { traceConfig: { includedCategories: ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'toplevel', 'viz', 'cc', ...(process.env.TRACE_CATS ? process.env.TRACE_CATS.split(',') : [])] } } as never);
  const r = await fn();
  await cdp.send('Tracing.end');
  await done;
  cdp.off('Tracing.dataCollected', collect);
  return { r, events };
}

/** With TRACE=1: Chromium's timeline instead of the JS profiler, ms per event name on the renderer's main thread. */
async function traced(cdp: CDPSession, name: string, fn: () => Promise<unknown>) {
  const { r, events } = await recordTrace(cdp, fn);
  printTrace(name, r, events);
  // TIMELINE=1: every click's events, from its pointerdown.
  if (process.env.TIMELINE)
    for (const down of events.filter((e) => e.name === 'EventDispatch' && e.args?.data?.type === 'pointerdown'))
      console.log(`pointerdown\n${timeline(events, down)}`);
}

function printTrace(name: string, r: unknown, events: readonly TraceEvent[]) {
  const main = events.find((e) => e.name === 'thread_name' && e.args?.name === 'CrRendererMain');
  // Wall time and the thread's own CPU time (tdur: what a busy machine does not inflate by waiting for a core).
  const sums = new Map<string, { dur: number; cpu: number }>();
  for (const e of events)
    if (main && e.tid === main.tid && e.pid === main.pid && e.ph === 'X' && e.dur) {
      // An input's handling by its type (pointerdown, click, …); a script by what ran it.
      const data = e.args?.data;
      const key =
        e.name === 'EventDispatch' && data?.type
          ? `EventDispatch ${data.type}`
          : e.name === 'FunctionCall' && data?.functionName !== undefined
            ? `FunctionCall ${data.functionName || '(anon)'}:${data.lineNumber ?? ''}`
            : e.name;
      const s = sums.get(key) ?? { dur: 0, cpu: 0 };
      s.dur += e.dur / 1000;
      s.cpu += (e.tdur ?? 0) / 1000;
      sums.set(key, s);
    }
  console.log(`==== ${name} (trace, wall ms / thread CPU ms): ${JSON.stringify(r)}`);
  for (const [k, v] of [...sums].sort((a, b) => b[1].dur - a[1].dur).slice(0, 30))
    console.log(`${v.dur.toFixed(1).padStart(8)} ${v.cpu.toFixed(1).padStart(8)} ms  ${k}`);
  console.log(threadTotals(events));
}

/** Installed before the app: counts the components each commit rendered, while window.__rr is set. */
function reactRendersHook() {
  interface Fiber {
    tag: number;
    type: { name?: string; displayName?: string; type?: { name?: string }; render?: { name?: string } } | string | null;
    child: Fiber | null;
    sibling: Fiber | null;
    alternate: Fiber | null;
    memoizedProps: unknown;
    memoizedState: unknown;
    actualStartTime?: number;
    selfBaseDuration?: number;
  }
  const w = window as unknown as { __rr?: Map<string, { n: number; ms: number }>; __REACT_DEVTOOLS_GLOBAL_HOOK__?: unknown };
  const name = (f: Fiber) => {
    const t = f.type;
    if (!t || typeof t === 'string') return undefined;
    return t.displayName ?? t.name ?? t.type?.name ?? t.render?.name ?? undefined;
  };
  let id = 0;
  w.__REACT_DEVTOOLS_GLOBAL_HOOK__ = {
    supportsFiber: true,
    renderers: new Map(),
    inject: () => ++id,
    checkDCE: () => {},
    onCommitFiberUnmount: () => {},
    onPostCommitFiberRoot: () => {},
    onCommitFiberRoot: (_id: number, root: { current: Fiber }) => {
      const out = w.__rr;
      (w as unknown as { __rrCommits: number }).__rrCommits = ((w as unknown as { __rrCommits?: number }).__rrCommits ?? 0) + 1;
      if (!out) return;
      const start = root.current.actualStartTime ?? 0;
      const walk = (f: Fiber | null) => {
        for (; f; f = f.sibling) {
          if ((f.actualStartTime ?? -1) >= start) {
            const a = f.alternate;
            const rendered = !a || a.memoizedProps !== f.memoizedProps || a.memoizedState !== f.memoizedState;
            const n = [0, 1, 11, 14, 15].includes(f.tag) && rendered ? name(f) : undefined;
            if (n) {
              const e = out.get(n) ?? { n: 0, ms: 0 };
              e.n++;
              e.ms += f.selfBaseDuration ?? 0;
              out.set(n, e);
            }
            walk(f.child);
          }
        }
      };
      walk(root.current);
    },
  };
}

/** TIMELINE=1: one click's top-level events per thread, from the pointerdown (ms: start +wall /CPU). */
function timeline(events: readonly TraceEvent[], down = events.find((e) => e.name === 'EventDispatch' && e.args?.data?.type === 'pointerdown')): string {
  const names = new Map<string, string>();
  for (const e of events) if (e.name === 'thread_name' && e.args?.name) names.set(`${e.pid}:${e.tid}`, e.args.name);
  if (!down) return '(no pointerdown)';
  const ends = new Map<string, number>();
  const lines: string[] = [];
  for (const e of [...events].sort((a, b) => a.ts - b.ts)) {
    if (e.ph !== 'X' || e.dur === undefined || e.ts < down.ts - 2000 || e.ts > down.ts + Number(process.env.WINDOW_MS ?? 60) * 1000) continue;
    const k = `${e.pid}:${e.tid}`;
    const sub = e.ts < (ends.get(k) ?? -Infinity);
    if (sub && !['EventDispatch', 'FunctionCall', 'Paint', 'Commit', 'Layout', 'UpdateLayoutTree', 'PrePaint', 'Layerize', 'FireAnimationFrame', 'TimerFire'].includes(e.name)) continue;
    if (!sub) ends.set(k, e.ts + e.dur);
    if (e.dur < (e.name === "Paint" ? 0 : 200)) continue;
    const data = e.args?.data;
    const what =
      data?.type ??
      (data?.functionName !== undefined
        ? `${data.functionName}:${data.lineNumber}`
        : ['Paint', 'Layout', 'UpdateLayoutTree'].includes(e.name) && process.env.TIMELINE === 'paint'
          ? JSON.stringify(e.name === 'Paint' ? data : e.args)
          : '');
    lines.push(`${((e.ts - down.ts) / 1000).toFixed(1).padStart(6)} +${(e.dur / 1000).toFixed(1)} /${((e.tdur ?? 0) / 1000).toFixed(1)}  ${(names.get(k) ?? k).slice(0, 24).padEnd(24)} ${sub ? '  ' : ''}${e.name} ${what}`);
  }
  return lines.join('\n');
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
  const project: Project = process.argv[3] === 'bottle' ? bottleFillerProject(50) : sealInProject(Number(process.env.NETWORKS ?? 1000));
  if (!existsSync(`${dist}/index.html`)) throw new Error(`${dist}/ is missing`);
  const server = await preview({ build: { outDir: dist }, preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'warn' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('no port');
  const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, args: [...CHROMIUM_ARGS, '--disable-gpu-vsync', '--disable-frame-rate-limit', ...(process.env.JS_FLAGS ? [`--js-flags=${process.env.JS_FLAGS}`] : [])], headless: true });
  try {
    const context = await browser.newContext({ viewport: { width: 1440, height: 900 }, permissions: ['clipboard-read', 'clipboard-write'] });
    const page = await context.newPage();
    // REACT_RENDERS=1 with a profiling build of React (react-dom/profiling): which components render
    // per click, and their own render time (the fibers begun in a commit whose props or state changed).
    // (tsx names nested functions through a helper, __name, that the page lacks.)
    if (process.env.REACT_RENDERS) await page.addInitScript({ content: `window.__name ??= (f) => f; (${reactRendersHook.toString()})();` });
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
    // STYLE='css': a diagnostic stylesheet added to the page (what a part of the page costs a click).
    if (process.env.STYLE) await page.addStyleTag({ content: process.env.STYLE });
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
    if (what === 'clicks') {
      // Clicks on the contact of networks spread over the POU, as bench:editor's select-ms does
      // (scrolled there first, like a user), each traced alone: latency and every thread's CPU.
      const count = project.pous[0]!.networks.length;
      const repeats = Number(process.env.REPEAT ?? 12);
      const out: number[] = [];
      const all: TraceEvent[] = [];
      const profiles: Profile[] = [];
      const renders = new Map<string, { n: number; ms: number }>();
      for (let k = 0; k < repeats; k++) {
        const p = await cellOnScreen(page, Math.floor(((k + 0.5) * count) / repeats), 0, 0);
        // PREMOVE=1: the pointer rests on the cell first (a user's hover), so the click is the press alone.
        if (process.env.PREMOVE) await page.mouse.move(p.x, p.y);
        // SETTLE=0 clicks two frames after the scroll, as bench:editor does; else 150 ms later.
        await page.evaluate((ms) => new Promise((r) => setTimeout(r, ms)), Number(process.env.SETTLE ?? 150));
        const click = async () => {
          if (process.env.REACT_RENDERS) await page.evaluate(() => ((window as unknown as { __rr: unknown }).__rr = new Map()));
          const ms = await timed(page, 'pointerdown', () => page.mouse.click(p.x, p.y));
          if (process.env.REACT_RENDERS) {
            const rr = await page.evaluate(() => {
              const w = window as unknown as { __rr?: Map<string, { n: number; ms: number }> };
              const m = [...(w.__rr ?? [])];
              delete w.__rr;
              return m;
            });
            for (const [n, e] of rr) {
              const t = renders.get(n) ?? { n: 0, ms: 0 };
              t.n += e.n;
              t.ms += e.ms;
              renders.set(n, t);
            }
          }
          return ms;
        };
        if (process.env.TRACE) {
          const { r, events } = await recordTrace(cdp, click);
          out.push(r);
          all.push(...events);
          if (process.env.TIMELINE) console.log(`click ${k}: ${Math.round(r * 10) / 10} ms\n${timeline(events)}`);
        } else {
          await cdp.send('Profiler.enable');
          await cdp.send('Profiler.setSamplingInterval', { interval: Number(process.env.INTERVAL ?? 200) });
          await cdp.send('Profiler.start');
          out.push(await click());
          profiles.push(((await cdp.send('Profiler.stop')) as unknown as { profile: Profile }).profile);
        }
        await page.evaluate(() => new Promise((r) => setTimeout(r, 150)));
      }
      if (process.env.REACT_RENDERS) {
        const rr = [...renders];
        console.log(`==== components rendered in ${repeats} clicks (count, own render ms); commits seen ${await page.evaluate(() => (window as unknown as { __rrCommits?: number }).__rrCommits)}`);
        for (const [n, e] of rr.sort((a, b) => b[1].ms - a[1].ms)) console.log(`${String(e.n).padStart(6)} ${e.ms.toFixed(1).padStart(8)} ms  ${n}`);
      }
      const sorted = [...out].sort((a, b) => a - b);
      const r = { median: Math.round(sorted[Math.floor((sorted.length - 1) / 2)]! * 10) / 10, each: out.map(Math.round) };
      if (process.env.TRACE) printTrace('clicks', r, all);
      else console.log(`==== clicks: ${JSON.stringify(r)}\n${summarize(profiles)}`);
    }
    // What the page does in the second after an undo of a commit with declaration, with no input (the
    // work a click that soon after lands on): bench:editor clicks 150 ms after such an undo.
    if (what === 'afterundo') {
      const count = project.pous[0]!.networks.length;
      for (let k = 0; k < Number(process.env.REPEAT ?? 3); k++) {
        const p = await cellOnScreen(page, Math.floor(((k + 0.5) * count) / 3), 0, 0);
        await page.mouse.click(p.x, p.y);
        await page.evaluate(() => new Promise((r) => setTimeout(r, 150)));
        await page.keyboard.press('Enter');
        await page.keyboard.press('Control+a');
        await page.keyboard.type(`After${k}Undo`);
        await page.keyboard.press('Enter');
        await page.evaluate(() => new Promise((r) => setTimeout(r, 150)));
        await page.keyboard.press('Control+z');
        await profiled(cdp, `afterundo${k}`, () => page.evaluate(() => new Promise((r) => setTimeout(r, Number(1000)))));
        await page.evaluate(() => new Promise((r) => setTimeout(r, 1000)));
      }
    }
    // bench:editor's own sequence (select, the same click again, type, commit, undo per network),
    // its select clicks alone traced (TRACE=1) or profiled: what select-ms measures.
    if (what === 'benchselect') {
      const all: TraceEvent[] = [];
      const profiles: Profile[] = [];
      const out: number[] = [];
      // RUNS=2: the sequence twice, the second on code the first has warmed (bench:editor's bottle
      // filler clicks are the first clicks of its page).
      for (let run = 0; run < Number(process.env.RUNS ?? 1); run++)
      await interactionFigures(page, Number(process.env.REPEAT ?? 7), async (click) => {
        let ms: number;
        if (process.env.TRACE) {
          // TAIL_MS: what the page does in that long after the scroll, with no click (traced), then the click (not).
          const tail = Number(process.env.TAIL_MS ?? 0);
          if (process.env.TAIL_DELAY) await page.evaluate((ms) => new Promise((res) => setTimeout(res, ms)), Number(process.env.TAIL_DELAY));
          const { r, events } = tail
            ? await recordTrace(cdp, () => page.evaluate((ms) => new Promise<number>((res) => setTimeout(() => res(ms), ms)), tail))
            : await recordTrace(cdp, click);
          if (tail) await click();
          all.push(...events);
          ms = r;
          if (process.env.TIMELINE) console.log(`click ${out.length}: ${Math.round(r * 10) / 10} ms\n${timeline(events)}`);
        } else {
          await cdp.send('Profiler.enable');
          await cdp.send('Profiler.setSamplingInterval', { interval: Number(process.env.INTERVAL ?? 200) });
          await cdp.send('Profiler.start');
          ms = await click();
          profiles.push(((await cdp.send('Profiler.stop')) as unknown as { profile: Profile }).profile);
        }
        out.push(ms);
        return ms;
      });
      const sorted = [...out].sort((a, b) => a - b);
      const r = { median: Math.round(sorted[Math.floor((sorted.length - 1) / 2)]! * 10) / 10, each: out.map(Math.round) };
      if (process.env.TRACE_OUT) writeFileSync(process.env.TRACE_OUT, JSON.stringify(all));
      if (process.env.TRACE) printTrace('benchselect', r, all);
      else console.log(`==== benchselect: ${JSON.stringify(r)}\n${summarize(profiles)}`);
    }
    if (what === 'interact') await profiled(cdp, 'interact', () => interactionFigures(page, Number(process.env.REPEAT ?? 3)));
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
