// `rungsmith simulate`: N scans on the virtual clock, a CSV trace of the watched values on stdout.
import { formatDiagnostic } from '../engine/compile/report';
import { describeSchedule, hasEventTask, tickConflict } from '../engine/compile/taskSchedule';
import { compileProgram, createPlc, type CompiledProgram } from '../engine/plc';
import { csvValue, parseValueText } from '../engine/values/literals';
import type { ElementaryType } from '../model/iecTypes';
import { blockLibrary } from '../model/library';
import type { Profile, Project } from '../model/project';
import { parseInterval } from '../plcopen/durations';
import { UsageError, type CliIo } from './io';
import { parseStimulus, type Stimulus } from './stimulus';
import { csvRow } from '../sim/csv';
import { machineNameHint, requirePlant, strayMapWarning } from '../plant/machines';
import type { PlantModel } from '../plant/types';
import { PlantLoop, plantValueType } from '../plant/loop';

export interface SimulateOptions {
  readonly pou?: string;
  readonly stimulus?: { readonly text: string; readonly file: string };
  readonly scans?: number;
  readonly cycle?: string;
  readonly watch?: string;
  readonly profile?: Profile;
  /** A machine in closed loop with the program (`tank`): stepped after every scan. */
  readonly plant?: string;
}

/** 10ms, 10, T#10ms, 0.5s → milliseconds. */
export function parseCycle(text: string): number {
  const t = text.trim();
  const ms = /^\d+(\.\d+)?$/.test(t) ? Number(t) : parseInterval(/^T(IME)?#/i.test(t) ? t : `T#${t}`);
  if (ms === undefined || !(ms > 0))
    throw new UsageError(`--cycle "${text}" is not a cycle time; write it like 10ms, 0.5s or T#100ms`);
  return ms;
}

/**
 * The time of one scan: --cycle, else the task's interval; tasks at different intervals run on their
 * common tick (a scan is one tick), which --cycle cannot change.
 */
function scanCycle(program: CompiledProgram, cycle: string | undefined, taskMs: number): number {
  const s = program.schedule;
  if (!s?.multiRate) return cycle !== undefined ? parseCycle(cycle) : taskMs;
  const conflict = tickConflict(s, cycle === undefined ? undefined : parseCycle(cycle));
  if (conflict) throw new UsageError(`--cycle ${cycle}: ${conflict}; leave --cycle out or give ${s.tickMs}ms`);
  return s.tickMs;
}

/** False for a body the simulator does not run (FBD kept as FBD, CODESYS CFC): a task's other program runs. */
const runs = (pou: Project['pous'][number]): boolean => pou.language !== 'FBD';

function programName(project: Project, wanted: string | undefined): string {
  if (wanted) return wanted;
  for (const t of project.tasks)
    for (const p of t.programs) {
      const pou = project.pous.find(
        (x) => x.name.toUpperCase() === p.pou.toUpperCase() && x.kind === 'PROGRAM' && runs(x),
      );
      if (pou) return pou.name;
    }
  const first = project.pous.find((p) => p.kind === 'PROGRAM' && runs(p)) ?? project.pous.find((p) => p.kind === 'PROGRAM');
  if (!first) throw new UsageError('the project has no PROGRAM to simulate');
  return first.name;
}

/**
 * Default watch: the POU's variables in declaration order, FB instances as INSTANCE.PIN (a user
 * FB's pins are its VAR_INPUTs and VAR_OUTPUTs); `prefix` names a program instance (`Line1.`).
 */
function defaultWatch(project: Project, pouName: string, names: readonly string[], prefix = ''): string[] {
  const pou = project.pous.find((p) => p.name.toUpperCase() === pouName.toUpperCase())!;
  const known = new Set(names.map((n) => n.toUpperCase()));
  const user = blockLibrary(project);
  const out: string[] = [];
  for (const v of pou.variables) {
    const name = `${prefix}${v.name}`;
    const fb = user.userPou(v.type);
    if (fb && fb.kind === 'FUNCTION_BLOCK') {
      for (const m of fb.variables)
        if ((m.varClass === 'input' || m.varClass === 'output') && known.has(`${name}.${m.name}`.toUpperCase()))
          out.push(`${name}.${m.name}`);
      continue;
    }
    // FB pins, and the leaves of a struct or array variable (P.X, A[1], G[1,2]).
    const pins = names.filter((n) => n.toUpperCase().startsWith(`${name.toUpperCase()}.`) || n.toUpperCase().startsWith(`${name.toUpperCase()}[`));
    if (pins.length) out.push(...pins);
    else if (known.has(name.toUpperCase())) out.push(name);
  }
  return out;
}

/** Program instances of the project's tasks, when there are several or an event task: simulated together. */
function configurationOf(project: Project): { instance: string; pou: string }[] | undefined {
  const instances = project.tasks.flatMap((t) => t.programs);
  return instances.length > 1 || hasEventTask(project.tasks) ? instances : undefined;
}

/**
 * The variable a name given to --watch/--inputs means. In a configuration, a bare name that is not a
 * global is the first program instance's (of the first task: what Beremiz/OpenPLC's debugger and the
 * MATIEC reference trace); `Inst.Var` names any instance.
 */
function resolveName(program: CompiledProgram, name: string, firstInstance: string | undefined): string {
  const opts = { literals: false, implicitLocations: false } as const;
  const r = program.symbols.resolve(name, opts);
  if (r.ok || !firstInstance) return name;
  const inInstance = `${firstInstance}.${name}`;
  return program.symbols.resolve(inInstance, opts).ok ? inInstance : name;
}

function typeOf(program: CompiledProgram, name: string, plant: PlantModel | undefined): ElementaryType {
  if (!plant && /^fault\s+\S+$/i.test(name.trim()))
    throw new UsageError(`"${name}" sets a machine's fault: run the program with its machine (--plant NAME)`);
  const r = program.symbols.resolve(name, { literals: false, implicitLocations: false });
  if (!r.ok) {
    const hint = machineNameHint(name, plant, (id) => `add --plant ${id}`);
    throw new UsageError(`unknown variable "${name}": ${r.message}${hint ? `; ${hint}` : ''}`);
  }
  if (r.access.kind === 'const') throw new UsageError(`"${name}" is a constant, not a variable`);
  return r.access.type;
}

export function simulate(io: CliIo, project: Project, opts: SimulateOptions): number {
  // Without --pou, a project whose tasks run several program instances runs them all, in order.
  const configuration = opts.pou === undefined ? configurationOf(project) : undefined;
  const pou = configuration ? 'the configuration' : programName(project, opts.pou);
  const { program, diagnostics } = compileProgram(project, {
    ...(configuration ? { configuration: true } : { pou }),
    ...(opts.profile ? { profile: opts.profile } : {}),
  });
  for (const d of diagnostics) if (d.severity === 'warning') io.err(`${formatDiagnostic(d)}\n`);
  if (!program) {
    for (const d of diagnostics) if (d.severity === 'error') io.err(`${formatDiagnostic(d)}\n`);
    io.err(`the program ${pou} has errors; it cannot be simulated\n`);
    return 1;
  }
  const task = configuration
    ? project.tasks.find((t) => t.programs.length > 0)
    : project.tasks.find((t) => t.programs.some((p) => p.pou.toUpperCase() === pou.toUpperCase()));
  const cycleMs = scanCycle(program, opts.cycle, task?.cycleMs ?? 10);
  if (program.schedule?.multiRate) io.err(`one scan = one tick of ${cycleMs} ms: ${describeSchedule(program.schedule)}\n`);
  const plc = createPlc(program, { cycleMs });
  let loop: PlantLoop | undefined;
  if (opts.plant !== undefined) {
    try {
      const model = requirePlant(opts.plant);
      loop = new PlantLoop(model, project.plant?.id === model.id ? project.plant.map : undefined, 0);
      const stray = project.plant?.id === model.id ? strayMapWarning(project.plant) : undefined;
      if (stray) io.err(`${stray}\n`);
    } catch (e) {
      throw new UsageError(`--plant: ${(e as Error).message}`);
    }
    loop.bind(plc);
  }
  /** `tank.level`, `tank.Start`: the machine's; `fault high_stuck_off`: its fault. */
  const onPlant = (name: string) => loop !== undefined && name.toLowerCase().startsWith(`${loop.model.id}.`);
  const faultOf = (name: string) => (loop ? /^fault\s+(\S+)$/i.exec(name.trim())?.[1] : undefined);
  const names = plc.variableNames();
  const watch =
    opts.watch !== undefined
      ? opts.watch
          .split(/,(?![^[]*\])/) // commas between names, not inside G[1,2]
          .map((s) => s.trim())
          .filter(Boolean)
      : configuration
        ? configuration.flatMap((c) => defaultWatch(project, c.pou, names, `${c.instance}.`))
        : defaultWatch(project, pou, names);
  const firstInstance = configuration?.[0]?.instance;
  const watched = watch.map((w) => (onPlant(w) ? w : resolveName(program, w, firstInstance)));
  const types = watched.map((w): ElementaryType => {
    if (!onPlant(w)) return typeOf(program, w, loop?.model);
    const t = plantValueType(loop!.model, w);
    if (!t) throw new UsageError(`--watch: ${loop!.model.id} has no quantity or point "${w.slice(loop!.model.id.length + 1)}" (rungsmith plants ${loop!.model.id} lists them)`);
    return t;
  });
  const read = (w: string) => (onPlant(w) ? loop!.read(w) : plc.read(w));
  const stim: Stimulus | undefined = opts.stimulus
    ? parseStimulus(opts.stimulus.text, opts.stimulus.file)
    : undefined;
  const stimTypes = new Map<string, ElementaryType>();
  for (const c of stim?.columns ?? []) {
    try {
      const fault = faultOf(c);
      if (fault !== undefined || onPlant(c)) {
        // Checked before the first scan: only the machine's operator controls and faults can be set.
        const model = loop!.model;
        if (fault !== undefined && !model.faults.some((f) => f.id === fault.toLowerCase()))
          throw new Error(`${model.id} has no fault "${fault}"; it has ${model.faults.map((f) => f.id).join(', ')}`);
        const operators = model.points.filter((p) => p.kind === 'operator');
        if (fault === undefined && !plantValueType(model, c))
          throw new Error(`${model.id} has no operator control "${c.slice(model.id.length + 1)}"; it has ${operators.map((p) => p.name).join(', ')}`);
        if (fault === undefined && !operators.some((p) => `${model.id}.${p.name}`.toLowerCase() === c.toLowerCase()))
          throw new Error(
            `only the machine's operator controls can be set (${operators.map((p) => `${model.id}.${p.name}`).join(', ')}); watch its state with --watch ${c}`,
          );
        stimTypes.set(c, 'BOOL');
        continue;
      }
      stimTypes.set(c, typeOf(program, resolveName(program, c, firstInstance), loop?.model));
    } catch (e) {
      throw new UsageError(`${opts.stimulus!.file}: column "${c}": ${(e as Error).message}`);
    }
  }
  const lastStim = stim?.rows.length ? stim.rows[stim.rows.length - 1]!.scan : 0;
  const scans = opts.scans ?? Math.max(lastStim, 10);
  const lines: string[] = [csvRow(['scan', 'time_ms', ...watch])];
  let next = 0;
  for (let k = 1; k <= scans; k++) {
    while (stim && next < stim.rows.length && stim.rows[next]!.scan === k) {
      const row = stim.rows[next++]!;
      for (const [name, text] of row.values) {
        const parsed = parseValueText(stimTypes.get(name)!, text);
        if (!parsed.ok)
          throw new UsageError(`${opts.stimulus!.file} line ${row.line}, column ${name}: ${parsed.message}`);
        try {
          const fault = faultOf(name);
          if (fault !== undefined) loop!.setFault(fault, parsed.value === true);
          else if (onPlant(name)) loop!.setOperator(name.slice(loop!.model.id.length + 1), parsed.value === true);
          else plc.write(resolveName(program, name, firstInstance), parsed.value);
        } catch (e) {
          throw new UsageError(
            `${opts.stimulus!.file} line ${row.line}, column ${name}: ${(e as Error).message}`,
          );
        }
      }
    }
    const report = plc.scan();
    if (report.fault) {
      io.out(`${lines.join('\n')}\n`);
      io.err(`fault in scan ${k}: ${report.fault.message}\n`);
      return 1;
    }
    for (const e of loop?.afterScan(k, (k - 1) * cycleMs, cycleMs) ?? []) io.err(`${e.severity} ${loop!.model.id}: ${e.text}\n`);
    const row = [String(k), String((k - 1) * cycleMs)];
    watched.forEach((w, i) => row.push(csvValue(types[i]!, read(w))));
    // RFC 4180: a cell with a comma, a quote or a line break is quoted (STRING values).
    lines.push(csvRow(row));
  }
  io.out(`${lines.join('\n')}\n`);
  return 0;
}
