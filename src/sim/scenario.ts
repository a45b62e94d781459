// Test scenarios (issue 14): the CLI's stimulus CSV plus expected columns. One row per scan that
// sets inputs (before that scan's input read) and/or checks values (after that scan ran):
//
//   # cycle: 100ms
//   scan,Start,Stop,expect Motor,expect T1.ET ~ 50ms
//   1,1,0,1,*
//   5,0,,1,400
//
// `expect NAME` columns are checked; `*` or an empty cell is "don't care"; an empty input cell
// leaves the input as it is. `~ TOL` after a column name (or a cell value, `400~20`) accepts values
// within TOL (TIME in ms or with a unit: `50ms`, `T#0.1s`). Comment lines `# cycle: 100ms` and
// `# pou: Main` set the cycle and the PROGRAM. Used by the Tests panel, the worker (replay into the
// timeline) and `rungsmith test`.
//
// `# plant: tank` runs the program in closed loop with that machine (issue 26, src/plant): columns
// `tank.Start` operate its controls, `fault high_stuck_off` columns (1/0) set its faults,
// `expect tank.level` checks its state, and a consequence (the tank overflowed) fails the scenario
// at the scan it happened.
import type { Plc, TaskSchedule } from '../engine/api';
import { tickConflict } from '../engine/compile/taskSchedule';
import type { CompiledProgram } from '../engine/plc';
import { compileProgram, createPlc } from '../engine/plc';
import { csvValue, formatValue, parseValueText } from '../engine/values/literals';
import type { ElementaryType, Value } from '../model/iecTypes';
import type { Project, Scenario } from '../model/project';
import { readCsv } from './csv';
import { runOptions } from './runTarget';
import { machineNameHint, requirePlant } from '../plant/machines';
import { PlantLoop, plantValueType } from '../plant/loop';
import type { PlantModel } from '../plant/types';

export interface ScenarioColumn {
  readonly name: string;
  /** fault: a machine's fault (`fault high_stuck_off`), on while the cell is 1. */
  readonly kind: 'input' | 'expect' | 'fault';
  /** Accepted difference (TIME in ms). */
  readonly tolerance?: number;
}

export interface ScenarioRow {
  readonly scan: number;
  readonly line: number;
  /** Column index -> cell text (non-empty, not `*`). */
  readonly cells: ReadonlyMap<number, string>;
}

export interface ParsedScenario {
  readonly name: string;
  readonly cycleMs?: number;
  readonly pou?: string;
  /** The machine the program runs against (`# plant: tank`). */
  readonly plant?: string;
  readonly columns: readonly ScenarioColumn[];
  readonly rows: readonly ScenarioRow[];
  /** Scans to run: the last row's scan. */
  readonly scans: number;
  /** Line of the header (for errors about a column). */
  readonly headerLine: number;
}

/** A scenario file that cannot be read: the line and what is wrong. */
export class ScenarioError extends Error {
  constructor(
    readonly line: number,
    message: string,
  ) {
    super(line > 0 ? `line ${line}: ${message}` : message);
  }
}

const FAULT_RE = /^fault[:\s]\s*(\S+)\s*$/i;
const EXPECT_RE = /^expect[:\s]\s*(.+?)\s*(?:~\s*(.+))?$/i;

function toleranceOf(text: string, line: number): number {
  const t = text.trim();
  if (/^\d+(\.\d+)?$/.test(t)) return Number(t);
  const r = parseValueText('TIME', /^T(IME)?#/i.test(t) ? t : `T#${t}`);
  if (!r.ok) throw new ScenarioError(line, `tolerance "${text}" is not a number or a duration (50ms, T#0.1s)`);
  return Number(r.value);
}

export function parseScenario(text: string, name = 'scenario'): ParsedScenario {
  let read: ReturnType<typeof readCsv>;
  try {
    read = readCsv(text);
  } catch (e) {
    throw new ScenarioError(0, (e as Error).message);
  }
  let cycleMs: number | undefined;
  let pou: string | undefined;
  let plant: { readonly id: string; readonly line: number } | undefined;
  for (const c of read.comments) {
    const m = /^(cycle|pou|plant)\s*:\s*(.+)$/i.exec(c.cells[0]!) ?? /^(plant)\s*:\s*()$/i.exec(c.cells[0]!);
    if (!m) continue;
    if (m[1]!.toLowerCase() === 'pou') pou = m[2]!.trim();
    else if (m[1]!.toLowerCase() === 'plant') {
      let id: string;
      try {
        id = requirePlant(m[2]!).id;
      } catch (e) {
        throw new ScenarioError(c.line, (e as Error).message);
      }
      // A second machine would silently replace the first: the columns of one would then be unknown.
      if (plant && plant.id !== id)
        throw new ScenarioError(c.line, `a scenario runs against one machine: line ${plant.line} already names ${plant.id}, this line ${id}`);
      plant = { id, line: c.line };
    }
    else {
      const ms = toleranceOf(m[2]!, c.line);
      if (!(ms > 0)) throw new ScenarioError(c.line, `cycle "${m[2]}" must be a positive duration`);
      cycleMs = ms;
    }
  }
  const head = read.rows[0];
  if (!head || head.cells[0]?.toLowerCase() !== 'scan')
    throw new ScenarioError(head?.line ?? 1, 'the first line must be the header scan,<input>,...,expect <variable>,...');
  const columns: ScenarioColumn[] = head.cells.slice(1).map((cell, i) => {
    if (cell === '') throw new ScenarioError(head.line, `column ${i + 2} has no variable name`);
    const f = FAULT_RE.exec(cell);
    if (f) {
      if (!plant) throw new ScenarioError(head.line, `column "${cell}": a fault needs a machine (# plant: tank) before the header`);
      return { name: f[1]!, kind: 'fault' };
    }
    const m = EXPECT_RE.exec(cell);
    if (!m) return { name: cell, kind: 'input' };
    return { name: m[1]!, kind: 'expect', ...(m[2] ? { tolerance: toleranceOf(m[2], head.line) } : {}) };
  });
  const rows: ScenarioRow[] = [];
  let last = 0;
  for (const r of read.rows.slice(1)) {
    const scanText = r.cells[0] ?? '';
    const scan = Number(scanText);
    if (!Number.isInteger(scan) || scan < 1) throw new ScenarioError(r.line, `scan "${scanText}" is not a scan number (1, 2, 3...)`);
    if (scan <= last) throw new ScenarioError(r.line, `scan ${scan} comes after scan ${last}; sort the rows by scan, one row per scan`);
    if (r.cells.length > columns.length + 1) throw new ScenarioError(r.line, 'more cells than header columns');
    last = scan;
    const cells = new Map<number, string>();
    columns.forEach((_, i) => {
      const cell = r.cells[i + 1];
      if (cell !== undefined && cell !== '' && cell !== '*') cells.set(i, cell);
    });
    rows.push({ scan, line: r.line, cells });
  }
  if (rows.length === 0) throw new ScenarioError(head.line, 'the scenario has no rows');
  return { name, columns, rows, scans: last, headerLine: head.line, ...(cycleMs !== undefined ? { cycleMs } : {}), ...(pou ? { pou } : {}), ...(plant ? { plant: plant.id } : {}) };
}

/** Where a run first differed from the scenario. */
export interface Divergence {
  readonly scan: number;
  readonly line: number;
  readonly name: string;
  readonly expected: string;
  readonly actual: string;
}

export interface ScenarioResult {
  readonly name: string;
  readonly ok: boolean;
  /** Scans run (up to and including the first divergent one). */
  readonly scans: number;
  /** Every expected column that differed at the first divergent scan. */
  readonly divergences: readonly Divergence[];
  /** The scenario or the program could not be run: why (the scenario line, the rule id). */
  readonly error?: string;
  /** The machine's consequences of severity warning (they fail nothing), located, in order. */
  readonly warnings?: readonly string[];
  /**
   * Failed on a machine's consequence (`error` says which, at what scan): the machine's quantity
   * counting it (`tank.overflows`), what "Why?" explains at that scan.
   */
  readonly consequence?: string;
}

interface Check {
  readonly column: number;
  readonly type: ElementaryType;
  readonly value: Value;
  readonly tolerance: number;
}

function typeOf(program: CompiledProgram, name: string, line: number, plant: PlantModel | undefined): ElementaryType {
  if (plant && name.toLowerCase().startsWith(`${plant.id}.`)) {
    const t = plantValueType(plant, name);
    if (!t) throw new ScenarioError(line, `${plant.id} has no quantity or point "${name.slice(plant.id.length + 1)}" (rungsmith plants lists them)`);
    return t;
  }
  const r = program.symbols.resolve(name, { literals: false, implicitLocations: false });
  if (!r.ok) {
    const hint = machineNameHint(name, plant, (id) => `add "# plant: ${id}" before the header`);
    throw new ScenarioError(line, `unknown variable "${name}": ${r.message}${hint ? `; ${hint}` : ''}`);
  }
  if (r.access.kind === 'const') throw new ScenarioError(line, `"${name}" is a constant, not a variable`);
  return r.access.type;
}

/** A value in a failure message: as in the CSV, a string as its literal ('a, b') so its ends show. */
const checkText = (type: ElementaryType, v: Value): string =>
  type === 'STRING' || type === 'WSTRING' ? formatValue(type, v) : csvValue(type, v);

function matches(check: Check, actual: Value): boolean {
  if (check.type === 'BOOL' || typeof actual === 'string') return actual === check.value;
  if (typeof actual === 'bigint' && typeof check.value === 'bigint' && check.tolerance === 0) return actual === check.value;
  return Math.abs(Number(actual) - Number(check.value)) <= check.tolerance;
}

/** A scenario prepared for one compiled program: values parsed at the variables' types. */
export interface PreparedScenario {
  readonly parsed: ParsedScenario;
  /** What each row sets before its scan: a program variable, a machine's control (`tank.Start`) or fault. */
  readonly inputs: readonly (readonly { readonly name: string; readonly value: Value; readonly target?: 'plant' | 'fault' }[])[];
  readonly checks: readonly (readonly Check[])[];
  readonly types: readonly ElementaryType[];
}

export function prepareScenario(parsed: ParsedScenario, program: CompiledProgram): PreparedScenario {
  const plant = parsed.plant ? requirePlant(parsed.plant) : undefined;
  const types = parsed.columns.map((c): ElementaryType => {
    if (c.kind !== 'fault') return typeOf(program, c.name, parsed.headerLine, plant);
    if (!plant!.faults.some((f) => f.id === c.name.toLowerCase()))
      throw new ScenarioError(parsed.headerLine, `${plant!.id} has no fault "${c.name}"; it has ${plant!.faults.map((f) => f.id).join(', ')}`);
    return 'BOOL';
  });
  const onPlant = (name: string) => plant !== undefined && name.toLowerCase().startsWith(`${plant.id}.`);
  const inputs = parsed.rows.map((row) =>
    [...row.cells].flatMap(([i, text]) => {
      const col = parsed.columns[i]!;
      if (col.kind === 'expect') return [];
      const r = parseValueText(types[i]!, text);
      if (!r.ok) throw new ScenarioError(row.line, `column ${col.kind === 'fault' ? 'fault ' : ''}${col.name}: ${r.message}`);
      if (col.kind === 'fault') return [{ name: col.name, value: r.value, target: 'fault' as const }];
      if (onPlant(col.name)) {
        const point = plant!.points.find((p) => `${plant!.id}.${p.name}`.toLowerCase() === col.name.toLowerCase());
        if (point?.kind !== 'operator') throw new ScenarioError(parsed.headerLine, `column ${col.name}: only the machine's operator controls can be set (${plant!.points.filter((p) => p.kind === 'operator').map((p) => `${plant!.id}.${p.name}`).join(', ')}); check its state with expect ${col.name}`);
        return [{ name: point.name, value: r.value, target: 'plant' as const }];
      }
      return [{ name: col.name, value: r.value }];
    }),
  );
  const checks = parsed.rows.map((row) =>
    [...row.cells].flatMap(([i, text]): Check[] => {
      const col = parsed.columns[i]!;
      if (col.kind !== 'expect') return [];
      const [valueText, tolText] = text.split('~');
      const r = parseValueText(types[i]!, valueText!);
      if (!r.ok) throw new ScenarioError(row.line, `column expect ${col.name}: ${r.message}`);
      return [{ column: i, type: types[i]!, value: r.value, tolerance: tolText !== undefined ? toleranceOf(tolText, row.line) : (col.tolerance ?? 0) }];
    }),
  );
  return { parsed, inputs, checks, types };
}

/**
 * Runs a prepared scenario on a PLC (cold restarted by the caller): inputs written before each
 * row's scan, checks after it. Stops after the first scan that diverges. `afterScan` sees every scan.
 */
export function runPrepared(
  plc: Plc,
  prep: PreparedScenario,
  afterScan?: (scan: number) => void,
  plant?: { readonly loop: PlantLoop; readonly cycleMs: number },
): Omit<ScenarioResult, 'name'> {
  const { parsed } = prep;
  if (parsed.plant && !plant) throw new ScenarioError(0, `the scenario runs against the machine ${parsed.plant}, which was not attached (internal)`);
  const loop = plant?.loop;
  loop?.bind(plc);
  const checked = new Set(parsed.columns.filter((c) => c.kind === 'expect').map((c) => c.name.toLowerCase()));
  const warnings: string[] = [];
  const done = (r: Omit<ScenarioResult, 'name'>): Omit<ScenarioResult, 'name'> => (warnings.length ? { ...r, warnings } : r);
  let row = 0;
  for (let scan = 1; scan <= parsed.scans; scan++) {
    const at = parsed.rows[row]?.scan === scan ? row : -1;
    if (at >= 0)
      for (const { name, value, target } of prep.inputs[at]!) {
        if (target === 'plant') loop!.setOperator(name, value === true);
        else if (target === 'fault') loop!.setFault(name, value === true);
        else plc.write(name, value);
      }
    const report = plc.scan();
    if (report.fault) {
      afterScan?.(scan);
      return done({ ok: false, scans: scan, divergences: [], error: `scan ${scan}: ${report.fault.message}` });
    }
    afterScan?.(scan);
    const events = loop?.afterScan(scan, (scan - 1) * plant!.cycleMs, plant!.cycleMs);
    const harm = events?.find((e) => e.severity === 'error' && !(e.counter && checked.has(`${loop!.model.id}.${e.counter}`.toLowerCase())));
    if (events) for (const e of events) if (e.severity === 'warning') warnings.push(e.text);
    if (harm)
      return done({
        ok: false,
        scans: scan,
        divergences: [],
        error: harm.text,
        ...(harm.counter ? { consequence: `${loop!.model.id}.${harm.counter}` } : {}),
      });
    if (at < 0) continue;
    row++;
    const divergences: Divergence[] = [];
    for (const check of prep.checks[at]!) {
      const col = parsed.columns[check.column]!;
      const actual = loop && col.name.toLowerCase().startsWith(`${loop.model.id}.`) ? loop.read(col.name) : plc.read(col.name);
      if (!matches(check, actual))
        divergences.push({
          scan,
          line: parsed.rows[at]!.line,
          name: col.name,
          expected: `${checkText(check.type, check.value)}${check.tolerance ? ` ± ${check.tolerance}` : ''}`,
          actual: checkText(check.type, actual),
        });
    }
    if (divergences.length) return done({ ok: false, scans: scan, divergences });
  }
  return done({ ok: true, scans: parsed.scans, divergences: [] });
}

/**
 * The scenario's cycle: its `# cycle:` line, else the task's interval, else 10 ms. A configuration
 * whose tasks run at different intervals (`schedule`) scans at their common tick, whatever the line says.
 */
export function scenarioCycle(project: Project, parsed: ParsedScenario, pou: string | undefined, schedule?: TaskSchedule): number {
  if (schedule?.multiRate) {
    const conflict = tickConflict(schedule, parsed.cycleMs);
    if (conflict) throw new ScenarioError(0, `"# cycle: ${parsed.cycleMs}ms" cannot apply: ${conflict}`);
    return schedule.tickMs;
  }
  if (parsed.cycleMs) return parsed.cycleMs;
  const task = project.tasks.find((t) => t.programs.some((p) => p.pou.toUpperCase() === pou?.toUpperCase()));
  return task?.cycleMs ?? 10;
}

export interface ScenarioRun {
  readonly result: ScenarioResult;
  /** With a divergence: the PLC stopped right after the divergent scan, and its program (for "Why?"). */
  readonly plc?: Plc;
  readonly program?: CompiledProgram;
}

/** Compiles the project and runs one scenario from a cold restart on the virtual clock. */
export function runScenario(project: Project, scenario: Scenario): ScenarioRun {
  const fail = (error: string): ScenarioRun => ({ result: { name: scenario.name, ok: false, scans: 0, divergences: [], error } });
  let parsed: ParsedScenario;
  try {
    parsed = parseScenario(scenario.csv, scenario.name);
  } catch (e) {
    return fail((e as Error).message);
  }
  // Without `# pou:`, what the simulator runs: the tasks' program instances (a configuration when
  // there are several, each task at its own interval), as the Tests panel's "Run" (in a simulation of its own) replays it.
  const { program, diagnostics } = compileProgram(project, parsed.pou ? { pou: parsed.pou } : runOptions(project));
  if (!program) {
    const first = diagnostics.find((d) => d.severity === 'error');
    return fail(`the program does not compile${first ? `: ${first.rule} ${first.pou}${first.network >= 0 ? ` network ${first.network + 1}` : ''}: ${first.message}` : ''}`);
  }
  let prep: PreparedScenario;
  try {
    prep = prepareScenario(parsed, program);
  } catch (e) {
    return fail((e as Error).message);
  }
  let cycleMs: number;
  try {
    cycleMs = scenarioCycle(project, parsed, program.pou, program.schedule);
  } catch (e) {
    return fail((e as Error).message);
  }
  const plc = createPlc(program, { cycleMs });
  let r: Omit<ScenarioResult, 'name'>;
  try {
    const plant = parsed.plant ? { loop: new PlantLoop(requirePlant(parsed.plant), project.plant?.id === parsed.plant ? project.plant.map : undefined), cycleMs } : undefined;
    r = runPrepared(plc, prep, undefined, plant);
  } catch (e) {
    return fail((e as Error).message);
  }
  return { result: { name: scenario.name, ...r }, ...(r.ok ? {} : { plc, program }) };
}
