// Contacts and coils scan by scan, against LD-SEMANTICS.md sections 2 and 3.
import { describe, expect, test } from 'vitest';
import { ladder, plcOf, project, vars } from './ladder';

/** Runs one scan per entry of `a`, returning X after each scan. */
function trace(rows: string[], a: number[], extraVars: string[] = []): number[] {
  const plc = plcOf(project(vars('A BOOL', 'B BOOL', 'X BOOL', 'Y BOOL', ...extraVars), [ladder(rows)]));
  return a.map((v) => {
    plc.write('A', v === 1);
    plc.scan();
    return plc.read('X') ? 1 : 0;
  });
}

describe('contacts (table 61)', () => {
  test.each([
    ['normally open', '[A] (X)', [0, 1, 1, 0], [0, 1, 1, 0]],
    ['normally closed', '[/A] (X)', [0, 1, 1, 0], [1, 0, 0, 1]],
    ['inverting (NOT left)', '[A] [NOT] (X)', [0, 1, 1, 0], [1, 0, 0, 1]],
    ['positive transition: ON for one scan when A rises', '[P:A] (X)', [0, 1, 1, 0, 1], [0, 1, 0, 0, 1]],
    ['negative transition: ON for one scan when A falls', '[N:A] (X)', [1, 0, 0, 1, 0], [0, 1, 0, 0, 1]],
    [
      'negative transition with A OFF at its first evaluation fires once (F_TRIG, M starts FALSE)',
      '[N:A] (X)',
      [0, 0, 0],
      [1, 0, 0],
    ],
    ['positive transition with A ON at its first evaluation fires', '[P:A] (X)', [1, 1], [1, 0]],
  ])('%s', (_name, row, a, x) => {
    expect(trace([row], a)).toEqual(x);
  });

  test('a contact never writes its variable', () => {
    const plc = plcOf(project(vars('A BOOL', 'X BOOL'), [ladder(['[A] [/A] [P:A] [N:A] (X)'])]));
    plc.write('A', true);
    plc.scans(3);
    expect(plc.read('A')).toBe(true);
  });

  test('edge memory is updated whatever the left link: A rising while B is OFF does not fire later', () => {
    const plc = plcOf(project(vars('A BOOL', 'B BOOL', 'X BOOL'), [ladder(['[B] [P:A] (X)'])]));
    plc.write('A', true);
    plc.scan(); // A rises while B is OFF
    plc.write('B', true);
    plc.scan();
    expect(plc.read('X')).toBe(false);
  });

  test('each transition element has its own memory', () => {
    const plc = plcOf(
      project(vars('A BOOL', 'X BOOL', 'Y BOOL'), [ladder(['[P:A] (X)']), ladder(['[P:A] (Y)'])]),
    );
    plc.write('A', true);
    plc.scan();
    expect([plc.read('X'), plc.read('Y')]).toEqual([true, true]);
  });

  test('an element skipped by a jump is not evaluated and keeps its memory', () => {
    const p = project(vars('A BOOL', 'Skip BOOL', 'X BOOL'), [
      ladder(['[Skip] >>END']),
      ladder(['[P:A] (X)']),
      ladder(['[Skip] (Skip)'], { label: 'END' }),
    ]);
    const plc = plcOf(p);
    plc.write('Skip', true);
    plc.write('A', true);
    plc.scan(); // A rises while the P contact is skipped
    expect(plc.read('X')).toBe(false);
    plc.write('Skip', false);
    plc.scan(); // evaluated again: its memory still says A was OFF, so it fires now
    expect(plc.read('X')).toBe(true);
    plc.scan();
    expect(plc.read('X')).toBe(false);
  });

  test('contacts read a bit of a word and an FB pin', () => {
    const plc = plcOf(
      project(vars('W WORD := 16#0008', 'X BOOL', 'Y BOOL', 'T1 TON'), [
        ladder(['[W.3] (X)']),
        ladder(['[T1.Q] (Y)']),
      ]),
    );
    plc.scan();
    expect(plc.read('X')).toBe(true);
    expect(plc.read('Y')).toBe(false);
  });
});

describe('coils (table 62)', () => {
  test.each([
    ['coil', '[A] (X)', [0, 1, 0], [0, 1, 0]],
    ['negated coil', '[A] (/X)', [0, 1, 0], [1, 0, 1]],
    ['set coil latches', '[A] (S:X)', [0, 1, 0, 0], [0, 1, 1, 1]],
    ['retentive coil', '[A] (M:X)', [0, 1, 0], [0, 1, 0]],
    ['retentive set coil', '[A] (SM:X)', [0, 1, 0], [0, 1, 1]],
    ['positive transition coil', '[A] (P:X)', [0, 1, 1, 0, 1], [0, 1, 0, 0, 1]],
    ['negative transition coil', '[A] (N:X)', [1, 0, 0, 1, 0], [0, 1, 0, 0, 1]],
    [
      'negative transition coil whose left link is OFF at its first evaluation is ON once',
      '[A] (N:X)',
      [0, 0],
      [1, 0],
    ],
  ])('%s', (_name, row, a, x) => {
    expect(trace([row], a)).toEqual(x);
  });

  test.each([
    ['reset coil', '[A] (R:X)'],
    ['retentive reset coil', '[A] (RM:X)'],
  ])('%s unlatches', (_name, row) => {
    const plc = plcOf(project(vars('A BOOL', 'X BOOL := TRUE'), [ladder([row])]));
    plc.scan();
    expect(plc.read('X')).toBe(true);
    plc.write('A', true);
    plc.scan();
    plc.write('A', false);
    plc.scan();
    expect(plc.read('X')).toBe(false);
  });

  test('every coil passes its left link to its right: coils in series', () => {
    expect(trace(['[A] (/X) (Y)'], [1])).toEqual([0]);
    const plc = plcOf(project(vars('A BOOL', 'X BOOL', 'Y BOOL'), [ladder(['[A] (/X) (Y)'])]));
    plc.write('A', true);
    plc.scan();
    expect(plc.read('Y')).toBe(true);
  });

  test('a coil writes an FB input and a bit of a word', () => {
    const plc = plcOf(
      project(vars('A BOOL', 'W WORD := 16#FFFF', 'T1 TON', 'X BOOL'), [
        ladder(['[A] (T1.IN)']),
        ladder(['[A] (W.15)']),
      ]),
    );
    plc.scan();
    expect(plc.read('T1.IN')).toBe(false);
    expect(plc.read('W')).toBe(0x7fff);
    plc.write('A', true);
    plc.scan();
    expect(plc.read('T1.IN')).toBe(true);
    expect(plc.read('W')).toBe(0xffff);
  });

  test('an OR of parallel branches drives one coil', () => {
    const plc = plcOf(project(vars('A BOOL', 'B BOOL', 'X BOOL'), [ladder(['[A] + (X)', '[B] + .'])]));
    plc.write('B', true);
    plc.scan();
    expect(plc.read('X')).toBe(true);
  });
});
