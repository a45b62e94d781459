// The watch table's tree of a structure/array variable's members, the struct/array variables
// offered for watching, and enumeration values shown by name.
import { expect, test } from 'vitest';
import { newProject, variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import type { SimVariable } from '../../src/sim/protocol';
import { aggregateCandidates, enumText, leafCount, modelLeaf, watchTree } from '../../src/editor/sim/watchTree';

const leaf = (name: string, type = 'INT'): SimVariable => ({ name, type, role: 'local' });

function project(): Project {
  const p = newProject('P');
  const main = p.pous[0]!;
  return {
    ...p,
    dataTypes: [
      { name: 'Color', def: { kind: 'enum', values: ['RED', 'GREEN', 'BLUE'] } },
      { name: 'Point', def: { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'C', type: 'Color' }] } },
      { name: 'Line', def: { kind: 'struct', members: [{ name: 'Pts', type: 'ARRAY[1..2] OF Point' }] } },
    ],
    pous: [{ ...main, variables: [variable('L', 'Line'), variable('P', 'Point'), variable('T1', 'TON'), variable('Go', 'BOOL')] }],
  };
}

const names = ['L.Pts[1].X', 'L.Pts[1].C', 'L.Pts[2].X', 'L.Pts[2].C', 'P.X', 'P.C', 'T1.Q', 'Go'].map((n) => leaf(n));

test('a watched structure is a tree of its members: nested structures and array elements are groups', () => {
  const tree = watchTree('l', names);
  expect(tree.map((n) => n.path)).toEqual(['l.Pts']);
  const pts = tree[0]!.children;
  expect(pts.map((n) => n.label)).toEqual(['[1]', '[2]']);
  expect(pts[0]!.children.map((n) => [n.path, n.leaf?.name])).toEqual([
    ['l.Pts[1].X', 'L.Pts[1].X'],
    ['l.Pts[1].C', 'L.Pts[1].C'],
  ]);
  expect(leafCount(tree)).toBe(4);
  expect(watchTree('Go', names)).toEqual([]);
  // P is not a prefix of an unrelated longer name.
  expect(watchTree('P', [...names, leaf('PX')]).map((n) => n.path)).toEqual(['P.X', 'P.C']);
});

test('struct and array variables are offered for watching; FB instances and plain variables are not added', () => {
  expect(aggregateCandidates(project(), names).map((c) => `${c.name} : ${c.type}`)).toEqual(['L : Line', 'P : Point']);
});

test('an enumeration leaf shows its value by name', () => {
  const p = project();
  const c = modelLeaf(p, 'L.Pts[2].C');
  expect(c?.enumValues).toEqual(['RED', 'GREEN', 'BLUE']);
  expect(enumText(c, '1')).toBe('GREEN');
  expect(enumText(modelLeaf(p, 'P.X'), '1')).toBe('1');
  expect(modelLeaf(p, 'Nope.X')).toBeUndefined();
});
