// PLCopen import never refuses what IEC 61131-3 allows and MATIEC compiles (issue 12): a block after
// a coil, one line into EN and IN1, one FB instance called from two networks, a coil on the left
// rail. Each imports without errors, is checked with warnings only, and runs as MATIEC would.
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { trace } from '../engine/ladder';
import { imported, run } from './fixtures';


describe('PLCopen import: programs that only vendor editors refuse', () => {
  const { project, report } = imported('vendor-rules-run.xml');
  const diagnostics = checkProject(project);
  const of = (pou: string) =>
    diagnostics.filter((d) => d.pou === pou).map((d) => `${d.severity} ${d.rule} ${d.network}`);

  it('imports without errors or redrawn wiring; the check gives warnings only', () => {
    expect(report.warnings).toEqual([]);
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
  });

  it('a TON after a coil (LD-R04 warning) takes the coil’s left state', () => {
    expect(of('CoilThenBlock')).toEqual(['warning LD-R04 0']);
    const on = { A: true };
    expect(trace(run(project, 'CoilThenBlock'), [on, on, on, { A: false }], ['X', 'Y'])).toEqual([
      [1, 0],
      [1, 0],
      [1, 1],
      [0, 0],
    ]);
  });

  it('one line into EN and IN1 of AND (LD-R10 warning): both pins get it', () => {
    expect(of('SharedLine')).toEqual(['warning LD-R10 0']);
    const steps = [
      { A: false, B: true },
      { A: true, B: false },
      { A: true, B: true },
    ];
    expect(trace(run(project, 'SharedLine'), steps, ['X', 'Y'])).toEqual([
      [0, 0],
      [1, 0],
      [1, 1],
    ]);
  });

  it('one CTU instance called from two networks (LD-R10 warning): both calls run, in order', () => {
    expect(of('TwoCalls')).toEqual(['warning LD-R10 1']);
    const steps = [
      { A: true, B: false, Rst: false },
      { A: true, B: false, Rst: false },
      { A: true, B: false, Rst: true },
      { A: true, B: false, Rst: false },
    ];
    expect(trace(run(project, 'TwoCalls'), steps, ['N1', 'N2'])).toEqual([
      [1, 1],
      [2, 2],
      [3, 0],
      [1, 1],
    ]);
  });

  it('a coil on the left rail (LD-R02 warning) is always energised', () => {
    expect(of('RailCoil')).toEqual(['warning LD-R02 0']);
    expect(trace(run(project, 'RailCoil'), [{ A: false }, { A: true }], ['X', 'Y'])).toEqual([
      [1, 0],
      [1, 1],
    ]);
  });
});
