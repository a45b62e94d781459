// The command on a real terminal and file system.
import { readFileSync, writeFileSync } from 'node:fs';
import type { CliIo } from './io';
import { main } from './main';

/** The reader of stdout went away (`rungsmith simulate … | head`): the rest of the output is dropped. */
let readerGone = false;

export const nodeIo: CliIo = {
  out: (t) => {
    if (!readerGone) process.stdout.write(t);
  },
  err: (t) => process.stderr.write(t),
  readFile: (p) => readFileSync(p, 'utf8'),
  writeFile: (p, t) => writeFileSync(p, t),
};

const isBrokenPipe = (e: unknown) =>
  typeof e === 'object' && e !== null && 'code' in e && (e.code === 'EPIPE' || e.code === 'ERR_STREAM_DESTROYED');

export function runFromNode(): void {
  // As Unix tools do, a reader that stops early ends the output quietly (no stack trace); the exit
  // code stays the command's (a failed test is still 1 under `set -o pipefail`).
  process.stdout.on('error', (e) => {
    if (!isBrokenPipe(e)) throw e;
    readerGone = true;
  });
  process.exitCode = main(process.argv.slice(2), nodeIo);
}
