// What the exported program does differently in Beremiz/OpenPLC (LD-X rules), and the fixes.
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { EXAMPLES } from '../../src/model/examples';
import type { Project } from '../../src/model/project';
import {
  applyExportFix,
  exportBehaviour,
  formatExportWarning,
  type ExportWarning,
} from '../../src/plcopen/exportBehaviour';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { ladder, plcOf, project, trace, vars } from '../engine/ladder';
import { firstDifference, traceProgram, without } from './trace';
import { schemaErrors } from './xsd';

const example = (id: string) => EXAMPLES.find((e) => e.id === id)!.build();
const rules = (p: Project) => exportBehaviour(p).map((w) => `${w.rule} ${w.network + 1}`);

/** Applies every offered fix, one at a time (each fix is computed on the project as it stands). */
function fixAll(p: Project): { project: Project; added: string[] } {
  const added: string[] = [];
  for (let w = exportBehaviour(p).find((x) => x.fix); w; w = exportBehaviour(p).find((x) => x.fix)) {
    added.push(...w.fix!.variables.map((v) => v.name));
    p = applyExportFix(p, w.fix!);
  }
  return { project: p, added };
}

/** The fix leaves what Rungsmith does unchanged: same trace over 200 scans, but for the new variables. */
function expectSameTrace(before: Project, after: Project, added: readonly string[]) {
  const a = traceProgram(before, 'Main')!;
  const b = traceProgram(after, 'Main')!;
  expect(a.rows.length).toBe(200);
  expect(firstDifference(a, without(b, added))).toBe('');
}

describe('LD-X01 jumps and LD-X02 RETURNs, dropped by Beremiz/OpenPLC', () => {
  it('a jump over a network: the network it skips runs every scan there; no fix', () => {
    const ws = exportBehaviour(example('jump-label'));
    expect(ws).toHaveLength(1);
    expect(ws[0]).toMatchObject({ rule: 'LD-X01', pou: 'Main', network: 0, cell: { row: 0, col: 9 } });
    expect(ws[0]!.fix).toBeUndefined();
    expect(formatExportWarning(ws[0]!)).toMatch(
      /^warning LD-X01 Main\/network 1:R1C10 Beremiz and OpenPLC drop the jump to "MAINT" without a word .*so network 2, which it skips when it is powered here, runs in every scan there\./,
    );
  });

  it('an unconditional jump over several networks, a backward jump, and a jump to the next network', () => {
    const v = vars('A BOOL %IX0.0', 'B BOOL', 'C BOOL', 'D BOOL');
    const p = project(v, [
      ladder(['- - >>END']),
      ladder(['[A] (B)']),
      ladder(['[A] (C)']),
      ladder(['[A] (D)'], { label: 'END' }),
      ladder(['[A] >>NEXT']),
      ladder(['[B] >>END'], { label: 'NEXT' }),
    ]);
    const ws = exportBehaviour(p);
    expect(ws.map((w) => `${w.rule} ${w.network + 1}`)).toEqual(['LD-X01 1', 'LD-X01 6']);
    expect(ws[0]!.message).toContain('so networks 2 to 3, which it skips every scan here, run in every scan there');
    expect(ws[1]!.message).toContain('so networks 4 to 6, which it runs again when it is powered here, run only once per scan there');
  });

  it('a RETURN before the last network is reported, one in the last network is not', () => {
    const v = vars('A BOOL %IX0.0', 'B BOOL');
    const early = project(v, [ladder(['[A] <RET>']), ladder(['[A] (B)'])]);
    const ws = exportBehaviour(early);
    expect(ws).toHaveLength(1);
    expect(formatExportWarning(ws[0]!)).toMatch(
      /^warning LD-X02 Main\/network 1:R1C2 Beremiz and OpenPLC drop the RETURN at R1C2 without a word .*so network 2, which it ends the POU before when it is powered here, runs in every scan there\./,
    );
    expect(exportBehaviour(project(v, [ladder(['[A] (B)']), ladder(['[A] <RET>'])]))).toEqual([]);
  });
});

describe('LD-X03 function blocks whose outputs reach only the right rail', () => {
  it('the traffic light: the lamps read the timers one scan late there; both timers get a coil fix', () => {
    const p = example('traffic-light');
    const ws = exportBehaviour(p);
    expect(ws.map((w) => [w.rule, w.network, w.cell])).toEqual([
      ['LD-X03', 0, { row: 0, col: 2 }],
      ['LD-X03', 1, { row: 0, col: 2 }],
    ]);
    expect(ws[0]!.message).toContain('the TON block "RedTime": its output Q reaches only the right rail');
    expect(ws[0]!.message).toContain("what reads RedTime's outputs in networks 4 and 5 sees them one scan late");
    expect(ws[0]!.fix!.label).toBe('Add a coil "RedTime_Q" on output Q of TON "RedTime"');
    expect(ws[1]!.fix!.label).toBe('Add a coil "GreenTime_Q" on output Q of TON "GreenTime"');
  });

  it('applying the fixes removes the warnings, keeps the trace, checks clean and exports a coil on Q', async () => {
    const p = example('traffic-light');
    const { project: fixed, added } = fixAll(p);
    expect(added).toEqual(['RedTime_Q', 'GreenTime_Q']);
    expect(exportBehaviour(fixed)).toEqual([]);
    expectSameTrace(p, fixed, added);
    expect(checkProject(fixed)).toEqual([]);
    const main = fixed.pous[0]!;
    // The coil took the last cell of the line from Q to the rail: the network keeps its size.
    expect(main.networks[0]!.cols).toBe(p.pous[0]!.networks[0]!.cols);
    expect(main.networks[0]!.elements).toContainEqual(
      expect.objectContaining({ kind: 'coil', coil: 'COIL', variable: 'RedTime_Q', row: 0, col: 9 }),
    );
    expect(main.variables.find((v) => v.name === 'RedTime_Q')).toMatchObject({ type: 'BOOL', varClass: 'local' });
    const xml = exportPlcopen(fixed);
    expect(await schemaErrors(xml)).toEqual([]);
    expect(xml).toMatch(/<coil [^>]*>(?:(?!<\/coil>)[\s\S])*<variable>RedTime_Q<\/variable>/);
    const back = importPlcopen(xml);
    expect(back.ok && exportBehaviour(back.project)).toEqual([]);
  });

  it('one fix at a time: fixing GreenTime first makes RedTime late for network 2 as well', () => {
    const p = example('traffic-light');
    const green = exportBehaviour(p).find((w) => w.message.includes('GreenTime'))!;
    const after = exportBehaviour(applyExportFix(p, green.fix!));
    expect(after).toHaveLength(1);
    expect(after[0]!.message).toContain("what reads RedTime's outputs in networks 2, 4 and 5 sees them one scan late");
  });

  it('a box at the right edge: the fix adds a column for the coil, the other rows carried on to the rail', () => {
    const v = vars('Start BOOL %IX0.0', 'Lamp BOOL %QX0.0', 'Other BOOL %QX0.1', 'Edge R_TRIG');
    const net = ladder(['[Start] - # #', '[Start] - - (Other)'], {
      boxes: [{ row: 0, col: 2, type: 'R_TRIG', instance: 'Edge' }],
    });
    const p = project(v, [{ ...net, rows: 2 }, ladder(['[Edge.Q] (Lamp)'])]);
    expect(checkProject(p).filter((d) => d.severity === 'error')).toEqual([]);
    expect(rules(p)).toEqual(['LD-X03 1']);
    const { project: fixed, added } = fixAll(p);
    expect(added).toEqual(['Edge_Q']);
    const n0 = fixed.pous[0]!.networks[0]!;
    expect(n0.cols).toBe(5);
    expect(n0.elements).toContainEqual(expect.objectContaining({ kind: 'coil', variable: 'Edge_Q', row: 0, col: 4 }));
    expect(n0.elements).toContainEqual(expect.objectContaining({ kind: 'link', row: 1, col: 4 }));
    expect(exportBehaviour(fixed)).toEqual([]);
    expect(checkProject(fixed).filter((d) => d.severity === 'error')).toEqual([]);
    expectSameTrace(p, fixed, added);
  });

  it('a variable the late call reads is written after it: read one scan early there', () => {
    const v = vars('Start BOOL %IX0.0', 'Run BOOL', 'T1 TON');
    const p = project(v, [
      ladder(['[Run] - # # -'], { boxes: [{ row: 0, col: 2, type: 'TON', instance: 'T1', inputs: { PT: 'T#50ms' } }] }),
      ladder(['[Start] (Run)']),
    ]);
    const ws = exportBehaviour(p);
    expect(ws.map((w) => w.rule)).toEqual(['LD-X03']);
    expect(ws[0]!.message).toContain('it reads "Run" after network 2 writes it, one scan early');
    const { project: fixed, added } = fixAll(p);
    expect(exportBehaviour(fixed)).toEqual([]);
    expectSameTrace(p, fixed, added);
  });

  it('not reported when nothing can tell: no later reader, no later write; nor for a block with an output variable', () => {
    const v = vars('Start BOOL %IX0.0', 'Lamp BOOL', 'Elapsed TIME', 'T1 TON', 'T2 TON');
    expect(
      rules(
        project(v, [
          ladder(['[T1.Q] (Lamp)']),
          ladder(['[Start] - # # -'], { boxes: [{ row: 0, col: 2, type: 'TON', instance: 'T1', inputs: { PT: 'T#1s' } }] }),
        ]),
      ),
    ).toEqual([]);
    expect(
      rules(
        project(v, [
          ladder(['[Start] - # # -'], {
            boxes: [{ row: 0, col: 2, type: 'TON', instance: 'T2', inputs: { PT: 'T#1s' }, outputs: { ET: 'Elapsed' } }],
          }),
          ladder(['[T2.Q] (Lamp)']),
        ]),
      ),
    ).toEqual([]);
  });
});

describe('LD-X04 functions with no input connected', () => {
  it('a function none of whose inputs is connected or assigned is never called there', () => {
    const v = vars('Sum INT := 5');
    const net = ladder(['- # #'], { boxes: [{ row: 0, col: 1, type: 'ADD', outputs: { OUT: 'Sum' } }] });
    const ws = exportBehaviour(project(v, [net]));
    expect(ws.map((w) => w.rule)).toEqual(['LD-X04']);
    expect(ws[0]!.message).toMatch(/^Beremiz and OpenPLC never call the ADD block at R1C2: none of its inputs is connected/);
    const assigned = ladder(['- # #'], { boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: '1' }, outputs: { OUT: 'Sum' } }] });
    expect(exportBehaviour(project(v, [assigned]))).toEqual([]);
  });
});

describe('LD-X05 contacts read again for each coil', () => {
  it('a toggle with a parallel coil: the second coil reads the toggled value there', () => {
    const v = vars('A BOOL', 'B BOOL');
    const ws: ExportWarning[] = exportBehaviour(project(v, [ladder(['[/A] + (A)', '. + (B)'])]));
    expect(ws.map((w) => [w.rule, w.cell])).toEqual([['LD-X05', { row: 0, col: 0 }]]);
    expect(ws[0]!.message).toContain(
      'Beremiz and OpenPLC read the normally closed contact "A" again for the coil "B", after the coil "A" writes it',
    );
    expect(ws[0]!.fix).toBeUndefined();
  });

  it('a coil in series after the coil that writes the contact', () => {
    const v = vars('A BOOL', 'B BOOL');
    expect(rules(project(v, [ladder(['[/A] (A) (B)'])]))).toEqual(['LD-X05 1']);
  });

  it('a seal-in with a parallel coil ends the same in both orders: not reported', () => {
    const v = vars('Start BOOL %IX0.0', 'Stop BOOL %IX0.1', 'Motor BOOL', 'Lamp BOOL');
    const net = ladder(['+ [Start] + [/Stop] + (Motor)', '+ [Motor] + . + (Lamp)']);
    expect(exportBehaviour(project(v, [net]))).toEqual([]);
    expect(exportBehaviour(example('motor-start-stop'))).toEqual([]);
  });
});

// Bugs of Beremiz's generator (issue 23, class 14), checked against the MATIEC reference on the
// exported XML (the MATIEC oracle, docs/CORPUS.md): the simulator reads the drawing, the export warns.
describe('LD-X06 a connector OR pasted without brackets', () => {
  const v = vars('I1 BOOL %IX0.1', 'I2 BOOL %IX0.2', 'I3 BOOL %IX0.3', 'Q0 BOOL %QX0.0');
  const drawn = ladder(['+ [I1] + >CX>|', '+ [I2] +', '|>CX> [I3] (Q0)']);

  it('an OR into a connector, a contact after its continuation: named with what they generate', () => {
    for (const profile of ['iec', 'openplc'] as const) {
      const ws = exportBehaviour(project(v, [drawn], profile));
      expect(ws.map((w) => [w.rule, w.network, w.cell])).toEqual([['LD-X06', 0, { row: 2, col: 0 }]]);
      expect(formatExportWarning(ws[0]!)).toMatch(
        /^warning LD-X06 Main\/network 1:R3C1 Beremiz and OpenPLC paste the OR that reaches the connector ">CX>" into what follows the continuation ">CX>" at R3C1 without brackets: they write the coil "Q0" as Q0 := I3 AND I1 OR I2, where AND binds before OR/,
      );
      expect(ws[0]!.fix).toBeUndefined();
    }
  });

  it('the simulator does not copy the bug: the whole OR is in series with I3', () => {
    const plc = plcOf(project(v, [drawn], 'openplc'));
    expect(trace(plc, [{ I2: true }, { I3: true }, { I2: false, I1: true }], ['Q0'])).toEqual([[0], [1], [1]]);
  });

  it('a file with that shape (an OR into a connector, a contact after the continuation) is named on import', () => {
    const r = importPlcopen(exportPlcopen(project(v, [drawn], 'openplc')));
    if (!r.ok) throw new Error('the export does not import');
    const notes = r.report.warnings.map((w) => w.message).filter((m) => m.includes('paste that OR'));
    expect(notes).toEqual([
      expect.stringMatching(/^contact "I3" follows continuation "CX", whose connector gathers an OR: Beremiz and OpenPLC paste that OR without brackets after the contact \(they write I3 AND I1 OR I2\)/),
    ]);
    // The drawing without that shape imports without the note.
    const plain = importPlcopen(exportPlcopen(project(v, [ladder(['+ [I1] + >CX>|', '+ [I2] +', '|>CX> - (Q0)'])], 'openplc')));
    expect(plain.ok && plain.report.warnings.some((w) => w.message.includes('paste that OR'))).toBe(false);
  });

  it('not reported where the pasted text stands alone: a continuation straight into a coil, or an OR that reaches the rail', () => {
    expect(exportBehaviour(project(v, [ladder(['+ [I1] + >CX>|', '+ [I2] +', '|>CX> - (Q0)'])]))).toEqual([]);
    expect(exportBehaviour(project(v, [ladder(['+ [I1] + >CX>|', '+ - +', '|>CX> [I3] (Q0)'])]))).toEqual([]);
    expect(exportBehaviour(project(v, [ladder(['[I1] [I2] >CX>|', '|>CX> [I3] (Q0)'])]))).toEqual([]);
  });
});

describe('LD-X07 coils in series after an OR join', () => {
  const v = vars('I1 BOOL %IX0.1', 'I2 BOOL %IX0.2', 'Q1 BOOL %QX0.1', 'Q2 BOOL %QX0.2');

  it('the coil after the join passes the AND of the branches to the next coil there', () => {
    const ws = exportBehaviour(project(v, [ladder(['+ [I1] + (Q1) (Q2)', '+ [I2] +'])]));
    expect(ws.map((w) => [w.rule, w.network, w.cell])).toEqual([['LD-X07', 0, { row: 0, col: 1 }]]);
    expect(ws[0]!.message).toMatch(
      /^the coil "Q1" joins 2 branches \(I1 OR I2\), and the coil "Q2" follows it in series: Beremiz and OpenPLC give the coil "Q2" the AND of those branches \(I1 AND I2\), not their OR/,
    );
    const plc = plcOf(project(v, [ladder(['+ [I1] + (Q1) (Q2)', '+ [I2] +'])], 'openplc'));
    expect(trace(plc, [{ I1: true }, { I1: false, I2: true }], ['Q1', 'Q2'])).toEqual([
      [1, 1],
      [1, 1],
    ]);
  });

  it('not reported for a coil after the join that reaches only the rail, nor for a series coil after one branch', () => {
    expect(exportBehaviour(project(v, [ladder(['+ [I1] + (Q1)', '+ [I2] +'])]))).toEqual([]);
    expect(exportBehaviour(project(v, [ladder(['[I1] [I2] (Q1) (Q2)'])]))).toEqual([]);
  });
});
