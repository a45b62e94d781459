import { expect, test } from 'vitest';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { LdElement } from '../../src/model/elements';
import type { ElementId } from '../../src/model/ids';
import { globalVariableUses, pouVariableUses } from '../../src/editor/variables/usage';

type Loose<T> = T extends unknown ? Omit<T, 'id'> & { id: string } : never;
const e = (x: Loose<LdElement>) => x as LdElement;
const elements: LdElement[] = [
  e({ id: 'c1', kind: 'contact', contact: 'NO', variable: 'start', row: 0, col: 0 }),
  e({
    id: 'b1',
    kind: 'box',
    blockType: 'TON',
    instance: 'T1',
    inputs: { PT: 'T#5s' },
    outputs: { ET: 'Elapsed' },
    row: 0,
    col: 1,
  }),
  e({ id: 'c2', kind: 'contact', contact: 'NO', variable: 'T1.Q', row: 0, col: 3 }),
  e({ id: 'k1', kind: 'coil', coil: 'COIL', variable: 'Status.3', row: 0, col: 4 }),
];

test('every reference counts as a use: plain names in any case, FB instances, pins and word bits', () => {
  const pou = newPou('Main', { networks: [newNetwork({ rows: 2, cols: 5, elements })] });
  const uses = pouVariableUses(pou);
  expect(uses.get('START')?.map((u) => u.element)).toEqual(['c1']);
  expect(uses.get('T1')?.map((u) => u.element)).toEqual(['b1', 'c2']);
  expect(uses.get('ELAPSED')?.map((u) => `${u.row},${u.col}`)).toEqual(['0,1']);
  expect(uses.get('STATUS')?.map((u) => u.element)).toEqual(['k1']);
  // A literal operand is not a use of anything.
  expect([...uses.keys()].sort()).toEqual(['ELAPSED', 'START', 'STATUS', 'T1']);
});

test('a global is not used where a POU declares the same name itself', () => {
  const net = () =>
    newNetwork({
      rows: 1,
      cols: 1,
      elements: [e({ id: 'x', kind: 'contact', contact: 'NO', variable: 'Alarm', row: 0, col: 0 })],
    });
  const shadowing = newPou('A', { variables: [variable('ALARM', 'BOOL')], networks: [net()] });
  const plain = newPou('B', { networks: [net()] });
  const uses = globalVariableUses(newProject('p', { pous: [shadowing, plain] }));
  expect(uses.get('ALARM')?.map((u) => u.pou)).toEqual([plain.id]);
  expect(uses.get('ALARM')?.[0]?.element).toBe('x' as ElementId);
});
