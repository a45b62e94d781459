import { defineConfig } from 'vitest/config';

// Unit and integration tests (Node). Browser journeys live in vitest.e2e.config.ts.
export default defineConfig({
  test: {
    include: ['tests/**/*.test.ts', 'tests/**/*.test.tsx'],
    exclude: ['tests/e2e/**', 'tests/interop/**', 'node_modules/**'],
    environment: 'node',
    testTimeout: 30_000,
  },
});
