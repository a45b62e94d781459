// Types typed in the variable table ("Other type…"): anonymous arrays, structures, enumerations and
// subranges are accepted as written; a malformed one is refused with the reason.
import { describe, expect, test } from 'vitest';
import { newPou, newProject, variable } from '../../src/model/factory';
import type { Variable } from '../../src/model/project';
import { issuesByField, validateVariables } from '../../src/editor/variables/validation';

const typeIssues = (vars: Variable[]) => {
  const project = newProject('T', { pous: [newPou('Main', { variables: vars })] });
  return vars.map((_, i) => issuesByField(validateVariables(vars, { project, pou: 'Main' }), i).type);
};

describe('anonymous type texts in the variable table', () => {
  test('accepts ARRAY, STRUCT, enumeration and subrange texts', () => {
    expect(
      typeIssues([
        variable('Buf', 'ARRAY[0..9] OF INT'),
        variable('Pump', 'STRUCT Run : BOOL; Speed : INT := 5; END_STRUCT'),
        variable('State', '(Idle, Run, Fault)'),
        variable('Pct', 'INT (0..100)'),
      ]),
    ).toEqual([undefined, undefined, undefined, undefined]);
  });
  test('says what is wrong with a malformed one', () => {
    const [a, b, c] = typeIssues([
      variable('Pump', 'STRUCT Run BOOL; END_STRUCT'),
      variable('Buf', 'ARRAY[5..1] OF INT'),
      variable('Pump2', 'STRUCT Run : BOOL;'),
    ]);
    expect(a).toMatch(/"Run BOOL" is not a member like X : INT/);
    expect(b).toMatch(/the range 5..1 is empty/);
    expect(c).toMatch(/a structure ends with END_STRUCT/);
  });
});
