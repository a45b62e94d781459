// Struct and array values on the pins of the project's own blocks, called from LD: inputs copied in
// before the call, outputs copied out after, VAR_IN_OUT by reference, a FUNCTION returning a
// structure (beside its pin and wired to another block), and the LD-R11 type errors, located.
import { describe, expect, test } from 'vitest';
import { compileProgram } from '../../src/engine/plc';
import { formatDiagnostic } from '../../src/engine/compile/report';
import { variable } from '../../src/model/factory';
import type { DataType, Pou, Variable } from '../../src/model/project';
import { ladder, plcOf, trace, vars, type BoxSpec } from './ladder';
import { io, multiProject, pou } from './userBlocksHelpers';
import { stErrors, stPlc, stProject, textPou } from './stHelpers';

const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });
const v = (name: string, type: string, varClass: Variable['varClass'] = 'local'): Variable => variable(name, type, { varClass });

const TYPES: DataType[] = [
  { name: 'ScaleCfg', def: { kind: 'struct', members: [{ name: 'Gain', type: 'INT', initial: '2' }, { name: 'Offset', type: 'INT' }] } },
  { name: 'OtherCfg', def: { kind: 'struct', members: [{ name: 'Gain', type: 'INT' }, { name: 'Offset', type: 'INT' }] } },
  { name: 'Pair', def: { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'Y', type: 'INT' }] } },
];

const typed = (pous: readonly Pou[], globals: readonly Variable[] = []) => ({ ...multiProject(pous, 'iec', globals), dataTypes: TYPES });

/** A box alone on its rows: `rows` rows of `. # # .` (cells covered by the box). */
const boxRows = (rows: number, width = 4): string[] => Array.from({ length: rows }, () => ['.', '#', '#', ...Array(width - 3).fill('.')].join(' '));

/**
 * Scale: Out := In * Cfg.Gain + Cfg.Offset; Last := Cfg (with Last.Gain + 100 written into its
 * own copy of Cfg after, which the caller must not see); Hist[1..4] := In, 2*In, 3*In, 4*In.
 */
const scale = () =>
  pou(
    'Scale',
    'FUNCTION_BLOCK',
    [v('Cfg', 'ScaleCfg', 'input'), ...io('input', 'In INT'), ...io('output', 'Out INT'), v('Last', 'ScaleCfg', 'output'), v('Hist', 'ARRAY[1..4] OF INT', 'output'), ...vars('T INT')],
    [
      ladder(boxRows(3), { boxes: [box('MUL', 0, 1, { inputs: { IN1: 'In', IN2: 'Cfg.Gain' }, outputs: { OUT: 'T' } })] }),
      ladder(boxRows(3), { boxes: [box('ADD', 0, 1, { inputs: { IN1: 'T', IN2: 'Cfg.Offset' }, outputs: { OUT: 'Out' } })] }),
      ladder(boxRows(2), { boxes: [box('MOVE', 0, 1, { inputs: { IN: 'Cfg.Gain' }, outputs: { OUT: 'Last.Gain' } })] }),
      ladder(boxRows(2), { boxes: [box('MOVE', 0, 1, { inputs: { IN: 'Cfg.Offset' }, outputs: { OUT: 'Last.Offset' } })] }),
      ladder(boxRows(3), { boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Cfg.Gain', IN2: '100' }, outputs: { OUT: 'Cfg.Gain' } })] }),
      ...[1, 2, 3, 4].map((k) =>
        ladder(boxRows(3), { boxes: [box('MUL', 0, 1, { inputs: { IN1: 'In', IN2: String(k) }, outputs: { OUT: `Hist[${k}]` } })] }),
      ),
    ],
  );

const errorsOf = (p: ReturnType<typeof typed>): string[] =>
  compileProgram(p).diagnostics.filter((d) => d.severity === 'error').map(formatDiagnostic);

describe('struct and array pins of user blocks', () => {
  test('a struct input is copied in before the call; struct and array outputs are copied out after', () => {
    const main = pou('Main', 'PROGRAM', [v('MyCfg', 'ScaleCfg'), v('Got', 'ScaleCfg'), v('H', 'ARRAY[1..4] OF INT'), ...vars('S1 Scale', 'X INT', 'Y INT')], [
      ladder(boxRows(4), {
        boxes: [box('Scale', 0, 1, { instance: 'S1', inputs: { Cfg: 'MyCfg', In: 'X' }, outputs: { Out: 'Y', Last: 'Got', Hist: 'H' } })],
      }),
    ]);
    const plc = plcOf(typed([main, scale()]));
    const rows = trace(plc, [{ X: 3 }, { 'MyCfg.Offset': 1 }, { 'MyCfg.Gain': 5, X: 2 }], ['Y', 'Got.Gain', 'Got.Offset', 'MyCfg.Gain', 'S1.Cfg.Gain', 'H[1]', 'H[4]']);
    // The body's write into its copy (Cfg.Gain + 100) is not the caller's MyCfg, and the next call copies MyCfg again.
    expect(rows).toEqual([
      [6, 2, 0, 2, 102, 3, 12],
      [7, 2, 1, 2, 102, 3, 12],
      [11, 5, 1, 5, 105, 2, 8],
    ]);
  });

  test('VAR_IN_OUT of a struct is the caller variable itself: a body write is seen at once, through another name too', () => {
    // Bump: Buf.X := Buf.X + 1, then Seen := G.X (G is the global the caller passes as Buf).
    const bump = pou(
      'Bump',
      'FUNCTION_BLOCK',
      [v('Buf', 'Pair', 'inOut'), ...io('output', 'Seen INT'), v('G', 'Pair', 'external')],
      [
        ladder(boxRows(3), { boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Buf.X', IN2: '1' }, outputs: { OUT: 'Buf.X' } })] }),
        ladder(boxRows(2), { boxes: [box('MOVE', 0, 1, { inputs: { IN: 'G.X' }, outputs: { OUT: 'Seen' } })] }),
      ],
    );
    const main = pou('Main', 'PROGRAM', [...vars('B1 Bump', 'After INT'), v('G', 'Pair', 'external')], [
      ladder(boxRows(2), { boxes: [box('Bump', 0, 1, { instance: 'B1', inputs: { Buf: 'G' } })] }),
      ladder(boxRows(2), { boxes: [box('MOVE', 0, 1, { inputs: { IN: 'G.X' }, outputs: { OUT: 'After' } })] }),
    ]);
    const plc = plcOf(typed([main, bump], [v('G', 'Pair')]));
    expect(trace(plc, [{}, {}, { 'G.X': 10 }], ['B1.Seen', 'After', 'G.X'])).toEqual([
      [1, 1, 1],
      [2, 2, 2],
      [11, 11, 11],
    ]);
  });

  test('VAR_IN_OUT of an array passed to two in-outs of one call: both names are one variable', () => {
    // Twice: A[1] := 5; B[2] := A[1] + B[1] (B is A).
    const twice = pou(
      'Twice',
      'FUNCTION_BLOCK',
      [v('A', 'ARRAY[1..2] OF INT', 'inOut'), v('B', 'ARRAY[1..2] OF INT', 'inOut')],
      [
        ladder(boxRows(2), { boxes: [box('MOVE', 0, 1, { inputs: { IN: '5' }, outputs: { OUT: 'A[1]' } })] }),
        ladder(boxRows(3), { boxes: [box('ADD', 0, 1, { inputs: { IN1: 'A[1]', IN2: 'B[1]' }, outputs: { OUT: 'B[2]' } })] }),
      ],
    );
    const main = pou('Main', 'PROGRAM', [v('Buf', 'ARRAY[1..2] OF INT'), ...vars('T1 Twice')], [
      ladder(boxRows(2), { boxes: [box('Twice', 0, 1, { instance: 'T1', inputs: { A: 'Buf', B: 'Buf' } })] }),
    ]);
    const plc = plcOf(typed([main, twice]));
    plc.scan();
    expect([plc.read('Buf[1]'), plc.read('Buf[2]')]).toEqual([5, 10]);
  });

  test('a FUNCTION returning a structure: beside its OUT pin, and wired into a struct input of another block', () => {
    // MakeCfg(G) := (Gain := G, Offset := G + 1)
    const makeCfg = pou(
      'MakeCfg',
      'FUNCTION',
      [...io('input', 'G INT')],
      [
        ladder(boxRows(2), { boxes: [box('MOVE', 0, 1, { inputs: { IN: 'G' }, outputs: { OUT: 'MakeCfg.Gain' } })] }),
        ladder(boxRows(3), { boxes: [box('ADD', 0, 1, { inputs: { IN1: 'G', IN2: '1' }, outputs: { OUT: 'MakeCfg.Offset' } })] }),
      ],
      'ScaleCfg',
    );
    const main = pou('Main', 'PROGRAM', [v('C', 'ScaleCfg'), ...vars('S1 Scale', 'K INT', 'Y INT')], [
      ladder(['- # # .', '. # # .'], { boxes: [box('MakeCfg', 0, 1, { inputs: { G: 'K' }, outputs: { OUT: 'C' } })] }),
      // MakeCfg's OUT (row 1) feeds Scale's Cfg (row 1): Y := 4 * K + (K + 1)
      ladder(['- # # . . .', '. # # # # .', '. . . # # .'], {
        boxes: [box('MakeCfg', 0, 1, { inputs: { G: 'K' } }), box('Scale', 1, 3, { instance: 'S1', inputs: { In: '4' }, outputs: { Out: 'Y' } })],
      }),
    ]);
    const plc = plcOf(typed([main, scale(), makeCfg]));
    expect(trace(plc, [{ K: 3 }, { K: 5 }], ['C.Gain', 'C.Offset', 'Y'])).toEqual([
      [3, 4, 16],
      [5, 6, 26],
    ]);
  });

  test('a struct or array of another type on a pin is LD-R11, naming the network, the block and both types', () => {
    const main = pou('Main', 'PROGRAM', [v('Mine', 'OtherCfg'), v('H', 'ARRAY[0..3] OF INT'), ...vars('S1 Scale', 'X INT')], [
      ladder(boxRows(2)),
      ladder(boxRows(4), { boxes: [box('Scale', 0, 1, { instance: 'S1', inputs: { Cfg: 'Mine', In: 'X' } })] }),
      ladder(boxRows(4), { boxes: [box('Scale', 0, 1, { instance: 'S1', inputs: { In: 'X' }, outputs: { Hist: 'H', Last: 'X' } })] }),
    ]);
    const errors = errorsOf(typed([main, scale()]));
    expect(errors).toEqual([
      'error LD-R11 Main/network 2:R1C2 input Cfg of the Scale block "S1" expects ScaleCfg; Mine is OtherCfg',
      'error LD-R11 Main/network 3:R1C2 output Last of the Scale block "S1" gives ScaleCfg, a whole structure; X is INT',
      'error LD-R11 Main/network 3:R1C2 output Hist of the Scale block "S1" gives ARRAY[1..4] OF INT; H is ARRAY[0..3] OF INT',
    ]);
  });

  test('an in-out struct pin needs a variable: a function result on its line is LD-E23', () => {
    const keep = pou('Keep', 'FUNCTION_BLOCK', [v('Buf', 'ScaleCfg', 'inOut')], [ladder(boxRows(2))]);
    const makeCfg = pou('MakeCfg', 'FUNCTION', [...io('input', 'G INT')], [ladder(boxRows(2))], 'ScaleCfg');
    const main = pou('Main', 'PROGRAM', [...vars('K1 Keep')], [
      ladder(['- # # . . .', '. # # # # .'], { boxes: [box('MakeCfg', 0, 1, { inputs: { G: '1' } }), box('Keep', 1, 3, { instance: 'K1' })] }),
    ]);
    const errors = errorsOf(typed([main, keep, makeCfg]));
    expect(errors).toEqual([
      'error LD-E23 Main/network 1:R2C4 the in-out Buf of the Keep block "K1" must name a variable: it is passed by reference, and the line from output OUT of the MakeCfg block at R1C2 carries a function\'s result',
    ]);
  });
});

describe('struct and array arguments of user blocks called from ST', () => {
  const makePair = textPou('MakePair', 'FUNCTION', [...io('input', 'A INT')], 'MakePair.X := A; MakePair.Y := A * 2;', { returnType: 'Pair' });
  // Swap: Old := P (copied out); P.X and P.Y swapped in the caller's variable (by reference).
  const swap = textPou('Swap', 'FUNCTION_BLOCK', [v('P', 'Pair', 'inOut'), v('Old', 'Pair', 'output'), ...vars('T INT')], 'Old := P; T := P.X; P.X := P.Y; P.Y := T;');

  test('a FUNCTION returning a structure assigned whole; an in-out struct by reference; a struct output copied out', () => {
    const main = textPou('Main', 'PROGRAM', [v('Q', 'Pair'), v('R', 'Pair'), ...vars('S1 Swap', 'K INT')], 'Q := MakePair(K); S1(P := Q, Old => R);');
    const plc = stPlc({ ...stProject([main, makePair, swap]), dataTypes: TYPES });
    expect(trace(plc, [{ K: 3 }, { K: 5 }], ['Q.X', 'Q.Y', 'R.X', 'R.Y'])).toEqual([
      [6, 3, 3, 6],
      [10, 5, 5, 10],
    ]);
  });

  test('a structure of another type is refused, at its line', () => {
    const main = textPou('Main', 'PROGRAM', [v('C', 'ScaleCfg'), v('R', 'Pair'), ...vars('S1 Swap')], 'C := MakePair(1);\nS1(P := C);\nS1(P := R, Old => C);');
    expect(stErrors({ ...stProject([main, makePair, swap]), dataTypes: TYPES })).toEqual([
      'error LD-E50 Main/line 1 col 6 the ST body of Main does not compile: line 1 col 6: "C" is the structure ScaleCfg; MakePair(...) returns Pair',
      'error LD-E50 Main/line 2 col 9 the ST body of Main does not compile: line 2 col 9: the in-out P of Swap is Pair; "C" is the structure ScaleCfg',
      'error LD-E50 Main/line 3 col 19 the ST body of Main does not compile: line 3 col 19: the output Old of Swap is the structure Pair; "C" is the structure ScaleCfg',
    ]);
  });
});
