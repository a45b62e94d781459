// `rungsmith simulate --watch` over variables of user data types: struct members and array
// elements by path, and the default watch listing their leaves.
import { describe, expect, it } from 'vitest';
import { newPou, newProject, variable } from '../../src/model/factory';
import { saveProject } from '../../src/model/load';
import { rungsmith } from './memoryIo';

function typedProject(): string {
  const main = newPou('Main', {
    language: 'ST',
    networks: [],
    source: 'P.X := P.X + 1; A[P.X] := P.X * 10; G[1, 2] := NOT G[1, 2];',
    variables: [variable('P', 'Point'), variable('A', 'ARRAY[1..3] OF INT'), variable('G', 'ARRAY[1..1, 1..2] OF BOOL')],
  });
  return saveProject({
    ...newProject('Typed', { pous: [main] }),
    dataTypes: [{ name: 'Point', def: { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'Y', type: 'INT', initial: '4' }] } }],
  });
}

describe('rungsmith simulate with data types', () => {
  it('--watch names struct members and array elements (commas inside brackets belong to the index)', () => {
    const r = rungsmith(['simulate', 'p.json', '--watch', 'P.X,A[2],G[1,2]', '--scans', '3'], { 'p.json': typedProject() });
    expect(r.err).toBe('');
    // A name holding a comma is quoted, as CSV needs.
    expect(r.out.split('\n')).toEqual(['scan,time_ms,P.X,A[2],"G[1,2]"', '1,0,1,0,1', '2,10,2,20,0', '3,20,3,20,1', '']);
  });

  it('the default watch lists every leaf of struct and array variables', () => {
    const r = rungsmith(['simulate', 'p.json', '--scans', '1'], { 'p.json': typedProject() });
    expect(r.out.split('\n')[0]).toBe('scan,time_ms,P.X,P.Y,A[1],A[2],A[3],"G[1,1]","G[1,2]"');
    expect(r.out.split('\n')[1]).toBe('1,0,1,4,10,0,0,0,1');
  });
});
