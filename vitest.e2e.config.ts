import { defineConfig } from 'vitest/config';

// End-to-end tests in a real Chromium (playwright-core + Debian's chromium) against the built app.
export default defineConfig({
  test: {
    include: ['tests/e2e/**/*.e2e.test.ts'],
    environment: 'node',
    globalSetup: ['tests/e2e/global-setup.ts'],
    testTimeout: 90_000,
    hookTimeout: 60_000,
    // Two files at a time, each worker with a server of its own (global-setup.ts) and every file
    // with browser contexts of its own in the run's one Chromium: a file waits on the page much of
    // the time, and two keep a 2-core machine busy. `--no-file-parallelism` runs one at a time.
    maxWorkers: 2,
    // One module cache per worker: playwright-core and the helpers are imported once, not per file
    // (about 3 s a file on a busy machine). The files keep no state in shared modules.
    isolate: false,
  },
});
