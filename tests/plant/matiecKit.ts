// The machines' reference solutions against MATIEC (issue 26): what scripts/plantOracle.ts (which
// runs the MATIEC reference, /tmp/oracle) and tests/plant/matiecReference.test.ts (which checks the
// simulator against the outputs MATIEC gave, kept in tests/plant/matiec/) share. An exercise's run:
// its reference solution in closed loop with its machine through its scenario's operator presses
// and faults, profile openplc, `rungsmith simulate --plant` as a user runs it.
import { rungsmith } from '../cli/memoryIo';
import { parseLocation } from '../../src/model/iecTypes';
import type { Example } from '../../src/model/examples';
import type { Project } from '../../src/model/project';

export interface ExerciseRun {
  readonly id: string;
  readonly project: Project;
  /** The scenario's cycle, e.g. `100ms`, in ms too. */
  readonly cycle: string;
  readonly cycleMs: number;
  readonly scans: number;
  /** The program's variables at the machine's addresses: what it reads, what it drives. */
  readonly inputs: readonly string[];
  readonly outputs: readonly string[];
  /** `scan,time_ms,<inputs>,<outputs>`: per scan, the values it read and wrote. */
  readonly trace: readonly string[][];
}

/** The scenario's stimulus columns (operator controls, faults), as `rungsmith simulate --inputs` takes them, and its last scan. */
export function scenarioStimulus(csv: string): { text: string; scans: number } {
  const lines = csv.split('\n').filter((l) => l.trim() && !l.startsWith('#'));
  const header = lines[0]!.split(',');
  const keep = header.map((h, i) => (i === 0 || !h.startsWith('expect') ? i : -1)).filter((i) => i >= 0);
  const rows = lines.slice(1).map((l) => l.split(','));
  const text = [keep.map((i) => header[i]).join(','), ...rows.map((r) => keep.map((i) => r[i] ?? '').join(','))].join('\n');
  return { text: `${text}\n`, scans: Math.max(...rows.map((r) => Number(r[0]))) };
}

function located(project: Project): { inputs: string[]; outputs: string[] } {
  const main = project.pous.find((p) => p.kind === 'PROGRAM')!;
  const inputs: string[] = [];
  const outputs: string[] = [];
  for (const v of main.variables) {
    const loc = v.location ? parseLocation(v.location) : undefined;
    if (loc?.area === 'I') inputs.push(v.name);
    if (loc?.area === 'Q') outputs.push(v.name);
  }
  return { inputs, outputs };
}

/** The exercise's reference solution run through its scenario by `rungsmith simulate --plant` (in memory). */
export function exerciseRun(example: Example): ExerciseRun {
  const project = example.build();
  const id = project.plant!.id;
  const scenario = project.scenarios![0]!;
  const cycle = /# cycle: (\S+)/.exec(scenario.csv)?.[1] ?? '10ms';
  const cycleMs = Number(/^(\d+)ms$/.exec(cycle)![1]);
  const { text, scans } = scenarioStimulus(scenario.csv);
  const { inputs, outputs } = located(project);
  const run = rungsmith(
    ['simulate', 'p.json', '--plant', id, '--inputs', 'stim.csv', '--scans', String(scans), '--cycle', cycle, '--profile', 'openplc', '--watch', [...inputs, ...outputs].join(',')],
    { 'p.json': JSON.stringify(project), 'stim.csv': text },
  );
  if (run.code !== 0) throw new Error(`${id}: rungsmith simulate failed: ${run.err}`);
  const trace = run.out.trim().split('\n').map((l) => l.split(','));
  return { id, project, cycle, cycleMs, scans, inputs, outputs, trace };
}

/**
 * A trace's rows where any of `names` changes (the first row too), as `scan,<names>` lines after
 * a header: what the kept MATIEC outputs hold (a few dozen lines for thousands of scans).
 */
export function changeRows(trace: readonly string[][], names: readonly string[]): string[] {
  const header = trace[0]!.map((h) => h.toUpperCase());
  const cols = names.map((n) => header.indexOf(n.toUpperCase()));
  if (cols.some((c) => c < 0)) throw new Error(`trace has no column ${names[cols.findIndex((c) => c < 0)]}`);
  const out = [['scan', ...names].join(',')];
  let last = '';
  for (const row of trace.slice(1)) {
    const values = cols.map((c) => row[c]).join(',');
    if (values !== last) out.push(`${row[0]},${values}`);
    last = values;
  }
  return out;
}

/** The kept file's first line: what it is. Then `scan,<inputs>,<outputs>` rows where any changes. */
export const KEPT_HEADER = (id: string, scans: number, cycle: string): string =>
  `# ${id}: ${scans} scans at ${cycle}. The inputs the machine presented to the ${id} exercise's reference solution in the simulator over its scenario, and the outputs MATIEC's compile of that program (profile openplc) gave for them, scan by scan: the rows where any changes. Made by scripts/plantOracle.ts --write; do not edit.`;

/** A kept file read back: its scans and cycle, columns and change rows. */
export function readKept(text: string): { scans: number; cycle: string; header: string[]; rows: string[][] } {
  const lines = text.trim().split('\n');
  const m = /^# \w+: (\d+) scans at (\S+)\./.exec(lines[0]!);
  if (!m) throw new Error('not a kept MATIEC run');
  return { scans: Number(m[1]), cycle: m[2]!, header: lines[1]!.split(','), rows: lines.slice(2).map((l) => l.split(',')) };
}
