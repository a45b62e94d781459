// npm run test:interop — ST and IL POUs of real PLCopen files (Beremiz first_steps, gracesrm vc999v3) import and run with
// the traces computed by hand from their source. The same on a fixture of the repository:
// tests/engine/stBodiesImport.test.ts.
import { describe, expect, test } from 'vitest';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import type { Project } from '../../src/model/project';
import { scanRead, stPlc, textPou, vars } from '../engine/stHelpers';
import { corpusText } from './corpusDir';

function imported(file: string): Project {
  const r = importPlcopen(corpusText(file));
  if (!r.ok) throw new Error(`${file} does not import`);
  return r.project;
}

/** The file's POUs named, with an ST program Main calling them first. */
function withMain(project: Project, names: readonly string[], main: string, variables: ReturnType<typeof vars>): Project {
  const pous = project.pous.filter((p) => names.includes(p.name));
  return { ...project, pous: [textPou('Main', 'PROGRAM', variables, main), ...pous] };
}

describe('beremiz first_steps: CounterST, CounterIL, AverageVal', () => {
  const project = imported('beremiz__first_steps.xml');

  test('they import as ST, IL and ST bodies', () => {
    const lang = (n: string) => project.pous.find((p) => p.name === n)?.language;
    expect([lang('CounterST'), lang('CounterIL'), lang('AverageVal')]).toEqual(['ST', 'IL', 'ST']);
  });

  test('both counters count each scan and load ResetCounterValue (17) while Reset is ON; AverageVal averages five inputs', () => {
    const p = withMain(
      project,
      ['CounterST', 'CounterIL', 'AverageVal'],
      `S1(Reset := rst); I1(Reset := rst);
       a := S1.OUT; b := I1.OUT;
       avg := AverageVal(a, b, 3, Cnt4 := 0, Cnt5 := 0);`,
      vars('S1 CounterST', 'I1 CounterIL', 'rst BOOL', 'a INT', 'b INT', 'avg REAL'),
    );
    const plc = stPlc(p);
    const rows = [];
    for (const reset of [false, false, false, true, false, false]) {
      plc.write('rst', reset);
      rows.push(scanRead(plc, 1, ['a', 'b', 'avg']));
    }
    // avg = INT_TO_REAL(a + b + 3 + 0 + 0) / 5.0
    expect(rows).toEqual([
      [1, 1, 1],
      [2, 2, 1.4],
      [3, 3, 1.8],
      [17, 17, 7.4],
      [18, 18, 7.8],
      [19, 19, 8.2],
    ].map(([a, b, avg]) => [a, b, Math.fround(avg!)]));
  });
});

describe('gracesrm vc999v3: TP_WITH_RESET', () => {
  const project = imported('gracesrm__vc999v3.xml');

  test('the whole file compiles and runs (its ST FB and its LD program)', () => {
    const plc = stPlc(project);
    expect(plc.scans(100).fault).toBeUndefined();
  });

  test('a pulse of PT from a rising IN, ended early by RESET; the clock comes from its __CURRENT_TIME pragma', () => {
    const p = withMain(project, ['TP_WITH_RESET'], 'TP1(IN := in, PT := T#50ms, RESET := rst); q := TP1.Q; et := TP1.ET;', vars('TP1 TP_WITH_RESET', 'in BOOL', 'rst BOOL', 'q BOOL', 'et TIME'));
    const plc = stPlc(p, { cycleMs: 10 });
    const steps: [boolean, boolean][] = [
      [true, false], // t=0: rising edge: Q, START_TIME 0
      [true, false], // 10
      [true, false], // 20
      [true, false], // 30
      [true, false], // 40
      [true, false], // 50: 0 + 50 <= 50: expired, ET := PT
      [false, false], // 60: STATE 2 and NOT IN: ET 0, STATE 0
      [true, false], // 70: rising again
      [true, true], // 80: counting (ET 10) then RESET: Q off, ET 0
      [true, false], // 90: IN still ON, no new edge: stays off
    ];
    const rows = steps.map(([i, r]) => {
      plc.write('in', i);
      plc.write('rst', r);
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
