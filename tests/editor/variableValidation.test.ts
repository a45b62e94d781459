import { describe, expect, test } from 'vitest';
import { newProject, variable } from '../../src/model/factory';
import type { Project, Variable } from '../../src/model/project';
import { identifierProblem, issuesByField, validateVariables } from '../../src/editor/variables/validation';

const fieldsOf = (vars: Variable[], project?: Project) =>
  vars.map((_, i) => issuesByField(validateVariables(vars, project ? { project, pou: 'Main' } : {}), i));

describe('variable names', () => {
  test('accepts IEC identifiers', () => {
    expect(identifierProblem('Start_PB')).toBeUndefined();
    expect(identifierProblem('_hidden1')).toBeUndefined();
  });
  test('refuses names that are not identifiers, with the reason', () => {
    expect(identifierProblem('')).toMatch(/needs a name/);
    expect(identifierProblem('1st')).toMatch(/not an IEC identifier/);
    expect(identifierProblem('Motor On')).toMatch(/not an IEC identifier/);
    expect(identifierProblem('a__b')).toMatch(/two underscores/);
    expect(identifierProblem('motor_')).toMatch(/ends with an underscore/);
  });
  test('refuses reserved words, type names and standard block names', () => {
    expect(identifierProblem('TRUE')).toMatch(/reserved/);
    expect(identifierProblem('int')).toMatch(/reserved/);
    expect(identifierProblem('ton')).toMatch(/standard block TON/);
  });
  test('reports a duplicate name ignoring case, on the second row', () => {
    const [first, second] = fieldsOf([variable('Motor', 'BOOL'), variable('MOTOR', 'BOOL')]);
    expect(first?.name).toBeUndefined();
    expect(second?.name).toMatch(/already declared in row 1/);
  });
});

describe('types', () => {
  test('accepts elementary types and FB types, refuses unknown ones', () => {
    const rows = fieldsOf([
      variable('a', 'INT'),
      variable('T1', 'TON'),
      variable('b', 'FLOAT'),
      variable('c', ''),
    ]);
    expect(rows[0]?.type).toBeUndefined();
    expect(rows[1]?.type).toBeUndefined();
    expect(rows[2]?.type).toMatch(/unknown type "FLOAT"/);
    expect(rows[3]?.type).toMatch(/choose a type/);
  });
});

describe('addresses', () => {
  test('refuses text that is not an IEC address', () => {
    const [row] = fieldsOf([variable('a', 'BOOL', { location: '%IZ0.1' })]);
    expect(row?.location).toMatch(/not an IEC address/);
  });
  test('refuses an address whose size does not fit the type', () => {
    const rows = fieldsOf([
      variable('a', 'INT', { location: '%IX0.0' }),
      variable('b', 'BOOL', { location: '%QW1' }),
      variable('c', 'INT', { location: '%MW3' }),
    ]);
    expect(rows[0]?.location).toMatch(/%IX0\.0 holds a bit \(BOOL\), which does not fit type INT/);
    expect(rows[1]?.location).toMatch(/16-bit word/);
    expect(rows[2]?.location).toBeUndefined();
  });
  test('reports an address used twice in the table, whatever its spelling', () => {
    const rows = fieldsOf([
      variable('a', 'BOOL', { location: '%IX0.0' }),
      variable('b', 'BOOL', { location: '%ix0.0' }),
    ]);
    expect(rows[0]?.location).toBeUndefined();
    expect(rows[1]?.location).toMatch(/%IX0\.0 is already used by "a" in row 1/);
  });
  test('reports an address already used by a global variable', () => {
    const project = newProject('p', { globals: [variable('Alarm', 'BOOL', { location: '%QX0.0' })] });
    const [row] = fieldsOf([variable('Lamp', 'BOOL', { location: '%QX0.0' })], project);
    expect(row?.location).toMatch(/already used by "Alarm" in the global variables/);
  });
  test('refuses an address on an FB instance and on temporary variables', () => {
    const rows = fieldsOf([
      variable('T1', 'TON', { location: '%MX0.0' }),
      variable('t', 'BOOL', { varClass: 'temp', location: '%MX0.1' }),
    ]);
    expect(rows[0]?.location).toMatch(/TON instance cannot sit at an address/);
    expect(rows[1]?.location).toMatch(/temporary variable cannot be given an address/);
  });
});

describe('initial values', () => {
  test('accepts literals of the variable type', () => {
    const rows = fieldsOf([
      variable('a', 'BOOL', { initial: 'TRUE' }),
      variable('b', 'TIME', { initial: 'T#5s' }),
      variable('c', 'INT', { initial: '-12' }),
    ]);
    expect(rows.map((r) => r.initial)).toEqual([undefined, undefined, undefined]);
  });
  test('refuses values that do not parse or do not fit', () => {
    const rows = fieldsOf([
      variable('a', 'SINT', { initial: '300' }),
      variable('b', 'TIME', { initial: '5 seconds' }),
      variable('T1', 'TON', { initial: '1' }),
    ]);
    expect(rows[0]?.initial).toMatch(/300/);
    expect(rows[1]?.initial).toBeDefined();
    expect(rows[2]?.initial).toMatch(/takes no initial value/);
  });
  test('a CONSTANT needs an initial value and cannot be RETAIN', () => {
    const [row] = fieldsOf([variable('k', 'INT', { constant: true, retain: true })]);
    expect(row?.initial).toMatch(/CONSTANT needs an initial value/);
    expect(row?.retain).toMatch(/cannot also be RETAIN/);
  });
});
