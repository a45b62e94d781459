// The command run in memory: files in a map, stdout/stderr collected.
import { main } from '../../src/cli/main';

export interface Run {
  readonly code: number;
  readonly out: string;
  readonly err: string;
  readonly files: Map<string, string>;
}

export function rungsmith(args: string[], files: Record<string, string> = {}): Run {
  const fs = new Map(Object.entries(files));
  let out = '';
  let err = '';
  const code = main(args, {
    out: (t) => (out += t),
    err: (t) => (err += t),
    readFile: (p) => {
      const t = fs.get(p);
      if (t === undefined) throw Object.assign(new Error(`ENOENT: ${p}`), { code: 'ENOENT' });
      return t;
    },
    writeFile: (p, t) => void fs.set(p, t),
  });
  return { code, out, err, files: fs };
}

/** CSV text → rows of cells (header first). */
export const csv = (text: string): string[][] =>
  text
    .trim()
    .split('\n')
    .map((l) => l.split(','));
