// The added blocks called from Structured Text: ST's operators and calls resolve through the same
// library (`T * 4` is MUL of a TIME by a number; TRUNC takes the type it is assigned to).
import { describe, expect, it } from 'vitest';
import { stPlc, stProject, textPou, vars } from '../stHelpers';

describe('added blocks in ST', () => {
  it('SQRT, EXPT, TRUNC, TIME * number, BCD and a PID instance', () => {
    const main = textPou(
      'Main',
      'PROGRAM',
      vars('X REAL := 8.0', 'T TIME := T#250ms', 'Y REAL', 'P LREAL', 'L TIME', 'H TIME', 'W INT', 'B BYTE', 'P1 PID', 'Out REAL'),
      `Y := SQRT(X);
P := EXPT(LREAL#2.0, 10);
L := T * 4;
H := DIVTIME(T, 2);
W := TRUNC(-2.7);
B := USINT_TO_BCD(USINT#42);
P1(AUTO := FALSE, PV := 8.0, SP := 10.0, X0 := 3.0, KP := 2.0, TR := 4.0, TD := 0.5, CYCLE := T#1s);
Out := P1.XOUT;`,
    );
    const plc = stPlc(stProject([main], 'openplc'));
    plc.scan();
    expect([plc.read('Y'), plc.read('P'), plc.read('L'), plc.read('H')]).toEqual([Math.fround(Math.SQRT2 * 2), 1024, 1000, 125]);
    expect([plc.read('W'), plc.read('B'), plc.read('Out')]).toEqual([-2, 0x42, 6]);
  });
});
