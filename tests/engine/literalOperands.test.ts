// Design decision: an untyped literal beside a generic pin (42, 16#FF, 2#1010, 1.5) adopts the type the block
// resolves to from its other operands, as in IEC 61131-3 and MATIEC; a typed literal (INT#5, T#1s) keeps its type.
import { expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { ladder, plcOf, project, vars } from './ladder';

const andBox = (in2: string) =>
  ladder(['- # # - (Ok)', '. # # . .', '. # # . .'], {
    cols: 5,
    boxes: [{ row: 0, col: 1, type: 'AND', inputs: { IN1: 'W', IN2: in2 }, outputs: { OUT: 'R' } }],
  });

test.each([
  ['16#FF', 0x34],
  ['2#1111_0000', 0x30],
  ['255', 0x34],
])('AND(WORD, %s) masks the word', (literal, expected) => {
  const p = project(vars('W WORD := 16#1234', 'R WORD', 'Ok BOOL'), [andBox(literal)]);
  expect(checkProject(p).filter((d) => d.severity === 'error')).toEqual([]);
  const plc = plcOf(p);
  plc.scan();
  expect(plc.read('R')).toBe(expected);
});

test('a typed literal of another type is refused with LD-R11', () => {
  const p = project(vars('W WORD := 16#1234', 'R WORD', 'Ok BOOL'), [andBox('INT#5')]);
  const errors = checkProject(p).filter((d) => d.severity === 'error');
  expect(errors.map((d) => d.rule)).toEqual(['LD-R11']);
});
