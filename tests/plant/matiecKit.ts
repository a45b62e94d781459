// The machines' reference solutions against MATIEC (issue 26): what scripts/plantOracle.ts (which
// runs the MATIEC reference, /tmp/oracle) and tests/plant/matiecReference.test.ts (which checks the
// simulator against the outputs MATIEC gave, kept in tests/plant/matiec/) share. An exercise's run:
// its reference solution in closed loop with its machine through its scenario's operator presses
// and faults (and a run of an operator's actions and faults mid-run), profile openplc,
// `rungsmith simulate --plant` as a user runs it.
import { rungsmith } from '../cli/memoryIo';
import { parseLocation } from '../../src/model/iecTypes';
import type { Example } from '../../src/model/examples';
import type { Project } from '../../src/model/project';
import { actionStimulus, MACHINES } from './operatorRuns';

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

/** What a closed-loop run is given: the stimulus (operator controls, faults), how long, at what cycle. */
interface RunSpec {
  readonly stimulus: string;
  readonly scans: number;
  readonly cycle: string;
}

/**
 * The two runs of each exercise's reference solution: its scenario (`ID`: the goal reached), and
 * the operator working the controls with faults set and cleared mid-run (`ID-operator`: stops,
 * restarts, the program's reactions to faults; the runs of faultTraces.test.ts, 2,000 scans).
 */
export function exerciseRuns(example: Example): { readonly name: string; readonly run: () => ExerciseRun }[] {
  const project = example.build();
  const id = project.plant!.id;
  const scenario = project.scenarios![0]!;
  const { text, scans } = scenarioStimulus(scenario.csv);
  const cycle = /# cycle: (\S+)/.exec(scenario.csv)?.[1] ?? '10ms';
  const operator = MACHINES.find((m) => m.id === id)!;
  return [
    { name: id, run: () => closedLoopRun(project, { stimulus: text, scans, cycle }) },
    { name: `${id}-operator`, run: () => closedLoopRun(project, { stimulus: actionStimulus(id, operator.actions), scans: 2000, cycle: `${operator.cycleMs}ms` }) },
  ];
}

/** A reference solution run in closed loop with its machine by `rungsmith simulate --plant` (in memory). */
function closedLoopRun(project: Project, spec: RunSpec): ExerciseRun {
  const id = project.plant!.id;
  const cycleMs = Number(/^(\d+)ms$/.exec(spec.cycle)![1]);
  const { inputs, outputs } = located(project);
  const run = rungsmith(
    ['simulate', 'p.json', '--plant', id, '--inputs', 'stim.csv', '--scans', String(spec.scans), '--cycle', spec.cycle, '--profile', 'openplc', '--watch', [...inputs, ...outputs].join(',')],
    { 'p.json': JSON.stringify(project), 'stim.csv': spec.stimulus },
  );
  if (run.code !== 0) throw new Error(`${id}: rungsmith simulate failed: ${run.err}`);
  const trace = run.out.trim().split('\n').map((l) => l.split(','));
  return { id, project, cycle: spec.cycle, cycleMs, scans: spec.scans, inputs, outputs, trace };
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
export const KEPT_HEADER = (name: string, id: string, scans: number, cycle: string): string =>
  `# ${name}: ${scans} scans at ${cycle}. The inputs the machine presented to the ${id} exercise's reference solution in the simulator over ${name === id ? 'its scenario' : 'an operator\'s actions and faults mid-run'}, and the outputs MATIEC's compile of that program (profile openplc) gave for them, scan by scan: the rows where any changes. Made by scripts/plantOracle.ts --write; do not edit.`;

/** A kept file read back: its scans and cycle, columns and change rows. */
export function readKept(text: string): { scans: number; cycle: string; header: string[]; rows: string[][] } {
  const lines = text.trim().split('\n');
  const m = /^# [\w-]+: (\d+) scans at (\S+)\./.exec(lines[0]!);
  if (!m) throw new Error('not a kept MATIEC run');
  return { scans: Number(m[1]), cycle: m[2]!, header: lines[1]!.split(','), rows: lines.slice(2).map((l) => l.split(',')) };
}
