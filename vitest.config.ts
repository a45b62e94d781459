import { availableParallelism } from 'node:os';
import { relative } from 'node:path';
import { BaseSequencer, type TestSpecification } from 'vitest/node';
import { defineConfig } from 'vitest/config';

/** Test files of the UI's modules (src/editor, src/store, src/bridge), which hold state of the page. */
const UI_TESTS = ['tests/editor/**/*.test.{ts,tsx}', 'tests/store/**/*.test.{ts,tsx}', 'tests/bridge/**/*.test.{ts,tsx}'];

/**
 * The order files start in. Vitest starts the files that took longest last time first (its cache
 * in node_modules/.vite); on a fresh clone it has no cache and starts the largest files first. Then
 * the gateway tests, which run real processes and mostly wait on them (tests/gateway/faultInjection:
 * about 2 minutes of 52 runs), come first here, so they run beside the other files instead of last.
 */
class WaitingFilesFirst extends BaseSequencer {
  override async sort(files: TestSpecification[]): Promise<TestSpecification[]> {
    const sorted = await super.sort(files);
    const cache = this.ctx.cache;
    const known = (f: TestSpecification) => cache.getFileTestResults(`${f.project.name}:${relative(this.ctx.config.root, f.moduleId)}`) !== undefined;
    if (sorted.every(known)) return sorted;
    const waiting = (f: TestSpecification) => /[\\/]tests[\\/]gateway[\\/]/.test(f.moduleId);
    return [...sorted.filter(waiting), ...sorted.filter((f) => !waiting(f))];
  }
}

// Unit and integration tests (Node). Browser journeys live in vitest.e2e.config.ts.
export default defineConfig({
  test: {
    exclude: ['tests/e2e/**', 'tests/interop/**', 'node_modules/**'],
    environment: 'node',
    testTimeout: 30_000,
    // At least two files at a time, also on 2 cores (Vitest's default there is one): many files
    // wait on child processes and timers, and the long fault-injection run then overlaps the rest.
    maxWorkers: Math.max(2, availableParallelism() - 1),
    sequence: { sequencer: WaitingFilesFirst },
    projects: [
      {
        // The layers below the UI (model, engine, plcopen, protocol, sim, cli, gateway) keep no state
        // in their modules but caches of pure functions, so a worker keeps one module cache for
        // all its files: each file does not import the engine and the PLCopen code again (about
        // 2 of the 4 minutes the unit tests took on a busy 2-core machine).
        extends: true,
        test: {
          name: 'unit',
          include: ['tests/**/*.test.ts', 'tests/**/*.test.tsx'],
          exclude: ['tests/e2e/**', 'tests/interop/**', 'node_modules/**', ...UI_TESTS],
          isolate: false,
        },
      },
      {
        // The editor's, the stores' and the bridge's modules hold state of the page (clipboard,
        // drafts, autosave stamps, workers): each of these files gets modules of its own.
        extends: true,
        test: { name: 'unit-ui', include: UI_TESTS, isolate: true },
      },
    ],
  },
});
