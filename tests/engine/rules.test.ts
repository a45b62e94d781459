// Each rule of LD-SEMANTICS.md section 9 (and the LD-E/LD-W checks) with a violating and a valid network.
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { formatDiagnostic } from '../../src/engine/compile/report';
import type { Network, Variable } from '../../src/model/project';
import { ladder, project, vars, type BoxSpec } from './ladder';

const VARS = vars(
  'A BOOL',
  'B BOOL',
  'C BOOL',
  'D BOOL',
  'X BOOL',
  'Y BOOL',
  'W WORD',
  'I INT',
  'S SINT',
  'L DINT',
  'K BOOL := TRUE CONSTANT',
  'In1 BOOL %IX0.0',
  'T1 TON',
  'T2 TON',
  'C1 CTU',
);

const check = (networks: Network[], extra: Variable[] = []) =>
  checkProject(project([...VARS, ...extra], networks));
const rules = (networks: Network[], extra: Variable[] = []) => check(networks, extra).map((d) => d.rule);
const lines = (networks: Network[], extra: Variable[] = []) => check(networks, extra).map(formatDiagnostic);
const ton = (inputs: Record<string, string>, extra: Partial<BoxSpec> = {}): BoxSpec => ({
  row: 0,
  col: 1,
  type: 'TON',
  instance: 'T1',
  inputs,
  ...extra,
});

interface Case {
  readonly rule: string;
  readonly what: string;
  readonly bad: Network[];
  readonly good: Network[];
  readonly extra?: Variable[];
}

const CASES: Case[] = [
  {
    rule: 'LD-R01',
    what: 'a branch that carries power back to the left',
    bad: [ladder(['[A] [B] + (X)', '. + - +', '. + [D] (Y)'])],
    good: [ladder(['[A] + [B] (X)', '[C] + . .'])],
  },
  {
    rule: 'LD-R01',
    what: 'a U-turn line that leaves a contact to the left before reaching a coil',
    bad: [ladder(['[A] [B] + . .', '. + - + . .', '. + - - - (X)'])],
    good: [ladder(['[A] - - - (X)'])],
  },
  {
    rule: 'LD-R01',
    what: 'a loop of contacts and coils through a connector pair (no block keeps a value to read)',
    bad: [ladder(['|>C> [A] (X) >C>|'])],
    good: [ladder(['[A] - >C>| .', '|>C> [B] - (Y)'])],
  },
  {
    rule: 'LD-W30',
    what: 'an explicit loop through a block: TON T1 fed back its own Q through an inverting contact (runs; warned)',
    bad: [ladder(['|>C> [NOT] # # (X) >C>|', '. . # # . .'], { boxes: [ton({ PT: 'T#1s' }, { col: 2 })] })],
    good: [ladder(['[/X] - # # (X)', '. . # # .'], { boxes: [ton({ PT: 'T#1s' }, { col: 2 })] })],
  },
  {
    rule: 'LD-R02',
    what: 'a coil joined to the left rail by bare lines',
    bad: [ladder(['- - (X)'])],
    good: [ladder(['[A] - (X)'])],
  },
  {
    rule: 'LD-R02',
    what: 'a bare branch to the right rail that bypasses a contact and coil',
    bad: [ladder(['[A] + [B] (X)', '. + - -'])],
    good: [ladder(['[A] + [B] (X)', '. + [C] (Y)'])],
  },
  {
    rule: 'LD-R02',
    what: 'the left rail joined straight to the right rail',
    bad: [ladder(['- - -', '[A] - (X)'])],
    good: [ladder(['[A] - (X)'])],
  },
  {
    rule: 'LD-R03',
    what: 'a contact whose right side leads nowhere',
    bad: [ladder(['[A] - .', '[B] - (X)'])],
    good: [ladder(['[A] - (X)'])],
  },
  {
    rule: 'LD-R03',
    what: 'a contact with an open left side',
    bad: [ladder(['. [A] (X)'])],
    good: [ladder(['- [A] (X)'])],
  },
  {
    rule: 'LD-R04',
    what: 'a contact after a coil',
    bad: [ladder(['[A] (X) [B] (Y)'])],
    good: [ladder(['[A] (X) (Y)'])],
  },
  {
    rule: 'LD-R05',
    what: 'two jumps in one network',
    bad: [ladder(['[A] >>L1', '[B] >>L1']), ladder(['[C] (X)'], { label: 'L1' })],
    good: [ladder(['[A] >>L1']), ladder(['[C] (X)'], { label: 'L1' })],
  },
  {
    rule: 'LD-R06',
    what: 'a label that is not an identifier or unsigned number',
    bad: [ladder(['[A] (X)'], { label: '1st' })],
    good: [ladder(['[A] (X)'], { label: '10' }), ladder(['[B] (Y)'], { label: 'Next_Step' })],
  },
  {
    rule: 'LD-R06',
    what: 'the same label twice (case does not count)',
    bad: [ladder(['[A] (X)'], { label: 'Loop' }), ladder(['[B] (Y)'], { label: 'LOOP' })],
    good: [ladder(['[A] (X)'], { label: 'Loop' }), ladder(['[B] (Y)'], { label: 'Loop2' })],
  },
  {
    rule: 'LD-R07',
    what: 'a jump to a label no network has',
    bad: [ladder(['[A] >>NOWHERE']), ladder(['[B] (Y)'], { label: 'THERE' })],
    good: [ladder(['[A] >>there']), ladder(['[B] (Y)'], { label: 'THERE' })],
  },
  {
    rule: 'LD-R08',
    what: 'a coil on an undeclared variable',
    bad: [ladder(['[A] (Nope)'])],
    good: [ladder(['[A] (X)'])],
  },
  {
    rule: 'LD-R08',
    what: 'a coil on an INT variable',
    bad: [ladder(['[A] (I)'])],
    good: [ladder(['[A] (W.3)'])],
  },
  {
    rule: 'LD-R08',
    what: 'a coil naming a constant',
    bad: [ladder(['[A] (TRUE)'])],
    good: [ladder(['[TRUE] (X)'])],
  },
  {
    rule: 'LD-R08',
    what: 'a transition contact naming a constant',
    bad: [ladder(['[P:TRUE] (X)'])],
    good: [ladder(['[P:A] (X)'])],
  },
  {
    rule: 'LD-R08',
    what: 'a coil writing a CONSTANT variable',
    bad: [ladder(['[A] (K)'])],
    good: [ladder(['[K] (X)'])],
  },
  {
    rule: 'LD-R08',
    what: 'a coil writing an FB output',
    bad: [ladder(['[A] (T1.Q)'])],
    good: [ladder(['[T1.Q] (T2.IN)'])],
  },
  {
    rule: 'LD-R08',
    what: 'a bit beyond the width of the word',
    bad: [ladder(['[W.16] (X)'])],
    good: [ladder(['[W.15] (X)'])],
  },
  {
    rule: 'LD-R09',
    what: 'a transition coil on the left rail',
    bad: [ladder(['(P:X)'])],
    good: [ladder(['[A] (P:X)'])],
  },
  {
    rule: 'LD-R10',
    what: 'a function block without an instance name',
    bad: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' }, { instance: undefined })] })],
    good: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' })] })],
  },
  {
    rule: 'LD-R10',
    what: 'an instance that is not declared',
    bad: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' }, { instance: 'T9' })] })],
    good: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' }, { instance: 'T2' })] })],
  },
  {
    rule: 'LD-R10',
    what: 'an instance of another block type',
    bad: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' }, { instance: 'C1' })] })],
    good: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' })] })],
  },
  {
    rule: 'LD-R10',
    what: 'one instance called by two boxes',
    bad: [
      ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' })] }),
      ladder(['[B] # #'], { boxes: [ton({ PT: 'T#2s' })] }),
    ],
    good: [
      ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' })] }),
      ladder(['[B] # #'], { boxes: [ton({ PT: 'T#2s' }, { instance: 'T2' })] }),
    ],
  },
  {
    rule: 'LD-R10',
    what: 'an input with no value',
    bad: [ladder(['[A] # #'], { boxes: [ton({})] })],
    good: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#500ms' })] })],
  },
  {
    rule: 'LD-R10',
    what: 'an input both wired and given an operand',
    bad: [ladder(['[A] # #'], { boxes: [ton({ IN: 'B', PT: 'T#1s' })] })],
    good: [ladder(['. # #'], { boxes: [ton({ IN: 'B', PT: 'T#1s' })] })],
  },
  {
    rule: 'LD-R11',
    what: 'an INT variable on a TIME pin',
    bad: [ladder(['[A] # #'], { boxes: [ton({ PT: 'I' })] })],
    good: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s' })] })],
  },
  {
    rule: 'LD-R11',
    what: 'a DINT sum written to an INT variable (no implicit narrowing)',
    bad: [
      ladder(['- # #'], {
        boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: 'L', IN2: 'I' }, outputs: { OUT: 'I' } }],
      }),
    ],
    good: [
      ladder(['- # #'], {
        boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: 'S', IN2: 'I' }, outputs: { OUT: 'L' } }],
      }),
    ],
  },
  {
    rule: 'LD-R11',
    what: 'an INT result wired to a coil',
    bad: [
      ladder(['- # # .', '. # # (X)'], { boxes: [{ row: 0, col: 1, type: 'MOVE', inputs: { IN: 'I' } }] }),
    ],
    good: [
      ladder(['- # # (X)'], {
        boxes: [{ row: 0, col: 1, type: 'MOVE', inputs: { IN: 'I' }, outputs: { OUT: 'I' } }],
      }),
    ],
  },
  {
    rule: 'LD-R12',
    what: 'a variable written by ( ) and (S)',
    bad: [ladder(['[A] (X)']), ladder(['[B] (S:X)'])],
    good: [ladder(['[A] (S:X)']), ladder(['[B] (R:X)'])],
  },
  {
    rule: 'LD-R13',
    what: 'a coil writing an input',
    bad: [ladder(['[A] (In1)'])],
    good: [ladder(['[In1] (X)'])],
  },
  {
    rule: 'LD-E01',
    what: 'an unknown block type',
    bad: [ladder(['- # #'], { boxes: [{ row: 0, col: 1, type: 'FROB', inputs: {} }] })],
    good: [
      ladder(['- # #'], {
        boxes: [{ row: 0, col: 1, type: 'NOT', inputs: { IN: 'W' }, outputs: { OUT: 'W' } }],
      }),
    ],
  },
  {
    rule: 'LD-E02',
    what: 'an undeclared variable beside a pin',
    bad: [ladder(['[A] # #'], { boxes: [ton({ PT: 'Delay' })] })],
    good: [ladder(['[A] # #'], { boxes: [ton({ PT: 'Delay' })] })],
  },
  {
    rule: 'LD-E03',
    what: 'a literal that does not fit the pin',
    bad: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1q' })] })],
    good: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s500ms' })] })],
  },
  {
    rule: 'LD-E04',
    what: 'an operand for a pin the block does not have',
    bad: [ladder(['[A] # #'], { boxes: [ton({ PT: 'T#1s', PV: '3' })] })],
    good: [ladder(['[A] # #'], { boxes: [ton({ pt: 'T#1s' })] })],
  },
  {
    rule: 'LD-E30',
    what: 'an element outside the grid',
    bad: [{ ...ladder(['[A] (X)']), cols: 1 }],
    good: [ladder(['[A] (X)'])],
  },
  {
    rule: 'LD-W01',
    what: 'an empty network',
    bad: [ladder(['[A] (X)']), ladder([''], { cols: 4 })],
    good: [ladder(['[A] (X)'])],
  },
];

describe('rules: a violating and a valid network each', () => {
  test.each(CASES.map((c) => [c.rule, c.what, c] as const))('%s %s', (rule, _what, c) => {
    if (rule === 'LD-E02') {
      expect(rules(c.bad)).toContain('LD-E02');
      expect(lines(c.good, vars('Delay TIME := T#3s'))).toEqual([]);
      return;
    }
    expect(rules(c.bad, c.extra)).toContain(rule);
    expect(lines(c.good, c.extra)).toEqual([]);
  });
});

describe('diagnostics are located and worded for a PLC programmer', () => {
  test('an open contact names the rule, network, cell and variable', () => {
    const out = lines([ladder(['[A] (X)']), ladder(['[A] (Y)', '[Start] .'])], vars('Start BOOL'));
    expect(out).toContain(
      'warning LD-R03 Main/network 2:R2C1 the contact "Start" has an open right side: its result goes nowhere; connect it to a coil, a block input or the right rail',
    );
  });

  test('a diagnostic carries the element id and the network label', () => {
    const net = ladder(['[A] (Nope)'], { label: 'START' });
    const [d] = check([net]);
    expect(d).toMatchObject({
      rule: 'LD-R08',
      network: 0,
      networkLabel: 'START',
      cell: { row: 0, col: 1 },
      elementId: net.elements[1]!.id,
    });
    expect(d!.message).toMatch(/coil "Nope".*not declared/);
  });

  test('half-drawn networks never crash the checker', () => {
    const odd: Network[] = [
      ladder(['+ + + +', '+ - + -', '- + - +']),
      ladder(['# # # #'], { boxes: [{ row: 0, col: 0, type: 'CTUD', inputs: {} }] }),
      ladder(['[A] - - -'], {
        vlinks: [
          { row: 5, boundary: 2 },
          { row: 0, boundary: 40 },
        ],
      }),
      ladder(['(X) [A] >>  <RET>']),
      ladder(['[] () [/] (S:)']),
    ];
    expect(() => check(odd)).not.toThrow();
    expect(check(odd).length).toBeGreaterThan(0);
  });
});

describe('the variable table', () => {
  const table = (...specs: Variable[]) =>
    checkProject(project(specs, [ladder(['[A] (X)'])])).map((d) => `${d.rule} ${d.network}`);
  test.each([
    ['LD-E10', 'a duplicate name', [...vars('A BOOL', 'X BOOL', 'a BOOL')]],
    ['LD-E11', 'an invalid name', [...vars('A BOOL', 'X BOOL', 'Bad__Name INT')]],
    ['LD-E12', 'a malformed location', [...vars('A BOOL', 'X BOOL', 'Q BOOL %QZ0.1')]],
    ['LD-W04', 'a bit beyond 7, which no device drives', [...vars('A BOOL', 'X BOOL', 'Q BOOL %QX0.9')]],
    ['LD-E13', 'a location that does not hold the type', [...vars('A BOOL', 'X BOOL', 'Q INT %QX0.1')]],
    ['LD-E14', 'a bad initial value', [...vars('A BOOL', 'X BOOL', 'N INT := 70000')]],
    ['LD-E15', 'an unknown type', [...vars('A BOOL', 'X BOOL', 'N MYTYPE')]],
    ['LD-W02', 'two variables at one location', [...vars('A BOOL %IX0.0', 'X BOOL', 'Alias BOOL %IX0.0')]],
  ] as const)('%s %s (network -1)', (rule, _what, specs) => {
    expect(table(...specs)).toContain(`${rule} -1`);
  });
  test('two variables at one location: a warning under iec, an error under openplc (MATIEC refuses it)', () => {
    const specs = vars('A BOOL %IX0.0', 'X BOOL', 'Alias BOOL %IX0.0');
    const iec = checkProject(project(specs, [ladder(['[A] (X)'])], 'iec'));
    expect(iec.find((d) => d.rule === 'LD-W02')?.severity).toBe('warning');
    const openplc = checkProject(project(specs, [ladder(['[A] (X)'])], 'openplc'));
    const e = openplc.find((d) => d.rule === 'LD-E17');
    expect(e?.severity).toBe('error');
    expect(e?.message).toBe(
      'the variable "Alias" shares the location %IX0.0 with "A": MATIEC refuses two variables at one location ("invalid location in global location declaration"); give each its own address, or use one variable',
    );
    expect(openplc.some((d) => d.rule === 'LD-W02')).toBe(false);
  });
  test('a clean table has no diagnostics', () => {
    expect(
      table(...vars('A BOOL %IX0.0', 'X BOOL %QX0.0', 'N INT %MW2 := -5 RETAIN', 'D TIME := T#2s')),
    ).toEqual([]);
  });
});
