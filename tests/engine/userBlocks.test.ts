// User FUNCTION_BLOCKs and FUNCTIONs written in LD, called from LD networks: each variable class,
// instance state (two instances, nesting, edge memories), FUNCTION statelessness, VAR_IN_OUT by
// reference, EN/ENO, RETURN in a body, paths.
import { describe, expect, test } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { ladder, plcOf, trace, vars, type BoxSpec } from './ladder';
import { io, multiProject, pou } from './userBlocksHelpers';

const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });

/** Motor: Run latches on Start, drops on Stop; counts its starts (a local) through a |P| contact. */
const motor = () =>
  pou(
    'Motor',
    'FUNCTION_BLOCK',
    [...io('input', 'Start BOOL', 'Stop BOOL'), ...io('output', 'Run BOOL', 'Starts INT'), ...vars('Edge BOOL')],
    [
      ladder(['+ [Start] + [/Stop] (Run)', '+ [Run] +']),
      ladder(['[P:Run] # # .', '. # # .', '. # # .'], {
        boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Starts', IN2: '1' }, outputs: { OUT: 'Starts' } })],
      }),
    ],
  );

/** Main: M1 and M2 (Motor), Start1/Start2 and one Stop. */
const twoMotors = () =>
  pou('Main', 'PROGRAM', vars('Start1 BOOL', 'Start2 BOOL', 'Stop BOOL', 'Run1 BOOL', 'Run2 BOOL', 'M1 Motor', 'M2 Motor'), [
    ladder(['[Start1] # # (Run1)', '. # # .'], { boxes: [box('Motor', 0, 1, { instance: 'M1', inputs: { Stop: 'Stop' } })] }),
    ladder(['[Start2] # # (Run2)', '. # # .'], { boxes: [box('Motor', 0, 1, { instance: 'M2', inputs: { Stop: 'Stop' } })] }),
  ]);

describe('user function blocks', () => {
  test('two instances of one FB keep their own state, edge memories included', () => {
    const plc = plcOf(multiProject([twoMotors(), motor()]));
    const rows = trace(
      plc,
      [{ Start1: true }, { Start1: false }, { Start2: true }, { Stop: true, Start2: false }, { Stop: false, Start1: true }],
      ['Run1', 'Run2', 'M1.Starts', 'M2.Starts'],
    );
    expect(rows).toEqual([
      [1, 0, 1, 0],
      [1, 0, 1, 0],
      [1, 1, 1, 1],
      [0, 0, 1, 1],
      [1, 0, 2, 1],
    ]);
  });

  test('an FB inside an FB, and a standard FB inside it, reached by path', () => {
    const line = pou(
      'Line',
      'FUNCTION_BLOCK',
      [...io('input', 'Go BOOL'), ...io('output', 'Ready BOOL'), ...vars('Drive Motor', 'Delay TON')],
      [
        ladder(['[Go] # # .', '. # # .'], { boxes: [box('Motor', 0, 1, { instance: 'Drive', inputs: { Stop: 'FALSE' } })] }),
        ladder(['[Drive.Run] # # (Ready)', '. # # .'], { boxes: [box('TON', 0, 1, { instance: 'Delay', inputs: { PT: 'T#20ms' } })] }),
      ],
    );
    const main = pou('Main', 'PROGRAM', vars('Go BOOL', 'Ready BOOL', 'L1 Line'), [
      ladder(['[Go] # # (Ready)', '. # # .'], { boxes: [box('Line', 0, 1, { instance: 'L1' })] }),
    ]);
    const plc = plcOf(multiProject([main, line, motor()]));
    expect(plc.variableNames()).toEqual(
      expect.arrayContaining(['L1.Go', 'L1.Drive.Run', 'L1.Drive.Starts', 'L1.Delay.ET', 'L1.Delay.Q']),
    );
    const rows = trace(plc, [{ Go: true }, {}, {}, {}], ['Ready', 'L1.Drive.Run', 'l1.delay.et', 'L1.DRIVE.STARTS']);
    expect(rows).toEqual([
      [0, 1, 0, 1],
      [0, 1, 10, 1],
      [1, 1, 20, 1],
      [1, 1, 20, 1],
    ]);
    plc.write('L1.Drive.Stop', true);
    expect(plc.read('L1.Drive.Stop')).toBe(true);
    plc.force('L1.Drive.Run', false);
    plc.scan();
    expect(plc.read('L1.Drive.Run')).toBe(false);
    expect(plc.read('Ready')).toBe(false);
  });

  test('VAR_TEMP starts at its initial value on every call, VAR keeps its value', () => {
    const count = pou(
      'Count',
      'FUNCTION_BLOCK',
      [...io('output', 'Calls INT', 'Temp INT'), ...vars('Kept INT'), ...io('temp', 'Scratch INT := 10')],
      [
        ladder(['- # # .', '. # # .', '. # # .'], {
          boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Kept', IN2: '1' }, outputs: { OUT: 'Kept' } })],
        }),
        ladder(['- # # .', '. # # .', '. # # .'], {
          boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Scratch', IN2: '1' }, outputs: { OUT: 'Scratch' } })],
        }),
        ladder(['- # # - # # .', '. # # . # # .'], {
          boxes: [
            box('MOVE', 0, 1, { inputs: { IN: 'Kept' }, outputs: { OUT: 'Calls' } }),
            box('MOVE', 0, 4, { inputs: { IN: 'Scratch' }, outputs: { OUT: 'Temp' } }),
          ],
        }),
      ],
    );
    const main = pou('Main', 'PROGRAM', vars('C Count'), [
      ladder(['- # # .', '. # # .'], { boxes: [box('Count', 0, 1, { instance: 'C' })] }),
    ]);
    const plc = plcOf(multiProject([main, count]));
    expect(trace(plc, [{}, {}, {}], ['C.Calls', 'C.Temp'])).toEqual([
      [1, 11],
      [2, 11],
      [3, 11],
    ]);
  });

  test('VAR_EXTERNAL in an FB is the global', () => {
    const bump = pou('Bump', 'FUNCTION_BLOCK', [...io('input', 'In BOOL'), ...io('external', 'Total DINT')], [
      ladder(['[In] # # .', '. # # .', '. # # .'], {
        boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Total', IN2: '5' }, outputs: { OUT: 'Total' } })],
      }),
    ]);
    const main = pou('Main', 'PROGRAM', vars('B1 Bump', 'B2 Bump'), [
      ladder(['- # # .', '. # # .'], { boxes: [box('Bump', 0, 1, { instance: 'B1' })] }),
      ladder(['- # # .', '. # # .'], { boxes: [box('Bump', 0, 1, { instance: 'B2' })] }),
    ]);
    const plc = plcOf(multiProject([main, bump], 'iec', vars('Total DINT := 100')));
    plc.scans(2);
    expect(plc.read('Total')).toBe(120);
  });

  test('an FB input left open keeps its previous value (written by a coil on Instance.Pin)', () => {
    const main = pou('Main', 'PROGRAM', vars('S BOOL', 'R BOOL', 'M Motor'), [
      ladder(['[S] (M.Stop)']),
      ladder(['[TRUE] # # (R)', '. # # .'], { boxes: [box('Motor', 0, 1, { instance: 'M' })] }),
    ]);
    const plc = plcOf(multiProject([main, motor()]));
    expect(trace(plc, [{}, { S: true }, { S: false }], ['R', 'M.Stop'])).toEqual([
      [1, 0],
      [0, 1],
      [1, 0],
    ]);
  });

  test('VAR_IN_OUT is passed by reference: the body reads and writes the caller variable', () => {
    const inc = pou('Inc', 'FUNCTION_BLOCK', [...io('input', 'By INT'), ...io('inOut', 'Value INT')], [
      ladder(['- # # .', '. # # .', '. # # .'], {
        boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Value', IN2: 'By' }, outputs: { OUT: 'Value' } })],
      }),
    ]);
    const main = pou('Main', 'PROGRAM', vars('A INT', 'B INT := 100', 'I Inc'), [
      ladder(['. # # .', '. # # .', '. # # .'], { boxes: [box('Inc', 0, 1, { instance: 'I', inputs: { By: '1', Value: 'A' } })] }),
      ladder(['. # # .', '. # # .', '. # # .'], { boxes: [box('Inc', 0, 1, { instance: 'I', inputs: { By: '10', Value: 'B' } })] }),
    ]);
    const plc = plcOf(multiProject([main, inc]));
    expect(trace(plc, [{}, {}], ['A', 'B', 'I.By'])).toEqual([
      [1, 110, 10],
      [2, 120, 10],
    ]);
  });

  test('RETURN in a body ends that body only; the caller goes on', () => {
    const early = pou('Early', 'FUNCTION_BLOCK', [...io('input', 'Skip BOOL'), ...io('output', 'Tail BOOL')], [
      ladder(['[Skip] <RET>']),
      ladder(['- (Tail)']),
    ]);
    const main = pou('Main', 'PROGRAM', vars('Skip BOOL', 'Tail BOOL', 'After BOOL', 'E Early'), [
      ladder(['. # # .', '. # # .'], { boxes: [box('Early', 0, 1, { instance: 'E', inputs: { Skip: 'Skip' }, outputs: { Tail: 'Tail' } })] }),
      ladder(['- (After)']),
    ]);
    const plc = plcOf(multiProject([main, early]));
    expect(trace(plc, [{ Skip: true }, { Skip: false }], ['Tail', 'After'])).toEqual([
      [0, 1],
      [1, 1],
    ]);
  });

  test('EN OFF: an FB with execution control is not executed, keeps its outputs, ENO is OFF', () => {
    const main = pou('Main', 'PROGRAM', vars('En BOOL', 'Go BOOL', 'R BOOL', 'Ok BOOL', 'M Motor'), [
      ladder(['[En] # # (Ok)', '. # # .', '. # # .'], {
        boxes: [{ ...box('Motor', 0, 1, { instance: 'M', inputs: { Start: 'Go', Stop: 'FALSE' }, outputs: { Run: 'R' } }) }],
      }),
    ]);
    const net = main.networks[0]!;
    const withEn = { ...main, networks: [{ ...net, elements: net.elements.map((e) => (e.kind === 'box' ? { ...e, executionControl: true } : e)) }] };
    const plc = plcOf(multiProject([withEn, motor()]));
    expect(trace(plc, [{ En: true, Go: true }, { En: false, Go: false }, { En: true }], ['R', 'Ok', 'M.Starts'])).toEqual([
      [1, 1, 1],
      [1, 0, 1],
      [1, 1, 1],
    ]);
  });

  test('EN OFF on a standard FB with execution control: the timer is not executed', () => {
    const main = pou('Main', 'PROGRAM', vars('En BOOL', 'In BOOL', 'Et TIME', 'T1 TON'), [
      ladder(['[En] # # .', '. # # .', '. # # .'], {
        boxes: [box('TON', 0, 1, { instance: 'T1', inputs: { IN: 'In', PT: 'T#1s' }, outputs: { ET: 'Et' } })],
      }),
    ]);
    const net = main.networks[0]!;
    const withEn = { ...main, networks: [{ ...net, elements: net.elements.map((e) => (e.kind === 'box' ? { ...e, executionControl: true } : e)) }] };
    const plc = plcOf(multiProject([withEn]));
    expect(trace(plc, [{ En: true, In: true }, {}, { En: false }, {}, { En: true }], ['Et'])).toEqual([[0], [10], [10], [10], [40]]);
  });
});

describe('user functions', () => {
  /** Scale(X, Gain := 2): keeps a running Sum local that must not survive between calls. */
  const scale = () =>
    pou(
      'Scale',
      'FUNCTION',
      [...io('input', 'X INT', 'Gain INT := 2'), ...io('output', 'Calls INT'), ...vars('Sum INT')],
      [
        ladder(['- # # .', '. # # .', '. # # .'], {
          boxes: [box('MUL', 0, 1, { inputs: { IN1: 'X', IN2: 'Gain' }, outputs: { OUT: 'Sum' } })],
        }),
        ladder(['- # # - # # .', '. # # . # # .', '. # # . # # .'], {
          boxes: [
            box('ADD', 0, 1, { inputs: { IN1: 'Sum', IN2: '0' }, outputs: { OUT: 'Scale' } }),
            box('ADD', 0, 4, { inputs: { IN1: 'Calls', IN2: '1' }, outputs: { OUT: 'Calls' } }),
          ],
        }),
      ],
      'INT',
    );

  test('a function keeps nothing between calls; an open input takes its declared initial value', () => {
    const main = pou('Main', 'PROGRAM', vars('A INT := 3', 'B INT := 5', 'Ya INT', 'Yb INT', 'Ca INT', 'Cb INT'), [
      ladder(['- # # .', '. # # .', '. # # .', '. # # .'], {
        boxes: [box('Scale', 0, 1, { inputs: { X: 'A', Gain: '10' }, outputs: { OUT: 'Ya', Calls: 'Ca' } })],
      }),
      ladder(['- # # .', '. # # .', '. # # .', '. # # .'], {
        boxes: [box('Scale', 0, 1, { inputs: { X: 'B' }, outputs: { OUT: 'Yb', Calls: 'Cb' } })],
      }),
    ]);
    const plc = plcOf(multiProject([main, scale()]));
    expect(trace(plc, [{}, { A: 4 }, {}], ['Ya', 'Yb', 'Ca', 'Cb'])).toEqual([
      [30, 10, 1, 1],
      [40, 10, 1, 1],
      [40, 10, 1, 1],
    ]);
    expect(plc.variableNames()).not.toEqual(expect.arrayContaining([expect.stringContaining('Sum')]));
  });

  test('EN OFF: the function is not called and its output variables are not assigned', () => {
    const main = pou('Main', 'PROGRAM', vars('En BOOL', 'A INT := 3', 'Y INT := 7', 'Ok BOOL'), [
      ladder(['[En] # # (Ok)', '. # # .', '. # # .', '. # # .'], {
        boxes: [box('Scale', 0, 1, { inputs: { X: 'A' }, outputs: { OUT: 'Y' } })],
      }),
    ]);
    const plc = plcOf(multiProject([main, scale()]));
    expect(trace(plc, [{}, { En: true }, { En: false, A: 10 }], ['Y', 'Ok'])).toEqual([
      [7, 0],
      [6, 1],
      [6, 0],
    ]);
  });

  test('a function VAR_IN_OUT writes the caller variable', () => {
    const swap = pou('Swap', 'FUNCTION', [...io('inOut', 'P INT', 'Q INT'), ...vars('T INT')], [
      ladder(['- # # - # # - # # .', '. # # . # # . # # .'], {
        boxes: [
          box('MOVE', 0, 1, { inputs: { IN: 'P' }, outputs: { OUT: 'T' } }),
          box('MOVE', 0, 4, { inputs: { IN: 'Q' }, outputs: { OUT: 'P' } }),
          box('MOVE', 0, 7, { inputs: { IN: 'T' }, outputs: { OUT: 'Q' } }),
        ],
        cols: 10,
      }),
    ], 'BOOL');
    const main = pou('Main', 'PROGRAM', vars('A INT := 1', 'B INT := 2'), [
      ladder(['- # # .', '. # # .', '. # # .'], { boxes: [box('Swap', 0, 1, { inputs: { P: 'A', Q: 'B' } })] }),
    ]);
    const plc = plcOf(multiProject([main, swap]));
    expect(trace(plc, [{}, {}, {}], ['A', 'B'])).toEqual([
      [2, 1],
      [1, 2],
      [2, 1],
    ]);
  });
});

describe('standard functions that fail keep their output variable (MATIEC)', () => {
  test('DIV by zero: ENO OFF and the output variable keeps its value', () => {
    const main = pou('Main', 'PROGRAM', vars('A INT := 100', 'Z INT', 'Q INT := 42', 'Ok BOOL'), [
      ladder(['- # # (Ok)', '. # # .', '. # # .'], { boxes: [box('DIV', 0, 1, { inputs: { IN1: 'A', IN2: 'Z' }, outputs: { OUT: 'Q' } })] }),
    ]);
    for (const profile of ['iec', 'openplc'] as const) {
      const plc = plcOf(multiProject([main], profile));
      expect(trace(plc, [{}, { Z: 4 }, { Z: 0 }], ['Q', 'Ok'])).toEqual([
        [42, 0],
        [25, 1],
        [25, 0],
      ]);
    }
  });

  test('MUX with a negative selector: ENO OFF (iec); under openplc ENO ON and OUT 0, as MATIEC', () => {
    const main = pou('Main', 'PROGRAM', vars('K INT := -1', 'Q INT := 9', 'Ok BOOL'), [
      ladder(['- # # (Ok)', '. # # .', '. # # .', '. # # .'], {
        boxes: [box('MUX', 0, 1, { inputs: { K: 'K', IN0: '10', IN1: '20' }, outputs: { OUT: 'Q' } })],
      }),
    ]);
    const iec = plcOf(multiProject([main], 'iec'));
    expect(trace(iec, [{}, { K: 1 }, { K: 2 }], ['Q', 'Ok'])).toEqual([
      [9, 0],
      [20, 1],
      [20, 0],
    ]);
    const openplc = plcOf(multiProject([main], 'openplc'));
    expect(trace(openplc, [{}, { K: 1 }, { K: 2 }], ['Q', 'Ok'])).toEqual([
      [0, 1],
      [20, 1],
      [20, 0],
    ]);
  });
});

describe('external blocks (vendor libraries)', () => {
  test('a call of an external FB runs as an empty body: inputs stored, outputs kept, a warning says so', () => {
    const main = pou('Main', 'PROGRAM', vars('Go BOOL', 'Sock INT := 3', 'Ok INT', 'C1 TCP_CLOSE'), [
      ladder(['[Go] # # .', '. # # .'], { boxes: [box('TCP_CLOSE', 0, 1, { instance: 'C1', inputs: { SOCKET_ID: 'Sock' }, outputs: { SUCCESS: 'Ok' } })] }),
    ]);
    const p = multiProject([main]);
    const { program, diagnostics } = compileProgram(p);
    expect(diagnostics.filter((d) => d.rule === 'LD-W10').map((d) => d.message)).toEqual([
      expect.stringMatching(/external block TCP_CLOSE .* does not run its body/),
    ]);
    const plc = createPlc(program!, { cycleMs: 10 });
    expect(trace(plc, [{ Go: true }], ['C1.CLOSE', 'C1.SOCKET_ID', 'Ok'])).toEqual([[1, 3, 0]]);
    plc.force('C1.SUCCESS', 7);
    plc.scan();
    expect(plc.read('Ok')).toBe(7);
  });
});
