// A scripted, deterministic stimulus for any program and the trace it gives: what "behaves the
// same" means for the export tests (tests/interop/trace.test.ts, tests/plcopen/exportBehaviour.test.ts).
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Value } from '../../src/model/iecTypes';
import type { Pou, Project } from '../../src/model/project';

/**
 * Variables a program writes: coils and block output operands of LD networks, `X :=` / `ST X` in
 * text bodies, output variables of kept FBD bodies (`<expression>X</expression>`).
 */
export function writtenNames(project: Project): (name: string) => boolean {
  const written = new Set<string>();
  for (const pou of project.pous)
    for (const net of pou.networks)
      for (const el of net.elements) {
        if (el.kind === 'coil') written.add(el.variable.toUpperCase());
        if (el.kind === 'box') for (const v of Object.values(el.outputs)) if (v) written.add(v.toUpperCase());
      }
  const texts = project.pous.map((p) => p.source ?? '').join('\n');
  return (name) => {
    if (written.has(name.toUpperCase())) return true;
    const n = name.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
    return new RegExp(`\\b${n}\\s*:=|\\b(?:ST|S|R)\\s+${n}\\b|<expression>\\s*${n}\\s*</expression>`, 'i').test(texts);
  };
}

/**
 * Input-like variables of a program: located %I inputs, VAR_INPUTs, and unlocated BOOLs nothing
 * writes (the program's own and the globals), in declaration order.
 */
export function inputLike(project: Project, pou: Pou): string[] {
  const isWritten = writtenNames(project);
  const names: string[] = [];
  for (const v of [...pou.variables, ...project.globals]) {
    if (v.constant || v.varClass === 'external') continue;
    if (v.location?.startsWith('%I') || v.varClass === 'input') names.push(v.name);
    else if (!v.location && v.type.toUpperCase() === 'BOOL' && !isWritten(v.name)) names.push(v.name);
  }
  return [...new Set(names)];
}

/** A small deterministic hash (seeded pattern): the same bits for the same arguments. */
function bit(seed: number, j: number, k: number): boolean {
  let h = (seed * 374761393 + j * 668265263 + k * 2246822519) >>> 0;
  h = Math.imul(h ^ (h >>> 13), 1274126177) >>> 0;
  return ((h ^ (h >>> 16)) & 1) === 1;
}

/** The value of input j before scan k (1-based): BOOLs toggled by a seeded pattern, numbers ramped. */
function stimulus(current: Value, j: number, k: number, seed: number): Value | undefined {
  const period = 1 + (j % 5); // each input changes at its own pace
  if (typeof current === 'boolean') return bit(seed, j, Math.floor(k / period));
  if (typeof current === 'number') return ((k * (j + 1)) % 100) + (Number.isInteger(current) ? 0 : 0.5);
  if (typeof current === 'bigint') return BigInt((k * (j + 1)) % 100);
  return undefined;
}

export interface ProgramTrace {
  readonly pou: string;
  /** Stimulated variables. */
  readonly inputs: readonly string[];
  /** One line per scan: every variable's value after the scan, `name=value` sorted by name. */
  readonly rows: readonly string[];
  readonly fault?: string;
}

/** The task interval of a program (its task's, else the first task's, else 10 ms). */
export function cycleOf(project: Project, pou: string): number {
  const task =
    project.tasks.find((t) => t.programs.some((p) => p.pou.toUpperCase() === pou.toUpperCase())) ?? project.tasks[0];
  return task?.cycleMs ?? 10;
}

/** Runs `scans` scans of PROGRAM `pou` under the stimulus; undefined when it does not compile. */
export function traceProgram(project: Project, pou: string, scans = 200, seed = 12): ProgramTrace | undefined {
  const { program } = compileProgram(project, { pou });
  if (!program) return undefined;
  const plc = createPlc(program, { cycleMs: cycleOf(project, pou) });
  const known = new Map(plc.variableNames().map((n) => [n.toUpperCase(), n]));
  const inputs = inputLike(project, project.pous.find((p) => p.name === pou)!)
    .map((n) => known.get(n.toUpperCase()))
    .filter((n): n is string => n !== undefined);
  const rows: string[] = [];
  for (let k = 1; k <= scans; k++) {
    inputs.forEach((name, j) => {
      const v = stimulus(plc.read(name), j, k, seed);
      if (v !== undefined) plc.write(name, v);
    });
    const r = plc.scan();
    if (r.fault) return { pou, inputs, rows, fault: `scan ${k}: ${r.fault.message}` };
    const values = plc.values();
    rows.push(
      Object.keys(values)
        .sort()
        .map((n) => `${n}=${String(values[n])}`)
        .join(' '),
    );
  }
  return { pou, inputs, rows };
}

/** The first scan where two traces differ, with both rows, or '' when they are the same. */
export function firstDifference(a: ProgramTrace, b: ProgramTrace): string {
  if (a.fault !== b.fault) return `fault: ${a.fault ?? 'none'} vs ${b.fault ?? 'none'}`;
  const n = Math.max(a.rows.length, b.rows.length);
  for (let k = 0; k < n; k++) {
    if (a.rows[k] === b.rows[k]) continue;
    const left = new Set((a.rows[k] ?? '').split(' '));
    const right = new Set((b.rows[k] ?? '').split(' '));
    const only = (x: Set<string>, y: Set<string>) => [...x].filter((s) => !y.has(s)).join(' ');
    return `${a.pou} scan ${k + 1}: before ${only(left, right)} | after ${only(right, left)}`;
  }
  return '';
}

/** The trace without some variables (e.g. the ones a fix declares), to compare the rest. */
export function without(t: ProgramTrace, names: readonly string[]): ProgramTrace {
  const drop = new Set(names.map((n) => n.toUpperCase()));
  return {
    ...t,
    rows: t.rows.map((r) =>
      r
        .split(' ')
        .filter((kv) => !drop.has(kv.slice(0, kv.indexOf('=')).toUpperCase()))
        .join(' '),
    ),
  };
}
