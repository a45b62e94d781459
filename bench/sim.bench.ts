// bench:sim — the simulator in a real Chromium on the built app (vite preview on 127.0.0.1):
// 1. scans per second the worker achieves at a 0 ms cycle on a generated 1,000-network program;
// 2. how well it keeps a 10 ms cycle on that program;
// 3. frame times (requestAnimationFrame deltas, median and p95) while it runs with the canvas visible,
//    for the 1,000-network program and a 200-network one.
// 4. the cost of a machine in closed loop (the tank, issue 26) per scan of a 100-network program (plantFigures.ts).
//    and the machine's history: bytes per recorded scan, time to show a recorded scan's machine.
// Last line: `bench:sim scans-per-s=<n> p95-frame-ms=<n> history-overhead-pct=<n> seek-ms=<n> search-ms=<n> plant-us=<n> plant-pct=<n> plant-history-bytes=<n> plant-moving-us=<n> plant-moving-pct=<n>`
// (p95 of the 1,000-network run; scan history on a 100-network program in Node, see historyFigures.ts:
// seek-ms the slowest of 300 seeks, search-ms the slowest search replaying all 100,000 scans).
import { existsSync } from 'node:fs';
import type { Page } from 'playwright-core';
import { preview } from 'vite';
import { checkProject } from '../src/engine/check';
import type { Project } from '../src/model/project';
import { launchChromium } from '../tests/e2e/browser';
import { describeHistoryFigures, historyFigures } from './historyFigures';
import { generateSimProgram } from './simProgram';
import { describePlantFigures, describePlantHistoryFigures, plantFigures, plantHistoryFigures } from './plantFigures';

const MEASURE_MS = 4000;

interface Handle {
  documentStore: { getState(): { loadProject(p: Project): void; project: Project } };
  simStore: { getState(): SimLike };
}
interface SimLike {
  scan: number;
  mode: string;
  overruns: number;
  exec: { lastMs: number; avgMs: number; maxMs: number };
  run(p: Project): void;
  pause(): void;
  reset(): void;
  setCycle(ms: number): void;
  toggleTrend(name: string): void;
}
declare const window: { rungsmith: Handle };

const percentile = (sorted: number[], p: number) => sorted[Math.min(sorted.length - 1, Math.floor(p * sorted.length))] ?? NaN;

async function load(page: Page, project: Project) {
  await page.evaluate((p) => {
    const sim = window.rungsmith.simStore.getState();
    sim.reset();
    window.rungsmith.documentStore.getState().loadProject(p);
  }, project);
}

async function startRun(page: Page, cycleMs: number) {
  await page.evaluate((cycle) => {
    const sim = window.rungsmith.simStore.getState();
    sim.setCycle(cycle);
    sim.run(window.rungsmith.documentStore.getState().project);
  }, cycleMs);
  await page.waitForFunction(() => window.rungsmith.simStore.getState().scan > 20, undefined, { timeout: 30_000 });
}

async function scanRate(page: Page): Promise<{ scansPerS: number; overruns: number; execAvgMs: number }> {
  const a = await page.evaluate(() => ({ scan: window.rungsmith.simStore.getState().scan, t: performance.now() }));
  await page.waitForTimeout(MEASURE_MS);
  const b = await page.evaluate(() => {
    const s = window.rungsmith.simStore.getState();
    return { scan: s.scan, t: performance.now(), overruns: s.overruns, execAvgMs: s.exec.avgMs };
  });
  return { scansPerS: ((b.scan - a.scan) * 1000) / (b.t - a.t), overruns: b.overruns, execAvgMs: b.execAvgMs };
}

async function frameTimes(page: Page): Promise<{ median: number; p95: number; max: number; frames: number }> {
  // A string, not a function: tsx would wrap named arrow functions in a helper the page lacks.
  const deltas = (await page.evaluate(`new Promise((resolve) => {
    const out = [];
    let last = performance.now();
    const end = last + ${MEASURE_MS};
    const tick = (t) => {
      out.push(t - last);
      last = t;
      if (t < end) requestAnimationFrame(tick);
      else resolve(out);
    };
    requestAnimationFrame(tick);
  })`)) as number[];
  const sorted = deltas.slice(1).sort((x, y) => x - y);
  return { median: percentile(sorted, 0.5), p95: percentile(sorted, 0.95), max: sorted[sorted.length - 1] ?? NaN, frames: sorted.length };
}

async function main() {
  if (!existsSync('dist/index.html')) throw new Error('dist/ is missing: run "npm run bench:sim" (it builds first)');
  const big = generateSimProgram(1000);
  const small = generateSimProgram(200);
  for (const p of [big, small]) {
    const errors = checkProject(p).filter((d) => d.severity === 'error');
    if (errors.length > 0) throw new Error(`generated program has errors: ${errors[0]!.rule} ${errors[0]!.message}`);
  }
  const server = await preview({ preview: { port: 0, host: '127.0.0.1', strictPort: false }, logLevel: 'warn' });
  const address = server.httpServer.address();
  if (!address || typeof address === 'string') throw new Error('preview server has no port');
  const browser = await launchChromium();
  try {
    const page = await browser.newPage({ viewport: { width: 1600, height: 1000 } });
    await page.goto(`http://127.0.0.1:${address.port}/`);
    await page.waitForFunction(() => Boolean(window.rungsmith?.documentStore && window.rungsmith?.simStore), undefined, { timeout: 30_000 });

    await load(page, big);
    await startRun(page, 0);
    const fast = await scanRate(page);
    console.log(`1,000 networks, 0 ms cycle: ${fast.scansPerS.toFixed(0)} scans/s in the worker (${(1e9 / fast.scansPerS / 1000).toFixed(0)} ns per network per scan, frames included), exec avg ${fast.execAvgMs.toFixed(3)} ms`);
    await page.evaluate(() => window.rungsmith.simStore.getState().pause());

    await startRun(page, 10);
    const paced = await scanRate(page);
    const bigFrames = await frameTimes(page);
    console.log(`1,000 networks, 10 ms cycle: ${paced.scansPerS.toFixed(1)} scans/s (target 100), overruns ${paced.overruns}`);
    console.log(`1,000 networks running, canvas visible: frame median ${bigFrames.median.toFixed(1)} ms, p95 ${bigFrames.p95.toFixed(1)} ms, max ${bigFrames.max.toFixed(1)} ms over ${bigFrames.frames} frames`);
    await page.evaluate(() => window.rungsmith.simStore.getState().pause());

    await load(page, small);
    // Everything visible: the trend of five signals open under the canvas, as a user would have it.
    await page.evaluate(() => {
      const sim = window.rungsmith.simStore.getState();
      for (const name of ['M1', 'M2', 'M3', 'Q0', 'T0.ET']) sim.toggleTrend(name);
    });
    await page.getByRole('tab', { name: 'Trend' }).click();
    await startRun(page, 10);
    const smallFrames = await frameTimes(page);
    const smallPaced = await scanRate(page);
    console.log(`200 networks running, canvas and trend visible: frame median ${smallFrames.median.toFixed(1)} ms, p95 ${smallFrames.p95.toFixed(1)} ms, max ${smallFrames.max.toFixed(1)} ms; ${smallPaced.scansPerS.toFixed(1)} scans/s at 10 ms`);
    await page.evaluate(() => window.rungsmith.simStore.getState().pause());

    const history = historyFigures();
    console.log(describeHistoryFigures(history));
    const plant = plantFigures();
    console.log(describePlantFigures(plant));
    const plantHistory = plantHistoryFigures();
    console.log(describePlantHistoryFigures(plantHistory));
    console.log(
      `bench:sim scans-per-s=${Math.round(fast.scansPerS)} p95-frame-ms=${bigFrames.p95.toFixed(1)} history-overhead-pct=${history.overheadPct.toFixed(0)} seek-ms=${history.seekMaxMs.toFixed(2)} search-ms=${Math.max(history.changeSearchMs, history.conditionSearchMs, history.conditionBackMs).toFixed(0)} plant-us=${plant.plantUs.toFixed(2)} plant-pct=${plant.overheadPct.toFixed(1)} plant-history-bytes=${plantHistory.bytesPerScan.toFixed(1)} plant-moving-us=${plant.movingPlantUs.toFixed(2)} plant-moving-pct=${plant.movingPct.toFixed(1)}`,
    );
  } finally {
    await browser.close();
    await new Promise<void>((resolve) => server.httpServer.close(() => resolve()));
  }
}

main().catch((error: unknown) => {
  console.error(error instanceof Error ? error.message : error);
  process.exit(1);
});
