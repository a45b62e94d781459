// compileProgram: the checked, lowered form of one PROGRAM POU (or of a task configuration: every
// program instance of the project's tasks, in declaration order, each run by its task at the task's
// interval or on its trigger's rising edge: taskSchedule.ts, taskTriggers.ts), with every call of a user FB or function flattened into body networks
// (flatten.ts), ready for createPlc.
import type { Pou, Project } from '../../model/project';
import { blockLibrary } from '../../model/library';
import type { CompileOptions, Diagnostic, TaskSchedule } from '../api';
import type { ResolvedFunction } from '../library/fnTypes';
import type { ElementaryType } from '../../model/iecTypes';
import { checkRecursion, reachablePous } from './callGraph';
import type { EdgeOwner } from './context';
import { reportDataTypes } from './aggregates';
import { Flattener, type BodyInfo } from './flatten';
import type { NetworkIR } from './ir';
import { checkDeclarations, lowerPou } from './pou';
import { Reporter } from './report';
import { SymbolTable, type Store, type VarSymbol } from './symbols';
import { buildSymbols, declareGlobals, storageFor } from './pouSymbols';
import { taskSchedule } from './taskSchedule';
import { taskTriggers, type TaskTrigger } from './taskTriggers';

export type { EdgeOwner } from './context';
export type { BodyInfo } from './flatten';

export interface CompiledProgram {
  /** The program's POU (a configuration: the first program's). */
  readonly pou: string;
  readonly profile: Project['profile'];
  /** Every network: the programs', then the bodies of calls. */
  readonly networks: readonly NetworkIR[];
  /** Number of elements and vertical links per network, for the power snapshot. */
  readonly shapes: readonly { readonly elements: number; readonly vlinks: number }[];
  readonly symbols: SymbolTable;
  readonly functions: readonly ResolvedFunction[];
  readonly edgeCount: number;
  /** Who owns each edge memory (indexed like the memories): the element, for online change. */
  readonly edges: readonly EdgeOwner[];
  readonly dataSlots: readonly {
    readonly store: Store;
    readonly slot: number;
    readonly type: ElementaryType;
  }[];
  /** Variables kept over a warm restart: RETAIN ones and those written by M/SM/RM coils. */
  readonly retentive: ReadonlySet<VarSymbol>;
  /** The programs, in declaration order: bodies 0..programs-1. */
  readonly programs: number;
  /**
   * A configuration: its tasks' rates, and the task of each program (indexed like bodies
   * 0..programs-1). A scan runs the programs whose task is due at that tick.
   */
  readonly schedule?: TaskSchedule;
  readonly programTask?: Int32Array;
  /** Each event task's trigger (indexed like `schedule.tasks`; undefined for a cyclic task). */
  readonly triggers?: readonly (TaskTrigger | undefined)[];
  /** Network ranges: programs, then one per call of a user FB or function. */
  readonly bodies: readonly BodyInfo[];
  /** Body of each network. */
  readonly bodyOf: Int32Array;
  /** Where the programs' networks end: networks [0, mainEnd) are the programs'. */
  readonly mainEnd: number;
  /** User FB instances (path, FB type), in declaration order, nested ones after their parent. */
  readonly instances: readonly { readonly path: string; readonly type: string }[];
}

function findPou(project: Project, name: string): Pou | undefined {
  return project.pous.find((p) => p.name.toUpperCase() === name.trim().toUpperCase());
}

export function assembleProgram(
  project: Project,
  opts: CompileOptions,
): { program?: CompiledProgram; diagnostics: Diagnostic[] } {
  const diagnostics: Diagnostic[] = [];
  const globals: Diagnostic[] = [];
  reportDataTypes(project, globals);
  const profile = opts.profile ?? project.profile;
  const library = blockLibrary(project);
  const flat = new Flattener(project, profile);
  let root: SymbolTable;
  let roots: Pou[];
  let schedule: { rates: TaskSchedule; programTask: Int32Array; triggers: (TaskTrigger | undefined)[] } | undefined;
  if (opts.configuration) {
    const r = new Reporter(diagnostics, project.name, -1);
    // Indexed like the schedule's tasks: those that run programs.
    const instances = project.tasks.filter((t) => t.programs.length > 0).flatMap((t, task) => t.programs.map((p) => ({ ...p, task })));
    if (instances.length === 0) {
      r.error('LD-E20', 'no task runs a program; add a program instance to a task');
      return { diagnostics };
    }
    root = new SymbolTable(storageFor(project, profile), '', library);
    declareGlobals(root, project, new Reporter(globals, 'globals', -1));
    roots = [];
    const seen = new Set<string>();
    const bound: { name: string; pou: Pou; task: number }[] = [];
    for (const inst of instances) {
      const pou = findPou(project, inst.pou);
      if (!pou || pou.kind !== 'PROGRAM') {
        r.error(
          'LD-E20',
          pou
            ? `the program instance ${inst.instance} runs ${pou.name}, a ${pou.kind}; only a PROGRAM can be run`
            : `the program instance ${inst.instance} runs "${inst.pou}", which is not a POU of the project`,
        );
        continue;
      }
      if (pou.language === 'FBD') {
        // A body the simulator does not run (FBD kept as FBD, CODESYS CFC): the task's other
        // programs run without it, and the run says so.
        r.warning(
          'LD-W51',
          `the program instance ${inst.instance} runs ${pou.name}, written in ${pou.source?.trimStart().startsWith('<CFC') ? 'CFC' : 'FBD'}, which the simulator does not run: the configuration runs without it`,
        );
        continue;
      }
      if (seen.has(inst.instance.toUpperCase()) || root.lookup(inst.instance)) {
        r.error('LD-E20', `the program instance name ${inst.instance} is used twice (or is a global's name)`);
        continue;
      }
      seen.add(inst.instance.toUpperCase());
      if (!roots.includes(pou)) roots.push(pou);
      bound.push({ name: inst.instance, pou, task: inst.task });
    }
    if (!bound.length && !diagnostics.some((d) => d.severity === 'error'))
      r.error('LD-E20', 'no task runs a program the simulator can run (LD, ST, IL or SFC)');
    const rates = taskSchedule(project.tasks);
    const triggers = taskTriggers(root, rates, r);
    if (diagnostics.some((d) => d.severity === 'error') || !triggers) return { diagnostics };
    // Each program is checked on its own (its findings name its variables as the program sees
    // them). Its declarations are checked here; its networks are lowered for its first instance
    // below, and only when that lowering finds anything are they lowered again on the program's
    // own table for the findings' words: a program without findings is not lowered twice (half of
    // an online change's compile of a 650-network program). An SFC program is checked as before.
    const rootFindings = roots.map((pou): Diagnostic[] => {
      const out: Diagnostic[] = [];
      if (pou.language === 'SFC') lowerPou(project, pou, profile, out, []);
      else checkDeclarations(project, pou, profile, out);
      return out;
    });
    const calleeFindings: Diagnostic[] = [];
    if (!checkCallees(project, roots, profile, calleeFindings)) {
      // Nothing is lowered: every program is checked on its own, for the Problems list.
      for (const pou of roots) lowerPou(project, pou, profile, diagnostics, []);
      return { diagnostics: [...globals, ...diagnostics, ...calleeFindings] };
    }
    flat.setRoot(root);
    // Every program's range first (contiguous, in declaration order), then their bodies and callees.
    const reserved = bound.map((b) => flat.reserve(b.pou, { kind: 'program', instance: b.name }));
    const instanceFindings = new Map<Pou, Diagnostic[]>();
    bound.forEach((b, i) => {
      const u = root.instantiate(b.pou, b.name, false);
      root.bind(b.name, u);
      let sink: Diagnostic[] | undefined;
      if (b.pou.language !== 'SFC' && !instanceFindings.has(b.pou)) instanceFindings.set(b.pou, (sink = []));
      if (reserved[i]) flat.lower(reserved[i], u.scope, sink);
    });
    roots.forEach((pou, i) => {
      const found = instanceFindings.get(pou);
      if (!found?.length) return;
      // Found something: the program's own check, for its findings in its own words.
      const own: Diagnostic[] = [];
      lowerPou(project, pou, profile, own, []);
      // (Never expected: an error of the instance's lowering the own check does not see is still reported.)
      const isError = (d: Diagnostic) => d.severity === 'error';
      if (found.some(isError) && !own.some(isError)) own.push(...found.filter(isError));
      rootFindings[i] = own;
    });
    diagnostics.push(...rootFindings.flat(), ...calleeFindings);
    schedule = { rates, programTask: Int32Array.from(bound, (b) => b.task), triggers };
  } else {
    const pou = opts.pou ? findPou(project, opts.pou) : project.pous.find((p) => p.kind === 'PROGRAM');
    const r = new Reporter(diagnostics, opts.pou ?? project.name, -1);
    if (!pou) {
      r.error(
        'LD-E20',
        opts.pou
          ? `there is no POU named "${opts.pou}" in the project`
          : 'the project has no PROGRAM to run; add one',
      );
      return { diagnostics };
    }
    if (pou.kind !== 'PROGRAM') {
      r.error('LD-E20', `${pou.name} is a ${pou.kind}; only a PROGRAM can be run`);
      return { diagnostics };
    }
    roots = [pou];
    const varReporter = new Reporter(diagnostics, pou.name, -1);
    if (!checkCallees(project, roots, profile, diagnostics)) {
      // Still check the program itself for the Problems list.
      lowerPou(project, pou, profile, diagnostics, globals);
      return { diagnostics: [...globals, ...diagnostics] };
    }
    root = buildSymbols(project, pou, varReporter, new Reporter(globals, 'globals', -1), library, profile);
    flat.setRoot(root);
    flat.body(pou, root, { kind: 'program' }, diagnostics);
  }
  diagnostics.unshift(...globals);
  const hasError = diagnostics.some((d) => d.severity === 'error');
  const networks = flat.complete();
  if (hasError || !networks) {
    if (!hasError) diagnostics.push(...flat.errors);
    return { diagnostics };
  }
  const programs = flat.bodies.filter((b) => b.kind === 'program').length;
  const mainEnd = programs ? flat.bodies[programs - 1]!.end : 0;
  const retentive = new Set<VarSymbol>(flat.shared.retentiveCoilVars);
  for (const v of root.vars) if (v.retain) retentive.add(v);
  const programNames = new Set(roots.map((p) => p.name.toUpperCase()));
  return {
    diagnostics,
    program: {
      pou: flat.bodies[0]?.pou ?? roots[0]!.name,
      profile,
      networks,
      shapes: flat.shapes,
      symbols: root,
      functions: flat.shared.functions,
      edgeCount: flat.shared.edges.count,
      edges: flat.shared.edges.owners,
      dataSlots: flat.shared.dataSlots,
      retentive,
      programs,
      ...(schedule ? { schedule: schedule.rates, programTask: schedule.programTask, triggers: schedule.triggers } : {}),
      bodies: flat.bodies,
      bodyOf: Int32Array.from(flat.bodyOf),
      mainEnd,
      instances: root.storage.ufbs
        .filter((u) => u.pou.kind === 'FUNCTION_BLOCK' && !programNames.has(u.type.toUpperCase()))
        .map((u) => ({ path: u.name, type: u.type })),
    },
  };
}

/**
 * Checks every user FB and function the roots reach, each once on its own (its diagnostics name
 * it), and recursion (LD-E21). False when one has an error.
 */
function checkCallees(project: Project, roots: readonly Pou[], profile: Project['profile'], out: Diagnostic[]): boolean {
  const callees = reachablePous(project, roots);
  const before = out.length;
  const recursive = checkRecursion(project, out, [...roots, ...callees]);
  // External blocks (no body, known by their interface only) are not POUs of the project to check.
  for (const callee of callees) if (project.pous.includes(callee)) lowerPou(project, callee, profile, out, []);
  return !recursive && !out.slice(before).some((d) => d.severity === 'error');
}
