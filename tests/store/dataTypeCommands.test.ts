// Data-type commands: add, rename (declarations and other types follow), duplicate, delete (with
// the places that use it), update; each is one undo step.
import { expect, test } from 'vitest';
import { newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { createDocumentStore } from '../../src/store/documentStore';
import {
  dataTypeNameProblem,
  dataTypeUsages,
  describeDataTypeUse,
  renameTypeInText,
} from '../../src/store/dataTypeCommands';

const typeNames = (p: Project) => (p.dataTypes ?? []).map((t) => t.name);

function pointProject() {
  const store = createDocumentStore(newProject('Plant'));
  const s = () => store.getState();
  s().addDataType('struct', 'Point');
  s().updateDataType('Point', {
    def: { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'Y', type: 'INT' }] },
  });
  s().addDataType('array', 'Path');
  s().updateDataType('Path', { def: { kind: 'array', dims: [{ lower: 1, upper: 4 }], of: 'Point' } });
  s().addVariable(variable('P', 'Point'));
  s().addVariable(variable('Line', 'ARRAY[1..2] OF Point'));
  s().addVariable(variable('G', 'point'), 'globals');
  const fn = s().addPou('FUNCTION', 'Origin')!;
  s().updatePou(fn, { returnType: 'Point' });
  return { store, s };
}

test('a new data type gets a fresh name per kind and a starting definition; undo removes it', () => {
  const store = createDocumentStore(newProject('P'));
  const s = () => store.getState();
  expect(s().addDataType('enum')).toBe('Enum');
  expect(s().addDataType('enum')).toBe('Enum2');
  expect(s().project.dataTypes![0]!.def).toEqual({ kind: 'enum', values: ['VALUE1', 'VALUE2'] });
  expect(s().addDataType('struct', 'Main')).toBeUndefined();
  expect(s().undoName).toBe('addDataType');
  s().undo();
  expect(typeNames(s().project)).toEqual(['Enum']);
  s().undo();
  expect(typeNames(s().project)).toEqual([]);
});

test('names: identifiers only, not an elementary type, a standard block, a POU or another data type', () => {
  const { s } = pointProject();
  const p = s().project;
  expect(dataTypeNameProblem(p, 'INT')).toMatch(/type INT/);
  expect(dataTypeNameProblem(p, 'TON')).toMatch(/standard block TON/);
  expect(dataTypeNameProblem(p, 'main')).toMatch(/POU named Main/);
  expect(dataTypeNameProblem(p, 'POINT')).toMatch(/data type named Point/);
  expect(dataTypeNameProblem(p, 'POINT', 'Point')).toBeUndefined();
  expect(dataTypeNameProblem(p, '2D')).toMatch(/not an IEC identifier/);
  // A POU cannot take a data type's name either.
  expect(s().addPou('PROGRAM', 'Point')).toBeUndefined();
});

test('renaming a data type retypes variables, globals, return types and other types in one undo step', () => {
  const { s } = pointProject();
  const before = s().project;
  expect(s().renameDataType('Point', 'Coord')).toBe(true);
  const p = s().project;
  const main = p.pous.find((x) => x.name === 'Main')!;
  expect(main.variables.map((v) => v.type)).toEqual(['Coord', 'ARRAY[1..2] OF Coord']);
  expect(p.globals.map((v) => v.type)).toEqual(['Coord']);
  expect(p.pous.find((x) => x.name === 'Origin')!.returnType).toBe('Coord');
  expect(p.dataTypes!.find((t) => t.name === 'Path')!.def).toMatchObject({ of: 'Coord' });
  expect(typeNames(p)).toEqual(['Coord', 'Path']);
  expect(s().undoName).toBe('renameDataType');
  s().undo();
  expect(s().project).toEqual(before);
  expect(s().renameDataType('Point', 'Path')).toBe(false);
});

test('a rename replaces whole words only', () => {
  expect(renameTypeInText('ARRAY[0..3] OF Point', 'point', 'Coord')).toBe('ARRAY[0..3] OF Coord');
  expect(renameTypeInText('Point3D', 'Point', 'Coord')).toBe('Point3D');
  expect(renameTypeInText('MyPoint', 'Point', 'Coord')).toBe('MyPoint');
});

test('the uses of a data type say where it is used; delete and duplicate are one undo step each', () => {
  const { s } = pointProject();
  const uses = dataTypeUsages(s().project, 'Point').map(describeDataTypeUse);
  expect(uses).toEqual([
    'Main: variable P',
    'Main: variable Line',
    'function Origin: return type',
    'global variables: variable G',
    'data type Path',
  ]);
  expect(dataTypeUsages(s().project, 'Path')).toEqual([]);
  expect(s().duplicateDataType('Point')).toBe('Point_copy');
  expect(typeNames(s().project)).toEqual(['Point', 'Point_copy', 'Path']);
  expect(s().deleteDataType('Point')).toBe(true);
  expect(typeNames(s().project)).toEqual(['Point_copy', 'Path']);
  // Declarations stay as they were: the checks report the unknown type.
  expect(s().project.globals[0]!.type).toBe('point');
  s().undo();
  expect(typeNames(s().project)).toEqual(['Point', 'Point_copy', 'Path']);
  expect(s().deleteDataType('Nope')).toBe(false);
});

test('updating the initial value and comment; empty text removes them; no change records nothing', () => {
  const { s } = pointProject();
  expect(s().updateDataType('Point', { initial: '(X := 1, Y := 2)', comment: 'A point' })).toBe(true);
  expect(s().project.dataTypes![0]).toMatchObject({ initial: '(X := 1, Y := 2)', comment: 'A point' });
  const depth = s().history.undo.length;
  expect(s().updateDataType('Point', { initial: '(X := 1, Y := 2)' })).toBe(false);
  expect(s().history.undo.length).toBe(depth);
  s().updateDataType('Point', { initial: '' });
  expect('initial' in s().project.dataTypes![0]!).toBe(false);
  s().undo();
  expect(s().project.dataTypes![0]!.initial).toBe('(X := 1, Y := 2)');
});
