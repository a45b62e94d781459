// Rules on user blocks: recursion (LD-E21), what a FUNCTION cannot hold (LD-E22), VAR_IN_OUT
// wired to a variable (LD-E23), no PROGRAM called from a network (LD-E24), the instance declared
// with the box's type (LD-R10), a changed interface (LD-E04), diagnostics once per POU.
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { compileProgram } from '../../src/engine/plc';
import type { Diagnostic } from '../../src/engine/api';
import { ladder, vars, type BoxSpec } from './ladder';
import { io, multiProject, pou } from './userBlocksHelpers';

const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });
const errors = (ds: readonly Diagnostic[]) => ds.filter((d) => d.severity === 'error');
const brief = (d: Diagnostic) => `${d.rule} ${d.pou}/${d.network + 1}`;

const caller = (name: string, kind: 'PROGRAM' | 'FUNCTION_BLOCK', callee: string, extraVars: string[] = []) =>
  pou(name, kind, vars(...extraVars, ...(callee ? [`I ${callee}`] : [])), [
    ladder(['- # # .', '. # # .'], { boxes: [box(callee, 0, 1, { instance: 'I' })] }),
  ]);

describe('recursion (LD-E21)', () => {
  test('an FB calling itself is refused, naming the cycle', () => {
    const self = pou('Loop', 'FUNCTION_BLOCK', vars('Again Loop'), [
      ladder(['- # # .', '. # # .'], { boxes: [box('Loop', 0, 1, { instance: 'Again' })] }),
    ]);
    const p = multiProject([caller('Main', 'PROGRAM', 'Loop'), self]);
    const { program, diagnostics } = compileProgram(p);
    expect(program).toBeUndefined();
    const e21 = errors(diagnostics).filter((d) => d.rule === 'LD-E21');
    expect(e21.map(brief)).toEqual(expect.arrayContaining(['LD-E21 Loop/0', 'LD-E21 Loop/1']));
    expect(e21[0]!.message).toContain('Loop → Loop');
  });

  test('indirect recursion through another FB is refused in both POUs', () => {
    const a = caller('A', 'FUNCTION_BLOCK', 'B');
    const b = caller('B', 'FUNCTION_BLOCK', 'A');
    const p = multiProject([caller('Main', 'PROGRAM', 'A'), a, b]);
    const { program, diagnostics } = compileProgram(p);
    expect(program).toBeUndefined();
    const e21 = errors(diagnostics).filter((d) => d.rule === 'LD-E21');
    expect(new Set(e21.map((d) => d.pou))).toEqual(new Set(['A', 'B']));
    expect(e21.find((d) => d.pou === 'A' && d.network === 0)!.message).toContain('A → B → A');
    // checkProject reports it too, for the Problems list.
    expect(checkProject(p).filter((d) => d.rule === 'LD-E21').length).toBeGreaterThanOrEqual(2);
  });

  test('a function calling itself is refused', () => {
    const f = pou('F', 'FUNCTION', io('input', 'X INT'), [
      ladder(['- # # .', '. # # .', '. # # .'], { boxes: [box('F', 0, 1, { inputs: { X: 'X' }, outputs: { OUT: 'F' } })] }),
    ], 'INT');
    const main = pou('Main', 'PROGRAM', vars('Y INT'), [
      ladder(['- # # .', '. # # .', '. # # .'], { boxes: [box('F', 0, 1, { inputs: { X: '1' }, outputs: { OUT: 'Y' } })] }),
    ]);
    const { program, diagnostics } = compileProgram(multiProject([main, f]));
    expect(program).toBeUndefined();
    expect(errors(diagnostics).map(brief)).toContain('LD-E21 F/1');
  });
});

describe('what a FUNCTION cannot hold (LD-E22)', () => {
  test('FB instances and edge contacts or coils in a function are refused, saying why', () => {
    const f = pou('F', 'FUNCTION', [...io('input', 'X BOOL'), ...vars('T TON')], [ladder(['[P:X] (N:F)'])], 'BOOL');
    const ds = errors(checkProject(multiProject([pou('Main', 'PROGRAM', [], [ladder(['- (Q)'])]), f])));
    const e22 = ds.filter((d) => d.rule === 'LD-E22');
    expect(e22.map(brief)).toEqual(['LD-E22 F/0', 'LD-E22 F/1', 'LD-E22 F/1']);
    expect(e22[0]!.message).toMatch(/keeps nothing between calls/);
    expect(e22[1]!.message).toMatch(/memory of the previous value would be lost/);
    expect(e22[1]!.cell).toEqual({ row: 0, col: 0 });
  });
});

describe('calls', () => {
  const inc = () =>
    pou('Inc', 'FUNCTION_BLOCK', io('inOut', 'Value INT'), [
      ladder(['- # # .', '. # # .', '. # # .'], { boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Value', IN2: '1' }, outputs: { OUT: 'Value' } })] }),
    ]);

  test('VAR_IN_OUT must name a variable: not a literal, not left open (LD-E23)', () => {
    const main = pou('Main', 'PROGRAM', vars('I1 Inc', 'I2 Inc', 'K INT CONSTANT'), [
      ladder(['. # # .'], { boxes: [box('Inc', 0, 1, { instance: 'I1', inputs: { Value: '5' } })] }),
      ladder(['. # # .'], { boxes: [box('Inc', 0, 1, { instance: 'I2' })] }),
      ladder(['. # # .'], { boxes: [box('Inc', 0, 1, { instance: 'I2', inputs: { Value: 'K' } })] }),
    ]);
    const { program, diagnostics } = compileProgram(multiProject([main, inc()]));
    expect(program).toBeUndefined();
    const e23 = errors(diagnostics).filter((d) => d.rule === 'LD-E23');
    expect(e23.map(brief)).toEqual(['LD-E23 Main/1', 'LD-E23 Main/2', 'LD-E23 Main/3']);
    expect(e23[0]!.message).toMatch(/in-out Value .* constant/);
    expect(e23[1]!.message).toMatch(/not connected/);
    expect(e23[2]!.message).toMatch(/CONSTANT/);
  });

  test('a PROGRAM is not called from a network (LD-E24)', () => {
    const main = pou('Main', 'PROGRAM', [], [ladder(['- # # .'], { boxes: [box('Other', 0, 1)] })]);
    const other = pou('Other', 'PROGRAM', [], [ladder(['- (Q)'])]);
    const ds = errors(compileProgram(multiProject([main, other])).diagnostics);
    expect(ds.map(brief)).toEqual(['LD-E24 Main/1']);
    expect(ds[0]!.message).toMatch(/calls the PROGRAM Other/);
  });

  test('the instance must be declared with the box type (LD-R10)', () => {
    const main = pou('Main', 'PROGRAM', vars('I TON', 'Q BOOL'), [
      ladder(['. # # .'], { boxes: [box('Inc', 0, 1, { instance: 'I', inputs: { Value: 'Q' } })] }),
      ladder(['. # # .'], { boxes: [box('Inc', 0, 1, { instance: 'Nope', inputs: { Value: 'Q' } })] }),
    ]);
    const ds = errors(compileProgram(multiProject([main, inc()])).diagnostics).filter((d) => d.rule === 'LD-R10');
    expect(ds.map((d) => d.message)).toEqual([
      expect.stringMatching(/"I" is declared as TON, not Inc/),
      expect.stringMatching(/"Nope" is not declared; add a variable "Nope" of type Inc/),
    ]);
  });

  test('a pin the interface no longer has is reported on the box, naming it (LD-E04)', () => {
    const main = pou('Main', 'PROGRAM', vars('I Inc', 'A INT', 'B INT'), [
      ladder(['. # # .', '. # # .'], { boxes: [box('Inc', 0, 1, { instance: 'I', inputs: { Value: 'A', Step: 'B' } })] }),
    ]);
    const ds = errors(compileProgram(multiProject([main, inc()])).diagnostics);
    expect(ds.map(brief)).toEqual(['LD-E04 Main/1']);
    expect(ds[0]!.message).toMatch(/no input "Step" \(the interface of Inc has no such pin; it may have changed/);
    expect(ds[0]!.cell).toEqual({ row: 0, col: 1 });
  });

  test("a callee's problems are reported once, under its own name, however often it is called", () => {
    const bad = pou('Bad', 'FUNCTION_BLOCK', io('input', 'X BOOL'), [ladder(['[X] (Missing)'])]);
    const main = pou('Main', 'PROGRAM', vars('B1 Bad', 'B2 Bad'), [
      ladder(['- # # .'], { boxes: [box('Bad', 0, 1, { instance: 'B1' })] }),
      ladder(['- # # .'], { boxes: [box('Bad', 0, 1, { instance: 'B2' })] }),
    ]);
    const ds = errors(compileProgram(multiProject([main, bad])).diagnostics);
    expect(ds.map(brief)).toEqual(['LD-R08 Bad/1']);
  });

  test('an FB no program calls is still checked by checkProject', () => {
    const unused = pou('Unused', 'FUNCTION_BLOCK', [], [ladder(['[Nothing] (Q)'])]);
    const p = multiProject([pou('Main', 'PROGRAM', vars('Q BOOL'), [ladder(['- (Q)'])]), unused]);
    expect(compileProgram(p).program).toBeDefined();
    expect(errors(checkProject(p)).map(brief)).toEqual(['LD-R08 Unused/1', 'LD-R08 Unused/1']);
  });
});

describe('LD-E25 POU names', () => {
  test('a POU named like a standard block, twice, or not an identifier is refused by name', () => {
    const body = [ladder(['[A] (B)'])];
    const project = multiProject([
      pou('Main', 'PROGRAM', vars('A BOOL', 'B BOOL'), body),
      pou('PID', 'FUNCTION_BLOCK', vars('A BOOL', 'B BOOL'), body),
      pou('Motor', 'FUNCTION_BLOCK', vars('A BOOL', 'B BOOL'), body),
      pou('MOTOR', 'FUNCTION_BLOCK', vars('A BOOL', 'B BOOL'), body),
      pou('2nd', 'FUNCTION_BLOCK', vars('A BOOL', 'B BOOL'), body),
    ]);
    const named = checkProject(project).filter((d) => d.rule === 'LD-E25');
    expect(named.map((d) => [d.pou, d.severity])).toEqual([
      ['PID', 'error'],
      ['MOTOR', 'error'],
      ['2nd', 'error'],
    ]);
    expect(named[0]!.message).toMatch(/standard function block PID/);
    expect(named[1]!.message).toMatch(/already used by Motor/);
  });
});
