// Functions and function blocks inside networks: EN/ENO, power flow through FBs, data lines,
// integer wrap and REAL rounding through programs, and the semantics profiles.
import { describe, expect, test } from 'vitest';
import { ladder, plcOf, project, vars, type BoxSpec } from './ladder';

const fn = (
  type: string,
  inputs: Record<string, string>,
  outputs: Record<string, string>,
  extra: Partial<BoxSpec> = {},
): BoxSpec => ({
  row: 0,
  col: 1,
  type,
  inputs,
  outputs,
  ...extra,
});

describe('functions with EN/ENO', () => {
  test('INT wraps at its width and REAL rounds to 32 bits, through a program', () => {
    const p = project(
      vars('I INT := 32767', 'R REAL := 0.1', 'U USINT := 250', 'Big LINT := 9223372036854775807'),
      [
        ladder(['- # #'], { boxes: [fn('ADD', { IN1: 'I', IN2: '1' }, { OUT: 'I' })] }),
        ladder(['- # #'], { boxes: [fn('ADD', { IN1: 'R', IN2: '0.2' }, { OUT: 'R' })] }),
        ladder(['- # #'], { boxes: [fn('ADD', { IN1: 'U', IN2: '10' }, { OUT: 'U' })] }),
        ladder(['- # #'], { boxes: [fn('ADD', { IN1: 'Big', IN2: '1' }, { OUT: 'Big' })] }),
      ],
    );
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('I')).toBe(-32768);
    expect(plc.read('R')).toBe(Math.fround(Math.fround(0.1) + Math.fround(0.2)));
    expect(plc.read('U')).toBe(4);
    expect(plc.read('Big')).toBe(-9223372036854775808n);
  });

  test('EN OFF: the function does not run, ENO is OFF, its output variable keeps its value', () => {
    const p = project(vars('Go BOOL', 'N INT := 5', 'Ok BOOL'), [
      ladder(['[Go] # # (Ok)', '. # # .', '. # # .'], {
        boxes: [fn('ADD', { IN1: 'N', IN2: '1' }, { OUT: 'N' })],
      }),
    ]);
    const plc = plcOf(p);
    plc.scan();
    expect([plc.read('N'), plc.read('Ok')]).toEqual([5, false]);
    plc.write('Go', true);
    plc.scan();
    expect([plc.read('N'), plc.read('Ok')]).toEqual([6, true]);
  });

  test('division by zero turns ENO OFF', () => {
    const p = project(vars('A INT := 10', 'B INT := 0', 'Q INT', 'Ok BOOL'), [
      ladder(['- # # (Ok)', '. # # .', '. # # .'], {
        boxes: [fn('DIV', { IN1: 'A', IN2: 'B' }, { OUT: 'Q' })],
      }),
    ]);
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('Ok')).toBe(false);
    plc.write('B', 3);
    plc.scan();
    expect([plc.read('Q'), plc.read('Ok')]).toEqual([3, true]);
  });

  test("a comparison's BOOL output drives a coil as power flow, and is OFF when EN is OFF", () => {
    const p = project(vars('Go BOOL := TRUE', 'Level INT := 80', 'High BOOL'), [
      ladder(['[Go] # # .', '. # # (High)', '. # # .'], {
        boxes: [fn('GT', { IN1: 'Level', IN2: '75' }, {})],
      }),
    ]);
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('High')).toBe(true);
    plc.write('Go', false);
    plc.scan();
    expect(plc.read('High')).toBe(false);
  });

  test('a function with EN not connected always runs', () => {
    const p = project(vars('A INT := 2', 'B INT'), [
      ladder(['. # #'], { boxes: [fn('MUL', { IN1: 'A', IN2: '21' }, { OUT: 'B' })] }),
    ]);
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('B')).toBe(42);
  });

  test('a data line carries ADD.OUT into MOVE.IN (as PLCopen imports draw it)', () => {
    // ADD at column 2: ENO row 1 and OUT row 2 on boundary 3; MOVE at column 5: EN row 1, IN row 2 on boundary 4.
    const p = project(vars('A INT := 2', 'B INT := 3', 'Sum INT'), [
      ladder(['- # # - # #', '. # # - # #', '. # # . . .'], {
        boxes: [
          fn('ADD', { IN1: 'A', IN2: 'B' }, {}),
          { row: 0, col: 4, type: 'MOVE', inputs: {}, outputs: { OUT: 'Sum' } },
        ],
      }),
    ]);
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('Sum')).toBe(5);
    plc.write('A', 40);
    plc.scan();
    expect(plc.read('Sum')).toBe(43);
  });

  test('implicit widening: a SINT variable feeds an INT addition into a DINT result', () => {
    const p = project(vars('S SINT := -100', 'I INT := 1000', 'D DINT'), [
      ladder(['- # #'], { boxes: [fn('ADD', { IN1: 'S', IN2: 'I' }, { OUT: 'D' })] }),
    ]);
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('D')).toBe(900);
  });
});

describe('function blocks in networks', () => {
  const timer = (type: 'TON' | 'TOF' | 'TP') =>
    project(vars('In BOOL', 'Q BOOL', 'T1 ' + type, 'Elapsed TIME'), [
      ladder(['[In] # # (Q)', '. # # .'], {
        boxes: [
          { row: 0, col: 1, type, instance: 'T1', inputs: { PT: 'T#30ms' }, outputs: { ET: 'Elapsed' } },
        ],
      }),
    ]);

  test.each([
    // In per scan (10 ms scans) -> Q after each scan
    ['TON', [1, 1, 1, 1, 1, 0], [0, 0, 0, 1, 1, 0]],
    ['TOF', [1, 0, 0, 0, 0, 0], [1, 1, 1, 1, 0, 0]],
    ['TP', [1, 0, 1, 1, 0, 0], [1, 1, 1, 0, 0, 0]],
  ] as const)('%s on the virtual clock (PT 30 ms, 10 ms scans)', (type, input, q) => {
    const plc = plcOf(timer(type), 10);
    const out = input.map((v) => {
      plc.write('In', v === 1);
      plc.scan();
      return plc.read('Q') ? 1 : 0;
    });
    expect(out).toEqual(q);
  });

  test('TON elapsed time is assigned to a variable beside ET', () => {
    const plc = plcOf(timer('TON'), 10);
    plc.write('In', true);
    plc.scans(3);
    expect(plc.read('Elapsed')).toBe(20);
  });

  test('an FB is called at every evaluation of its network, even without power flow', () => {
    const p = project(vars('In BOOL', 'Q BOOL', 'T1 TON'), [
      ladder(['[In] # # (Q)', '. # # .'], {
        boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#20ms' } }],
      }),
    ]);
    const plc = plcOf(p, 10);
    plc.write('In', true);
    plc.scans(3);
    expect(plc.read('Q')).toBe(true);
    plc.write('In', false);
    plc.scan(); // the TON sees IN OFF and resets
    expect([plc.read('Q'), plc.read('T1.ET')]).toEqual([false, 0]);
  });

  const counter = (profile: 'iec' | 'openplc') =>
    plcOf(
      project(
        vars('Pulse BOOL', 'Clear BOOL', 'C1 CTU', 'Count INT', 'Full BOOL'),
        [
          ladder(['[Pulse] # # (Full)', '. # # .', '. # # .'], {
            boxes: [
              {
                row: 0,
                col: 1,
                type: 'CTU',
                instance: 'C1',
                inputs: { R: 'Clear', PV: '3' },
                outputs: { CV: 'Count' },
              },
            ],
          }),
        ],
        profile,
      ),
    );
  const pulses = (plc: ReturnType<typeof counter>, n: number) => {
    for (let i = 0; i < n; i++) {
      plc.write('Pulse', true);
      plc.scan();
      plc.write('Pulse', false);
      plc.scan();
    }
  };

  test('profile iec: CTU counts past PV', () => {
    const plc = counter('iec');
    pulses(plc, 5);
    expect([plc.read('Count'), plc.read('Full')]).toEqual([5, true]);
  });

  test('profile openplc: CTU stops counting at PV, as MATIEC-compiled programs do', () => {
    const plc = counter('openplc');
    expect(plc.profile).toBe('openplc');
    pulses(plc, 5);
    expect([plc.read('Count'), plc.read('Full')]).toEqual([3, true]);
  });

  test('reset held: count edges do not count', () => {
    const plc = counter('iec');
    plc.write('Clear', true);
    pulses(plc, 2);
    expect(plc.read('Count')).toBe(0);
  });

  test.each([
    ['iec', 2000],
    ['openplc', 2],
  ] as const)('profile %s: TIME_TO_DINT of T#2s gives %d', (profile, expected) => {
    const p = project(
      vars('D DINT'),
      [ladder(['- # #'], { boxes: [fn('TIME_TO_DINT', { IN: 'T#2s' }, { OUT: 'D' })] })],
      profile,
    );
    const plc = plcOf(p);
    plc.scan();
    expect(plc.read('D')).toBe(expected);
  });

  // MOD(x, 0) is 0; with ENO OFF (iec) the output variable is not assigned and keeps its value,
  // as MATIEC-compiled programs assign an output only when ENO is ON.
  test.each([
    ['iec', false, 5],
    ['openplc', true, 0],
  ] as const)('profile %s: MOD by zero with ENO %s leaves M at %s', (profile, eno, m) => {
    const p = project(
      vars('A INT := 7', 'Z INT', 'M INT := 5', 'Ok BOOL'),
      [
        ladder(['- # # (Ok)', '. # # .', '. # # .'], {
          boxes: [fn('MOD', { IN1: 'A', IN2: 'Z' }, { OUT: 'M' })],
        }),
      ],
      profile,
    );
    const plc = plcOf(p);
    plc.scan();
    expect([plc.read('M'), plc.read('Ok')]).toEqual([m, eno]);
  });
});

describe('data lines of BOOL type', () => {
  test('a MOVE of a BOOL variable drives a coil as power flow', () => {
    const p = project(vars('A BOOL', 'X BOOL'), [
      ladder(['- # # .', '. # # (X)'], { boxes: [fn('MOVE', { IN: 'A' }, {})] }),
    ]);
    const plc = plcOf(p);
    plc.write('A', true);
    plc.scan();
    expect(plc.read('X')).toBe(true);
  });
});
