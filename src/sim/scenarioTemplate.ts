// A new, empty test scenario for the program the project runs: a column per input (%I) and an
// `expect` column per output (%Q), one row at scan 1 ready to fill in (issue 22, 2.3).
import type { Project } from '../model/project';
import { csvRow } from './csv';
import { findPou, readableNames } from './layout';
import { programInstances, runOptions } from './runTarget';

/** Inputs and outputs of what the project runs, as scenario column names. */
export function scenarioColumns(project: Project): { inputs: string[]; outputs: string[] } {
  const inputs: string[] = [];
  const outputs: string[] = [];
  const seen = new Set<string>();
  const add = (name: string, role: string) => {
    if (seen.has(name.toUpperCase())) return;
    seen.add(name.toUpperCase());
    if (role === 'input') inputs.push(name);
    else if (role === 'output') outputs.push(name);
  };
  const opts = runOptions(project);
  const globals = new Set(project.globals.map((g) => g.name.toUpperCase()));
  if (opts.configuration) {
    // A configuration: a program instance's own variables by path, the globals by name.
    for (const inst of programInstances(project)) {
      const pou = findPou(project, inst.pou);
      if (!pou) continue;
      for (const v of readableNames(project, pou))
        add(globals.has(v.name.toUpperCase()) ? v.name : `${inst.instance}.${v.name}`, v.role);
    }
  } else {
    const pou = opts.pou ? findPou(project, opts.pou) : project.pous.find((p) => p.kind === 'PROGRAM');
    if (pou) for (const v of readableNames(project, pou)) add(v.name, v.role);
  }
  return { inputs, outputs };
}

/** The CSV of a new scenario: the header and scan 1 with every input FALSE/0 and every expectation "don't care". */
export function newScenarioCsv(project: Project): string {
  const { inputs, outputs } = scenarioColumns(project);
  const cycle = project.tasks[0]?.cycleMs;
  return [
    '# A new scenario: set inputs per scan (empty: unchanged), expect outputs (* or empty: don\'t care).',
    ...(cycle ? [`# cycle: ${cycle}ms`] : []),
    csvRow(['scan', ...inputs, ...outputs.map((o) => `expect ${o}`)]),
    csvRow(['1', ...inputs.map(() => ''), ...outputs.map(() => '*')]),
    '',
  ].join('\n');
}

/** "Scenario N", the first N not taken. */
export function newScenarioName(taken: readonly { name: string }[]): string {
  let n = taken.length + 1;
  while (taken.some((s) => s.name === `Scenario ${n}`)) n++;
  return `Scenario ${n}`;
}
