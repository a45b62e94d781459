// Programs that IEC 61131-3 allows and MATIEC (Beremiz, OpenPLC) compiles are never refused
// (LD-SEMANTICS.md sections 4 and 9): vendor editor rules are warnings naming the rule, network and
// element, and the program runs with MATIEC's semantics. Issue 12, sections 2 and 6.
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { Network, Variable } from '../../src/model/project';
import { ladder, plcOf, project, trace, vars } from './ladder';

const VARS = vars(
  'A BOOL',
  'B BOOL',
  'Rst BOOL',
  'X BOOL',
  'Y BOOL',
  'Z BOOL',
  'N1 INT',
  'N2 INT',
  'D TIME',
  'T1 TON',
  'C1 CTU',
  'C2 CTUD',
);

const build = (networks: Network[], extra: Variable[] = []) => project([...VARS, ...extra], networks);
/** `severity rule network element` of every diagnostic. */
const diags = (networks: Network[]) =>
  checkProject(build(networks)).map((d) => ({
    severity: d.severity,
    rule: d.rule,
    network: d.network,
    elementId: d.elementId,
  }));


describe('1. an FB input left unconnected keeps the instance value (IEC; Beremiz passes only connected inputs)', () => {
  test('CTUD with only CU and PV connected counts up; no diagnostic for CD, R, LD', () => {
    const nets = [
      ladder(['[A] # # (X)', '. # # .', '. # # .', '. # # .', '. # # .'], {
        boxes: [{ row: 0, col: 1, type: 'CTUD', instance: 'C2', inputs: { PV: '2' }, outputs: { CV: 'N1' } }],
      }),
    ];
    expect(diags(nets)).toEqual([]);
    const plc = plcOf(build(nets));
    const A = (a: boolean) => ({ A: a });
    expect(trace(plc, [A(true), A(false), A(true), A(false), A(true)], ['N1', 'X', 'C2.QD'])).toEqual([
      [1, 0, 0],
      [1, 0, 0],
      [2, 1, 0],
      [2, 1, 0],
      [3, 1, 0],
    ]);
  });

  test('TON without PT: a warning naming the block; PT keeps the instance value (T#0s, or what was written to T1.PT)', () => {
    const ton = { row: 0, col: 1, type: 'TON', instance: 'T1', inputs: {}, outputs: { ET: 'D' } };
    const nets = [ladder(['[A] # # (X)'], { boxes: [ton] })];
    const d = diags(nets);
    expect(d).toEqual([
      { severity: 'warning', rule: 'LD-R10', network: 0, elementId: nets[0]!.elements.at(-1)!.id },
    ]);
    expect(checkProject(build(nets))[0]!.message).toMatch(/input PT of the TON block "T1" is not connected/);
    // PT = T#0s: MATIEC's TON starts timing at the rising edge (Q stays FALSE in that call) and
    // sets Q at the next call, where ET >= PT.
    const plc = plcOf(build(nets));
    expect(trace(plc, [{ A: false }, { A: true }, { A: true }, { A: false }], ['X'])).toEqual([
      [0],
      [0],
      [1],
      [0],
    ]);
    // A MOVE writing T1.PT in an earlier network gives the unconnected PT its value.
    const withPt = [
      ladder(['- # #'], {
        boxes: [{ row: 0, col: 1, type: 'MOVE', inputs: { IN: 'T#20ms' }, outputs: { OUT: 'T1.PT' } }],
      }),
      ladder(['[A] # # (X)'], { boxes: [ton] }),
    ];
    const plc2 = plcOf(build(withPt));
    expect(trace(plc2, [{ A: true }, { A: true }, { A: true }, { A: true }], ['X', 'D'])).toEqual([
      [0, 0],
      [0, 10],
      [1, 20],
      [1, 20],
    ]);
  });

  test("an FB whose power-flow input is unconnected runs with the instance's IN (a warning)", () => {
    const nets = [
      ladder(['[A] (T1.IN)']),
      ladder(['. # # (X)'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#10ms' } }] }),
    ];
    const d = diags(nets);
    expect(d.map((x) => `${x.severity} ${x.rule} ${x.network}`)).toEqual(['warning LD-R10 1']);
    const plc = plcOf(build(nets));
    expect(trace(plc, [{ A: true }, { A: true }, { A: true }, { A: false }], ['X'])).toEqual([
      [0],
      [1],
      [1],
      [0],
    ]);
  });
});

describe('2. elements after a coil (IEC table 62: a coil passes its left state on)', () => {
  test('a contact and a coil after a coil: LD-R04 warning, Y = A AND B', () => {
    const nets = [ladder(['[A] (X) [B] (Y)'])];
    expect(diags(nets)).toEqual([
      { severity: 'warning', rule: 'LD-R04', network: 0, elementId: nets[0]!.elements[2]!.id },
    ]);
    const plc = plcOf(build(nets));
    const steps = [
      { A: true, B: false },
      { A: true, B: true },
      { A: false, B: true },
    ];
    expect(trace(plc, steps, ['X', 'Y'])).toEqual([
      [1, 0],
      [1, 1],
      [0, 0],
    ]);
  });

  test('a function block after a coil takes the coil’s left state as its power flow', () => {
    const nets = [
      ladder(['[A] (X) # # (Y)'], {
        boxes: [{ row: 0, col: 2, type: 'TON', instance: 'T1', inputs: { PT: 'T#20ms' } }],
      }),
    ];
    expect(diags(nets).map((d) => `${d.severity} ${d.rule}`)).toEqual(['warning LD-R04']);
    const plc = plcOf(build(nets));
    const on = { A: true };
    expect(trace(plc, [on, on, on, on, { A: false }], ['X', 'Y', 'T1.ET'])).toEqual([
      [1, 0, 0],
      [1, 0, 10],
      [1, 1, 20],
      [1, 1, 20],
      [0, 0, 0],
    ]);
  });
});

describe('3. one power-flow line into EN and another input of the same block', () => {
  test('AND with EN and IN1 on one line: LD-R10 warning; both pins get the line', () => {
    const nets = [
      ladder(['[A] + # # (X)', '. + # # (Y)'], {
        boxes: [{ row: 0, col: 1, type: 'AND', inputs: { IN2: 'B' } }],
      }),
    ];
    expect(diags(nets).map((d) => `${d.severity} ${d.rule} ${d.network}`)).toEqual(['warning LD-R10 0']);
    const plc = plcOf(build(nets));
    const steps = [
      { A: false, B: true },
      { A: true, B: false },
      { A: true, B: true },
    ];
    // X is ENO (= EN), Y is OUT = IN1 AND IN2 = A AND B (OFF while EN is OFF).
    expect(trace(plc, steps, ['X', 'Y'])).toEqual([
      [0, 0],
      [1, 0],
      [1, 1],
    ]);
  });
});

describe('4. one FB instance called twice (IEC, MATIEC: every call runs, in order)', () => {
  const ctu = (inputs: Record<string, string>, outputs: Record<string, string>) => ({
    row: 0,
    col: 1,
    type: 'CTU',
    instance: 'C1',
    inputs: { PV: '10', ...inputs },
    outputs,
  });
  const nets = () => [
    ladder(['[A] # #'], { boxes: [ctu({ R: 'FALSE' }, { CV: 'N1' })] }),
    ladder(['[B] # #'], { boxes: [ctu({ R: 'Rst' }, { CV: 'N2' })] }),
  ];

  test('a warning on the second call, naming the first', () => {
    const n = nets();
    expect(diags(n)).toEqual([
      { severity: 'warning', rule: 'LD-R10', network: 1, elementId: n[1]!.elements.at(-1)!.id },
    ]);
    expect(checkProject(build(n))[0]!.message).toMatch(/the CTU block "C1" is a second call of its instance \(first at network 1\)/);
  });

  test('each call updates the instance; outputs read after a call see that call', () => {
    const plc = plcOf(build(nets()));
    // Call 1 sees CU = A, call 2 CU = B: with A ON and B OFF the edge memory falls between the calls,
    // so call 1 counts in every scan; call 2's reset shows in N2 but not in N1 of the same scan.
    const steps = [
      { A: true, B: false, Rst: false },
      { A: true, B: false, Rst: false },
      { A: true, B: false, Rst: true },
      { A: true, B: false, Rst: false },
    ];
    expect(trace(plc, steps, ['N1', 'N2'])).toEqual([
      [1, 1],
      [2, 2],
      [3, 0],
      [1, 1],
    ]);
  });
});

describe('5. a coil on the left rail by a bare line is always energised', () => {
  test('LD-R02 warning; the coil is TRUE from the first scan', () => {
    const nets = [ladder(['- - (X)']), ladder(['(Y)'])];
    expect(diags(nets)).toEqual([
      { severity: 'warning', rule: 'LD-R02', network: 0, elementId: nets[0]!.elements[2]!.id },
      { severity: 'warning', rule: 'LD-R02', network: 1, elementId: nets[1]!.elements[0]!.id },
    ]);
    const plc = plcOf(build(nets));
    expect(trace(plc, [{}, {}], ['X', 'Y'])).toEqual([
      [1, 1],
      [1, 1],
    ]);
  });

  test('a transition coil on the rail (LD-R09) is a warning and pulses once', () => {
    const nets = [ladder(['(P:X)'])];
    expect(diags(nets).map((d) => `${d.severity} ${d.rule}`)).toEqual(['warning LD-R09']);
    expect(trace(plcOf(build(nets)), [{}, {}, {}], ['X'])).toEqual([[1], [0], [0]]);
  });

  test('a bare line from rail to rail and one bypassing a contact run as drawn', () => {
    const nets = [ladder(['- - -', '[A] - (X)']), ladder(['[A] + [B] (Y)', '. + - -'])];
    expect(diags(nets).map((d) => `${d.severity} ${d.rule} ${d.network}`)).toEqual([
      'warning LD-R02 0',
      'warning LD-R02 1',
    ]);
    const plc = plcOf(build(nets));
    expect(
      trace(
        plc,
        [
          { A: true, B: false },
          { A: true, B: true },
        ],
        ['X', 'Y'],
      ),
    ).toEqual([
      [1, 0],
      [1, 1],
    ]);
  });
});
