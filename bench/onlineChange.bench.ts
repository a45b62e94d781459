// bench:online — Run to first scan and the cycles an online change misses, at 650 and 1,000
// networks, in a real Chromium on the built app served by the real server (bin/rungsmith-gateway.mjs,
// with its CSP). Build first (`npx vite build`). To measure another checkout's build (the figures
// before a change), point RUNGSMITH_ROOT at it: its server and its dist/ are used, this file's
// measuring code (bench/onlineChangeFigures.ts).
// Last line: `bench:online run-first-scan-ms=<650>/<1000> online-change-overruns=<650>/<1000>`.
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { resolve } from 'node:path';
import { launchChromium } from '../tests/e2e/browser';
import { measureRunAndOnlineChange, type OnlineChangeFigures } from './onlineChangeFigures';
import { generateSimProgram } from './simProgram';

const root = resolve(process.env.RUNGSMITH_ROOT ?? '.');
const SIZES = [650, 1000];
const RUNS = Number(process.env.RUNS ?? 3);

function startServer(): Promise<{ url: string; stop(): void }> {
  return new Promise((ok, fail) => {
    const child = spawn(process.execPath, [`${root}/bin/rungsmith-gateway.mjs`, '--port', '0', '--sim-port', '0'], {
      cwd: root,
      stdio: ['ignore', 'pipe', 'pipe'],
      env: { ...process.env, PORT: '' },
    });
    let out = '';
    child.stdout.setEncoding('utf8');
    child.stdout.on('data', (d: string) => {
      out += d;
      const m = /open (http:\/\/127\.0\.0\.1:\d+\/#token=\S+)/.exec(out);
      if (m) ok({ url: m[1]!, stop: () => child.kill('SIGTERM') });
    });
    child.once('exit', (code) => fail(new Error(`the server exited (${code}) before printing its URL`)));
  });
}

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)]!;

async function main() {
  if (!existsSync(`${root}/dist/index.html`)) throw new Error(`${root}/dist is missing: run "npx vite build" there first`);
  const server = await startServer();
  const browser = await launchChromium();
  const results: { size: number; runs: OnlineChangeFigures[] }[] = [];
  try {
    const page = await browser.newPage({ viewport: { width: 1440, height: 900 } });
    await page.goto(server.url);
    await page.getByTestId('ladder-canvas').waitFor({ timeout: 60_000 });
    for (const size of SIZES) {
      const project = generateSimProgram(size);
      const runs: OnlineChangeFigures[] = [];
      for (let r = 0; r < RUNS; r++) runs.push(await measureRunAndOnlineChange(page, project));
      results.push({ size, runs });
      const f = (pick: (x: OnlineChangeFigures) => number) => runs.map((x) => Math.round(pick(x))).join(', ');
      console.log(
        `${size} networks: run to first scan ${f((x) => x.runFirstScanMs)} ms; online change: missed cycles at 10 ms ${f((x) => x.onlineChangeOverruns)}` +
          `${runs[0]!.lateCounted ? '' : ' (this build counts only dropped scans)'}, dropped ${f((x) => x.onlineChangeDropped)}, edit to applied ${f((x) => x.appliedMs)} ms`,
      );
    }
  } finally {
    await browser.close();
    server.stop();
  }
  const pick = (k: keyof OnlineChangeFigures) => results.map((r) => Math.round(median(r.runs.map((x) => Number(x[k]))))).join('/');
  console.log(`bench:online (${SIZES.join('/')} networks, median of ${RUNS}) run-first-scan-ms=${pick('runFirstScanMs')} online-change-overruns=${pick('onlineChangeOverruns')}`);
}

main().catch((error: unknown) => {
  console.error(error instanceof Error ? error.message : error);
  process.exit(1);
});
