// Scenario files: parsing (columns, don't care, tolerances, directives) and the errors a user sees.
import { describe, expect, it } from 'vitest';
import { parseScenario, ScenarioError } from '../../src/sim/scenario';

describe('scenario files', () => {
  it('reads inputs, expected columns with tolerances, don\'t-care cells and directives', () => {
    const s = parseScenario('# cycle: 100ms\n# pou: Main\nscan,Start,expect Motor,expect T1.ET ~ 50ms\n1,1,*,\n4,,1,300~20\n', 'x');
    expect(s.cycleMs).toBe(100);
    expect(s.pou).toBe('Main');
    expect(s.columns).toEqual([
      { name: 'Start', kind: 'input' },
      { name: 'Motor', kind: 'expect' },
      { name: 'T1.ET', kind: 'expect', tolerance: 50 },
    ]);
    expect(s.rows.map((r) => [r.scan, [...r.cells]])).toEqual([
      [1, [[0, '1']]],
      [4, [[1, '1'], [2, '300~20']]],
    ]);
    expect(s.scans).toBe(4);
  });

  it('names the line of a bad row', () => {
    expect(() => parseScenario('scan,A\n2,1\n1,0\n')).toThrow('line 3: scan 1 comes after scan 2');
    expect(() => parseScenario('time,A\n')).toThrow(ScenarioError);
    expect(() => parseScenario('scan,A,expect B ~ soon\n')).toThrow('line 1: tolerance "soon"');
  });
});
