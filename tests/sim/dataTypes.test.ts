// The simulator's names of data type leaves: the watch table and scenarios name struct members and
// array elements by path (`P.X`, `A[2]`, `Main.P.X`) and get their elementary types.
import { describe, expect, it } from 'vitest';
import { newPou, newProject, variable } from '../../src/model/factory';
import { describeName } from '../../src/sim/layout';

describe('names of data type leaves', () => {
  it('describes struct members, array elements and alias variables by their elementary type', () => {
    const main = newPou('Main', {
      variables: [variable('P', 'Point'), variable('A', 'ARRAY[1..3] OF Point'), variable('Lamp', 'HMI_BOOL', { location: '%QX0.0' })],
    });
    const project = {
      ...newProject('T', { pous: [main] }),
      dataTypes: [{ name: 'Point', def: { kind: 'struct' as const, members: [{ name: 'X', type: 'INT' }, { name: 'On', type: 'BOOL' }] } }],
    };
    expect(describeName(project, main, 'P.X')).toMatchObject({ name: 'P.X', type: 'INT', role: 'local' });
    expect(describeName(project, main, 'A[2].On')).toMatchObject({ type: 'BOOL' });
    expect(describeName(project, main, 'Lamp')).toMatchObject({ type: 'BOOL', role: 'output' });
    expect(describeName(project, main, 'A[4].On')).toBeUndefined();
    expect(describeName(project, main, 'P.Z')).toBeUndefined();
  });
});
