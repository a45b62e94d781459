// IL bodies: every operator, deferred operators, labels and jumps, calls; run through the same
// checker and code generator as ST, with values computed by hand.
import { describe, expect, test } from 'vitest';
import { translateIl } from '../../src/engine/il/translate';
import { io, scanRead, stErrors, stMain, stProject, textPou, vars } from './stHelpers';

const ilProgram = (source: string, variables = vars()) => stProject([textPou('Main', 'PROGRAM', variables, source, { language: 'IL' })]);
const runIl = (source: string, variables: ReturnType<typeof vars>, names: string[], scans = 1, others = []) =>
  scanRead(stMain('IL1();', vars('IL1 Body'), [textPou('Body', 'FUNCTION_BLOCK', variables, source, { language: 'IL' }), ...others]), scans, names.map((n) => `IL1.${n}`));

describe('IL translation', () => {
  test('the current result, labels and jumps become ST statements', () => {
    const tree = translateIl('  LD a\n  JMPC L1\nL1: ST b (* done *)');
    expect(tree.map((s) => s.k)).toEqual(['setcr', 'if', 'label', 'assign']);
    expect(tree[2]).toMatchObject({ k: 'label', name: 'L1', pos: { line: 3, col: 1 } });
  });

  test('errors are located', () => {
    expect(() => translateIl('LD a\n  FOO(')).toThrow(/line 2 col 3: FOO cannot be deferred/);
    expect(() => translateIl('LD a\n)')).toThrow(/line 2 col 1: "\)" closes no deferred operator/);
    expect(() => translateIl('LD a\nAND( b')).toThrow(/line 2 col 1: "AND\(" is never closed/);
  });
});

describe('IL semantics', () => {
  test('logic with N modifiers, S and R, deferred operators', () => {
    const v = vars('a BOOL := TRUE', 'b BOOL', 'c BOOL := TRUE', 'x BOOL', 'y BOOL', 'z BOOL', 's1 BOOL', 'r1 BOOL := TRUE');
    const src = `
      LD a
      AND( b
      OR c
      )
      ST x        (* a AND (b OR c) *)
      LDN a
      ORN b
      STN y       (* NOT (NOT a OR NOT b) *)
      LD b
      XORN c
      ST z        (* b XOR NOT c *)
      LD x
      S s1
      R r1`;
    expect(runIl(src, v, ['x', 'y', 'z', 's1', 'r1'])).toEqual([true, false, false, true, false]);
  });

  test('arithmetic, comparisons, functions and literals that take the type of their use', () => {
    const v = vars('i INT := 7', 'k INT', 'g BOOL', 'mx INT', 'u USINT', 'd DINT');
    const src = `
      LD i
      ADD 5
      MUL( 2
      SUB 5
      )
      ST k        (* (7 + 5) * (2 - 5) = -36 *)
      GT -40
      ST g
      LD i
      MAX 3, 11
      ST mx
      LD 200
      ST u
      LD i
      ST d        (* INT widens to DINT *)`;
    expect(runIl(src, v, ['k', 'g', 'mx', 'u', 'd'])).toEqual([-36, true, 11, 200, 7]);
  });

  test('a backward jump loops; JMPCN and RETC', () => {
    const v = vars('n INT', 'm INT', 'after INT');
    const src = `
        LD 0
        ST n
  again: LD n
        ADD 1
        ST n
        LT 5
        JMPC again
        LD n
        EQ 6
        JMPCN skip
        LD 100
        ST m
  skip: LD TRUE
        RETC
        LD 1
        ST after`;
    expect(runIl(src, v, ['n', 'm', 'after'])).toEqual([5, 0, 0]);
  });

  test('CAL, CALC and CALCN run an FB instance', () => {
    const v = vars('T1 TON', 'C1 CTU', 'go BOOL := TRUE', 'q BOOL', 'cv INT');
    const src = `
      CAL T1(IN := go, PT := T#20ms)
      LD T1.Q
      ST q
      LD go
      CALC C1(CU := T1.Q, PV := 10)
      LD go
      CALCN C1(CU := FALSE)
      LD C1.CV
      ST cv`;
    // scans at 0, 10, 20, 30 ms: Q from the third; CU rises once
    expect(runIl(src, v, ['q', 'cv'], 4)).toEqual([true, 1]);
  });

  test('type errors name the line; the current result must agree at a label', () => {
    const errs = (src: string) => stErrors(ilProgram(src, vars('b BOOL', 'i INT')));
    expect(errs('LD i\nST b')[0]).toMatch(/LD-E50 Main\/line 2 col 1 the IL body of Main does not compile: line 2 col 1: cannot assign to b: BOOL is needed and the value is INT/);
    expect(errs('LD b\nJMPC L\nLD i\nL: ST i')[0]).toMatch(/line 4 col 1: the current result is INT here but BOOL where jumps to L come from/);
    expect(errs('LD b\nJMPC L\nLD i\nL: LD 1\nST i')).toEqual([]);
    expect(errs('JMP nowhere')[0]).toMatch(/line 1 col 1: there is no label nowhere/);
    expect(errs('ST i')[0]).toMatch(/there is no current result here/);
  });

  test('a FUNCTION written in IL', () => {
    const twice = textPou('Twice', 'FUNCTION', io('input', 'X INT'), 'LD X\nMUL 2\nST Twice', { language: 'IL', returnType: 'INT' });
    const plc = stMain('a := Twice(21);', vars('a INT'), [twice]);
    expect(scanRead(plc, 1, ['a'])).toEqual([42]);
  });
});
