// Differential fuzzer: random LD programs (scripts/fuzzGen.ts) run by the MATIEC reference
// (Beremiz's generator + iec2c, ../shared/tools/oracle) and by `rungsmith simulate --profile openplc`,
// compared scan by scan. docs/fuzz.md says what it covers and how to read its output.
//
//   npx tsx scripts/fuzz.ts --count N --seed S [--oracle /tmp/oracle] [--keep DIR] [--only NAME,...]
import { spawn } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { parseArgs } from 'node:util';
import { main } from '../src/cli/main';
import { rows, same } from '../tests/plcopen/traceCompare';
import { generate, type FuzzCase } from './fuzzGen';

const { values } = parseArgs({
  options: {
    count: { type: 'string', default: '20' },
    seed: { type: 'string', default: '1' },
    start: { type: 'string', default: '0' },
    oracle: { type: 'string', default: '/tmp/oracle' },
    keep: { type: 'string' },
    only: { type: 'string' },
  },
});
const count = Number(values.count);
const seed = Number(values.seed);
const start = Number(values.start);
const oracle = resolve(values.oracle!);
const dir = values.keep ? resolve(values.keep) : mkdtempSync(join(tmpdir(), 'rungsmith-fuzz-'));
mkdirSync(dir, { recursive: true });
const only = values.only ? new Set(values.only.split(',')) : undefined;

/** Our run, in process: the CLI's `simulate` on in-memory files. */
function ours(c: FuzzCase): { code: number; out: string; err: string } {
  const files = new Map([
    ['case.xml', c.xml],
    ['stim.csv', c.stim],
  ]);
  let out = '';
  let err = '';
  let code: number;
  try {
    code = main(
      [
        'simulate',
        'case.xml',
        '--inputs',
        'stim.csv',
        '--scans',
        String(c.scans),
        '--cycle',
        '10ms',
        '--watch',
        c.watch.join(','),
        '--profile',
        'openplc',
      ],
      {
        out: (t) => (out += t),
        err: (t) => (err += t),
        readFile: (p) => {
          const t = files.get(p);
          if (t === undefined) throw Object.assign(new Error(`ENOENT: ${p}`), { code: 'ENOENT' });
          return t;
        },
        writeFile: () => {},
      },
    );
  } catch (e) {
    code = 99;
    err += `crash: ${(e as Error).stack ?? String(e)}`;
  }
  return { code, out, err };
}

/** The first difference of two traces, or undefined when they agree. */
function firstDifference(expected: string, actual: string): string | undefined {
  const e = rows(expected);
  const a = rows(actual);
  const header = e[0] ?? [];
  if ((a[0] ?? []).join(',') !== header.join(','))
    return `header: reference ${header.join(',')}, Rungsmith ${(a[0] ?? []).join(',')}`;
  for (let k = 1; k < e.length; k++)
    for (let j = 2; j < header.length; j++) {
      const x = e[k]![j]!;
      const y = a[k]?.[j] ?? '(missing)';
      if (!same(x, y)) return `scan ${e[k]![0]} ${header[j]}: reference ${x}, Rungsmith ${y}`;
    }
  return a.length === e.length ? undefined : `${a.length - 1} scans, reference ${e.length - 1}`;
}

async function main2(): Promise<void> {
  const cases: FuzzCase[] = [];
  for (let i = start; i < start + count; i++) {
    const c = generate(seed, i);
    if (only && !only.has(c.name)) continue;
    cases.push(c);
    writeFileSync(join(dir, `${c.name}.xml`), c.xml);
    writeFileSync(join(dir, `${c.name}.stim.csv`), c.stim);
  }
  const jobs = cases
    .map((c) => {
      const line = [
        join(dir, `${c.name}.xml`),
        join(dir, `${c.name}.stim.csv`),
        c.watch.join(','),
        String(c.scans),
        join(dir, `${c.name}.expected.csv`),
      ];
      if (values.keep) line.push('--work', join(dir, `${c.name}.work`), '--keep');
      return line.join('\t');
    })
    .join('\n');
  writeFileSync(join(dir, 'JOBS.tsv'), `${jobs}\n`);

  // The reference runs in its own process while we run ours here (two cores).
  const rc = new Map<string, number>();
  const refErr = new Map<string, string>();
  const oracleDone = new Promise<void>((done) => {
    const p = spawn('python3', [join(oracle, 'bin', 'run_oracle.py'), '--batch', join(dir, 'JOBS.tsv')], {
      stdio: ['ignore', 'pipe', 'pipe'],
    });
    let buf = '';
    p.stdout.on('data', (d: Buffer) => {
      buf += d.toString();
      let i;
      while ((i = buf.indexOf('\n')) >= 0) {
        const line = buf.slice(0, i);
        buf = buf.slice(i + 1);
        const m = /^(.*)\.expected\.csv rc=(\d+)$/.exec(line);
        if (m) rc.set(m[1]!.slice(dir.length + 1), Number(m[2]));
      }
    });
    let ebuf = '';
    p.stderr.on('data', (d: Buffer) => {
      ebuf += d.toString();
    });
    p.on('close', () => {
      for (const line of ebuf.split('\n')) {
        const m = /^(s\d+_\d+): (.*)$/.exec(line);
        if (m && !refErr.has(m[1]!)) refErr.set(m[1]!, m[2]!);
        else if (!m && line.trim() && /error/i.test(line)) {
          // iec2c's own messages do not name the case: keep the last one seen for the case that fails next
          refErr.set('_last', line.trim());
        }
      }
      done();
    });
  });

  const mine = new Map<string, { code: number; out: string; err: string }>();
  for (const c of cases) {
    const r = ours(c);
    mine.set(c.name, r);
    writeFileSync(join(dir, `${c.name}.ours.csv`), r.out);
    if (r.err) writeFileSync(join(dir, `${c.name}.ours.err`), r.err);
    await new Promise((s) => setImmediate(s));
  }
  await oracleDone;

  const tally = { agree: 0, disagree: 0, refRefuses: 0, weRefuse: 0, bothRefuse: 0 };
  const report: string[] = [];
  const featureFails = new Map<string, number>();
  const featureAll = new Map<string, number>();
  for (const c of cases) {
    const ref = rc.get(c.name) ?? -1;
    const me = mine.get(c.name)!;
    const weRefuse = me.code !== 0 || /^(error|rungsmith:)/m.test(me.err);
    const errLine =
      me.err.split('\n').find((l) => /^(error|rungsmith:|crash)/.test(l)) ?? me.err.split('\n')[0];
    for (const f of c.features) featureAll.set(f, (featureAll.get(f) ?? 0) + 1);
    if (ref !== 0 && weRefuse) {
      tally.bothRefuse++;
      report.push(`both refuse ${c.name}: reference rc=${ref}; Rungsmith: ${errLine}`);
    } else if (ref !== 0) {
      tally.refRefuses++;
      report.push(
        `reference refuses ${c.name} (rc=${ref}${refErr.get(c.name) ? `: ${refErr.get(c.name)}` : ''})`,
      );
    } else if (weRefuse) {
      tally.weRefuse++;
      report.push(`we refuse ${c.name}: ${errLine}`);
    } else {
      const diff = firstDifference(readFileSync(join(dir, `${c.name}.expected.csv`), 'utf8'), me.out);
      if (diff === undefined) tally.agree++;
      else {
        tally.disagree++;
        for (const f of c.features) featureFails.set(f, (featureFails.get(f) ?? 0) + 1);
        report.push(`DISAGREE ${join(dir, `${c.name}.xml`)}: ${diff}  [${c.features.join(' ')}]`);
      }
    }
  }
  for (const l of report) console.log(l);
  console.log(
    `\nseed ${seed}, ${cases.length} programs: ${tally.agree} agree, ${tally.disagree} disagree, ${tally.refRefuses} refused by the reference only, ${tally.weRefuse} refused by Rungsmith only, ${tally.bothRefuse} refused by both`,
  );
  if (tally.disagree > 0)
    console.log(
      `features of the disagreeing programs: ${[...featureFails.entries()]
        .sort((a, b) => b[1] - a[1])
        .map(([f, n]) => `${f} ${n}/${featureAll.get(f)}`)
        .join(', ')}`,
    );
  if (!values.keep && existsSync(dir)) rmSync(dir, { recursive: true, force: true });
  else console.log(`files in ${dir}`);
  process.exitCode = tally.disagree + tally.weRefuse > 0 ? 1 : 0;
}

void main2();
