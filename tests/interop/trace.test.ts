// npm run test:interop — issue 12 "Tests and done": every real PLCopen file imports with no error
// and no "cannot be drawn exactly" warning, simulates 200 scans under a scripted stimulus
// (tests/plcopen/trace.ts), re-exports, validates against the TC6 v2.01 schema, re-imports and
// simulates to the same trace.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { compileProgram } from '../../src/engine/plc';
import type { Project } from '../../src/model/project';
import { firstDifference, traceProgram, type ProgramTrace } from '../plcopen/trace';
import { schemaErrors } from '../plcopen/xsd';
import { corpusDir } from './corpusDir';

const CORPUS = corpusDir();
const FILES = readdirSync(CORPUS)
  .filter((f) => f.endsWith('.xml'))
  .sort();

const SCANS = 200;

/**
 * Files that do not pass yet, each with why. Shrink this list as the import improves: a listed file
 * that passes makes "still fails" below fail, so the list never holds a file that works.
 */
const NOT_YET: Readonly<Record<string, string>> = {};

/**
 * Files whose programs MATIEC refuses too, by the rule the simulator names: they import, draw,
 * export, validate and re-import like the others, and every PROGRAM stops on that rule alone (no
 * trace). DS401GUI's MAIN_TEST calls Test_SFC (a legacy v1.0 chart, read and run since v1.0 charts
 * are upgraded to v2.01), whose action COUNT2 writes TEST_ARRAY[0,0] of an ARRAY[1..8, 1..8]:
 * MATIEC's stage 3 (array_range_check) refuses a constant index out of bounds ("Array access out
 * of bounds."), the simulator refuses it as LD-E44.
 */
const MATIEC_REFUSES: Readonly<Record<string, string>> = {
  'beremiz__legacy_tc6v10_test_master_DS401GUI.xml': 'LD-E44',
};

/** Programs traced, and those whose trace changes over the scans (the stimulus reaches them). */
const stats = { traced: 0, moving: 0, inputs: 0 };

/** The whole round trip of one file; throws, naming the stage, where it breaks. Returns the programs traced. */
async function roundTrip(file: string): Promise<string[]> {
  const text = readFileSync(join(CORPUS, file), 'utf8');
  const first = importPlcopen(text);
  if (!first.ok) throw new Error(`import: ${first.errors.map((e) => e.message).join('; ')}`);
  const undrawn = first.report.warnings.filter((w) => /cannot be drawn exactly/.test(w.message));
  if (undrawn.length) throw new Error(`import: ${undrawn.map((w) => `${w.pou}: ${w.message}`).join('; ')}`);
  const programs = first.project.pous.filter((p) => p.kind === 'PROGRAM').map((p) => p.name);
  const before = new Map<string, ProgramTrace>();
  for (const pou of programs) {
    const t = traceProgram(first.project, pou, SCANS);
    if (!t) continue;
    if (t.fault) throw new Error(`simulate ${pou}: ${t.fault}`);
    before.set(pou, t);
    stats.traced++;
    stats.inputs += t.inputs.length;
    if (new Set(t.rows).size > 1) stats.moving++;
  }
  const refused = MATIEC_REFUSES[file];
  if (refused) {
    if (before.size) throw new Error(`simulate: ${[...before.keys()].join(', ')} compiles although MATIEC refuses it (${refused})`);
    for (const pou of programs) expect(compileErrors(first.project, pou), pou).toEqual([refused]);
  } else if (!before.size) throw new Error('simulate: no PROGRAM of the file compiles');
  const xml = exportPlcopen(first.project);
  const invalid = await schemaErrors(xml, file);
  if (invalid.length) throw new Error(`export: schema errors: ${invalid.slice(0, 3).join('; ')}`);
  const again = importPlcopen(xml);
  if (!again.ok) throw new Error(`re-import: ${again.errors.map((e) => e.message).join('; ')}`);
  for (const pou of refused ? programs : []) expect(compileErrors(again.project, pou), pou).toEqual([refused]);
  // Networks imported side by side run interleaved under openplc (Network.turns); the export draws
  // them one under another, so the exported file runs network by network (export review LD-X08):
  // the re-import is compared with that order.
  const turned = first.project.pous.some((p) => p.networks.some((n) => n.turns !== undefined));
  const plain: Project = {
    ...first.project,
    pous: first.project.pous.map((p) => ({ ...p, networks: p.networks.map(({ turns: _t, ...n }) => n) })),
  };
  for (const [pou, t0] of before) {
    const t = turned ? (traceProgram(plain, pou, SCANS) ?? t0) : t0;
    const after = traceProgram(again.project, pou, SCANS);
    if (!after) throw new Error(`re-import: ${pou} no longer compiles`);
    const diff = firstDifference(t, after);
    if (diff) throw new Error(`trace differs after the round trip: ${diff}`);
  }
  return [...before.keys()];
}

/** The rules of a program's compile errors, each once. */
function compileErrors(project: Project, pou: string): string[] {
  return [...new Set(compileProgram(project, { pou }).diagnostics.filter((d) => d.severity === 'error').map((d) => d.rule))];
}

describe('PLCopen corpus: 200 scans, export, re-import, same trace', () => {
  it('has the real files', () => {
    expect(FILES.length, `no corpus in ${CORPUS}`).toBeGreaterThanOrEqual(20);
  });

  it('lists only corpus files as not yet passing', () => {
    for (const f of [...Object.keys(NOT_YET), ...Object.keys(MATIEC_REFUSES)]) expect(FILES).toContain(f);
  });

  const passing = FILES.filter((f) => !(f in NOT_YET));
  it.each(passing)('%s', async (file) => {
    const traced = await roundTrip(file);
    expect(traced.length).toBeGreaterThan(file in MATIEC_REFUSES ? -1 : 0);
  });

  it('the stimulus moves most traced programs', () => {
    // Runs after the files above (same file, in order): most programs change under the stimulus.
    expect(stats.traced).toBeGreaterThanOrEqual(15);
    expect(stats.moving).toBeGreaterThanOrEqual(Math.ceil(stats.traced * 0.7));
    expect(stats.inputs).toBeGreaterThanOrEqual(stats.traced);
  });

  const waiting = Object.keys(NOT_YET);
  if (waiting.length)
    it.each(waiting)('%s still fails (remove it from NOT_YET when it passes)', async (file) => {
      await expect(roundTrip(file), NOT_YET[file]).rejects.toThrow();
    });
});
