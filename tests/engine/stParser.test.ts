// The ST parser: precedence, every statement form, located syntax errors.
import { describe, expect, test } from 'vitest';
import type { Expr } from '../../src/engine/st/ast';
import { parseExpression, parseStatements } from '../../src/engine/st/parser';

/** An expression as a fully parenthesised string. */
function show(e: Expr): string {
  switch (e.k) {
    case 'lit':
      return e.text;
    case 'name':
    case 'path':
      return e.text;
    case 'unary':
      return `(${e.op} ${show(e.a)})`;
    case 'binary':
      return `(${show(e.a)} ${e.op} ${show(e.b)})`;
    case 'call':
      return `${e.name}(${e.args.map((a) => `${a.name ? `${a.name}${a.out ? '=>' : ':='}` : ''}${show(a.value)}`).join(', ')})`;
    case 'cr':
      return 'CR';
  }
}
const p = (text: string) => show(parseExpression(text));

describe('ST expressions', () => {
  test('IEC precedence, left to right within a level', () => {
    expect(p('a + b * c')).toBe('(a + (b * c))');
    expect(p('a - b - c')).toBe('((a - b) - c)');
    expect(p('a OR b XOR c AND d')).toBe('(a OR (b XOR (c AND d)))');
    expect(p('a & b = c')).toBe('(a AND (b = c))');
    expect(p('a = b < c')).toBe('(a = (b < c))');
    expect(p('NOT a AND b')).toBe('((NOT a) AND b)');
    expect(p('-x ** 2')).toBe('(- (x ** 2))');
    expect(p('a MOD b / c * d')).toBe('(((a MOD b) / c) * d)');
    expect(p('(a + b) * c')).toBe('((a + b) * c)');
    expect(p('x <> -5')).toBe('(x <> -5)');
  });

  test('literals, members, bits, locations and calls', () => {
    expect(p('INT#-5 + 16#FF + 2#1010 + 1.5E-3 + T#1h2m3s + TIME#-2s')).toBe('(((((INT#-5 + 16#FF) + 2#1010) + 1.5E-3) + T#1h2m3s) + TIME#-2s)');
    expect(p('T1.Q AND w.3 AND %IX0.1')).toBe('((T1.Q AND w.3) AND %IX0.1)');
    expect(p('SEL(G := g, IN0 := 1, IN1 := ADD(a, b))')).toBe('SEL(G:=g, IN0:=1, IN1:=ADD(a, b))');
    expect(p('TRUE OR false')).toBe('(TRUE OR FALSE)');
  });
});

describe('ST statements', () => {
  test('every statement form', () => {
    const body = parseStatements(`
      x := 1;
      T1(IN := a, PT := T#5s, Q => q, NOT Q => nq);
      IF a THEN x := 1; ELSIF b THEN x := 2; ELSE x := 3; END_IF;
      CASE n OF 1: x := 1; 2, 3: x := 2; 4..6, -1: ; ELSE x := 0; END_CASE;
      FOR i := 1 TO 10 BY 2 DO EXIT; END_FOR;
      WHILE a DO CONTINUE; END_WHILE;
      REPEAT x := x + 1; UNTIL x > 3 END_REPEAT;
      RETURN;
      ;;
    `);
    expect(body.map((s) => s.k)).toEqual(['assign', 'call', 'if', 'case', 'for', 'while', 'repeat', 'return']);
    const c = body[3] as Extract<(typeof body)[number], { k: 'case' }>;
    expect(c.arms.map((a) => a.labels.map((l) => (l.hi ? `${show(l.lo)}..${show(l.hi)}` : show(l.lo))))).toEqual([['1'], ['2', '3'], ['4..6', '-1']]);
    expect(c.otherwise).toHaveLength(1);
    const call = body[1] as Extract<(typeof body)[number], { k: 'call' }>;
    expect(call.args.map((a) => [a.name, a.out ?? false, a.negated ?? false])).toEqual([
      ['IN', false, false],
      ['PT', false, false],
      ['Q', true, false],
      ['Q', true, true],
    ]);
  });

  test('pragmas: MATIEC\'s clock pragma is a statement, others are reported', () => {
    const seen: string[] = [];
    const body = parseStatements('{__SET_VAR(data__->,NOW_T,,__CURRENT_TIME)}\n{ some C code }\nx := 1;', { onPragma: (t) => seen.push(t.trim()) });
    expect(body.map((s) => s.k)).toEqual(['now', 'assign']);
    expect(seen).toEqual(['some C code']);
  });

  test('a C code block {{ ... }} with C braces inside is one pragma; the IEC statements around it run', () => {
    const seen: string[] = [];
    const body = parseStatements('{{\n  if (x) { y(); }\n}}\nIF a THEN\n{{ setup(&v); }}\n  b := TRUE;\nEND_IF;', {
      onPragma: (t) => seen.push(t.trim()),
    });
    expect(body.map((s) => s.k)).toEqual(['if']);
    expect(seen).toEqual(['if (x) { y(); }', 'setup(&v);']);
  });

  test('syntax errors name the line and column', () => {
    const err = (text: string) => {
      try {
        parseStatements(text);
      } catch (e) {
        return (e as Error).message;
      }
      return 'no error';
    };
    expect(err('x := 1\ny := 2;')).toBe('line 2 col 1: expected ";" to end the statement, found "y"');
    expect(err('IF a THEN\n  x := 1;\nEND_WHILE;')).toBe('line 3 col 1: expected END_IF to close the IF, found "END_WHILE"');
    expect(err('x = 1;')).toBe('line 1 col 3: expected ":=" (assignment); "=" compares, found "="');
    expect(err('x := (a + ;')).toBe('line 1 col 11: expected a value (a variable, a literal, a call or "("), found ";"');
    expect(err('END_IF;')).toBe('line 1 col 1: "END_IF" closes nothing that is open here');
    expect(err('(* open comment\nx := 1;')).toBe('line 1 col 1: this comment "(*" is never closed with "*)"');
    expect(err('FOR i := 1 DO END_FOR;')).toBe('line 1 col 12: expected TO in the FOR statement, found "DO"');
    expect(err('x := a$;')).toBe('line 1 col 7: unexpected character "$"');
  });
});
