// EN as MATIEC (the reference) and the IEC text give it: an FB instance keeps EN like any input
// (issue 23, class 11), and a function error with EN not connected writes MATIEC's error value
// under the openplc profile (class 12). Traces of the reference: tests/fixtures/reference/c11-*, c12-*.
import { describe, expect, it } from 'vitest';
import { ladder, plcOf, project, trace, vars } from './ladder';
import type { Profile } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';

/** CTU C1 called with EN from contact En, then again without EN, its CU from contact Up2. */
const keptEn = (profile: Profile) =>
  project(
    vars('En BOOL', 'Up1 BOOL', 'Up2 BOOL', 'C1 CTU', 'N1 INT', 'N2 INT'),
    [
      ladder(['[En] # # -'], { boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', executionControl: true, inputs: { CU: 'Up1', PV: '100' }, outputs: { CV: 'N1' } }] }),
      ladder(['[Up2] # # -'], { boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { PV: '100' }, outputs: { CV: 'N2' } }] }),
    ],
    profile,
  );

describe('an FB instance keeps EN like any input (class 11)', () => {
  for (const profile of ['openplc', 'iec'] as const)
    it(`${profile}: a call without EN runs only if the last EN given was ON`, () => {
      const plc = plcOf(keptEn(profile));
      const rows = trace(
        plc,
        [
          { En: true, Up2: true }, // both calls run: the second counts
          { Up2: false },
          { En: false, Up2: true }, // EN OFF: the second call does not run either
          { Up2: false },
          { Up2: true },
          { En: true }, // EN ON again: the second call runs, CU was FALSE at its last run
        ],
        ['N2', 'C1.CV'],
      );
      expect(rows).toEqual([
        [1, 1],
        [1, 1],
        [1, 1],
        [1, 1],
        [1, 1],
        [2, 2],
      ]);
    });

  it('a call with EN OFF still gives the instance its inputs (MATIEC assigns them, then the body tests EN)', () => {
    const plc = plcOf(keptEn('openplc'));
    plc.write('Up1', true);
    plc.scan();
    expect(plc.read('C1.CU')).toBe(false); // the second call gave CU := Up2
    expect(plc.read('C1.CV')).toBe(0);
  });

  it('an instance never called with EN always runs', () => {
    const p = project(vars('Up BOOL', 'C1 CTU', 'N INT'), [
      ladder(['[Up] # # -'], { boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { PV: '10' }, outputs: { CV: 'N' } }] }),
    ]);
    const plc = plcOf(p, 10, 'openplc');
    expect(trace(plc, [{ Up: true }, { Up: false }, { Up: true }], ['N'])).toEqual([[1], [1], [2]]);
  });
});

/** DIV by D (0 at first) written to Q (initially 7), EN from the rail, from a file that left it open or not. */
const divByZero = (enOpen: boolean, profile: Profile, row = '- # # -') =>
  project(vars('D INT', 'Go BOOL := TRUE', 'Q INT := 7'), [
    ladder([row], { boxes: [{ row: 0, col: 1, type: 'DIV', enOpen, inputs: { IN1: '100', IN2: 'D' }, outputs: { OUT: 'Q' } }] }),
  ], profile);

describe('a function error with EN not connected (class 12)', () => {
  it('openplc: the variable beside OUT takes the error value (Beremiz writes no IF ENO without EN)', () => {
    const plc = plcOf(divByZero(true, 'openplc'));
    expect(trace(plc, [{}, { D: 4 }, { D: 0 }], ['Q'])).toEqual([[0], [25], [0]]);
  });

  it('iec, or EN connected (to the rail, or a contact): the variable keeps its value on an error', () => {
    for (const plc of [plcOf(divByZero(true, 'iec')), plcOf(divByZero(false, 'openplc')), plcOf(divByZero(true, 'openplc', '[Go] # # -'))])
      expect(trace(plc, [{}, { D: 4 }, { D: 0 }], ['Q'])).toEqual([[7], [25], [25]]);
  });

  it('an export leaves the open EN out again, and an import of that file gives enOpen back', () => {
    const xml = exportPlcopen(divByZero(true, 'openplc'));
    expect(xml).not.toMatch(/formalParameter="EN"/);
    expect(exportPlcopen(divByZero(false, 'openplc'))).toMatch(/formalParameter="EN"/);
    const back = importPlcopen(xml);
    if (!back.ok) throw new Error('the export does not import');
    const box = back.project.pous[0]?.networks[0]?.elements.find((e) => e.kind === 'box');
    expect(box).toMatchObject({ blockType: 'DIV', enOpen: true });
  });
});
