import { expect, test } from 'vitest';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { LdElement } from '../../src/model/elements';
import { undeclaredVariables } from '../../src/editor/variables/undeclared';

type Loose<T> = T extends unknown ? Omit<T, 'id'> & { id: string } : never;
const e = (x: Loose<LdElement>) => x as LdElement;

test('names used on the canvas but not declared get the type their first use implies', () => {
  const elements = [
    e({ id: 'a', kind: 'contact', contact: 'NO', variable: 'Start', row: 0, col: 0 }),
    e({ id: 'b', kind: 'contact', contact: 'NC', variable: 'stop', row: 0, col: 1 }),
    e({
      id: 'c',
      kind: 'box',
      blockType: 'CTU',
      instance: 'Parts',
      inputs: { R: 'Reset', PV: 'Preset' },
      outputs: { CV: 'Count' },
      row: 0,
      col: 2,
    }),
    e({
      id: 'd',
      kind: 'box',
      blockType: 'TON',
      instance: 'T1',
      inputs: { PT: 'T#5s' },
      outputs: {},
      row: 0,
      col: 5,
    }),
    e({ id: 'f', kind: 'contact', contact: 'NO', variable: 'T1.Q', row: 1, col: 0 }),
    e({ id: 'g', kind: 'coil', coil: 'COIL', variable: 'START', row: 1, col: 1 }),
    e({ id: 'h', kind: 'coil', coil: 'COIL', variable: 'Lamp', row: 1, col: 9 }),
    e({ id: 'i', kind: 'contact', contact: 'NOT', variable: '', row: 2, col: 0 }),
  ];
  const pou = newPou('Main', {
    variables: [variable('Stop', 'BOOL')],
    networks: [newNetwork({ rows: 3, cols: 10, elements })],
  });
  const project = newProject('p', {
    pous: [pou],
    globals: [variable('Lamp', 'BOOL', { location: '%QX0.0' })],
  });
  expect(undeclaredVariables(project, pou).map((v) => `${v.name}:${v.type}`)).toEqual([
    'Start:BOOL',
    'Parts:CTU',
    'Reset:BOOL',
    'Preset:INT',
    'Count:INT',
    'T1:TON',
  ]);
});
