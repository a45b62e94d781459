import { defineConfig } from 'vitest/config';
import { corpusMissingMessage, findCorpus } from './tests/interop/corpusDir';

// npm run test:interop: the import against the real PLCopen corpus (third-party files outside the
// repository: RUNGSMITH_PLCOPEN_CORPUS or ../shared/plcopen/examples). Not needed for npm test.
// Without the corpus it stops at once with one plain message and fails: a run that tested nothing
// must not look like a pass.
const corpus = findCorpus();
if (!corpus.dir) {
  process.stderr.write(`\nnpm run test:interop: ${corpusMissingMessage(corpus.looked)}\n\n`);
  process.exit(1);
}

export default defineConfig({
  test: {
    include: ['tests/interop/**/*.test.ts'],
    environment: 'node',
    testTimeout: 120_000,
  },
});
