import { defineConfig } from 'vitest/config';

// End-to-end tests in a real Chromium (playwright-core + Debian's chromium) against the built app.
export default defineConfig({
  test: {
    include: ['tests/e2e/**/*.e2e.test.ts'],
    environment: 'node',
    globalSetup: ['tests/e2e/global-setup.ts'],
    testTimeout: 90_000,
    hookTimeout: 60_000,
    // One file at a time. The global setup starts a server per worker and a file only talks to its
    // own worker's server (appPage.ts appUrl()), so `--maxWorkers=2` runs two files at a time
    // against servers of their own; on a busy 2-core machine (load 20-30) that made the hardware
    // and small-screen journeys miss their deadlines, so it is not the default.
    maxWorkers: 1,
    // One module cache per worker: playwright-core and the helpers are imported once, not per file
    // (about 3 s a file on a busy machine). The files keep no state in shared modules.
    isolate: false,
  },
});
