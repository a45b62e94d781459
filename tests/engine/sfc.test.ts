// SFC POUs run as MATIEC runs them (src/engine/sfc): hand-written charts, traces computed by hand
// from MATIEC's cycle (generate_c_sfc.cc): transitions tested on the steps active at the start of
// the call, step flags and times updated, then actions by qualifier.
import { describe, expect, test } from 'vitest';
import { compileProgram } from '../../src/engine/plc';
import { io, multiProject, pou } from './userBlocksHelpers';
import { ladder, plcOf, trace, vars, type BoxSpec } from './ladder';
import { sfcPou, step, tr } from './sfcHelpers';
import { textPou } from './stHelpers';

describe('SFC charts', () => {
  test('a sequence: transitions, N on a BOOL variable, step time T', () => {
    const main = sfcPou('Main', 'PROGRAM', vars('Go BOOL', 'Busy BOOL'), {
      steps: [step('Idle*'), step('Run', 'N Busy'), step('Done')],
      transitions: [tr('Idle', 'Run', 'Go'), tr('Run', 'Done', 'Run.T >= T#30ms'), tr('Done', 'Idle', 'NOT Go')],
      actions: [],
    });
    const plc = plcOf(multiProject([main]));
    expect(
      trace(plc, [{ Go: true }, {}, {}, {}, { Go: false }], ['Idle.X', 'Run.X', 'Done.X', 'Busy', 'Run.T']),
    ).toEqual([
      [0, 1, 0, 1, 0],
      [0, 1, 0, 1, 10],
      [0, 1, 0, 1, 20],
      [0, 0, 1, 0, 30],
      [1, 0, 0, 0, 30],
    ]);
  });
});

describe('SFC qualifiers', () => {
  test('S, P, D, L on BOOL variables, N on an ST action, R from another step', () => {
    const main = sfcPou('Main', 'PROGRAM', vars('Go BOOL', 'Sx BOOL', 'Px BOOL', 'Dx BOOL', 'Lx BOOL', 'Cnt INT'), {
      steps: [step('A*'), step('B', 'S Sx', 'P Px', 'D Dx T#20ms', 'L Lx T#20ms', 'N Count'), step('C', 'R Sx')],
      transitions: [tr('A', 'B', 'Go'), tr('B', 'C', 'NOT Go'), tr('C', 'A', 'TRUE')],
      actions: [{ name: 'Count', body: { language: 'ST', text: 'Cnt := Cnt + 1;' } }],
    });
    const plc = plcOf(multiProject([main]));
    expect(trace(plc, [{ Go: true }, {}, {}, { Go: false }, {}], ['B.X', 'Sx', 'Px', 'Dx', 'Lx', 'Cnt'])).toEqual([
      [1, 1, 1, 0, 1, 1], // B activated: S stores, P pulses, L on, D waits
      [1, 1, 0, 0, 1, 2],
      [1, 1, 0, 1, 0, 3], // B.T = 20 ms: D on, L off
      [0, 0, 0, 0, 0, 3], // B left: D off, C resets Sx; Count no longer runs
      [0, 0, 0, 0, 0, 3],
    ]);
  });

  test('SD stores after its delay, DS is cancelled when its step ends first, SL stores for a time', () => {
    const main = sfcPou('Main', 'PROGRAM', vars('Go BOOL', 'X1 BOOL', 'X2 BOOL', 'X3 BOOL'), {
      steps: [step('A*'), step('B', 'SD X1 T#20ms', 'DS X2 T#20ms', 'SL X3 T#20ms'), step('C', 'R X2')],
      transitions: [tr('A', 'B', 'Go'), tr('B', 'C', 'NOT Go'), tr('C', 'A', 'FALSE')],
      actions: [],
    });
    const plc = plcOf(multiProject([main]));
    expect(trace(plc, [{ Go: true }, { Go: false }, {}, {}], ['X1', 'X2', 'X3', 'C.X'])).toEqual([
      [0, 0, 1, 0],
      [0, 0, 1, 1],
      [1, 0, 0, 1], // 20 ms after B's activation: SD sets X1 (B has ended), SL's time is over
      [1, 0, 0, 1],
    ]);
  });
});

describe('SFC divergences', () => {
  const chart = (p1?: number, p2?: number) =>
    sfcPou('Main', 'PROGRAM', vars('Go BOOL', 'Done BOOL'), {
      steps: [step('A*'), step('B'), step('C'), step('D')],
      transitions: [tr('A', 'B', 'Go', p1), tr('A', 'C', 'Go', p2), tr('B & C', 'D', 'Done')],
      actions: [],
    });

  test('a selection with PRIORITY fires the transition of the lowest number only', () => {
    const plc = plcOf(multiProject([chart(2, 1)]));
    expect(trace(plc, [{ Go: true }], ['A.X', 'B.X', 'C.X'])).toEqual([[0, 0, 1]]);
  });

  test('without PRIORITY, MATIEC fires every true transition of a selection', () => {
    const plc = plcOf(multiProject([chart()]));
    expect(trace(plc, [{ Go: true }], ['A.X', 'B.X', 'C.X'])).toEqual([[0, 1, 1]]);
  });

  test('a simultaneous convergence waits for all its steps', () => {
    const main = sfcPou('Main', 'PROGRAM', vars('Go BOOL', 'Done BOOL'), {
      steps: [step('A*'), step('B'), step('C'), step('D')],
      transitions: [tr('A', 'B & C', 'Go'), tr('B', 'B', 'FALSE'), tr('B & C', 'D', 'Done AND C.X')],
      actions: [],
    });
    const plc = plcOf(multiProject([main]));
    expect(trace(plc, [{ Go: true }, { Go: false }, { Done: true }], ['A.X', 'B.X', 'C.X', 'D.X'])).toEqual([
      [0, 1, 1, 0],
      [0, 1, 1, 0],
      [0, 0, 0, 1],
    ]);
  });
});

describe('SFC function blocks', () => {
  test('each instance of an SFC FB keeps its own chart; steps are read by path', () => {
    const seq = sfcPou('Seq', 'FUNCTION_BLOCK', [...io('input', 'Go BOOL'), ...io('output', 'Busy BOOL')], {
      steps: [step('Idle*'), step('Run', 'N Busy')],
      transitions: [tr('Idle', 'Run', 'Go'), tr('Run', 'Idle', 'NOT Go')],
      actions: [],
    });
    const box = (instance: string): BoxSpec => ({ row: 0, col: 1, type: 'Seq', instance });
    const main = pou('Main', 'PROGRAM', vars('Go1 BOOL', 'Go2 BOOL', 'B1 BOOL', 'B2 BOOL', 'S1 Seq', 'S2 Seq'), [
      ladder(['[Go1] # # (B1)', '. # # .'], { boxes: [box('S1')] }),
      ladder(['[Go2] # # (B2)', '. # # .'], { boxes: [box('S2')] }),
    ]);
    const plc = plcOf(multiProject([main, seq]));
    expect(trace(plc, [{ Go1: true }, { Go2: true }, { Go1: false }], ['S1.Run.X', 'S2.Run.X', 'B1', 'B2', 'S1.Run.T'])).toEqual([
      [1, 0, 1, 0, 0],
      [1, 1, 1, 1, 10],
      [0, 1, 0, 1, 20], // T grows before the transitions are tested, and keeps its value once Run ends
    ]);
  });
});

describe('ST in charts (the ST compiler: the whole language)', () => {
  test('an ST action calls a user function, a user FB and a TON; a condition calls a function', () => {
    const twice = textPou('Twice', 'FUNCTION', io('input', 'X INT'), 'Twice := X * 2;', { returnType: 'INT' });
    const acc = textPou('Acc', 'FUNCTION_BLOCK', [...io('input', 'Inc INT'), ...io('output', 'Sum INT')], 'Sum := Sum + Inc;');
    const main = sfcPou('Main', 'PROGRAM', vars('Go BOOL', 'A Acc', 'T1 TON', 'Val INT', 'Total INT', 'Done BOOL'), {
      steps: [step('Idle*'), step('Run', 'N Work'), step('End')],
      transitions: [tr('Idle', 'Run', 'Go'), tr('Run', 'End', 'T1.Q AND Twice(Total) >= 20')],
      actions: [
        {
          name: 'Work',
          body: {
            language: 'ST',
            text: 'Val := Twice(Val + 1);\nA(Inc := Val);\nTotal := A.Sum;\nT1(IN := TRUE, PT := T#20ms, Q => Done);',
          },
        },
      ],
    });
    const plc = plcOf(multiProject([main, twice, acc]));
    // Scan 1: Idle -> Run, Work runs: Val = 2*(0+1) = 2, Sum = 2, T1 starts. Scan 2: Val = 2*3 = 6,
    // Sum = 8. Scan 3: Val = 14, Sum = 22, T1 has run 20 ms: Done. Scan 4: T1.Q AND 2*22 >= 20:
    // Run -> End, Work no longer runs.
    expect(trace(plc, [{ Go: true }, {}, {}, {}, {}], ['Run.X', 'End.X', 'Val', 'Total', 'Done'])).toEqual([
      [1, 0, 2, 2, 0],
      [1, 0, 6, 8, 0],
      [1, 0, 14, 22, 1],
      [0, 1, 14, 22, 1],
      [0, 1, 14, 22, 1],
    ]);
  });

  test('CASE and FOR in an action; an error names the line and column', () => {
    const main = sfcPou('Main', 'PROGRAM', vars('Go BOOL', 'I INT', 'N INT', 'Mode INT'), {
      steps: [step('A*', 'N Work')],
      transitions: [],
      actions: [{ name: 'Work', body: { language: 'ST', text: 'CASE Mode OF 0: N := 0; ELSE FOR I := 1 TO Mode DO N := N + I; END_FOR; END_CASE; Mode := Mode + 1;' } }],
    });
    const plc = plcOf(multiProject([main]));
    expect(trace(plc, [{}, {}, {}, {}], ['N', 'Mode'])).toEqual([
      [0, 1],
      [1, 2],
      [4, 3],
      [10, 4],
    ]);
    const bad = sfcPou('Main', 'PROGRAM', vars('Go BOOL'), {
      steps: [step('A*', 'N Work')],
      transitions: [],
      actions: [{ name: 'Work', body: { language: 'ST', text: 'Go := TRUE;\nNope(1);' } }],
    });
    const errs = compileProgram(multiProject([bad]), {}).diagnostics.filter((d) => d.severity === 'error');
    expect(errs.map((d) => d.rule)).toEqual(['LD-E44']);
    expect(errs[0]!.message).toMatch(/the action Work of Main .*line 2 col 1: .*Nope/);
  });
});

describe('SFC checks', () => {
  const diagnostics = (chart: Parameters<typeof sfcPou>[3]) =>
    compileProgram(multiProject([sfcPou('Main', 'PROGRAM', vars('Go BOOL'), chart)]), {}).diagnostics.filter(
      (d) => d.severity === 'error',
    );

  test('a chart without an initial step, an unknown action and a bad qualifier are named', () => {
    expect(diagnostics({ steps: [step('A')], transitions: [], actions: [] }).map((d) => d.rule)).toContain('LD-E40');
    const errs = diagnostics({
      steps: [step('A*', 'N Lamp', 'X Go', 'D Go')],
      transitions: [tr('A', 'B', 'Go')],
      actions: [],
    });
    expect(errs.map((d) => d.rule).sort()).toEqual(['LD-E42', 'LD-E43', 'LD-E43', 'LD-E43']);
    expect(errs.map((d) => d.message).join('\n')).toMatch(/"Lamp", which is neither an action of Main nor a variable/);
  });

  test('ST that does not check is named with its text', () => {
    const errs = diagnostics({ steps: [step('A*'), step('B')], transitions: [tr('A', 'B', 'Go + 1')], actions: [] });
    expect(errs).toHaveLength(1);
    expect(errs[0]!.rule).toBe('LD-E44');
    expect(errs[0]!.message).toMatch(/transition 1 .*Go \+ 1/);
  });
});
