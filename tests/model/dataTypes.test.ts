import { describe, expect, it } from 'vitest';
import {
  checkDataTypes,
  enumValues,
  formatInitial,
  leafPaths,
  parseInitial,
  resolveType,
} from '../../src/model/dataTypes';
import type { DataType, Project } from '../../src/model/project';

const types: DataType[] = [
  { name: 'Color', def: { kind: 'enum', values: ['RED', 'GREEN', 'BLUE'] }, initial: 'GREEN' },
  {
    name: 'Point',
    def: { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'Y', type: 'INT', initial: '5' }] },
  },
  { name: 'Grid', def: { kind: 'array', dims: [{ lower: 1, upper: 2 }, { lower: 0, upper: 2 }], of: 'INT' } },
  { name: 'Percent', def: { kind: 'subrange', base: 'INT', lower: 0, upper: 100 }, initial: '10' },
  { name: 'Speed', def: { kind: 'alias', base: 'Percent' } },
  {
    name: 'Shape',
    def: {
      kind: 'struct',
      members: [
        { name: 'Pts', type: 'ARRAY[1..2] OF Point' },
        { name: 'Fill', type: 'Color' },
      ],
    },
  },
];
const project = { dataTypes: types, pous: [] } as unknown as Project;

describe('resolving data type names', () => {
  it('resolves aliases to their base, keeps FB types and reports unknown names and cycles', () => {
    const speed = resolveType(project, 'Speed');
    expect(speed.ok && speed.shape.kind === 'subrange' && speed.shape.base).toBe('INT');
    expect(resolveType(project, 'TON')).toEqual({ ok: true, shape: { kind: 'fb', name: 'TON' } });
    expect(resolveType(project, 'STRING[20]')).toMatchObject({ ok: true, shape: { kind: 'elementary', type: 'STRING' } });
    expect(resolveType(project, 'HMI_BOOL')).toMatchObject({ ok: true, shape: { kind: 'elementary', type: 'BOOL' } });
    expect(resolveType(project, 'Nope')).toMatchObject({ ok: false, message: expect.stringContaining('"Nope" is not a type') });
    const cyclic = {
      pous: [],
      dataTypes: [
        { name: 'A', def: { kind: 'struct', members: [{ name: 'B', type: 'B' }] } },
        { name: 'B', def: { kind: 'alias', base: 'A' } },
      ],
    } as unknown as Project;
    expect(resolveType(cyclic, 'A')).toMatchObject({ ok: false, message: expect.stringContaining('A -> B -> A') });
    expect(checkDataTypes(cyclic).map((e) => e.name)).toEqual(['A', 'B']);
  });

  it('lists enum values', () => {
    expect(enumValues(project, 'color')).toEqual(['RED', 'GREEN', 'BLUE']);
    expect(enumValues(project, 'Point')).toBeUndefined();
  });
});

describe('leaf paths of a variable', () => {
  it('expands structs, multi-dimensional arrays and nested arrays of structs with their initial values', () => {
    const p = leafPaths(project, { name: 'P', type: 'Point', initial: '(X := 1)' });
    expect(p.ok && p.leaves.map((l) => [l.path, l.type, l.initial])).toEqual([
      ['P.X', 'INT', '1'],
      ['P.Y', 'INT', '5'],
    ]);
    const g = leafPaths(project, { name: 'G', type: 'Grid', initial: '[2(7), 4(1)]' });
    expect(g.ok && g.leaves.map((l) => `${l.path}=${l.initial}`)).toEqual([
      'G[1,0]=7', 'G[1,1]=7', 'G[1,2]=1', 'G[2,0]=1', 'G[2,1]=1', 'G[2,2]=1',
    ]);
    const s = leafPaths(project, { name: 'S', type: 'Shape', initial: '(Pts := [(X := 3), (Y := 4)])' });
    expect(s.ok && s.leaves.map((l) => `${l.path}:${l.typeName}=${l.initial ?? ''}`)).toEqual([
      'S.Pts[1].X:INT=3', 'S.Pts[1].Y:INT=5', 'S.Pts[2].X:INT=', 'S.Pts[2].Y:INT=4', 'S.Fill:Color=GREEN',
    ]);
  });

  it('gives one leaf for elementary, enum and subrange variables, with range and values', () => {
    const v = leafPaths(project, { name: 'V', type: 'Speed' });
    expect(v.ok && v.leaves).toEqual([{ path: 'V', type: 'INT', typeName: 'Speed', range: { lower: 0, upper: 100 }, initial: '10' }]);
    const c = leafPaths(project, { name: 'C', type: 'Color', initial: 'BLUE' });
    expect(c.ok && c.leaves[0]).toMatchObject({ enumValues: ['RED', 'GREEN', 'BLUE'], initial: 'BLUE' });
  });

  it('reports initial values that do not fit the type', () => {
    expect(leafPaths(project, { name: 'G', type: 'Grid', initial: '[7(0)]' })).toMatchObject({ ok: false, message: expect.stringContaining('gives 7 elements') });
    expect(leafPaths(project, { name: 'P', type: 'Point', initial: '(Z := 1)' })).toMatchObject({ ok: false, message: expect.stringContaining('no member Z') });
    expect(leafPaths(project, { name: 'P', type: 'Point', initial: '3' })).toMatchObject({ ok: false });
  });
});

describe('initial value texts', () => {
  it('reads repetitions, structures and strings with commas and writes them back', () => {
    const v = parseInitial("[32(0), 30(1), 2((X := 'a,b', Y := 2)), 3()]");
    expect('error' in v).toBe(false);
    expect(formatInitial(v as never)).toBe("[32(0), 30(1), 2((X := 'a,b', Y := 2)), 3()]");
    expect(parseInitial('[1, 2')).toMatchObject({ error: expect.any(String) });
  });

  it('checks declared types: empty ranges, duplicate enum values, bad enum initial values, non-integer subranges', () => {
    const bad = {
      pous: [],
      dataTypes: [
        { name: 'E', def: { kind: 'enum', values: ['A', 'a'] } },
        { name: 'R', def: { kind: 'subrange', base: 'INT', lower: 5, upper: 1 } },
        { name: 'Q', def: { kind: 'enum', values: ['A'] }, initial: 'B' },
        { name: 'F', def: { kind: 'subrange', base: 'REAL', lower: 0, upper: 10 } },
      ],
    } as unknown as Project;
    const msgs = checkDataTypes(bad).map((e) => `${e.name}: ${e.message}`);
    expect(msgs).toEqual([
      'E: the enumeration E has the value a twice',
      'R: the subrange R (5..1) is empty',
      'Q: Q: B is not a value of Q (A)',
      'F: the subrange F must be of an integer type, not REAL',
    ]);
  });
});
