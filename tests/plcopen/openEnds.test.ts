// PLCopen import does not refuse open ends (LD-R03) or function inputs left unconnected (issue 12,
// section 2): they import, the check warns, and they run as Beremiz generates them (a path that
// leads nowhere is unused, a coil with nothing on its left is not assigned) and as MATIEC runs them
// (a function input left out of the call takes its type's initial value).
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { trace } from '../engine/ladder';
import { imported, run } from './fixtures';


describe('PLCopen import: open ends and unconnected function inputs', () => {
  const { project } = imported('open-ends-run.xml');
  const diagnostics = checkProject(project);
  const of = (pou: string) => diagnostics.filter((d) => d.pou === pou).map((d) => `${d.severity} ${d.rule}`);

  it('imports; the check gives warnings only', () => {
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
  });

  it('a contact leading nowhere and a coil fed by nothing: LD-R03 warnings; the coil keeps its value', () => {
    expect(of('OpenEnds').length).toBeGreaterThan(0);
    expect(new Set(of('OpenEnds'))).toEqual(new Set(['warning LD-R03']));
    const steps = [
      { A: true, B: false },
      { A: false, B: true },
    ];
    // Y is TRUE initially and written by a negated coil with nothing on its left: never assigned.
    expect(trace(run(project, 'OpenEnds'), steps, ['X', 'Y'])).toEqual([
      [0, 1],
      [1, 1],
    ]);
  });

  it('AND and ADD with IN2 unconnected: LD-R10 warnings; IN2 is FALSE / 0', () => {
    expect(of('UnwiredInputs')).toEqual(['warning LD-R10', 'warning LD-R10']);
    const steps = [
      { A: true, B: true, N1: 5 },
      { A: false, B: true, N1: 9 },
    ];
    expect(trace(run(project, 'UnwiredInputs'), steps, ['X', 'Y', 'N2'])).toEqual([
      [1, 0, 5],
      [0, 0, 9],
    ]);
  });
});
