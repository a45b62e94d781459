// Only the Run and online-change figures of bench:editor (bench/onlineChangeFigures.ts), on the
// bottle filler (650 networks) and the 1,000-network project, several runs each, in the built app
// served by vite preview: for comparing two builds run interleaved on a shared machine. Chromium runs
// with its frame rate capped to the display, as a user's does (bench:editor's online-change-overruns);
// UNCAPPED=1 takes the cap off as bench:editor's other figures do (its online-change-overruns-uncapped).
//   npx vite build --outDir /tmp/x && RUNGSMITH_DIST=/tmp/x npx tsx bench/onlineChangeBrowser.ts [runs]
// TRACE=1: Chromium's timeline of each run, and per thread (page, simulator worker, checker worker)
// the CPU it used from the edit to the change applied (the marks oc-edit and oc-applied), with the
// simulator worker's garbage collections: what competed with the scans for the 2 cores.
import { existsSync } from 'node:fs';
import { chromium, type CDPSession, type Page } from 'playwright-core';
import { preview } from 'vite';
import { CHROMIUM_ARGS, CHROMIUM_PATH } from '../tests/e2e/browser';
import { sealInProject } from '../tests/e2e/sealInProject';
import { bottleFillerProject } from './bottleFiller';
import { measureRunAndOnlineChange } from './onlineChangeFigures';

interface TraceEvent {
  name: string;
  cat: string;
  ph: string;
  ts: number;
  dur?: number;
  tdur?: number;
  tid: number;
  pid: number;
  args?: { name?: string };
}

/** Runs `fn` under Chromium's tracing and prints each thread's CPU between the marks oc-edit and oc-applied (+1 s). */
async function traced<T>(cdp: CDPSession, fn: () => Promise<T>): Promise<T> {
  const events: TraceEvent[] = [];
  const onData = (e: { value: unknown }) => events.push(...(e.value as TraceEvent[]));
  cdp.on('Tracing.dataCollected', onData);
  const done = new Promise<void>((r) => cdp.once('Tracing.tracingComplete', () => r()));
  await cdp.send('Tracing.start', {
    traceConfig: { includedCategories: ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'blink.user_timing', 'v8', 'toplevel'] },
  } as never);
  const r = await fn();
  await cdp.send('Tracing.end');
  await done;
  cdp.off('Tracing.dataCollected', onData);
  const names = new Map<string, string>();
  for (const e of events) if (e.name === 'thread_name') names.set(`${e.pid}:${e.tid}`, e.args?.name ?? '?');
  const mark = (n: string) => events.find((e) => e.name === n && e.cat.includes('user_timing'))?.ts;
  const from = mark('oc-edit');
  const applied = mark('oc-applied');
  if (from === undefined || applied === undefined) {
    console.log('  (trace: marks not found)');
    return r;
  }
  for (const [label, to] of [['edit to applied', applied], ['applied to +1 s', applied + 1e6]] as const) {
    const start = label === 'edit to applied' ? from : applied;
    const cpu = new Map<string, { cpu: number; gc: number; longest: number; gcLongest: number; gcs: number }>();
    for (const e of events) {
      if (e.ph !== 'X' || e.ts < start || e.ts > to) continue;
      const key = `${e.pid}:${e.tid}`;
      const t = cpu.get(key) ?? { cpu: 0, gc: 0, longest: 0, gcLongest: 0, gcs: 0 };
      // Top-level tasks only (their nested events are inside them).
      if (e.name === 'ThreadControllerImpl::RunTask' || e.name === 'RunTask') {
        t.cpu += (e.tdur ?? 0) / 1000;
        t.longest = Math.max(t.longest, (e.dur ?? 0) / 1000);
      }
      if (/^(MinorGC|MajorGC|V8\.GC_SCAVENGER$|V8\.GC_MARK_COMPACTOR$|V8\.GCScavenger$|V8\.GCFinalizeMC$)/.test(e.name)) {
        t.gc += (e.dur ?? 0) / 1000;
        t.gcLongest = Math.max(t.gcLongest, (e.dur ?? 0) / 1000);
        t.gcs++;
      }
      cpu.set(key, t);
    }
    const rows = [...cpu]
      .filter(([, t]) => t.cpu > 1 || t.gc > 1)
      .map(([k, t]) => `${(names.get(k) ?? k).padEnd(28)} CPU ${t.cpu.toFixed(0).padStart(5)} ms  GC ${t.gc.toFixed(0).padStart(4)} ms (${t.gcs}, longest ${t.gcLongest.toFixed(1)} ms)  longest task ${t.longest.toFixed(0)} ms`);
    console.log(`  ${label} (${((to - start) / 1000).toFixed(0)} ms):\n    ${rows.join('\n    ')}`);
  }
  return r;
}

/**
 * CONTROL=1: the cycles the same program misses running as long as the figure's window (edit to 1 s
 * after the change) without any change: what the machine's load alone costs.
 */
async function missedWithoutChange(page: Page, windowMs: number): Promise<number> {
  await page.evaluate(() => {
    const sim = (window as unknown as ControlHandle).rungsmith.simStore.getState();
    sim.run((window as unknown as ControlHandle).rungsmith.documentStore.getState().project);
  });
  await page.waitForTimeout(1000);
  const start = await page.evaluate(() => (window as unknown as ControlHandle).rungsmith.simStore.getState().exec.late ?? 0);
  await page.waitForTimeout(windowMs);
  return page.evaluate((s) => {
    const sim = (window as unknown as ControlHandle).rungsmith.simStore.getState();
    const late = (sim.exec.late ?? 0) - s;
    sim.pause();
    return late;
  }, start);
}

interface ControlHandle {
  rungsmith: {
    documentStore: { getState(): { project: unknown } };
    simStore: { getState(): { exec: { late?: number }; run(p: unknown): void; pause(): void } };
  };
}

async function main() {
  const dist = process.env.RUNGSMITH_DIST ?? 'dist';
  const runs = Number(process.argv[2] ?? 3);
  if (!existsSync(`${dist}/index.html`)) throw new Error(`${dist}/ is missing`);
  const server = await preview({ build: { outDir: dist }, preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'warn' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('no port');
  const browser = await chromium.launch({ executablePath: CHROMIUM_PATH, args: process.env.UNCAPPED ? [...CHROMIUM_ARGS, '--disable-gpu-vsync', '--disable-frame-rate-limit'] : CHROMIUM_ARGS, headless: true });
  try {
    const page = await browser.newPage({ viewport: { width: 1440, height: 900 } });
    const cdp = await page.context().newCDPSession(page);
    await page.goto(`http://127.0.0.1:${address.port}/`);
    await page.getByTestId('ladder-canvas').waitFor();
    const out: string[] = [];
    for (const [name, project] of [['bottle650', bottleFillerProject(50)], ['seal1000', sealInProject(1000)]] as const) {
      const missed: number[] = [];
      const applied: number[] = [];
      const control: number[] = [];
      const firstScan: number[] = [];
      for (let r = 0; r < runs; r++) {
        const f = process.env.TRACE ? await traced(cdp, () => measureRunAndOnlineChange(page, project)) : await measureRunAndOnlineChange(page, project);
        missed.push(f.onlineChangeOverruns);
        applied.push(Math.round(f.appliedMs));
        firstScan.push(Math.round(f.runFirstScanMs));
        if (process.env.CONTROL) control.push(await missedWithoutChange(page, f.appliedMs + 1000));
      }
      out.push(`${name}: missed ${missed.join(',')} applied-ms ${applied.join(',')} run-first-scan-ms ${firstScan.join(',')}${control.length ? ` without a change ${control.join(',')}` : ''}`);
      console.log(out[out.length - 1]);
    }
  } finally {
    await browser.close();
    await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
  }
}

main().catch((e: unknown) => {
  console.error(e);
  process.exit(1);
});
