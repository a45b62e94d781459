// Each machine's reference solution runs as MATIEC runs it (issue 26; LD-SEMANTICS.md section 9):
// tests/plant/matiec/<id>.csv keeps, for the exercise's scenario in closed loop with its machine
// (<id>-operator.csv: for an operator's actions and faults mid-run, faultTraces.test.ts's run),
// the inputs the machine presented scan by scan and the outputs MATIEC's compile of the same
// program (what an OpenPLC runtime runs) gave for them (scripts/plantOracle.ts, with the MATIEC
// reference built). Here the simulator, profile openplc, is fed those inputs and must drive the
// very same outputs at every scan: so the exercise behaves alike on a real OpenPLC against
// `npm start -- --plant`, and a change to the engine that breaks that fails here.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, test } from 'vitest';
import { PLANT_EXAMPLES } from '../../src/plant/exercises';
import { rungsmith } from '../cli/memoryIo';
import { changeRows, readKept } from './matiecKit';

describe("the machines' reference solutions against MATIEC", () => {
  for (const example of PLANT_EXAMPLES) {
    const { plant, scenarios: _s, ...project } = example.build();
    test.each([plant!.id, `${plant!.id}-operator`])(`%s: fed the inputs its machine presented, the outputs equal MATIEC's at every scan`, (name) => {
      const kept = readKept(readFileSync(join(import.meta.dirname, 'matiec', `${name}.csv`), 'utf8'));
      const main = project.pous.find((p) => p.kind === 'PROGRAM')!;
      const located = (area: string) => main.variables.filter((v) => v.location?.toUpperCase().startsWith(`%${area}`)).map((v) => v.name);
      const inputs = located('I');
      const outputs = located('Q');
      expect(kept.header).toEqual(['scan', ...inputs, ...outputs]);
      // Sample and hold, as the reference was fed: a row sets the inputs before its scan's input read.
      const stim = [['scan', ...inputs].join(','), ...kept.rows.map((r) => r.slice(0, 1 + inputs.length).join(','))].join('\n');
      const run = rungsmith(
        ['simulate', 'p.json', '--inputs', 'stim.csv', '--scans', String(kept.scans), '--cycle', kept.cycle, '--profile', 'openplc', '--watch', outputs.join(',')],
        { 'p.json': JSON.stringify(project), 'stim.csv': `${stim}\n` },
      );
      expect(run.err).toBe('');
      expect(run.code).toBe(0);
      const ours = changeRows(run.out.trim().split('\n').map((l) => l.split(',')), outputs);
      const theirs = changeRows([['scan', ...outputs], ...expandRows(kept.rows, kept.scans).map((r) => [r[0]!, ...r.slice(1 + inputs.length)])], outputs);
      // The outputs switch during the run (the test compares a run, not a standstill).
      expect(theirs.length).toBeGreaterThan(3);
      expect(ours).toEqual(theirs);
    });
  }
});

/** Change rows back to one row per scan 1..scans (each row holds until the next). */
function expandRows(rows: readonly string[][], scans: number): string[][] {
  const out: string[][] = [];
  let i = 0;
  for (let k = 1; k <= scans; k++) {
    while (i + 1 < rows.length && Number(rows[i + 1]![0]) <= k) i++;
    out.push([String(k), ...rows[i]!.slice(1)]);
  }
  return out;
}
