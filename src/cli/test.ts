// `rungsmith test PROJECT`: runs every test scenario stored in the project (src/sim/scenario.ts)
// headless, prints PASS/FAIL per scenario with the first divergent scan and "Why?" on the differing
// output, a summary, and exits 1 on any failure; `--junit FILE` writes JUnit XML for CI systems.
import { explain, liveScanView } from '../engine/explain';
import type { Project } from '../model/project';
import { runScenario, type ScenarioResult } from '../sim/scenario';
import { UsageError, type CliIo } from './io';
import { plantById, strayMapWarning } from '../plant/machines';

export interface TestOptions {
  readonly junit?: string;
  /** Only the scenarios with this name (case-insensitive). */
  readonly scenario?: string;
}

interface Outcome {
  readonly result: ScenarioResult;
  readonly ms: number;
  /** "Why?" on the first differing output, in plain words. */
  readonly why: readonly string[];
}

const xml = (s: string) => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');

function failureText(r: ScenarioResult): string {
  if (r.error) return r.error;
  const d = r.divergences;
  return `scan ${d[0]!.scan} (line ${d[0]!.line}): ${d.map((x) => `${x.name} expected ${x.expected}, got ${x.actual}`).join('; ')}`;
}

export function junitXml(suite: string, outcomes: readonly Outcome[]): string {
  const failures = outcomes.filter((o) => !o.result.ok).length;
  const total = outcomes.reduce((s, o) => s + o.ms, 0) / 1000;
  const cases = outcomes.map((o) => {
    const head = `    <testcase classname="${xml(suite)}" name="${xml(o.result.name)}" time="${(o.ms / 1000).toFixed(3)}"`;
    if (o.result.ok) return `${head}/>`;
    const body = [failureText(o.result), ...o.why].join('\n');
    return `${head}>\n      <failure message="${xml(failureText(o.result))}">${xml(body)}</failure>\n    </testcase>`;
  });
  return [
    '<?xml version="1.0" encoding="UTF-8"?>',
    `<testsuites tests="${outcomes.length}" failures="${failures}" time="${total.toFixed(3)}">`,
    `  <testsuite name="${xml(suite)}" tests="${outcomes.length}" failures="${failures}" errors="0" skipped="0" time="${total.toFixed(3)}">`,
    ...cases,
    '  </testsuite>',
    '</testsuites>',
    '',
  ].join('\n');
}

export function testProject(io: CliIo, project: Project, opts: TestOptions): number {
  const all = project.scenarios ?? [];
  const chosen = opts.scenario ? all.filter((s) => s.name.toUpperCase() === opts.scenario!.toUpperCase()) : all;
  if (opts.scenario && chosen.length === 0)
    throw new UsageError(`the project has no scenario named "${opts.scenario}" (it has: ${all.map((s) => s.name).join(', ') || 'none'})`);
  if (chosen.length === 0) {
    io.err(`the project ${project.name} has no test scenarios; record one in the Tests panel or add one to "scenarios"\n`);
    return 1;
  }
  const stray = strayMapWarning(project.plant);
  if (stray) io.err(`${stray}\n`);
  const outcomes: Outcome[] = [];
  for (const scenario of chosen) {
    const t0 = performance.now();
    const run = runScenario(project, scenario);
    const ms = performance.now() - t0;
    const r = run.result;
    let why: string[] = [];
    // "Why?" explains a program variable; a machine's quantity (tank.level) has no network to explain.
    const onMachine = r.divergences[0] !== undefined && plantById(r.divergences[0].name.split('.')[0]!) !== undefined;
    if (!r.ok && run.plc && run.program && r.divergences[0] && !onMachine) {
      const pou = project.pous.find((p) => p.name.toUpperCase() === run.program!.pou.toUpperCase());
      if (pou) {
        const e = explain(run.program, pou, liveScanView(run.plc, run.program), { kind: 'variable', name: r.divergences[0].name });
        why = [`Why? ${e.title}`, ...e.lines.map((l) => `  ${l}`)];
      }
    }
    outcomes.push({ result: r, ms, why });
    if (r.ok) io.out(`PASS ${r.name} (${r.scans} scan${r.scans === 1 ? '' : 's'})\n`);
    else {
      io.out(`FAIL ${r.name}: ${failureText(r)}\n`);
      for (const l of why) io.out(`  ${l}\n`);
    }
    // The machine's warnings fail nothing, but the run had them (the door moved without its warning).
    for (const w of r.warnings ?? []) io.out(`  warning: ${w}\n`);
  }
  const failed = outcomes.filter((o) => !o.result.ok).length;
  io.out(`${outcomes.length - failed} passed, ${failed} failed (${outcomes.length} scenario${outcomes.length === 1 ? '' : 's'} of ${project.name})\n`);
  if (opts.junit) io.writeFile(opts.junit, junitXml(project.name, outcomes));
  return failed > 0 ? 1 : 0;
}
