import { defineConfig } from 'vitest/config';

// Imports every real PLCopen file in ../shared/plcopen/examples (not needed for a user's npm test).
export default defineConfig({
  test: {
    include: ['tests/interop/**/*.test.ts'],
    environment: 'node',
    testTimeout: 120_000,
  },
});
