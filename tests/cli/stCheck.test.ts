// `rungsmith check` on a project whose ST bodies have errors: each reported with its POU, line and
// column and its rule id, exit code 1; the same body fixed checks clean.
import { describe, expect, it } from 'vitest';
import { newPou, newProject } from '../../src/model/factory';
import { saveProject } from '../../src/model/load';
import type { Variable } from '../../src/model/project';
import { rungsmith } from './memoryIo';

const v = (name: string, type: string, varClass: Variable['varClass'] = 'local'): Variable => ({
  name,
  type,
  varClass,
  retain: false,
  comment: '',
});

function plant(scaleBody: string, mainBody: string): string {
  return saveProject(
    newProject('Plant', {
      pous: [
        newPou('Main', {
          variables: [v('Raw', 'REAL'), v('Level', 'REAL'), v('H1', 'Hyst')],
          networks: [],
          language: 'ST',
          source: mainBody,
        }),
        newPou('Scale', {
          kind: 'FUNCTION',
          returnType: 'REAL',
          variables: [v('In', 'REAL', 'input')],
          networks: [],
          language: 'ST',
          source: scaleBody,
        }),
        newPou('Hyst', {
          kind: 'FUNCTION_BLOCK',
          variables: [v('X', 'REAL', 'input'), v('Q', 'BOOL', 'output')],
          networks: [],
          language: 'ST',
          source: 'Q := X > 50.0;\n',
        }),
      ],
    }),
  );
}

describe('rungsmith check on ST bodies', () => {
  it('reports each ST error with the POU, line and column and its rule id, and exits 1', () => {
    const r = rungsmith(['check', 'p.json'], {
      'p.json': plant(
        'Scale := In * 2;\nScale := TRUE;\n',
        'Level := Scale(In := Raw);\nH1(X := Level);\nIF H1.Q THEN\n  Level := 0.0\nEND_IF;\n',
      ),
    });
    expect(r.code).toBe(1);
    const lines = r.out.trim().split('\n');
    expect(lines).toEqual([
      expect.stringMatching(
        /^error LD-E50 Main\/line 5 col 1 the ST body of Main does not compile: line 5 col 1: expected ";" to end the statement, found "END_IF"$/,
      ),
      expect.stringMatching(
        /^error LD-E50 Scale\/line 2 col 10 the ST body of Scale does not compile: line 2 col 10: cannot assign to Scale: REAL is needed and the value is BOOL/,
      ),
    ]);
  });

  it('the same bodies fixed check clean', () => {
    const r = rungsmith(['check', 'p.json'], {
      'p.json': plant(
        'Scale := In * 2.0;\n',
        'Level := Scale(In := Raw);\nH1(X := Level);\nIF H1.Q THEN\n  Level := 0.0;\nEND_IF;\n',
      ),
    });
    expect(r).toMatchObject({ code: 0, out: '' });
  });
});
