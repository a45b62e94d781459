// Design decisions on the order of evaluation (LD-SEMANTICS.md section 6). These results are
// part of the engine's contract: the editor, the docs and PLCopen round trips rely on them.
import { checkProject } from '../../src/engine/check';
import { describe, expect, test } from 'vitest';
import { ladder, plcOf, project, vars } from './ladder';

const V = vars('A BOOL', 'B BOOL', 'X BOOL', 'Y BOOL', 'I INT', 'Done BOOL');

describe('evaluation order (design decisions)', () => {
  test('parallel coils run top to bottom: a reset coil drawn below a set coil on the same variable wins', () => {
    const setAbove = plcOf(project(V, [ladder(['[A] + (S:X)', '. + (R:X)'])]));
    setAbove.write('A', true);
    setAbove.scan();
    expect(setAbove.read('X')).toBe(false);

    // Why: Beremiz orders coils by drawing position and so does the engine; swapping the rows swaps the winner.
    const resetAbove = plcOf(project(V, [ladder(['[A] + (R:X)', '. + (S:X)'])]));
    resetAbove.write('A', true);
    resetAbove.scan();
    expect(resetAbove.read('X')).toBe(true);
  });

  test('a contact reads the value a coil above it in the same network has just written', () => {
    const plc = plcOf(project(V, [ladder(['[A] - (X)', '[X] - (Y)'])]));
    plc.write('A', true);
    plc.scan();
    // Why: among elements ready at the same time the upper row goes first, so coil X runs before contact X.
    expect(plc.read('Y')).toBe(true);
  });

  test('a contact drawn above the coil that writes its variable reads the previous value (one scan late)', () => {
    const plc = plcOf(project(V, [ladder(['[X] - (Y)', '[A] - (X)'])]));
    plc.write('A', true);
    plc.scan();
    expect([plc.read('X'), plc.read('Y')]).toEqual([true, false]);
    plc.scan();
    expect(plc.read('Y')).toBe(true);
  });

  test('a later network sees what an earlier one wrote in the same scan', () => {
    const plc = plcOf(project(V, [ladder(['[A] (X)']), ladder(['[X] (Y)'])]));
    plc.write('A', true);
    plc.scan();
    expect(plc.read('Y')).toBe(true);
  });

  test('an earlier network sees what a later one wrote only in the next scan (implicit feedback through a variable)', () => {
    const plc = plcOf(project(V, [ladder(['[X] (Y)']), ladder(['[A] (X)'])]));
    plc.write('A', true);
    plc.scan();
    expect(plc.read('Y')).toBe(false);
    plc.scan();
    expect(plc.read('Y')).toBe(true);
  });

  test('a network with a powered jump still completes: every element of it is evaluated, then execution continues at the label', () => {
    const plc = plcOf(
      project(V, [
        ladder(['[A] - >>SKIP', '[B] - (X)']),
        ladder(['[B] - (Y)']),
        ladder(['[A] - (Done)'], { label: 'SKIP' }),
      ]),
    );
    plc.write('A', true);
    plc.write('B', true);
    plc.scan();
    // Why: 4.1.3 says a network is complete only when every element is evaluated; the jump takes effect after.
    expect([plc.read('X'), plc.read('Y'), plc.read('Done')]).toEqual([true, false, true]);
  });

  test('a powered RETURN ends the program for this scan; an unpowered one does nothing', () => {
    const plc = plcOf(project(V, [ladder(['[A] <RET>']), ladder(['[B] (X)'])]));
    plc.write('B', true);
    plc.write('A', true);
    plc.scan();
    expect(plc.read('X')).toBe(false);
    expect(plc.snapshot().networks.map((n) => n.executed)).toEqual([true, false]);
    plc.write('A', false);
    plc.scan();
    expect(plc.read('X')).toBe(true);
  });

  test('an unconditional jump attached to the left rail always jumps', () => {
    const plc = plcOf(
      project(V, [ladder(['>>END']), ladder(['[B] (X)']), ladder(['[B] (Y)'], { label: 'END' })]),
    );
    plc.write('B', true);
    plc.scan();
    expect([plc.read('X'), plc.read('Y')]).toEqual([false, true]);
  });

  test('a backward jump repeats networks within one scan (a bounded loop)', () => {
    const plc = plcOf(
      project(vars('I INT', 'Again BOOL'), [
        ladder(['- # #'], {
          boxes: [{ row: 0, col: 1, type: 'MOVE', inputs: { IN: '0' }, outputs: { OUT: 'I' } }],
        }),
        ladder(['- # #'], {
          boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: 'I', IN2: '1' }, outputs: { OUT: 'I' } }],
          label: 'LOOP',
        }),
        ladder(['- # # . .', '. # # - (Again)'], {
          boxes: [{ row: 0, col: 1, type: 'LT', inputs: { IN1: 'I', IN2: '5' } }],
        }),
        ladder(['[Again] >>LOOP']),
      ]),
    );
    plc.scan();
    expect(plc.read('I')).toBe(5);
  });

  test('LD-W03: a backward jump is named as a possible loop; a forward jump is not', () => {
    const loop = project(vars('Again BOOL', 'Skip BOOL', 'X BOOL'), [
      ladder(['[Skip] >>END']),
      ladder(['[X] (X)'], { label: 'LOOP' }),
      ladder(['[Again] >>LOOP']),
      ladder(['[X] (X)'], { label: 'END' }),
    ]);
    const warned = checkProject(loop).filter((d) => d.rule === 'LD-W03');
    expect(warned.map((d) => [d.network, d.severity])).toEqual([[2, 'warning']]);
    expect(warned[0]!.message).toMatch(/jumps back to network 2 \("LOOP"\)/);
  });
});
