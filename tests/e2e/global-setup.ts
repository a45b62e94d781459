// Starts the server `npm start` starts (bin/rungsmith-gateway.mjs: the gateway's static server with
// its CSP and headers, /io and the simulated device) on free loopback ports, serving the built app
// (dist/), and checks for Chromium. Browser tests therefore run the app exactly as users get it.
// One server per worker (vitest.e2e.config.ts runs one file at a time; `--maxWorkers=2` two), and a
// file only ever talks to its own worker's server (appPage.ts appUrl(), simModbusPort()), so the
// files of one worker see one server one after another exactly as in a run of one file at a time.
// It also starts the one Chromium the test files connect to (appPage.ts useChromium); each file
// opens its pages in contexts of its own.
import { spawn, type ChildProcess } from 'node:child_process';
import { existsSync } from 'node:fs';
import type { TestProject } from 'vitest/node';
import type { BrowserServer } from 'playwright-core';
import { CHROMIUM_PATH, launchChromiumServer } from './browser';

const servers: ChildProcess[] = [];
let chromium: BrowserServer | undefined;

/** Waits for the line the gateway prints when it is ready: "Rungsmith gateway: open http://127.0.0.1:PORT/#token=…". */
function startServer(): Promise<{ child: ChildProcess; url: string; simModbusPort: number }> {
  return new Promise((resolve, reject) => {
    const child = spawn(process.execPath, ['bin/rungsmith-gateway.mjs', '--port', '0', '--sim-port', '0'], {
      stdio: ['ignore', 'pipe', 'pipe'],
      env: { ...process.env, PORT: '' },
    });
    let out = '';
    let err = '';
    let url: string | undefined;
    let simModbusPort: number | undefined;
    const ready = () => {
      if (url === undefined || simModbusPort === undefined) return;
      clearTimeout(timer);
      resolve({ child, url, simModbusPort });
    };
    const timer = setTimeout(() => {
      child.kill('SIGTERM');
      reject(new Error(`the app server did not print its URL and its simulated device's Modbus port within 60 s\n${err}`));
    }, 60_000);
    child.stdout?.setEncoding('utf8');
    child.stderr?.setEncoding('utf8');
    // The simulated device's Modbus server: "[gateway] simulated I/O device (…), Modbus TCP on 127.0.0.1:PORT".
    child.stderr?.on('data', (d: string) => {
      err += d;
      const m = /simulated I\/O device .*Modbus TCP on 127\.0\.0\.1:(\d+)/.exec(err);
      if (m && simModbusPort === undefined) {
        simModbusPort = Number(m[1]);
        ready();
      }
    });
    child.stdout?.on('data', (d: string) => {
      out += d;
      const m = /open (http:\/\/127\.0\.0\.1:\d+\/#token=\S+)/.exec(out);
      if (m && url === undefined) {
        url = m[1]!;
        ready();
      }
    });
    child.once('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`the app server exited (${code}) before it was ready\n${err}`));
    });
  });
}

export async function setup(project: TestProject) {
  if (!existsSync(CHROMIUM_PATH)) {
    throw new Error(
      `Chromium not found at ${CHROMIUM_PATH}. Browser tests need Debian's chromium: run "sudo apt-get install -y chromium" (never "npx playwright install").`,
    );
  }
  if (!existsSync('dist/index.html')) throw new Error('dist/ is missing: run "npm run build" (npm run test:e2e does it).');
  const workers = Math.max(1, project.config.maxWorkers || 1);
  try {
    const [started] = await Promise.all([
      Promise.all(
        Array.from({ length: workers }, async () => {
          const s = await startServer();
          servers.push(s.child);
          return s;
        }),
      ),
      launchChromiumServer().then((c) => (chromium = c)),
    ]);
    project.provide(
      'appUrls',
      started.map((s) => s.url),
    );
    project.provide(
      'simModbusPorts',
      started.map((s) => s.simModbusPort),
    );
    project.provide('browserWsEndpoint', chromium!.wsEndpoint());
  } catch (e) {
    await teardown();
    throw e;
  }
}

export async function teardown() {
  await chromium?.close();
  await Promise.all(
    servers.splice(0).map(
      (child) =>
        new Promise<void>((resolve) => {
          if (child.exitCode !== null || child.signalCode !== null) return resolve();
          child.once('exit', () => resolve());
          child.kill('SIGTERM');
        }),
    ),
  );
}

declare module 'vitest' {
  export interface ProvidedContext {
    /** Per worker (VITEST_POOL_ID 1, 2, …), the URL its app server printed: http://127.0.0.1:PORT/#token=…; read it with appPage.ts appUrl(). */
    appUrls: string[];
    /** Per worker, the Modbus TCP port of its app server's simulated I/O device (127.0.0.1); appPage.ts simModbusPort(). */
    simModbusPorts: number[];
    /** Where the run's Chromium listens (playwright's browser server). */
    browserWsEndpoint: string;
  }
}
