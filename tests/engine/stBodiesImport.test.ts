// ST and IL POUs of a PLCopen file (tests/fixtures/plcopen/st-il-bodies.xml, written as Beremiz
// and OpenPLC Editor write them) import and run with the traces computed by hand from their
// source. The same checks on real files of the corpus: tests/interop/stCorpus.test.ts.
import { readFileSync } from 'node:fs';
import { describe, expect, test } from 'vitest';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import type { Project } from '../../src/model/project';
import { scanRead, stPlc, textPou, vars } from './stHelpers';

const FILE = new URL('../fixtures/plcopen/st-il-bodies.xml', import.meta.url);

function imported(): Project {
  const r = importPlcopen(readFileSync(FILE, 'utf8'));
  if (!r.ok) throw new Error('st-il-bodies.xml does not import');
  return r.project;
}

/** The file's POUs named, with an ST program Main calling them first. */
function withMain(project: Project, names: readonly string[], main: string, variables: ReturnType<typeof vars>): Project {
  const pous = project.pous.filter((p) => names.includes(p.name));
  return { ...project, pous: [textPou('Main', 'PROGRAM', variables, main), ...pous] };
}

const project = imported();

test('StepST, StepIL, Mean3 and OneShot import as ST, IL, ST and ST bodies; Cell stays LD', () => {
  const lang = (n: string) => project.pous.find((p) => p.name === n)?.language;
  expect(['StepST', 'StepIL', 'Mean3', 'OneShot', 'Cell'].map(lang)).toEqual(['ST', 'IL', 'ST', 'ST', 'LD']);
});

test('both steppers add 2 each scan and load the CONSTANT global Preset (40) while Clear is ON; Mean3 averages three INTs', () => {
  const p = withMain(
    project,
    ['StepST', 'StepIL', 'Mean3'],
    `S1(Clear := rst); I1(Clear := rst);
     a := S1.N; b := I1.N;
     avg := Mean3(a, b, 3);`,
    vars('S1 StepST', 'I1 StepIL', 'rst BOOL', 'a INT', 'b INT', 'avg REAL'),
  );
  const plc = stPlc(p);
  const rows = [];
  for (const clear of [false, false, false, true, false, false]) {
    plc.write('rst', clear);
    rows.push(scanRead(plc, 1, ['a', 'b', 'avg']));
  }
  // avg = INT_TO_REAL(a + b + 3) / 3.0
  expect(rows).toEqual(
    [
      [2, 2, 7 / 3],
      [4, 4, 11 / 3],
      [6, 6, 5],
      [40, 40, 83 / 3],
      [42, 42, 29],
      [44, 44, 91 / 3],
    ].map(([a, b, avg]) => [a, b, Math.fround(avg!)]),
  );
});

describe('OneShot: a pulse that reads the clock through the __CURRENT_TIME pragma', () => {
  test('the whole file compiles and runs: Go lights Lamp for the LD program’s 30 ms pulse', () => {
    const plc = stPlc(project, { cycleMs: 10 });
    expect(plc.scans(20).fault).toBeUndefined();
    plc.write('Go', true);
    const lamp = [1, 2, 3, 4, 5].map(() => scanRead(plc, 1, ['Lamp'])[0]);
    expect(lamp).toEqual([true, true, true, false, false]);
  });

  test('a pulse of PT from a rising Trig, ended early by Abort', () => {
    const p = withMain(project, ['OneShot'], 'P1(Trig := trig, PT := T#50ms, Abort := abort); q := P1.Q; et := P1.ET;', vars('P1 OneShot', 'trig BOOL', 'abort BOOL', 'q BOOL', 'et TIME'));
    const plc = stPlc(p, { cycleMs: 10 });
    const steps: [boolean, boolean][] = [
      [true, false], // t=0: rising edge: Q, Since 0
      [true, false], // 10
      [true, false], // 20
      [true, false], // 30
      [true, false], // 40
      [true, false], // 50: ET 50 >= PT: Q off, ET := PT
      [false, false], // 60: Trig off: ET 0
      [true, false], // 70: rising again: Since 70
      [true, true], // 80: ET 10, then Abort: Q off, ET 0
      [true, false], // 90: Trig still ON, no new edge: stays off
    ];
    const rows = steps.map(([trig, abort]) => {
      plc.write('trig', trig);
      plc.write('abort', abort);
      return scanRead(plc, 1, ['q', 'et']);
    });
    expect(rows).toEqual([
      [true, 0],
      [true, 10],
      [true, 20],
      [true, 30],
      [true, 40],
      [false, 50],
      [false, 0],
      [true, 0],
      [false, 0],
      [false, 0],
    ]);
  });
});
