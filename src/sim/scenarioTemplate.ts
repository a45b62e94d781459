// A new, empty test scenario for the program the project runs: a column per input (%I) and an
// `expect` column per output (%Q), one row at scan 1 ready to fill in (issue 22, 2.3).
import { locationText, parseLocation } from '../model/iecTypes';
import type { Project } from '../model/project';
import { mappedPoints } from '../plant/loop';
import { plantById } from '../plant/machines';
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

/**
 * The CSV of a new scenario: the header and scan 1 with every input FALSE/0 and every expectation
 * "don't care". With a machine chosen (issue 26) it runs against the machine (`# plant: tank`):
 * the machine's operator controls are columns (`tank.Start`) instead of the inputs the machine
 * writes (a value set there would run the program without the machine, or be overwritten by it).
 */
export function newScenarioCsv(project: Project): string {
  const { inputs, outputs } = scenarioColumns(project);
  const cycle = project.tasks[0]?.cycleMs;
  const model = project.plant ? plantById(project.plant.id) : undefined;
  if (!model) {
    return [
      '# A new scenario: set inputs per scan (empty: unchanged), expect outputs (* or empty: don\'t care).',
      ...(cycle ? [`# cycle: ${cycle}ms`] : []),
      csvRow(['scan', ...inputs, ...outputs.map((o) => `expect ${o}`)]),
      csvRow(['1', ...inputs.map(() => ''), ...outputs.map(() => '*')]),
      '',
    ].join('\n');
  }
  const points = mappedPoints(model, project.plant?.map ?? {});
  const canonical = (address: string | undefined) => {
    const loc = address ? parseLocation(address.trim()) : undefined;
    return loc ? locationText(loc) : undefined;
  };
  const machineWrites = new Set(points.filter((p) => p.kind !== 'actuator').map((p) => canonical(p.address)));
  const written = new Set(
    [...project.globals, ...project.pous.flatMap((p) => p.variables)]
      .filter((v) => machineWrites.has(canonical(v.location)))
      .map((v) => v.name.toUpperCase()),
  );
  const own = inputs.filter((n) => !written.has(n.split('.').pop()!.toUpperCase()));
  const controls = points.filter((p) => p.kind === 'operator').map((p) => `${model.id}.${p.name}`);
  const first = controls[0] ?? `${model.id}.Start`;
  return [
    `# A new scenario against the machine ${model.id}: operate its controls per scan (${first}: 1 pressed, 0 released;`,
    '# empty: unchanged), set the program\'s other inputs, expect outputs or the machine\'s quantities',
    `# (expect ${model.id}.${model.quantities[0]?.name ?? 'level'}; * or empty: don't care). The machine writes its sensors.`,
    `# plant: ${model.id}`,
    ...(cycle ? [`# cycle: ${cycle}ms`] : []),
    csvRow(['scan', ...controls, ...own, ...outputs.map((o) => `expect ${o}`)]),
    csvRow(['1', ...controls.map(() => ''), ...own.map(() => ''), ...outputs.map(() => '*')]),
    '',
  ].join('\n');
}

/** "Scenario N", the first N not taken. */
export function newScenarioName(taken: readonly { name: string }[]): string {
  let n = taken.length + 1;
  while (taken.some((s) => s.name === `Scenario ${n}`)) n++;
  return `Scenario ${n}`;
}
