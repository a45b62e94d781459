// Where `npm run test:interop` finds the real PLCopen corpus (third-party files, some GPL, kept
// outside the repository): RUNGSMITH_PLCOPEN_CORPUS, else ../shared/plcopen/examples next to the
// repository. `npm test` never reads it; its unit tests use tests/fixtures only.
import { existsSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../..', import.meta.url));

/** The corpus directory, or undefined when it is not there. */
export function findCorpus(): { dir: string | undefined; looked: string } {
  const candidate = process.env.RUNGSMITH_PLCOPEN_CORPUS || join(root, '..', 'shared', 'plcopen', 'examples');
  const dir = resolve(candidate);
  return { dir: existsSync(dir) ? dir : undefined, looked: dir };
}

export const corpusMissingMessage = (looked: string) =>
  `The PLCopen corpus is absent: no directory ${looked}. npm run test:interop tests the import against real ` +
  'third-party PLCopen files, which the repository does not contain; put them in ../shared/plcopen/examples ' +
  'next to the repository or set RUNGSMITH_PLCOPEN_CORPUS to their directory. Nothing was tested. ' +
  '(npm test does not need them.)';

/** The corpus directory; throws the plain message when it is absent. */
export function corpusDir(): string {
  const { dir, looked } = findCorpus();
  if (!dir) throw new Error(corpusMissingMessage(looked));
  return dir;
}

/** The text of one corpus file. */
export const corpusText = (file: string): string => readFileSync(join(corpusDir(), file), 'utf8');
