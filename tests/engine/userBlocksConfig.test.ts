// Several program instances per task (compileProgram { configuration: true }): run in task order
// each scan, their variables reached as Instance.Var, globals by name; RETURN ends one program.
import { describe, expect, test } from 'vitest';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { newProject } from '../../src/model/factory';
import { ladder, trace, vars, type BoxSpec } from './ladder';
import { io, pou } from './userBlocksHelpers';

const box = (type: string, row: number, col: number, extra: Partial<BoxSpec> = {}): BoxSpec => ({ row, col, type, ...extra });
const add = (v: string) =>
  ladder(['- # # .', '. # # .', '. # # .'], { boxes: [box('ADD', 0, 1, { inputs: { IN1: v, IN2: '1' }, outputs: { OUT: v } })] });

const count = () =>
  pou('Count', 'PROGRAM', [...vars('N INT', 'Stop BOOL'), ...io('external', 'Total INT')], [
    add('N'),
    ladder(['[Stop] <RET>']),
    add('Total'),
  ]);
const report = () =>
  pou('Report', 'PROGRAM', [...vars('Seen INT'), ...io('external', 'Total INT')], [
    ladder(['- # # .', '. # # .'], { boxes: [box('MOVE', 0, 1, { inputs: { IN: 'Total' }, outputs: { OUT: 'Seen' } })] }),
  ]);

const configProject = () =>
  newProject('Plant', {
    pous: [count(), report()],
    globals: vars('Total INT'),
    tasks: [
      {
        name: 'Main',
        cycleMs: 10,
        priority: 1,
        programs: [
          { instance: 'C1', pou: 'Count' },
          { instance: 'C2', pou: 'Count' },
          { instance: 'R', pou: 'Report' },
        ],
      },
    ],
  });

describe('several programs per task', () => {
  test('program instances run in task order each scan, with their own variables', () => {
    const { program, diagnostics } = compileProgram(configProject(), { configuration: true });
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 10 });
    expect(plc.variableNames()).toEqual(['Total', 'C1.N', 'C1.Stop', 'C2.N', 'C2.Stop', 'R.Seen']);
    expect(trace(plc, [{}, {}, { 'c1.stop': true }, {}], ['C1.N', 'C2.N', 'Total', 'R.Seen'])).toEqual([
      [1, 1, 2, 2],
      [2, 2, 4, 4],
      // RETURN in C1 ends C1 only: C2 and R still run.
      [3, 3, 5, 5],
      [4, 4, 6, 6],
    ]);
  });

  test('programs that call FBs: each program runs once, in task order, and its calls with it', () => {
    // Inc counts its calls; P1 calls two instances, P2 one; P2 copies P1's count into its own.
    const inc = pou('Inc', 'FUNCTION_BLOCK', io('output', 'Q INT'), [add('Q')]);
    const call = (instance: string, out: string, row = 0) =>
      box('Inc', row, 1, { instance, outputs: { Q: out } });
    const p1 = pou('P1', 'PROGRAM', vars('A INT', 'B INT', 'I1 Inc', 'I2 Inc'), [
      ladder(['. # # .', '. # # .'], { boxes: [call('I1', 'A')] }),
      ladder(['. # # .', '. # # .'], { boxes: [call('I2', 'B')] }),
    ]);
    const p2 = pou('P2', 'PROGRAM', [...vars('C INT', 'Seen INT', 'I3 Inc'), ...io('external', 'Total INT')], [
      ladder(['. # # .', '. # # .'], { boxes: [call('I3', 'C')] }),
      ladder(['- # # .', '. # # .'], { boxes: [box('MOVE', 0, 1, { inputs: { IN: 'Total' }, outputs: { OUT: 'Seen' } })] }),
    ]);
    const p0 = pou('P0', 'PROGRAM', io('external', 'Total INT'), [add('Total')]);
    const project = newProject('Plant', {
      pous: [p1, p2, p0, inc],
      globals: vars('Total INT'),
      tasks: [
        {
          name: 'Main',
          cycleMs: 10,
          priority: 1,
          programs: [
            { instance: 'X', pou: 'P1' },
            { instance: 'T', pou: 'P0' },
            { instance: 'Y', pou: 'P2' },
          ],
        },
      ],
    });
    const { program, diagnostics } = compileProgram(project, { configuration: true });
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    const plc = createPlc(program!, { cycleMs: 10 });
    expect(trace(plc, [{}, {}, {}], ['X.A', 'X.B', 'Y.C', 'Total', 'Y.Seen'])).toEqual([
      [1, 1, 1, 1, 1],
      [2, 2, 2, 2, 2],
      [3, 3, 3, 3, 3],
    ]);
  });

  test('one program of the configuration can still be compiled alone (--pou)', () => {
    const { program } = compileProgram(configProject(), { pou: 'Count' });
    const plc = createPlc(program!, { cycleMs: 10 });
    plc.scans(2);
    expect([plc.read('N'), plc.read('Total')]).toEqual([2, 2]);
  });

  test('a task instance naming a missing POU or a FUNCTION_BLOCK is reported', () => {
    const base = configProject();
    const fb = pou('Fb', 'FUNCTION_BLOCK', [], [ladder(['- (Q)'])]);
    const p = {
      ...base,
      pous: [...base.pous, fb],
      tasks: [{ ...base.tasks[0]!, programs: [{ instance: 'X', pou: 'Nope' }, { instance: 'Y', pou: 'Fb' }] }],
    };
    const { program, diagnostics } = compileProgram(p, { configuration: true });
    expect(program).toBeUndefined();
    expect(diagnostics.map((d) => `${d.rule} ${d.message}`)).toEqual([
      expect.stringMatching(/LD-E20 .*X runs "Nope", which is not a POU/),
      expect.stringMatching(/LD-E20 .*Y runs Fb, a FUNCTION_BLOCK/),
    ]);
  });

  test('two instances of one program keep their own edge memories', () => {
    const pulse = pou('Pulse', 'PROGRAM', [...vars('Hits INT'), ...io('external', 'In BOOL')], [
      ladder(['[P:In] # # .', '. # # .', '. # # .'], {
        boxes: [box('ADD', 0, 1, { inputs: { IN1: 'Hits', IN2: '1' }, outputs: { OUT: 'Hits' } })],
      }),
    ]);
    const p = newProject('Pulses', {
      pous: [pulse],
      globals: vars('In BOOL'),
      tasks: [{ name: 'T', cycleMs: 10, priority: 1, programs: [{ instance: 'A', pou: 'Pulse' }, { instance: 'B', pou: 'Pulse' }] }],
    });
    const plc = createPlc(compileProgram(p, { configuration: true }).program!, { cycleMs: 10 });
    expect(trace(plc, [{ In: true }, {}, { In: false }, { In: true }], ['A.Hits', 'B.Hits'])).toEqual([
      [1, 1],
      [1, 1],
      [1, 1],
      [2, 2],
    ]);
    expect(plc.stateItems().filter((i) => i.kind === 'edge').map((i) => i.label)).toEqual([
      expect.stringMatching(/^\|P\| In in network 1 of A \(Pulse\)$/),
      expect.stringMatching(/^\|P\| In in network 1 of B \(Pulse\)$/),
    ]);
  });
});
