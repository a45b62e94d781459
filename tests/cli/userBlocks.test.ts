// `rungsmith simulate` and `check` on a project with a two-level FB program: Main calls Seq, whose
// two Stage instances each delay their input by a TON (PT 20 ms). Expected trace worked out by hand.
import { describe, expect, it } from 'vitest';
import { newProject } from '../../src/model/factory';
import { saveProject } from '../../src/model/load';
import { ladder, vars } from '../engine/ladder';
import { io, pou } from '../engine/userBlocksHelpers';
import { rungsmith } from './memoryIo';

function sequenceProject(): string {
  const stage = pou('Stage', 'FUNCTION_BLOCK', [...io('input', 'In BOOL'), ...io('output', 'Done BOOL'), ...vars('T TON')], [
    ladder(['[In] # # (Done)', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T', inputs: { PT: 'T#20ms' } }] }),
  ]);
  const seq = pou('Seq', 'FUNCTION_BLOCK', [...io('input', 'Go BOOL'), ...io('output', 'A BOOL', 'B BOOL'), ...vars('S1 Stage', 'S2 Stage')], [
    ladder(['[Go] # # (A)', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'Stage', instance: 'S1' }] }),
    ladder(['[A] # # (B)', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'Stage', instance: 'S2' }] }),
  ]);
  const main = pou('Main', 'PROGRAM', vars('Go BOOL', 'L Seq', 'OutA BOOL', 'OutB BOOL'), [
    ladder(['[Go] # # (OutA)', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'Seq', instance: 'L', outputs: { B: 'OutB' } }] }),
  ]);
  return saveProject(newProject('Sequence', { pous: [main, seq, stage] }));
}

describe('rungsmith on user function blocks', () => {
  it('simulate traces nested instance paths, scan by scan', () => {
    const r = rungsmith(
      ['simulate', 'seq.json', '--inputs', 'stim.csv', '--scans', '9', '--watch', 'Go,L.A,L.B,L.S1.T.ET,l.s2.done'],
      { 'seq.json': sequenceProject(), 'stim.csv': 'scan,Go\n2,1\n8,0\n' },
    );
    expect(r.err).toBe('');
    expect(r.code).toBe(0);
    // S1's timer starts in scan 2 (10 ms): ET 10 at 20 ms, Q at 30 ms (scan 4), so A rises in scan 4
    // and S2 (later in the same scan) starts timing then: B in scan 6. Go off in scan 8 resets both.
    expect(r.out).toBe(
      [
        'scan,time_ms,Go,L.A,L.B,L.S1.T.ET,l.s2.done',
        '1,0,0,0,0,0,0',
        '2,10,1,0,0,0,0',
        '3,20,1,0,0,10,0',
        '4,30,1,1,0,20,0',
        '5,40,1,1,0,20,0',
        '6,50,1,1,1,20,1',
        '7,60,1,1,1,20,1',
        '8,70,0,0,0,0,0',
        '9,80,0,0,0,0,0',
        '',
      ].join('\n'),
    );
  });

  it("the default watch lists a user FB instance's inputs and outputs as INSTANCE.PIN", () => {
    const r = rungsmith(['simulate', 'seq.json', '--scans', '1'], { 'seq.json': sequenceProject() });
    expect(r.code).toBe(0);
    expect(r.out.split('\n')[0]).toBe('scan,time_ms,Go,L.Go,L.A,L.B,OutA,OutB');
  });

  it('check reports a problem inside an FB under its own name', () => {
    const project = JSON.parse(sequenceProject()) as { pous: { name: string; variables: { name: string }[] }[] };
    const stage = project.pous.find((p) => p.name === 'Stage')!;
    stage.variables = stage.variables.filter((v) => v.name !== 'Done');
    const r = rungsmith(['check', 'seq.json'], { 'seq.json': JSON.stringify(project) });
    expect(r.code).toBe(1);
    expect(r.out).toMatch(/^error LD-R08 Stage\/network 1:R1C4 /m);
  });
});

describe('rungsmith simulate on several program instances', () => {
  it('runs every program instance of the tasks, in order, watching Instance.Var', () => {
    const counter = pou('Counter', 'PROGRAM', [...vars('N INT'), ...io('external', 'Total INT')], [
      ladder(['- # # .', '. # # .', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: 'N', IN2: '1' }, outputs: { OUT: 'N' } }] }),
      ladder(['- # # .', '. # # .', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'ADD', inputs: { IN1: 'Total', IN2: 'N' }, outputs: { OUT: 'Total' } }] }),
    ]);
    const project = newProject('Two', {
      pous: [counter],
      globals: vars('Total INT'),
      tasks: [{ name: 'T', cycleMs: 100, priority: 1, programs: [{ instance: 'A', pou: 'Counter' }, { instance: 'B', pou: 'Counter' }] }],
    });
    const r = rungsmith(['simulate', 'two.json', '--scans', '2', '--watch', 'A.N,B.N,Total'], { 'two.json': saveProject(project) });
    expect(r.err).toBe('');
    expect(r.out).toBe('scan,time_ms,A.N,B.N,Total\n1,0,1,1,2\n2,100,2,2,6\n');
    const byDefault = rungsmith(['simulate', 'two.json', '--scans', '1'], { 'two.json': saveProject(project) });
    expect(byDefault.out.split('\n')[0]).toBe('scan,time_ms,A.N,B.N');
  });
});
