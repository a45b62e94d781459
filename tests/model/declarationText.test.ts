// Declarations as IEC text (src/engine/st/declarations.ts): printing the variable list, parsing it
// back, located syntax errors, comments, and what an edited text changes (rename, add, remove).
import { describe, expect, it } from 'vitest';
import {
  DECLARATION_SYNTAX_RULE,
  parseDeclarations,
  planDeclarationEdit,
  printDeclarations,
} from '../../src/engine/st/declarations';
import { variable } from '../../src/model/factory';
import type { Variable } from '../../src/model/project';

const pouVars: Variable[] = [
  variable('Start', 'BOOL', { varClass: 'input', location: '%IX0.0', initial: 'FALSE', comment: 'start button' }),
  variable('Stop', 'BOOL', { varClass: 'input', location: '%IX0.1' }),
  variable('Motor', 'BOOL', { varClass: 'output', location: '%QX0.0', comment: 'contactor K1' }),
  variable('Buf', 'ARRAY[1..8] OF INT', { varClass: 'inOut' }),
  variable('T1', 'TON'),
  variable('Count', 'INT', { initial: '10' }),
  variable('Name', 'STRING[20]', { initial: "'pump  one'" }),
  variable('Limit', 'INT', { initial: '100', constant: true, comment: 'a (* nested *) note' }),
  variable('Hours', 'UDINT', { retain: true }),
  variable('Pt', 'STRUCT X : INT; Y : INT := 5; END_STRUCT'),
  variable('Scratch', 'REAL', { varClass: 'temp' }),
  variable('Level', 'INT', { varClass: 'external', comment: 'two\nlines' }),
  variable('Mode', '(IDLE, RUN, STOP)', { initial: 'IDLE' }),
];

describe('printing declarations', () => {
  it('prints blocks of one class and qualifiers, in the list order, as IEC text', () => {
    const text = printDeclarations(pouVars.slice(0, 9), 'pou');
    expect(text).toBe(
      [
        'VAR_INPUT',
        '\tStart AT %IX0.0 : BOOL := FALSE; (* start button *)',
        '\tStop AT %IX0.1 : BOOL;',
        'END_VAR',
        '',
        'VAR_OUTPUT',
        '\tMotor AT %QX0.0 : BOOL; (* contactor K1 *)',
        'END_VAR',
        '',
        'VAR_IN_OUT',
        '\tBuf : ARRAY[1..8] OF INT;',
        'END_VAR',
        '',
        'VAR',
        '\tT1 : TON;',
        '\tCount : INT := 10;',
        "\tName : STRING[20] := 'pump  one';",
        'END_VAR',
        '',
        'VAR CONSTANT',
        '\tLimit : INT := 100; (* a (* nested *) note *)'.replace('(* a (* nested *) note *)', '// a (* nested *) note'),
        'END_VAR',
        '',
        'VAR RETAIN',
        '\tHours : UDINT;',
        'END_VAR',
        '',
      ].join('\n'),
    );
  });

  it('prints globals in VAR_GLOBAL blocks and an empty list as an empty block to type into', () => {
    const globals = [
      variable('Level', 'INT', { location: '%IW0' }),
      variable('MaxLevel', 'INT', { initial: '900', constant: true }),
    ];
    expect(printDeclarations(globals, 'globals')).toBe(
      'VAR_GLOBAL\n\tLevel AT %IW0 : INT;\nEND_VAR\n\nVAR_GLOBAL CONSTANT\n\tMaxLevel : INT := 900;\nEND_VAR\n',
    );
    expect(printDeclarations([], 'pou')).toBe('VAR\nEND_VAR\n');
    expect(parseDeclarations(printDeclarations([], 'globals'), 'globals').variables).toEqual([]);
  });
});

describe('round trip', () => {
  it('parsing the printed text of a list gives the same list', () => {
    const parsed = parseDeclarations(printDeclarations(pouVars, 'pou'), 'pou');
    expect(parsed.problems).toEqual([]);
    expect(parsed.variables).toEqual(pouVars);
  });

  it('parse → print → parse is stable for hand-written text', () => {
    const text = `var_input start, stop : bool; (* buttons *)
END_VAR
VAR  T1:TON;   (* the
  delay *)
  // above Speed
  Speed :   REAL:=1.5E3 ; Arr : ARRAY [0..3] OF INT := [4(0)];
  Init : Point := (X := 1,Y := 2);
END_VAR`;
    const first = parseDeclarations(text, 'pou');
    expect(first.ok).toBe(true);
    const printed = printDeclarations(first.variables, 'pou');
    const second = parseDeclarations(printed, 'pou');
    expect(second.variables).toEqual(first.variables);
    expect(printDeclarations(second.variables, 'pou')).toBe(printed);
    expect(first.variables.map((v) => [v.name, v.type, v.varClass, v.initial, v.comment])).toEqual([
      ['start', 'bool', 'input', undefined, 'buttons'],
      ['stop', 'bool', 'input', undefined, 'buttons'],
      ['T1', 'TON', 'local', undefined, 'the\n  delay'],
      ['Speed', 'REAL', 'local', '1.5E3', 'above Speed'],
      ['Arr', 'ARRAY [0..3] OF INT', 'local', '[4(0)]', ''],
      ['Init', 'Point', 'local', '(X := 1,Y := 2)', ''],
    ]);
  });
});

describe('what the ST lexer reads in declarations', () => {
  it('keeps strings, typed and based literals, times and qualifiers as written', () => {
    const text = `VAR_OUTPUT RETAIN
	Msg : STRING[30] := 'a; (* not a comment *) b';
	W : WORD := 16#FF_FF;
	Dt : TIME := T#1s500ms;
	N : SINT := SINT#-5;
END_VAR
VAR NON_RETAIN
	Ws : WSTRING := "wide";
END_VAR
VAR_GLOBAL PERSISTENT
END_VAR`;
    const result = parseDeclarations(text, 'pou');
    expect(result.variables.map((v) => [v.name, v.type, v.initial, v.varClass, v.retain])).toEqual([
      ['Msg', 'STRING[30]', "'a; (* not a comment *) b'", 'output', true],
      ['W', 'WORD', '16#FF_FF', 'output', true],
      ['Dt', 'TIME', 'T#1s500ms', 'output', true],
      ['N', 'SINT', 'SINT#-5', 'output', true],
      ['Ws', 'WSTRING', '"wide"', 'local', false],
    ]);
    expect(result.variables.every((v) => v.comment === '')).toBe(true);
    // VAR_GLOBAL in a POU's text is an error located at it; PERSISTENT is a warning.
    expect(result.problems.map((p) => [p.severity, p.line])).toEqual([
      ['error', 10],
      ['warning', 10],
    ]);
  });

  it('reads a pragma as a warning and leaves the declaration as it is', () => {
    const result = parseDeclarations("VAR\n\t{attribute 'hide'}\n\tA : INT;\nEND_VAR", 'pou');
    expect(result.ok).toBe(true);
    expect(result.variables).toEqual([variable('A', 'INT')]);
    expect(result.problems).toEqual([expect.objectContaining({ severity: 'warning', line: 2, col: 2 })]);
  });
});

describe('syntax errors are located', () => {
  const errorsOf = (text: string, section: 'pou' | 'globals' = 'pou') =>
    parseDeclarations(text, section).problems.filter((p) => p.severity === 'error');

  it('names the line and column of a missing ";"', () => {
    const result = parseDeclarations('VAR\n\tA : INT;\n\tB : BOOL\n\tC : INT;\nEND_VAR\n', 'pou');
    expect(result.ok).toBe(false);
    expect(result.problems).toEqual([
      expect.objectContaining({ severity: 'error', line: 3, col: 10, message: expect.stringContaining('";" missing') }),
    ]);
    expect(DECLARATION_SYNTAX_RULE).toMatch(/^LD-E\d+$/);
  });

  it('keeps reading after an error and reports each one at its place', () => {
    const errors = errorsOf('VAR\n\tA INT;\n\tB : ;\n\tC : INT := ;\n\t1x : INT;\nEND_VAR\n');
    expect(errors.map((e) => [e.line, e.col])).toEqual([
      [2, 4],
      [3, 6],
      [4, 13],
      [5, 2],
    ]);
    expect(errors[0]!.message).toContain('expected ":"');
    expect(errors[1]!.message).toContain('needs a type');
    expect(errors[2]!.message).toContain('initial value is missing');
    expect(errors[3]!.message).toContain('expected a variable name');
  });

  it('reports a block not closed, an unclosed comment, a duplicate and a block of the wrong kind', () => {
    expect(errorsOf('VAR\n\tA : INT;\n')[0]).toMatchObject({ line: 3, col: 1, message: expect.stringContaining('END_VAR missing') });
    expect(errorsOf('VAR\n\tA : INT; (* open\nEND_VAR')[0]).toMatchObject({ line: 2, col: 11 });
    expect(errorsOf('VAR\n\tA : INT;\n\ta : BOOL;\nEND_VAR')[0]).toMatchObject({
      line: 3,
      col: 2,
      message: expect.stringContaining('already declared at line 2'),
    });
    expect(errorsOf('VAR_GLOBAL\n\tA : INT;\nEND_VAR')[0]?.message).toContain('Global view');
    expect(errorsOf('VAR\n\tA : INT;\nEND_VAR', 'globals')[0]?.message).toContain('VAR_GLOBAL');
    expect(errorsOf('VAR\n\tA, B AT %IX0.0 : BOOL;\nEND_VAR')[0]?.message).toContain('cannot share one address');
    expect(errorsOf('VAR\n\tA AT 5 : BOOL;\nEND_VAR')[0]?.message).toContain('AT needs an address');
    expect(errorsOf('A : INT;')[0]).toMatchObject({ line: 1, col: 1, message: expect.stringContaining('to open a block') });
  });

  it('warns about a comment no variable owns, and keeps going', () => {
    const result = parseDeclarations('VAR (* locals *)\n\tA : INT;\n\t(* trailing *)\nEND_VAR', 'pou');
    expect(result.ok).toBe(true);
    expect(result.variables).toEqual([variable('A', 'INT')]);
    expect(result.problems.map((p) => [p.severity, p.line])).toEqual([
      ['warning', 1],
      ['warning', 3],
    ]);
  });
});

describe('what an edited text changes', () => {
  const before = [variable('A', 'INT'), variable('B', 'BOOL'), variable('C', 'TIME', { scope: 'resource' })];

  it('one name changed at the same place is a rename', () => {
    const plan = planDeclarationEdit(before, [variable('A', 'INT'), variable('Run', 'BOOL'), before[2]!]);
    expect(plan.renames).toEqual([{ from: 'B', to: 'Run' }]);
    expect(plan.removed).toEqual([]);
    expect(plan.added).toEqual([]);
    expect(plan.updated).toEqual([]);
  });

  it('a name changed and its type too is a rename plus an update', () => {
    const plan = planDeclarationEdit(before, [before[0]!, variable('Run', 'INT'), before[2]!]);
    expect(plan.renames).toEqual([{ from: 'B', to: 'Run' }]);
    expect(plan.updated).toEqual([{ name: 'Run', after: variable('Run', 'INT') }]);
  });

  it('several names changed at their places in one edit are renames, each with its own changes', () => {
    const plan = planDeclarationEdit(before, [variable('X', 'INT'), variable('Run', 'INT'), before[2]!]);
    expect(plan.renames).toEqual([
      { from: 'A', to: 'X' },
      { from: 'B', to: 'Run' },
    ]);
    expect(plan.removed).toEqual([]);
    expect(plan.added).toEqual([]);
    expect(plan.updated).toEqual([{ name: 'Run', after: variable('Run', 'INT') }]);
  });

  it('otherwise names gone are removed and new names added; a global keeps its scope', () => {
    const plan = planDeclarationEdit(before, [variable('C', 'TIME', { initial: 'T#5s' }), variable('D', 'INT'), variable('E', 'INT')]);
    expect(plan.renames).toBeUndefined();
    expect(plan.removed).toEqual(['A', 'B']);
    expect(plan.added.map((v) => v.name)).toEqual(['D', 'E']);
    expect(plan.updated).toEqual([{ name: 'C', after: { ...variable('C', 'TIME', { initial: 'T#5s' }), scope: 'resource' } }]);
    expect(plan.order).toEqual(['C', 'D', 'E']);
  });

  it('an unchanged text changes nothing', () => {
    const plan = planDeclarationEdit(before, parseDeclarations(printDeclarations(before, 'globals'), 'globals').variables);
    expect(plan).toEqual({ removed: [], updated: [], added: [], order: ['A', 'B', 'C'] });
  });
});
