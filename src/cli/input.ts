// Reading a project from a `.json` Rungsmith project or a PLCopen `.xml` file.
import { loadProject } from '../model/load';
import type { Project } from '../model/project';
import { importPlcopen } from '../plcopen/importPlcopen';
import type { ImportReport } from '../plcopen/types';
import { UsageError, type CliIo } from './io';
import { formatIssue } from './report';

export interface Loaded {
  readonly project: Project;
  readonly report?: ImportReport;
}

export function readText(io: CliIo, path: string): string {
  try {
    return io.readFile(path);
  } catch (e) {
    throw new UsageError(`cannot read ${path}: ${(e as NodeJS.ErrnoException).code ?? (e as Error).message}`);
  }
}

/** Loads FILE by its extension (.xml = PLCopen, otherwise a project JSON); import warnings go to stderr. */
export function loadInput(io: CliIo, path: string, quiet = false, profile?: 'iec' | 'openplc'): Loaded {
  const text = readText(io, path);
  if (/\.xml$/i.test(path) || text.trimStart().startsWith('<')) {
    // A profile asked for on the command line is imported for (network order, Beremiz's order).
    const r = importPlcopen(text, profile ? { profile } : undefined);
    if (!r.ok) throw new UsageError(r.errors.map((e) => `${path}: ${formatIssue(e)}`).join('\n'));
    if (!quiet) for (const w of r.report.warnings) io.err(`${path}: warning: ${formatIssue(w)}\n`);
    return { project: r.project, report: r.report };
  }
  const r = loadProject(text);
  if (!r.ok) throw new UsageError(r.errors.map((e) => `${path}: ${e.path}: ${e.message}`).join('\n'));
  return { project: r.project };
}
