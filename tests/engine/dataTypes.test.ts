import { describe, expect, it } from 'vitest';
import type { DataType, Project } from '../../src/model/project';
import { ladder, plcOf, project, trace, vars } from './ladder';

const TYPES: DataType[] = [
  { name: 'Color', def: { kind: 'enum', values: ['RED', 'GREEN', 'BLUE'] }, initial: 'GREEN' },
  {
    name: 'Valve',
    def: {
      kind: 'struct',
      members: [
        { name: 'Open', type: 'BOOL' },
        { name: 'Cmd', type: 'BOOL' },
        { name: 'Pos', type: 'INT', initial: '5' },
      ],
    },
  },
  { name: 'Grid', def: { kind: 'array', dims: [{ lower: 1, upper: 2 }, { lower: 1, upper: 3 }], of: 'BOOL' } },
  { name: 'Percent', def: { kind: 'subrange', base: 'INT', lower: 0, upper: 100 } },
];

const withTypes = (p: Project, types: readonly DataType[] = TYPES): Project => ({ ...p, dataTypes: types });

describe('data types in LD', () => {
  it('contacts, coils and pins name struct members and array elements with constant indexes', () => {
    const p = withTypes(
      project(vars('V Valve', 'G Grid', 'Lamp BOOL'), [
        ladder(['[V.Cmd] - (V.Open)']),
        ladder(['[G[2,3]] - (Lamp)']),
      ]),
    );
    const plc = plcOf(p);
    expect(plc.read('V.Pos')).toBe(5);
    expect(trace(plc, [{}, { 'V.Cmd': true }, { 'G[2,3]': true }], ['V.Open', 'Lamp'])).toEqual([
      [0, 0],
      [1, 0],
      [1, 1],
    ]);
  });
});
