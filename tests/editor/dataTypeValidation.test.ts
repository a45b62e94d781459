// The data-type editor's checks: each problem names the field it belongs to, in plain words.
import { expect, test } from 'vitest';
import { newProject, variable } from '../../src/model/factory';
import { validateVariables } from '../../src/editor/variables/validation';
import type { DataType, DataTypeDef, Project } from '../../src/model/project';
import { declarationText } from '../../src/editor/dataTypes/typeText';
import { dataTypeProblems } from '../../src/editor/dataTypes/validation';

const withTypes = (...types: DataType[]): Project => ({ ...newProject('P'), dataTypes: types });
const dt = (name: string, def: DataTypeDef, initial?: string): DataType => ({ name, def, ...(initial ? { initial } : {}) });
const fields = (p: Project, name: string) =>
  dataTypeProblems(p, p.dataTypes!.find((t) => t.name === name)!).map((x) => `${x.field}: ${x.message}`);

test('a structure: duplicate member and unknown member type are marked on their row', () => {
  const p = withTypes(
    dt('Point', { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'x', type: 'Nope' }] }),
  );
  const out = fields(p, 'Point');
  expect(out).toContainEqual('member:1:name: member x is already in row 1');
  expect(out.some((m) => m.startsWith('member:1:type: member x:') && m.includes('Nope'))).toBe(true);
});

test('an array: lower bound above upper bound, per dimension; the element type may be a data type', () => {
  const p = withTypes(
    dt('Point', { kind: 'struct', members: [{ name: 'X', type: 'INT' }] }),
    dt('Grid', { kind: 'array', dims: [{ lower: 1, upper: 3 }, { lower: 5, upper: 2 }], of: 'Point' }),
  );
  expect(fields(p, 'Grid')).toEqual(['dim:1: dimension 2: lower bound 5 is above upper bound 2']);
});

test('a subrange: integer base, bounds in order and inside the base', () => {
  const p = withTypes(
    dt('Pct', { kind: 'subrange', base: 'INT', lower: 100, upper: 0 }),
    dt('Big', { kind: 'subrange', base: 'SINT', lower: 0, upper: 300 }),
    dt('Odd', { kind: 'subrange', base: 'REAL', lower: 0, upper: 1 }),
  );
  expect(fields(p, 'Pct')).toEqual(['bounds: lower bound 100 is above upper bound 0']);
  expect(fields(p, 'Big')).toEqual(['bounds: 0..300 does not fit SINT (-128..127)']);
  expect(fields(p, 'Odd')[0]).toMatch(/^base: a subrange narrows an integer type/);
});

test('an enumeration: duplicate and invalid values; a wrong initial value', () => {
  const p = withTypes(dt('Color', { kind: 'enum', values: ['RED', 'GREEN', 'red', '2X'] }, 'BLUE'));
  const out = fields(p, 'Color');
  expect(out).toContainEqual('value:2: value red is already in row 1');
  expect(out).toContainEqual('value:3: value "2X" is not an IEC identifier (letters, digits and single underscores)');
  expect(out.some((m) => m.startsWith('initial:') && m.includes('BLUE'))).toBe(true);
});

test('a type containing itself is reported on the type as a whole', () => {
  const p = withTypes(
    dt('A', { kind: 'struct', members: [{ name: 'B', type: 'B' }] }),
    dt('B', { kind: 'array', dims: [{ lower: 1, upper: 2 }], of: 'A' }),
  );
  const out = fields(p, 'A');
  expect(out).toHaveLength(1);
  expect(out[0]).toMatch(/^(type|member:0:type): .*contains itself/);
});

test('a good type has no problems and is written as IEC text', () => {
  const p = withTypes(
    dt('Point', { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'Y', type: 'INT', initial: '5' }] }),
  );
  expect(fields(p, 'Point')).toEqual([]);
  expect(declarationText(p.dataTypes![0]!)).toBe(
    'TYPE\n  Point : STRUCT\n    X : INT;\n    Y : INT := 5;\n  END_STRUCT;\nEND_TYPE',
  );
});

test('the variable table knows data types and inline arrays, and checks their initial values', () => {
  const p: Project = {
    ...withTypes(dt('Point', { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'Y', type: 'INT' }] })),
  };
  const vars = [
    variable('P', 'Point', { initial: '(X := 1, Y := 2)' }),
    variable('A', 'ARRAY[1..10] OF INT'),
    variable('Q', 'Point', { initial: '(Z := 1)' }),
    variable('B', 'ARRAY[1..2] OF Pointe'),
    variable('C', 'Pointe'),
  ];
  const issues = validateVariables(vars, { project: p, pou: 'Main' }).map((i) => `${vars[i.index]!.name} ${i.field}: ${i.message}`);
  expect(issues).toHaveLength(3);
  expect(issues[0]).toMatch(/^Q initial: .*no member Z/);
  expect(issues[1]).toMatch(/^B type: .*Pointe/);
  expect(issues[2]).toBe('C type: unknown type "Pointe"');
});
