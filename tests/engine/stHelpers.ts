// Test helper: projects with POUs written in ST or IL.
import { newPou, newProject } from '../../src/model/factory';
import type { Pou, PouKind, Profile, Project, Variable } from '../../src/model/project';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { Plc } from '../../src/engine/api';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { io } from './userBlocksHelpers';
import { vars } from './ladder';

export { io, vars };

/** A POU whose body is ST (or IL) text. */
export function textPou(
  name: string,
  kind: PouKind,
  variables: readonly Variable[],
  source: string,
  opts: { language?: 'ST' | 'IL'; returnType?: string } = {},
): Pou {
  return newPou(name, {
    kind,
    variables,
    networks: [],
    language: opts.language ?? 'ST',
    source,
    ...(opts.returnType ? { returnType: opts.returnType } : {}),
  });
}

export function stProject(pous: readonly Pou[], profile: Profile = 'iec', globals: readonly Variable[] = []): Project {
  return newProject('Test', { pous, profile, globals });
}

/** A PLC of the project's first PROGRAM; throws with the diagnostics when it does not compile. */
export function stPlc(p: Project, opts: { cycleMs?: number; maxScanMs?: number } = {}): Plc {
  const { program, diagnostics } = compileProgram(p, {});
  if (!program) throw new Error(`program does not compile:\n${diagnostics.map(formatDiagnostic).join('\n')}`);
  return createPlc(program, { cycleMs: opts.cycleMs ?? 10, ...(opts.maxScanMs ? { maxScanMs: opts.maxScanMs } : {}) });
}

/** A PROGRAM Main in ST with the given variables (locals unless given by `io`). */
export function stMain(source: string, variables: readonly Variable[], others: readonly Pou[] = [], profile: Profile = 'iec'): Plc {
  return stPlc(stProject([textPou('Main', 'PROGRAM', variables, source), ...others], profile));
}

/** Errors of compiling the project, formatted. */
export function stErrors(p: Project): string[] {
  return compileProgram(p, {}).diagnostics.filter((d) => d.severity === 'error').map(formatDiagnostic);
}

/** Scans `n` times and reads the names. */
export function scanRead(plc: Plc, n: number, names: readonly string[]): unknown[] {
  for (let i = 0; i < n; i++) plc.scan();
  return names.map((x) => plc.read(x));
}
