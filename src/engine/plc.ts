// The engine's entry points: compileProgram (check + lower a PROGRAM) and createPlc (run it).
import { withLibraries } from '../model/libraries';
import type { Project } from '../model/project';
import type { CompileOptions, Diagnostic, Plc, PlcOptions } from './api';
import { assembleProgram, type CompiledProgram } from './compile/program';
import { ScanPlc } from './runtime/scanner';

export type { CompiledProgram } from './compile/program';
export { planStateTransfer } from './runtime/instanceState';

/**
 * Checks and lowers one PROGRAM (default: the first). `program` is present only when there is no
 * error. The blocks of the project's libraries (project.libraries) are compiled with it.
 */
export function compileProgram(
  project: Project,
  opts: CompileOptions = {},
): { program?: CompiledProgram; diagnostics: Diagnostic[] } {
  return assembleProgram(withLibraries(project), opts);
}

/** A PLC running a compiled program, cold-restarted (every variable at its initial value). */
export function createPlc(program: CompiledProgram, opts: PlcOptions): Plc {
  if (!(opts.cycleMs > 0) && !opts.clock)
    throw new Error('cycleMs must be a positive number of milliseconds');
  const s = program.schedule;
  if (s?.multiRate && !opts.clock && opts.cycleMs !== s.tickMs)
    throw new Error(`the tasks run at different intervals or on events: a scan is their common tick of ${s.tickMs} ms, not ${opts.cycleMs} ms`);
  return new ScanPlc(program, opts);
}
