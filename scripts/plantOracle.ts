// The machines' reference solutions against the MATIEC reference (issue 26, "runs as the reference
// runs"): for each exercise under File > Examples, `rungsmith simulate --plant` runs the reference
// solution in closed loop with its machine through the exercise's scenario (its operator presses
// and faults), and through an operator's actions and faults mid-run, profile openplc; the inputs the machine presented, scan by scan, are then given to
// the same program exported as PLCopen XML and compiled by MATIEC (../shared/tools/oracle, built
// in /tmp/oracle), and its outputs must equal the simulator's at every scan. Equal outputs at
// every scan mean an equal drive, so the MATIEC-compiled program (what an OpenPLC runtime runs)
// in closed loop with the machine gives the very same run.
//
//   npx tsx scripts/plantOracle.ts [--write] [MACHINE...]      (ORACLE=/tmp/oracle by default)
//
// --write keeps the inputs and MATIEC's outputs in tests/plant/matiec/<id>.csv and <id>-operator.csv, which
// tests/plant/matiecReference.test.ts checks the simulator against in npm test (no oracle there).
// Exit 0 when every machine agrees, 1 on a difference (the first one printed), 2 without the oracle.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { PLANT_EXAMPLES } from '../src/plant/exercises';
import { exportPlcopen } from '../src/plcopen/exportPlcopen';
import { changeRows, exerciseRuns, KEPT_HEADER, type ExerciseRun } from '../tests/plant/matiecKit';

const ORACLE = process.env.ORACLE ?? '/tmp/oracle';
const RUN = join(ORACLE, 'bin', 'run_oracle.py');
const WORK = '/tmp/plant-oracle';
const KEPT = join(import.meta.dirname, '..', 'tests', 'plant', 'matiec');

if (!existsSync(RUN)) {
  process.stderr.write(`plantOracle: no MATIEC reference at ${ORACLE} (build it: ../shared/tools/oracle/README.md)\n`);
  process.exit(2);
}

function check(name: string, run: ExerciseRun, write: boolean): boolean {
  const { id, inputs, outputs, trace, scans } = run;
  const dir = join(WORK, name);
  mkdirSync(dir, { recursive: true });
  writeFileSync(join(dir, 'project.xml'), exportPlcopen(run.project));
  // The reference gets exactly the inputs each scan of the simulator read.
  const col = (name: string) => trace[0]!.indexOf(name);
  writeFileSync(
    join(dir, 'stim.csv'),
    [['scan', ...inputs].join(','), ...trace.slice(1).map((r) => [r[0], ...inputs.map((n) => r[col(n)])].join(','))].join('\n') + '\n',
  );
  const out = join(dir, 'oracle.csv');
  try {
    execFileSync('python3', [RUN, join(dir, 'project.xml'), join(dir, 'stim.csv'), outputs.join(','), String(scans), out, '--cycle', String(run.cycleMs)], { stdio: 'pipe' });
  } catch (e) {
    const err = e as { status?: number; stderr?: Buffer };
    process.stdout.write(`${name}: the oracle refused the program (exit ${err.status}): ${err.stderr?.toString().slice(0, 2000)}\n`);
    return false;
  }
  const ref = readFileSync(out, 'utf8').trim().split('\n').map((l) => l.split(','));
  const theirs = changeRows(ref, outputs);
  const ours = changeRows(trace, outputs);
  const at = ours.findIndex((line, i) => line !== theirs[i]);
  if (at >= 0 || ours.length !== theirs.length) {
    const i = at >= 0 ? at : Math.min(ours.length, theirs.length);
    process.stdout.write(`${name}: the outputs differ (scan,${outputs.join(',')}): rungsmith ${ours[i] ?? 'ends'}, MATIEC ${theirs[i] ?? 'ends'} (files in ${dir})\n`);
    return false;
  }
  if (write) {
    // The inputs as fed, with MATIEC's outputs beside them.
    const fed = readFileSync(join(dir, 'stim.csv'), 'utf8').trim().split('\n').map((l) => l.split(','));
    const both = fed.map((r, i) => [...r, ...outputs.map((o) => ref[i]![ref[0]!.indexOf(o)]!)]);
    writeFileSync(join(KEPT, `${name}.csv`), [KEPT_HEADER(name, id, scans, run.cycle), ...changeRows(both, [...inputs, ...outputs])].join('\n') + '\n');
  }
  process.stdout.write(`${name}: ${scans} scans at ${run.cycle}: ${outputs.length} outputs, ${theirs.length - 2} changes, equal to MATIEC's at every scan\n`);
  return true;
}

const args = process.argv.slice(2);
const write = args.includes('--write');
const only = args.filter((a) => a !== '--write');
let ok = true;
for (const ex of PLANT_EXAMPLES) {
  if (only.length && !only.includes(ex.build().plant!.id)) continue;
  for (const { name, run } of exerciseRuns(ex)) ok = check(name, run(), write) && ok;
}
process.exit(ok ? 0 : 1);
