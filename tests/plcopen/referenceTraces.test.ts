// Reference traces: every case in tests/fixtures/reference is a small PLCopen file of our own
// (CASE.xml), an optional stimulus (CASE.stim.csv, `scan,<inputs>`, sample and hold) and the trace
// the MATIEC reference (the oracle of docs/CORPUS.md: Beremiz's generator + iec2c + a scan driver, 10 ms
// cycle) gives for it (CASE.expected.csv, `scan,time_ms,<watched>`). Rungsmith runs each file as
// `rungsmith simulate CASE.xml --profile openplc --cycle 10ms` does and must give the same values
// scan by scan. A case whose first line of CASE.expected.csv is preceded by `# profile: iec`
// runs under that profile instead. How to add one: docs/CORPUS.md.
import { readFileSync, readdirSync, existsSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { rungsmith } from '../cli/memoryIo';
import { rows, same } from './traceCompare';

const dir = fileURLToPath(new URL('../fixtures/reference/', import.meta.url));
const cases = readdirSync(dir)
  .filter((f) => f.endsWith('.expected.csv'))
  .map((f) => f.slice(0, -'.expected.csv'.length))
  .sort();

describe('traces of the MATIEC reference (tests/fixtures/reference)', () => {
  it('has cases', () => {
    expect(cases.length).toBeGreaterThan(0);
  });

  for (const name of cases) {
    it(name, () => {
      const expectedText = readFileSync(join(dir, `${name}.expected.csv`), 'utf8');
      const profile = /^#\s*profile:\s*(\w+)/m.exec(expectedText)?.[1] ?? 'openplc';
      const expected = rows(expectedText);
      const header = expected[0]!;
      const watch = header.slice(2).join(',');
      const files: Record<string, string> = { 'case.xml': readFileSync(join(dir, `${name}.xml`), 'utf8') };
      const args = ['simulate', 'case.xml', '--scans', String(expected.length - 1), '--cycle', '10ms'];
      args.push('--watch', watch, '--profile', profile);
      const stim = join(dir, `${name}.stim.csv`);
      if (existsSync(stim)) {
        files['stim.csv'] = readFileSync(stim, 'utf8');
        args.push('--inputs', 'stim.csv');
      }
      const run = rungsmith(args, files);
      expect(run.err.split('\n').filter((l) => /^error|rungsmith:/.test(l))).toEqual([]);
      expect(run.code).toBe(0);
      const actual = rows(run.out);
      expect(actual[0]).toEqual(header);
      const differences: string[] = [];
      for (let k = 1; k < expected.length; k++)
        for (let j = 0; j < header.length; j++) {
          const e = expected[k]![j]!;
          const a = actual[k]?.[j] ?? '(missing)';
          if (!same(e, a)) differences.push(`scan ${expected[k]![0]} ${header[j]}: reference ${e}, Rungsmith ${a}`);
        }
      expect(differences.slice(0, 10)).toEqual([]);
      expect(actual.length).toBe(expected.length);
    });
  }
});
