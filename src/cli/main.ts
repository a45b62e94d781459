// The `rungsmith` command: check, simulate, export, import (ARCHITECTURE.md "Contracts").
import { parseArgs } from 'node:util';
import { checkProject } from '../engine/check';
import { formatDiagnostic } from '../engine/compile/report';
import { saveProject } from '../model/load';
import { exportBehaviour, formatExportWarning } from '../plcopen/exportBehaviour';
import { exportPlcopen } from '../plcopen/exportPlcopen';
import { HELP } from './help';
import { loadInput } from './input';
import { UsageError, type CliIo } from './io';
import { simulate } from './simulate';
import { testProject } from './test';
import { listPlants } from './plants';

const COMMANDS = ['check', 'simulate', 'export', 'import', 'test', 'plants'] as const;
type Command = (typeof COMMANDS)[number];

function parse(command: Command, args: string[]) {
  try {
    return parseArgs({
      args,
      allowPositionals: true,
      strict: true,
      options: {
        help: { type: 'boolean', short: 'h' },
        output: { type: 'string', short: 'o' },
        ...(command === 'simulate'
          ? {
              pou: { type: 'string' },
              inputs: { type: 'string' },
              scans: { type: 'string' },
              cycle: { type: 'string' },
              watch: { type: 'string' },
              profile: { type: 'string' },
              plant: { type: 'string' },
            }
          : {}),
        ...(command === 'test' ? { junit: { type: 'string' }, scenario: { type: 'string' } } : {}),
      },
    });
  } catch (e) {
    throw new UsageError(`${(e as Error).message}\n\n${HELP[command]}`);
  }
}

function oneFile(command: Command, positionals: string[]): string {
  if (positionals.length !== 1) throw new UsageError(`${command} needs exactly one FILE\n\n${HELP[command]}`);
  return positionals[0]!;
}

function run(io: CliIo, argv: readonly string[]): number {
  const [first, ...rest] = argv;
  if (!first || first === '--help' || first === '-h' || first === 'help') {
    const topic = first === 'help' ? rest[0] : undefined;
    io.out(
      `${topic && (COMMANDS as readonly string[]).includes(topic) ? HELP[topic as Command] : HELP.main}\n`,
    );
    return first ? 0 : 2;
  }
  if (first === '--version') {
    io.out('rungsmith 0.1.0\n');
    return 0;
  }
  if (!(COMMANDS as readonly string[]).includes(first))
    throw new UsageError(`unknown command "${first}"\n\n${HELP.main}`);
  const command = first as Command;
  const { values, positionals } = parse(command, rest);
  if (values.help) {
    io.out(`${HELP[command]}\n`);
    return 0;
  }
  if (command === 'plants') {
    if (positionals.length > 1) throw new UsageError(`plants takes at most one machine\n\n${HELP.plants}`);
    io.out(listPlants(positionals[0]));
    return 0;
  }
  const file = oneFile(command, positionals);
  switch (command) {
    case 'check': {
      const { project } = loadInput(io, file);
      const diagnostics = checkProject(project);
      for (const d of diagnostics) io.out(`${formatDiagnostic(d)}\n`);
      return diagnostics.some((d) => d.severity === 'error') ? 1 : 0;
    }
    case 'simulate': {
      const v = values as Record<string, string | boolean | undefined>;
      const scansText = v.scans as string | undefined;
      const scans = scansText === undefined ? undefined : Number(scansText);
      if (scans !== undefined && !(Number.isInteger(scans) && scans >= 0))
        throw new UsageError(`--scans "${scansText}" is not a number of scans`);
      const profile = v.profile as string | undefined;
      if (profile !== undefined && profile !== 'iec' && profile !== 'openplc')
        throw new UsageError(`--profile must be iec or openplc, not "${profile}"`);
      const { project } = loadInput(io, file, false, profile);
      const inputs = v.inputs as string | undefined;
      return simulate(io, project, {
        ...(v.pou !== undefined ? { pou: v.pou as string } : {}),
        ...(inputs !== undefined ? { stimulus: { text: readStim(io, inputs), file: inputs } } : {}),
        ...(scans !== undefined ? { scans } : {}),
        ...(v.cycle !== undefined ? { cycle: v.cycle as string } : {}),
        ...(v.watch !== undefined ? { watch: v.watch as string } : {}),
        ...(profile ? { profile } : {}),
        ...(v.plant !== undefined ? { plant: v.plant as string } : {}),
      });
    }
    case 'test': {
      const { project } = loadInput(io, file);
      const v = values as Record<string, string | boolean | undefined>;
      return testProject(io, project, {
        ...(typeof v.junit === 'string' ? { junit: v.junit } : {}),
        ...(typeof v.scenario === 'string' ? { scenario: v.scenario } : {}),
      });
    }
    case 'export': {
      const { project } = loadInput(io, file);
      const xml = exportPlcopen(project);
      if (values.output) io.writeFile(values.output, xml);
      else io.out(xml);
      // What Beremiz/OpenPLC would run differently (LD-X rules): said, never an error.
      for (const w of exportBehaviour(project))
        io.err(`${formatExportWarning(w)}${w.fix ? ` Fix: ${w.fix.label}.` : ''}\n`);
      return 0;
    }
    case 'import': {
      const { project, report } = loadInput(io, file);
      const json = saveProject(project);
      if (values.output) io.writeFile(values.output, json);
      else io.out(json);
      if (report) {
        const pous = report.pous
          .map((p) => `${p.name} (${p.networks} network${p.networks === 1 ? '' : 's'})`)
          .join(', ');
        io.err(
          `imported ${report.pous.length} LD POU${report.pous.length === 1 ? '' : 's'}: ${pous || 'none'}; ${report.warnings.length} warning${report.warnings.length === 1 ? '' : 's'}\n`,
        );
        io.err(`${report.profileReason} (rungsmith simulate --profile overrides it)\n`);
      }
      return 0;
    }
  }
}

function readStim(io: CliIo, path: string): string {
  try {
    return io.readFile(path);
  } catch (e) {
    throw new UsageError(`cannot read ${path}: ${(e as NodeJS.ErrnoException).code ?? (e as Error).message}`);
  }
}

/** Runs the command; returns the exit code (0 ok, 1 errors in the program, 2 bad usage or input). */
export function main(argv: readonly string[], io: CliIo): number {
  try {
    return run(io, argv);
  } catch (e) {
    if (e instanceof UsageError) {
      io.err(`rungsmith: ${e.message}\n`);
      return 2;
    }
    io.err(`rungsmith: internal error: ${(e as Error).stack ?? String(e)}\n`);
    return 70;
  }
}
