// ST bodies run as MATIEC runs them: values computed by hand from each source, scan by scan.
import { describe, expect, test } from 'vitest';
import { io, scanRead, stErrors, stMain, stPlc, stProject, textPou, vars } from './stHelpers';

describe('ST arithmetic', () => {
  test('integer division truncates toward zero; MOD takes the sign of the dividend', () => {
    const plc = stMain(
      'q1 := -7 / 2; q2 := 7 / -2; m1 := -7 MOD 2; m2 := 7 MOD -2; m3 := a MOD b; q3 := a / b;',
      vars('q1 INT', 'q2 INT', 'm1 INT', 'm2 INT', 'm3 INT', 'q3 INT', 'a INT := 17', 'b INT := 5'),
    );
    expect(scanRead(plc, 1, ['q1', 'q2', 'm1', 'm2', 'm3', 'q3'])).toEqual([-3, -3, -1, 1, 2, 3]);
  });

  test('division by zero: integers give 0 (the C code MATIEC writes would stop the runtime), REAL gives IEEE infinities as C does', () => {
    const plc = stMain('q := a / z; m := a MOD z; r := x / rz; n := rz / rz; k := 1.0 / 3.0;', vars('q INT := 5', 'm INT := 5', 'a INT := 7', 'z INT', 'r REAL', 'x REAL := -2.0', 'rz REAL', 'n REAL', 'k REAL'));
    const [q, m, r, n, k] = scanRead(plc, 1, ['q', 'm', 'r', 'n', 'k']);
    expect([q, m, r, Number.isNaN(n), k]).toEqual([0, 0, -Infinity, true, Math.fround(1 / 3)]);
  });

  test('results wrap at the width of their type', () => {
    const plc = stMain(
      `i := i + 1; s := s + 1; u := u + 1; d := d + 1; ud := ud - 1; l := l + 1;
       w := w + 1; m := i * 2;`,
      vars('i INT := 32767', 's SINT := 127', 'u USINT := 255', 'd DINT := 2147483647', 'ud UDINT', 'l LINT := 9223372036854775807', 'w UINT := 65535', 'm INT'),
    );
    expect(scanRead(plc, 1, ['i', 's', 'u', 'd', 'ud', 'l', 'w', 'm'])).toEqual([
      -32768, -128, 0, -2147483648, 4294967295, -9223372036854775808n, 0, 0,
    ]);
  });

  test('operators group by IEC precedence', () => {
    const plc = stMain(
      `a := 2 + 3 * 4; b := (2 + 3) * 4; c := 20 - 6 - 4; d := 100 / 10 / 5;
       e := NOT x AND y; f := x OR y AND FALSE; g := x XOR y OR TRUE;
       h := -2.0 ** 2.0; k := 2.0 ** 10; n := 1 + 2 = 3 AND 4 < 5;`,
      vars('a INT', 'b INT', 'c INT', 'd INT', 'e BOOL', 'f BOOL', 'g BOOL', 'h REAL', 'k REAL', 'n BOOL', 'x BOOL', 'y BOOL := TRUE'),
    );
    expect(scanRead(plc, 1, ['a', 'b', 'c', 'd', 'e', 'f', 'g', 'h', 'k', 'n'])).toEqual([14, 20, 10, 2, true, false, true, -4, 1024, true]);
  });

  test('REAL results are rounded to 32 bits; implicit widening INT -> REAL and INT -> DINT', () => {
    const plc = stMain('r := 0.1 + 0.2; lr := 0.1 + 0.2; d := i + d; r2 := i;', vars('r REAL', 'lr LREAL', 'd DINT := 70000', 'i INT := 5', 'r2 REAL'));
    expect(scanRead(plc, 1, ['r', 'lr', 'd', 'r2'])).toEqual([Math.fround(Math.fround(0.1) + Math.fround(0.2)), 0.1 + 0.2, 70005, 5]);
  });

  test('typed and based literals, bit access, locations and comments', () => {
    const plc = stMain(
      `(* a comment *) w := 16#00F0 OR 2#0001; // another
       b3 := w.4; w.0 := FALSE; t := T#1s500ms + TIME#2s; k := INT#-5; %QX0.1 := TRUE;`,
      vars('w WORD', 'b3 BOOL', 't TIME', 'k INT', 'o BOOL %QX0.1'),
    );
    expect(scanRead(plc, 1, ['w', 'b3', 't', 'k', 'o'])).toEqual([0xf0, true, 3500, -5, true]);
  });

  test('standard functions by position and by name', () => {
    const plc = stMain(
      `a := SEL(G := g, IN0 := 10, IN1 := 20); b := MAX(3, 9, 4); c := LIMIT(MN := 0, IN := 150, MX := 100);
       d := REAL_TO_INT(2.5); e := ADD(1, 2, 3, 4); f := SHL(IN := w, N := 4);`,
      vars('a INT', 'b INT', 'c INT', 'd INT', 'e INT', 'f WORD', 'g BOOL := TRUE', 'w WORD := 16#0F0F'),
    );
    expect(scanRead(plc, 1, ['a', 'b', 'c', 'd', 'e', 'f'])).toEqual([20, 9, 100, 2, 10, 0xf0f0]);
  });
});

describe('ST statements', () => {
  test('IF / ELSIF / ELSE picks the first true branch', () => {
    const plc = stMain(
      'IF x < 0 THEN s := -1; ELSIF x = 0 THEN s := 0; ELSIF x < 10 THEN s := 1; ELSE s := 2; END_IF; x := x + 7;',
      vars('x INT := -3', 's INT'),
    );
    const seen = [];
    for (let k = 0; k < 4; k++) seen.push(scanRead(plc, 1, ['s'])[0]);
    // x: -3 -> 4 -> 11 -> 18
    expect(seen).toEqual([-1, 1, 2, 2]);
  });

  test('CASE with values, lists, ranges and ELSE', () => {
    const plc = stMain(
      `CASE x OF
         1: s := 10;
         2, 4: s := 20;
         5..7: s := 30; t := t + 1;
       ELSE
         s := -1;
       END_CASE;
       x := x + 1;`,
      vars('x INT', 's INT', 't INT'),
    );
    const seen = [];
    for (let k = 0; k < 9; k++) seen.push(scanRead(plc, 1, ['s'])[0]);
    expect(seen).toEqual([-1, 10, 20, -1, 20, 30, 30, 30, -1]);
    expect(plc.read('t')).toBe(3);
  });

  test('FOR with BY (up and down), EXIT and CONTINUE; the control variable ends past the bound', () => {
    const plc = stMain(
      `s := 0; FOR i := 1 TO 10 BY 3 DO s := s + i; END_FOR;       (* 1 4 7 10 *)
       d := 0; FOR j := 10 TO 1 BY -4 DO d := d * 10 + j; END_FOR;  (* 10 6 2 *)
       e := 0; FOR k := 1 TO 100 DO IF k > 4 THEN EXIT; END_IF; e := e + k; END_FOR;
       c := 0; FOR m := 1 TO 6 DO IF m MOD 2 = 0 THEN CONTINUE; END_IF; c := c + m; END_FOR;`,
      vars('s INT', 'i INT', 'd DINT', 'j INT', 'e INT', 'k INT', 'c INT', 'm INT'),
    );
    expect(scanRead(plc, 1, ['s', 'i', 'd', 'j', 'e', 'k', 'c', 'm'])).toEqual([22, 13, ((0 * 10 + 10) * 10 + 6) * 10 + 2, -2, 10, 5, 9, 7]);
  });

  test('WHILE and REPEAT', () => {
    const plc = stMain(
      `n := 0; WHILE n * n < 50 DO n := n + 1; END_WHILE;
       r := 0; REPEAT r := r + 5; UNTIL r >= 12 END_REPEAT;
       z := 0; WHILE FALSE DO z := 1; END_WHILE;
       y := 0; REPEAT y := y + 1; UNTIL TRUE END_REPEAT;`,
      vars('n INT', 'r INT', 'z INT', 'y INT'),
    );
    expect(scanRead(plc, 1, ['n', 'r', 'z', 'y'])).toEqual([8, 15, 0, 1]);
  });

  test('RETURN ends the body for this scan', () => {
    const plc = stMain('a := a + 1; IF a > 2 THEN RETURN; END_IF; b := b + 1;', vars('a INT', 'b INT'));
    expect(scanRead(plc, 5, ['a', 'b'])).toEqual([5, 2]);
  });

  test('a long body (run as several networks) runs its statements in order, once each; a runaway loop late in it is named by its line', () => {
    // 60 statements x(k) := x(k-1) + 1 on the same scan, then a sum over an FB called before and after.
    const chain = Array.from({ length: 60 }, (_, k) => `x${k + 1} := x${k} + 1;`).join('\n');
    const decl = vars(...Array.from({ length: 61 }, (_, k) => `x${k} INT`), 'T1 TON', 'q BOOL');
    const plc = stMain(`x0 := x0 + 10;\n${chain}\nT1(IN := TRUE, PT := T#20ms, Q => q);`, decl);
    expect(scanRead(plc, 1, ['x1', 'x30', 'x60', 'q'])).toEqual([11, 40, 70, false]);
    expect(scanRead(plc, 2, ['x0', 'x60', 'q'])).toEqual([30, 90, true]);
    const looping = stPlc(stProject([textPou('Main', 'PROGRAM', [...vars('x DINT'), ...decl], `${chain}\nWHILE TRUE DO\n  x := x + 1;\nEND_WHILE;`)]), { maxScanMs: 30 });
    expect(looping.scan().fault?.message).toMatch(/looping in the loop at line 61 of Main/);
  });

  test('RETURN in a long body ends it for this scan', () => {
    const chain = Array.from({ length: 40 }, (_, k) => `x${k + 1} := x${k} + 1;`).join('\n');
    const plc = stMain(`x0 := x0 + 1;\n${chain}\nIF x0 > 1 THEN RETURN; END_IF;\nb := b + 1;\n${chain}`, vars(...Array.from({ length: 41 }, (_, k) => `x${k} INT`), 'b INT'));
    expect(scanRead(plc, 3, ['x0', 'x40', 'b'])).toEqual([3, 43, 1]);
  });

  test('a runaway WHILE faults with the POU and the line of the loop named', () => {
    const plc = stPlc(stProject([textPou('Main', 'PROGRAM', vars('x DINT'), 'x := 0;\nWHILE TRUE DO\n  x := x + 1;\nEND_WHILE;')]), { maxScanMs: 30 });
    const report = plc.scan();
    expect(report.fault?.kind).toBe('watchdog');
    expect(report.fault?.pou).toBe('Main');
    expect(report.fault?.message).toMatch(/looping in the loop at line 2 of Main/);
  });
});

describe('calls from ST', () => {
  test('a TON instance keeps its state across scans; outputs by => and by Instance.Pin', () => {
    const plc = stMain('T1(IN := go, PT := T#30ms, Q => q, ET => et); q2 := T1.Q;', vars('T1 TON', 'go BOOL', 'q BOOL', 'et TIME', 'q2 BOOL'), [], 'iec');
    plc.write('go', true);
    const rows = [];
    for (let k = 0; k < 5; k++) rows.push(scanRead(plc, 1, ['q', 'et', 'q2']));
    // scans at 0, 10, 20, 30, 40 ms; IN rose at 0
    expect(rows).toEqual([
      [false, 0, false],
      [false, 10, false],
      [false, 20, false],
      [true, 30, true],
      [true, 30, true],
    ]);
  });

  test('a user FB called from ST: two instances keep their own state; outputs by => and Inst.Out', () => {
    const counter = textPou(
      'Count',
      'FUNCTION_BLOCK',
      [...io('input', 'Step INT', 'Reset BOOL'), ...io('output', 'Total INT'), ...vars('Calls INT')],
      'Calls := Calls + 1;\nIF Reset THEN Total := 0; ELSE Total := Total + Step; END_IF;',
    );
    const plc = stMain('A(Step := 2, Total => ta); B(Step := 5, Reset := rst); tb := B.Total;', vars('A Count', 'B Count', 'ta INT', 'tb INT', 'rst BOOL'), [counter]);
    expect(scanRead(plc, 3, ['ta', 'tb', 'A.Calls'])).toEqual([6, 15, 3]);
    plc.write('rst', true);
    expect(scanRead(plc, 1, ['ta', 'tb'])).toEqual([8, 0]);
  });

  test('a user FUNCTION called from ST by position and by name; its variables start fresh on every call', () => {
    const scale = textPou('Scale', 'FUNCTION', [...io('input', 'X INT', 'K INT := 10'), ...vars('Seen INT')], 'Seen := Seen + 1;\nScale := X * K + Seen;', { returnType: 'INT' });
    const plc = stMain('a := Scale(3, 2); b := Scale(X := 4); c := Scale(1, 1) + Scale(2, 1);', vars('a INT', 'b INT', 'c INT'), [scale]);
    expect(scanRead(plc, 2, ['a', 'b', 'c'])).toEqual([7, 41, 5]);
  });

  test('VAR_IN_OUT by reference from ST', () => {
    const inc = textPou('Inc', 'FUNCTION_BLOCK', [...io('inOut', 'V DINT')], 'V := V + 1;');
    const plc = stMain('I1(V := n); I1(V := n);', vars('I1 Inc', 'n DINT'), [inc]);
    expect(scanRead(plc, 3, ['n'])).toEqual([6]);
  });

  test('a function calling itself through another is refused (LD-E21)', () => {
    const f = textPou('F', 'FUNCTION', io('input', 'X INT'), 'F := G(X);', { returnType: 'INT' });
    const g = textPou('G', 'FUNCTION', io('input', 'X INT'), 'G := F(X);', { returnType: 'INT' });
    const errs = stErrors(stProject([textPou('Main', 'PROGRAM', vars('y INT'), 'y := F(1);'), f, g]));
    expect(errs.some((e) => /LD-E21/.test(e) && /F → G → F|G → F → G/.test(e))).toBe(true);
  });
});

describe('ST errors are located and name the POU', () => {
  const errorsOf = (source: string, variables = vars('i INT', 'r REAL', 'w WORD', 'b BOOL')) => stErrors(stProject([textPou('Main', 'PROGRAM', variables, source)]));

  test('a type mismatch needs a conversion', () => {
    expect(errorsOf('i := 1;\ni := r;')).toEqual([
      'error LD-E50 Main/line 2 col 6 the ST body of Main does not compile: line 2 col 6: cannot assign to i: INT is needed and the value is REAL; convert it with REAL_TO_INT',
    ]);
  });

  test('unknown variables, mixed types, a syntax error', () => {
    expect(errorsOf('i := j + 1;')[0]).toMatch(/line 1 col 6: "j" is not declared/);
    expect(errorsOf('i := i + w;')[0]).toMatch(/line 1 col 8: ADD cannot add INT and WORD/);
    expect(errorsOf('IF b THEN\n  i := 1;\nEND_IF')[0]).toMatch(/line 3 col 7: expected ";" to end the statement, found the end of the text/);
    expect(errorsOf('IF i THEN i := 1; END_IF;')[0]).toMatch(/line 1 col 4: the IF condition must be BOOL; "i" is INT/);
    expect(errorsOf('i := arr[1];')[0]).toMatch(/LD-E50 .*line 1 col 6: "arr" is not declared/);
    expect(errorsOf("i := 'abc';")[0]).toMatch(/line 1 col 6: cannot assign to i: INT is needed and the value is STRING/);
  });

  test('several errors are all reported', () => {
    expect(errorsOf('i := r;\nb := 5.5;\nEXIT;')).toHaveLength(3);
  });
});
