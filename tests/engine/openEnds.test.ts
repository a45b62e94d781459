// Open ends (LD-R03) and function inputs left unconnected run as Beremiz/MATIEC run them
// (LD-SEMANTICS.md sections 4 and 9; issue 12, section 2). Beremiz generates code from coils and
// blocks backwards (PLCGenerator.py ComputeProgram/GeneratePaths): every block is called, a path
// that leads nowhere is never read, a coil with no connection on its left gets no assignment, and
// an input with no connection is left out of the call. MATIEC gives a function input left out of
// the call its type's initial value (stage4 generate_c: default_value, else type_initial_value).
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { Network, Variable } from '../../src/model/project';
import { ladder, plcOf, project, trace, vars } from './ladder';

const VARS = vars(
  'A BOOL',
  'B BOOL',
  'X BOOL',
  'Y BOOL := TRUE',
  'Z BOOL',
  'N1 INT',
  'N2 INT',
  'D TIME',
  'E TIME',
  'T1 TON',
  'C1 CTU',
);

const build = (networks: Network[], extra: Variable[] = []) => project([...VARS, ...extra], networks);
const diags = (networks: Network[]) =>
  checkProject(build(networks)).map((d) => ({
    severity: d.severity,
    rule: d.rule,
    network: d.network,
    elementId: d.elementId,
  }));
const brief = (networks: Network[]) =>
  checkProject(build(networks)).map((d) => `${d.severity} ${d.rule} ${d.network}`);
const messages = (networks: Network[]) => checkProject(build(networks)).map((d) => d.message);


describe('1. open ends (LD-R03) are warnings and the network runs', () => {
  test('a contact whose right side leads nowhere: a warning naming it; the rest of the network runs', () => {
    const nets = [ladder(['[A] - .', '[B] - (X)'])];
    // The line after it ends in nothing (named first), and the contact's result goes nowhere.
    expect(diags(nets)).toEqual([
      { severity: 'warning', rule: 'LD-R03', network: 0, elementId: nets[0]!.elements[1]!.id },
      { severity: 'warning', rule: 'LD-R03', network: 0, elementId: nets[0]!.elements[0]!.id },
    ]);
    expect(messages(nets)[1]).toMatch(/the contact "A" has an open right side: its result goes nowhere/);
    const steps = [
      { A: true, B: false },
      { A: false, B: true },
      { A: true, B: true },
    ];
    expect(trace(plcOf(build(nets)), steps, ['X'])).toEqual([[0], [1], [1]]);
  });

  test('a block whose output leads nowhere is still called: a TON and a CTU run for their side effects', () => {
    const nets = [
      ladder(['[A] # #'], {
        boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#20ms' } }],
      }),
      ladder(['[B] # #'], { boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { PV: '2' } }] }),
      ladder(['[T1.Q] (X)']),
    ];
    expect(diags(nets)).toEqual([]);
    const steps = [
      { A: true, B: true },
      { A: true, B: false },
      { A: true, B: true },
      { A: false, B: false },
    ];
    expect(trace(plcOf(build(nets)), steps, ['T1.ET', 'X', 'C1.CV', 'C1.Q'])).toEqual([
      [0, 0, 1, 0],
      [10, 0, 1, 0],
      [20, 1, 2, 1],
      [0, 0, 2, 1],
    ]);
  });

  test('a contact with an open left side is never energised: the coil it feeds is written FALSE', () => {
    const nets = [ladder(['. [A] (Y)'])];
    expect(diags(nets)).toEqual([
      { severity: 'warning', rule: 'LD-R03', network: 0, elementId: nets[0]!.elements[0]!.id },
    ]);
    expect(messages(nets)[0]).toMatch(/the contact "A" has an open left side: it is never energised/);
    // Y starts TRUE; the coil runs with the contact's FALSE right side even while A is ON.
    expect(trace(plcOf(build(nets)), [{ A: true }, { A: false }], ['Y'])).toEqual([[0], [0]]);
  });

  test('a coil with nothing on its left is not executed (Beremiz emits no assignment): its variable keeps its value', () => {
    const nets = [ladder(['. (Y)', '. (/Z)', '. (N:X)'])];
    expect(brief(nets)).toEqual(['warning LD-R03 0', 'warning LD-R03 0', 'warning LD-R03 0']);
    expect(messages(nets)[0]).toMatch(/the coil "Y" has an open left side: it is never executed/);
    // Had they run with a FALSE left side, Y would be FALSE, Z TRUE and the N coil would pulse X once.
    expect(trace(plcOf(build(nets)), [{}, {}], ['Y', 'Z', 'X'])).toEqual([
      [1, 0, 0],
      [1, 0, 0],
    ]);
  });

  test('a line that ends in nothing, and one that starts nowhere into a block input (left unconnected)', () => {
    const nets = [
      ladder(['[A] - . (X)', '[B] (Z) . .']),
      ladder(['. - # # (X)'], {
        boxes: [{ row: 0, col: 2, type: 'TON', instance: 'T1', inputs: { PT: 'T#10ms' } }],
      }),
      ladder(['[A] (T1.IN)']),
    ];
    const found = brief(nets);
    expect(found.every((d) => d.startsWith('warning'))).toBe(true);
    expect(found).toContain('warning LD-R03 0');
    expect(found).toContain('warning LD-R03 1');
    expect(messages(nets).join('\n')).toMatch(
      /input IN of the TON block "T1" is wired to a line that starts nowhere/,
    );
    // Network 1: the TON's IN counts as unconnected, so it keeps the instance value (set by network 2
    // in the previous scan), exactly as an FB input Beremiz leaves out of the call.
    const steps = [
      { A: true, B: true },
      { A: true, B: false },
      { A: true, B: false },
      { A: false, B: false },
    ];
    expect(trace(plcOf(build(nets)), steps, ['X', 'Z', 'T1.ET'])).toEqual([
      [0, 1, 0],
      [0, 0, 0],
      [1, 0, 10],
      [1, 0, 10],
    ]);
  });
});

describe("2. a function input left unconnected takes its type's initial value (IEC, MATIEC)", () => {
  test('ADD with IN2 unconnected: a warning naming the pin; OUT = IN1 + 0', () => {
    const nets = [
      ladder(['- # #'], {
        boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: 'N1' }, outputs: { OUT: 'N2' } }],
      }),
    ];
    expect(diags(nets)).toEqual([
      { severity: 'warning', rule: 'LD-R10', network: 0, elementId: nets[0]!.elements.at(-1)!.id },
    ]);
    expect(messages(nets)[0]).toMatch(
      /input IN2 of the ADD block at R1C2 is not connected: it takes the initial value of INT \(0\)/,
    );
    expect(trace(plcOf(build(nets)), [{ N1: 5 }, { N1: -7 }], ['N2'])).toEqual([[5], [-7]]);
  });

  test('AND with IN2 unconnected: OUT is always FALSE (IN2 = FALSE), ENO follows EN', () => {
    const nets = [
      ladder(['[A] # # (X)', '. # # (Y)'], {
        boxes: [{ row: 0, col: 1, type: 'AND', inputs: { IN1: 'B' } }],
      }),
    ];
    expect(brief(nets)).toEqual(['warning LD-R10 0']);
    expect(messages(nets)[0]).toMatch(
      /input IN2 of the AND block at R1C2 is not connected: it takes the initial value of BOOL \(FALSE\)/,
    );
    const steps = [
      { A: true, B: true },
      { A: false, B: true },
      { A: true, B: false },
    ];
    expect(trace(plcOf(build(nets)), steps, ['X', 'Y'])).toEqual([
      [1, 0],
      [0, 0],
      [1, 0],
    ]);
  });

  test('TIME and non-generic pins: ADD(D, open) = D; SEL with G open selects IN0', () => {
    const nets = [
      ladder(['- # #'], {
        boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: 'D' }, outputs: { OUT: 'E' } }],
      }),
      ladder(['- # #'], {
        boxes: [{ row: 0, col: 1, type: 'SEL', inputs: { IN0: 'N1', IN1: '99' }, outputs: { OUT: 'N2' } }],
      }),
    ];
    expect(brief(nets)).toEqual(['warning LD-R10 0', 'warning LD-R10 1']);
    expect(messages(nets)[0]).toMatch(/initial value of TIME \(T#0s\)/);
    expect(messages(nets)[1]).toMatch(
      /input G of the SEL block at R1C2 is not connected: it takes the initial value of BOOL \(FALSE\)/,
    );
    expect(trace(plcOf(build(nets)), [{ D: 1500, N1: 3 }], ['E', 'N2'])).toEqual([[1500, 3]]);
  });

  test('no pin gives the generic type: the type an untyped literal takes (INT) is assumed and named', () => {
    const nets = [
      ladder(['[A] # # (X)'], { boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN2: '40000' } }] }),
    ];
    // 40000 does not fit INT: the untyped literal is read as INT, as with every other pin of the block.
    expect(brief(nets)).toContain('error LD-E03 0');
    const ok = [ladder(['[A] # # (X)'], { boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN2: '4' } }] })];
    expect(brief(ok)).toEqual(['warning LD-R10 0']);
    expect(messages(ok)[0]).toMatch(
      /input IN1 of the ADD block at R1C2 is not connected: .*no other input gives the block a type, so INT is assumed/,
    );
    expect(trace(plcOf(build(ok)), [{ A: true }, { A: false }], ['X'])).toEqual([[1], [0]]);
  });
});
