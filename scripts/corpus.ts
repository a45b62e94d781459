// npm run corpus -- DIR [--oracle /tmp/oracle] [--oracle-bin DIR] [--out report.md] [--cache DIR]
//                     [--sources FILE.tsv] [--classes FILE.tsv] [--only SUBSTRING] [--json FILE] [--seed N]
//
// Runs every PLCopen file of DIR through Rungsmith (import, check, `simulate --profile openplc`) and
// through the MATIEC reference (Beremiz's generator + iec2c + a scan driver, ../shared/tools/oracle),
// with the same generated stimulus, and compares the two traces scan by scan (docs/CORPUS.md).
//
// - The reference traces the first program instance of the first resource; so does this script.
// - Stimulus: the program's input-like variables (located %I, VAR_INPUT, BOOLs nothing writes), BOOLs
//   toggled by a seeded pattern, integer and REAL inputs ramped (0..99). Without timers: 100 scans
//   of 10 ms, each input changing every 1-5 scans; with a timer (TON/TOF/TP or a TIME literal): 600
//   scans, inputs held 20-100 scans so that timers of up to a second or so can run out.
// - Watch: the traced program's variables that the program writes (coils, block outputs, ST
//   assignments) or that are located outputs/memory, plus Q/ET/CV/Q1 of its standard FB instances;
//   every other elementary variable when the program is not LD. STRING variables are left out.
// - Reference results are cached (keyed by the file, stimulus, watch and scans) in --cache.
import { createHash } from 'node:crypto';
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { parseArgs } from 'node:util';
import { checkProject } from '../src/engine/check';
import { formatDiagnostic } from '../src/engine/compile/report';
import { main as cliMain } from '../src/cli/main';
import type { CliIo } from '../src/cli/io';
import { formatIssue } from '../src/cli/report';
import { isElementaryType } from '../src/model/iecTypes';
import type { Pou, Project, Variable } from '../src/model/project';
import { importPlcopen } from '../src/plcopen/importPlcopen';
import { writtenNames } from '../tests/plcopen/trace';

const { values: opt, positionals } = parseArgs({
  allowPositionals: true,
  options: {
    oracle: { type: 'string', default: '/tmp/oracle' },
    'oracle-bin': { type: 'string' },
    out: { type: 'string' },
    json: { type: 'string' },
    cache: { type: 'string' },
    sources: { type: 'string' },
    classes: { type: 'string' },
    only: { type: 'string' },
    seed: { type: 'string', default: '12' },
  },
});
const dir = positionals[0];
if (!dir) {
  process.stderr.write('usage: npx tsx scripts/corpus.ts DIR [--oracle /tmp/oracle] [--out report.md] [--cache DIR]\n');
  process.exit(2);
}
const oracle = resolve(opt.oracle!);
const seed = Number(opt.seed);
// The scripts (run_oracle.py, compare.py); --oracle-bin runs a patched copy against the same build.
const oracleBin = resolve(opt['oracle-bin'] ?? join(oracle, 'bin'));
const cacheDir = resolve(opt.cache ?? join(dirname(resolve(dir)), 'cache'));
mkdirSync(join(cacheDir, 'work'), { recursive: true });

type Result =
  | 'match'
  | 'differs'
  | 'Rungsmith refuses (false error)'
  | 'reference refuses, Rungsmith refuses too'
  | 'reference refuses, Rungsmith runs'
  | 'no LD program to trace'
  | 'harness error';

interface FileResult {
  file: string;
  result: Result;
  detail: string;
  importErrors: string[];
  checkErrors: string[];
  instance?: string;
  pou?: string;
  language?: string;
  inputs: string[];
  watch: string[];
  scans: number;
  oracleRc?: number;
  oracleMessage?: string;
  rungsmithRc?: number;
  rungsmithMessage?: string;
  notes: string[];
}

/** The first program instance of the first resource, as MATIEC's generated configuration lists it. */
function firstInstance(xml: string): { instance: string; type: string } | undefined {
  const res = /<resource\b[\s\S]*?<\/resource>/.exec(xml);
  if (!res) return undefined;
  const m = /<pouInstance\b[^>]*>/.exec(res[0]);
  if (!m) return undefined;
  const name = /\bname="([^"]*)"/.exec(m[0])?.[1];
  const type = /\b(?:typeName|type)="([^"]*)"/.exec(m[0])?.[1];
  return name && type ? { instance: name, type } : undefined;
}

const STD_FB_OUTPUTS: Record<string, string[]> = {
  TON: ['Q', 'ET'],
  TOF: ['Q', 'ET'],
  TP: ['Q', 'ET'],
  CTU: ['Q', 'CV'],
  CTD: ['Q', 'CV'],
  CTUD: ['QU', 'QD', 'CV'],
  R_TRIG: ['Q'],
  F_TRIG: ['Q'],
  SR: ['Q1'],
  RS: ['Q1'],
};

const INTEGER = /^(SINT|INT|DINT|LINT|USINT|UINT|UDINT|ULINT|BYTE|WORD|DWORD|LWORD)$/;

/** Input-like variables (as tests/plcopen/trace.ts inputLike), elementary non-STRING, non-TIME only. */
function inputsOf(project: Project, pou: Pou, isWritten: (n: string) => boolean): Variable[] {
  const out: Variable[] = [];
  for (const own of pou.variables) {
    // A VAR_EXTERNAL is the global of that name (its location, its constancy).
    const v = own.varClass === 'external' ? project.globals.find((g) => g.name.toUpperCase() === own.name.toUpperCase()) : own;
    if (!v || v.constant || own.constant || v.varClass === 'inOut') continue;
    const t = v.type.toUpperCase();
    if (!(t === 'BOOL' || INTEGER.test(t) || t === 'REAL' || t === 'LREAL')) continue;
    if (v.location?.startsWith('%I') || v.varClass === 'input') out.push(v);
    else if (!v.location && t === 'BOOL' && !isWritten(v.name)) out.push(v);
  }
  return out;
}

function watchOf(pou: Pou, inputs: Set<string>, isWritten: (n: string) => boolean): string[] {
  const out: string[] = [];
  const ld = pou.language === 'LD';
  for (const v of pou.variables) {
    const t = v.type.toUpperCase();
    if (inputs.has(v.name.toUpperCase())) continue;
    if (STD_FB_OUTPUTS[t]) {
      for (const p of STD_FB_OUTPUTS[t]!) out.push(`${v.name}.${p}`);
      continue;
    }
    if (!isElementaryType(t) || t === 'STRING' || t === 'WSTRING' || v.constant) continue;
    if (!ld || isWritten(v.name) || /^%[QM]/i.test(v.location ?? '')) out.push(v.name);
  }
  if (out.length) return out;
  // Nothing written that the program declares (e.g. an FBD body read as LD): every other variable.
  for (const v of pou.variables) {
    const t = v.type.toUpperCase();
    if (inputs.has(v.name.toUpperCase()) || !isElementaryType(t) || t === 'STRING' || t === 'WSTRING' || v.constant) continue;
    out.push(v.name);
  }
  return out;
}

function hasTimers(xml: string): boolean {
  // A TIME literal in a body or an initial value; a task's interval="T#20ms" does not count.
  return /typeName="(TON|TOF|TP|BLINK|TONR|RTO)"/i.test(xml) || /(?<!interval=")\bT(IME)?#/i.test(xml);
}

/** A seeded pseudo-random bit per (input, step): murmur3's finaliser over the three numbers. */
function bit(seed: number, j: number, k: number): boolean {
  let h = Math.imul(seed + 1, 0x9e3779b1) ^ Math.imul(j + 1, 0x85ebca77) ^ Math.imul(k + 1, 0xc2b2ae3d);
  h ^= h >>> 16;
  h = Math.imul(h, 0x85ebca6b);
  h ^= h >>> 13;
  h = Math.imul(h, 0xc2b2ae35);
  h ^= h >>> 16;
  return h >>> 31 === 1;
}

/** `scan,<inputs>` rows for every scan: BOOL inputs by the seeded pattern, numbers ramped. */
function stimulusCsv(inputs: Variable[], scans: number, slow: boolean, seed: number): string {
  const base = slow ? 20 : 1;
  const lines = [['scan', ...inputs.map((v) => v.name)].join(',')];
  for (let k = 1; k <= scans; k++) {
    const row = [String(k)];
    inputs.forEach((v, j) => {
      const period = base * (1 + (j % 5));
      if (v.type.toUpperCase() === 'BOOL') row.push(bit(seed, j, Math.floor(k / period)) ? '1' : '0');
      else {
        // Numbers jump around their range (0..99 for 8-bit types, 0..999 otherwise) so that
        // comparisons with set points (GT(level, 100), ...) go both ways.
        const range = /^(SINT|USINT|BYTE)$/i.test(v.type) ? 100 : 1000;
        row.push(String((Math.floor(k / base) * 37 * (j + 1) + 13 * j) % range));
      }
    });
    lines.push(row.join(','));
  }
  return `${lines.join('\n')}\n`;
}

interface OracleRun {
  rc: number;
  csv?: string;
  message: string;
}

function runOracle(xmlPath: string, stim: string, watch: string[], scans: number): OracleRun {
  const key = createHash('sha256')
    .update(readFileSync(xmlPath))
    .update('\0' + stim + '\0' + watch.join(',') + '\0' + scans)
    .digest('hex')
    .slice(0, 24);
  const cached = join(cacheDir, `${key}.json`);
  if (existsSync(cached)) return JSON.parse(readFileSync(cached, 'utf8')) as OracleRun;
  const name = basename(xmlPath).replace(/\.xml$/i, '');
  const stimPath = join(cacheDir, 'work', `${name}.stim.csv`);
  const outPath = join(cacheDir, 'work', `${name}.out.csv`);
  writeFileSync(stimPath, stim);
  const r = spawnSync(
    'python3',
    [
      join(oracleBin, 'run_oracle.py'),
      xmlPath,
      stimPath,
      watch.join(','),
      String(scans),
      outPath,
      '--work',
      join(cacheDir, 'work', name),
    ],
    { encoding: 'utf8', maxBuffer: 64 * 1024 * 1024, timeout: 600_000, env: { ...process.env, ORACLE: oracle } },
  );
  const rc = r.status ?? 99;
  const run: OracleRun = {
    rc,
    message: (r.stderr ?? '')
      .split('\n')
      .filter((l) => l.trim())
      .slice(-6)
      .join('\n'),
    ...(rc === 0 ? { csv: readFileSync(outPath, 'utf8') } : {}),
  };
  writeFileSync(cached, JSON.stringify(run));
  return run;
}

function runRungsmith(
  file: string,
  stimPath: string,
  watch: string[],
  scans: number,
  profile: 'openplc' | 'iec' = 'openplc',
): { rc: number; out: string; err: string } {
  let out = '';
  let err = '';
  const io: CliIo = {
    out: (t) => void (out += t),
    err: (t) => void (err += t),
    readFile: (p) => readFileSync(p, 'utf8'),
    writeFile: () => undefined,
  };
  const args = ['simulate', file, '--inputs', stimPath, '--scans', String(scans), '--cycle', '10ms', '--profile', profile];
  if (watch.length) args.push('--watch', watch.join(','));
  const rc = cliMain(args, io);
  return { rc, out, err };
}

function compare(expected: string, actual: string, workBase: string): string {
  writeFileSync(`${workBase}.expected.csv`, expected);
  writeFileSync(`${workBase}.actual.csv`, actual);
  const r = spawnSync('python3', [join(oracleBin, 'compare.py'), `${workBase}.expected.csv`, `${workBase}.actual.csv`, '--name', basename(workBase)], {
    encoding: 'utf8',
  });
  return r.status === 0 ? '' : (r.stdout || r.stderr).trim();
}

const lastLines = (s: string, n = 3) =>
  s
    .replaceAll(`${join(cacheDir, 'work')}/`, '')
    .split('\n')
    .filter((l) => l.trim() && !/: warning: |^warning /.test(l))
    .slice(0, n)
    .join(' / ');

/** How many watched columns of a trace take more than one value (how much of the program the run exercised). */
function changing(csv: string): number {
  const rows = csv.trim().split('\n').map((l) => l.split(','));
  const width = rows[0]!.length;
  let n = 0;
  for (let c = 2; c < width; c++) if (new Set(rows.slice(1).map((r) => r[c])).size > 1) n++;
  return n;
}

/** The CSV with `INSTANCE.` taken off the header's names. */
function bareHeader(csv: string, instance: string | undefined): string {
  if (!instance) return csv;
  const [head, ...rest] = csv.split('\n');
  const prefix = `${instance}.`;
  return [head!.split(',').map((c) => (c.startsWith(prefix) ? c.slice(prefix.length) : c)).join(','), ...rest].join('\n');
}

function runFile(file: string): FileResult {
  const xml = readFileSync(file, 'utf8');
  const r: FileResult = { file: basename(file), result: 'harness error', detail: '', importErrors: [], checkErrors: [], inputs: [], watch: [], scans: 0, notes: [] };
  const imported = importPlcopen(xml);
  const first = firstInstance(xml);
  if (!imported.ok) {
    r.importErrors = imported.errors.map((e) => formatIssue(e));
  }
  const project = imported.ok ? imported.project : undefined;
  if (project) r.checkErrors = checkProject(project).filter((d) => d.severity === 'error').map((d) => formatDiagnostic(d));
  // The program the reference traces; without a configuration, Rungsmith's default program.
  const pouName = first?.type;
  const pou = project?.pous.find((p) => p.name.toUpperCase() === (pouName ?? '').toUpperCase());
  r.instance = first?.instance;
  r.pou = pouName;
  if (project && !pou) {
    r.result = 'no LD program to trace';
    r.detail = first ? `program ${first.type} of instance ${first.instance} not found` : 'no program instance in a resource';
    return r;
  }
  r.language = pou?.language;
  const slow = hasTimers(xml);
  r.scans = slow ? 600 : 100;
  let inputs: Variable[] = [];
  if (project && pou) {
    const isWritten = writtenNames(project);
    inputs = inputsOf(project, pou, isWritten);
    r.inputs = inputs.map((v) => v.name);
    r.watch = watchOf(pou, new Set(r.inputs.map((n) => n.toUpperCase())), isWritten);
  } else if (first) {
    // Rungsmith refused the file: watch nothing but the reference's verdict matters.
    r.watch = [];
  }
  const stim = stimulusCsv(inputs, r.scans, slow, seed);
  const name = basename(file).replace(/\.xml$/i, '');
  const workBase = join(cacheDir, 'work', name);
  const stimPath = `${workBase}.stim.csv`;
  writeFileSync(stimPath, stim);
  if (project && pou && r.watch.length === 0) {
    r.result = 'no LD program to trace';
    r.detail = `program ${pou.name} (${pou.language}) writes no variable of its own to watch`;
    return r;
  }
  const o = runOracle(resolve(file), stim, r.watch.length ? r.watch : ['__none__'], r.scans);
  r.oracleRc = o.rc;
  r.oracleMessage = o.rc === 0 ? '' : o.message;
  const refRefuses = o.rc >= 3 && o.rc <= 5;
  if (!project || r.checkErrors.length) {
    const why = r.importErrors.length ? `import: ${r.importErrors.slice(0, 2).join(' / ')}` : `check: ${r.checkErrors.slice(0, 2).join(' / ')}`;
    r.result = refRefuses || !first ? 'reference refuses, Rungsmith refuses too' : 'Rungsmith refuses (false error)';
    r.detail = refRefuses ? `${why} || reference (rc ${o.rc}): ${lastLines(o.message, 2)}` : why;
    if (!refRefuses && o.rc !== 0) r.notes.push(`reference rc ${o.rc}: ${lastLines(o.message, 2)}`);
    return r;
  }
  let simStim = stimPath;
  let simWatch = r.watch;
  let sim = runRungsmith(file, simStim, simWatch, r.scans);
  if (sim.rc !== 0 && /unknown variable/.test(sim.err) && r.instance) {
    r.notes.push(`bare names refused (class 5): ${lastLines(sim.err, 1)}`);
    const [stimHead, ...stimRows] = stim.split('\n');
    const prefixed = `${workBase}.prefixed.stim.csv`;
    writeFileSync(prefixed, [stimHead!.split(',').map((c, i) => (i ? `${r.instance}.${c}` : c)).join(','), ...stimRows].join('\n'));
    simStim = prefixed;
    simWatch = r.watch.map((w) => `${r.instance}.${w}`);
    sim = runRungsmith(file, simStim, simWatch, r.scans);
    // Header back to bare names for the comparison.
    sim.out = bareHeader(sim.out, r.instance);
  }
  r.rungsmithRc = sim.rc;
  r.rungsmithMessage = sim.rc === 0 ? '' : lastLines(sim.err, 3);
  if (refRefuses) {
    r.result = sim.rc === 0 ? 'reference refuses, Rungsmith runs' : 'reference refuses, Rungsmith refuses too';
    r.detail = `reference (rc ${o.rc}): ${lastLines(o.message, 3)}${sim.rc ? ` || Rungsmith: ${r.rungsmithMessage}` : ''}`;
    return r;
  }
  if (o.rc !== 0) {
    r.result = 'harness error';
    r.detail = `reference rc ${o.rc}: ${lastLines(o.message, 3)}`;
    return r;
  }
  if (sim.rc !== 0) {
    r.result = 'Rungsmith refuses (false error)';
    r.detail = `simulate: ${r.rungsmithMessage}`;
    return r;
  }
  const diff = compare(o.csv!, sim.out, workBase);
  r.result = diff ? 'differs' : 'match';
  r.detail = diff.replace(/^[^:]*: /, '');
  if (!diff) r.detail = `${changing(o.csv!)} of ${r.watch.length} watched values change; ${inputs.length} inputs stimulated`;
  if (diff) {
    // The same run under --profile iec: tells an `openplc`-profile difference from the others.
    const iec = runRungsmith(file, simStim, simWatch, r.scans, 'iec');
    const iecDiff = iec.rc === 0 ? compare(o.csv!, bareHeader(iec.out, r.instance), `${workBase}.iec`) : `refused: ${lastLines(iec.err, 1)}`;
    r.notes.push(iecDiff ? `under iec: ${iecDiff.replace(/^[^:]*: /, '')}` : 'matches under --profile iec');
  }
  return r;
}

// ---- main
const files = readdirSync(dir)
  .filter((f) => /\.xml$/i.test(f))
  .filter((f) => !opt.only || f.includes(opt.only))
  .sort();
const results: FileResult[] = [];
for (const f of files) {
  const t0 = Date.now();
  let r: FileResult;
  try {
    r = runFile(join(dir, f));
  } catch (e) {
    r = { file: f, result: 'harness error', detail: String((e as Error).stack ?? e).split('\n').slice(0, 3).join(' '), importErrors: [], checkErrors: [], inputs: [], watch: [], scans: 0, notes: [] };
  }
  results.push(r);
  process.stderr.write(`${f}: ${r.result}${r.detail ? ` — ${r.detail.slice(0, 200)}` : ''} (${Date.now() - t0} ms)\n`);
}

// ---- report
const readTsv = (p: string | undefined) => {
  if (!p || !existsSync(p)) return new Map<string, Record<string, string>>();
  const [head, ...rows] = readFileSync(p, 'utf8').split('\n').filter(Boolean);
  const cols = head!.split('\t');
  return new Map(
    rows.map((l) => {
      const cells = l.split('\t');
      const rec = Object.fromEntries(cols.map((c, i) => [c, cells[i] ?? '']));
      return [rec[cols[0]!]!, rec];
    }),
  );
};
const sources = readTsv(opt.sources);
const classes = readTsv(opt.classes);
const cell = (s: string | undefined) => (s ?? '').replace(/\|/g, '\\|').replace(/\n/g, ' ');
const count = (key: (r: FileResult) => string) => {
  const m = new Map<string, number>();
  for (const r of results) m.set(key(r), (m.get(key(r)) ?? 0) + 1);
  return [...m].sort((a, b) => b[1] - a[1]);
};
const lines: string[] = [];
lines.push(`# Corpus run: ${results.length} files`, '');
lines.push('| result | files |', '|---|---|', ...count((r) => r.result).map(([k, n]) => `| ${k} | ${n} |`), '');
if (sources.size) {
  lines.push('| tool | files | match |', '|---|---|---|');
  for (const [tool, n] of count((r) => sources.get(r.file)?.tool ?? '?'))
    lines.push(`| ${tool} | ${n} | ${results.filter((r) => (sources.get(r.file)?.tool ?? '?') === tool && r.result === 'match').length} |`);
  lines.push('');
}
if (classes.size) {
  lines.push('| class | files |', '|---|---|', ...count((r) => classes.get(r.file)?.class ?? (r.result === 'match' ? '-' : 'unclassified')).map(([k, n]) => `| ${k} | ${n} |`), '');
}
lines.push(
  '| file | source | tool | licence | program | scans | result | class | first difference / reason |',
  '|---|---|---|---|---|---|---|---|---|',
);
for (const r of results) {
  const s = sources.get(r.file);
  const src = s ? `[${s.url.replace('https://github.com/', '')}](${s.url}) \`${s.path}\` @ ${s.snapshot.slice(0, 8)}` : '';
  const c = classes.get(r.file);
  lines.push(
    `| ${cell(r.file)} | ${cell(src)} | ${cell(s?.tool)} | ${cell(s?.licence)} | ${cell(r.instance ? `${r.instance}: ${r.pou} (${r.language ?? '?'})` : '')} | ${r.scans} | ${r.result} | ${cell(c?.class)} | ${cell([r.detail, ...r.notes, c?.note].filter(Boolean).join(' — ').slice(0, 400))} |`,
  );
}
const report = `${lines.join('\n')}\n`;
if (opt.out) writeFileSync(opt.out, report);
else process.stdout.write(report);
if (opt.json) writeFileSync(opt.json, JSON.stringify(results, null, 1));
