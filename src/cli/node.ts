// The command on a real terminal and file system.
import { readFileSync, writeFileSync } from 'node:fs';
import type { CliIo } from './io';
import { main } from './main';

export const nodeIo: CliIo = {
  out: (t) => process.stdout.write(t),
  err: (t) => process.stderr.write(t),
  readFile: (p) => readFileSync(p, 'utf8'),
  writeFile: (p, t) => writeFileSync(p, t),
};

export function runFromNode(): void {
  process.exitCode = main(process.argv.slice(2), nodeIo);
}
