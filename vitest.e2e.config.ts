import { defineConfig } from 'vitest/config';

// End-to-end tests in a real Chromium (playwright-core + Debian's chromium) against the built app.
export default defineConfig({
  test: {
    include: ['tests/e2e/**/*.e2e.test.ts'],
    environment: 'node',
    globalSetup: ['tests/e2e/global-setup.ts'],
    testTimeout: 90_000,
    hookTimeout: 60_000,
    fileParallelism: false,
    // One module cache for the run: playwright-core and the helpers are imported once, not per file
    // (about 3 s a file on a busy machine). The files keep no state in shared modules.
    isolate: false,
  },
});
