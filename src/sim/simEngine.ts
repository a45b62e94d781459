// The engine as the simulation session sees it: compile, create a PLC, parse a typed value.
import type { Diagnostic, Plc, PlcOptions } from '../engine/api';
import type { Value } from '../model/iecTypes';
import type { Project } from '../model/project';

/** The engine as the session uses it (src/sim/engineAdapter.ts binds the real one). */
export interface SimEngine {
  compile(project: Project): { readonly program?: unknown; readonly diagnostics: readonly Diagnostic[] };
  createPlc(program: unknown, options: PlcOptions): Plc;
  parseValue(type: string, text: string): { ok: true; value: Value } | { ok: false; message: string };
}
