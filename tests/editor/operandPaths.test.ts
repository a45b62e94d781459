// Operands naming a struct member or an array element (P.X, A[3]): accepted, typed, offered by
// completion after "P.", and wrong paths explained.
import { expect, test } from 'vitest';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { LdElement } from '../../src/model/elements';
import { undeclaredVariables } from '../../src/editor/variables/undeclared';
import type { Project } from '../../src/model/project';
import { candidatesFor, describeLiteral, pinRole, rankCandidates, resolveName } from '../../src/editor/inspector/operands';
import { pouVariableUses } from '../../src/editor/variables/usage';

function project(): Project {
  const p = newProject('P');
  return {
    ...p,
    dataTypes: [
      { name: 'Color', def: { kind: 'enum', values: ['RED', 'GREEN'] } },
      { name: 'Point', def: { kind: 'struct', members: [{ name: 'X', type: 'INT' }, { name: 'Y', type: 'INT' }, { name: 'On', type: 'BOOL' }, { name: 'C', type: 'Color' }] } },
    ],
    pous: [{ ...p.pous[0]!, variables: [variable('P', 'Point'), variable('A', 'ARRAY[1..3] OF BOOL'), variable('G', 'ARRAY[1..2, 0..1] OF INT'), variable('N', 'INT')] }],
  };
}

test('P.X, A[3] and G[1, 0] resolve to the member type; wrong members and indexes say why', () => {
  const p = project();
  const pou = p.pous[0]!;
  expect(resolveName(p, pou, 'P.X')).toEqual({ status: 'declared', type: 'INT' });
  expect(resolveName(p, pou, 'p.on')).toEqual({ status: 'declared', type: 'BOOL' });
  expect(resolveName(p, pou, 'P.C')).toEqual({ status: 'declared', type: 'Color' });
  expect(resolveName(p, pou, 'A[3]')).toEqual({ status: 'declared', type: 'BOOL' });
  expect(resolveName(p, pou, 'G[1, 0]')).toEqual({ status: 'declared', type: 'INT' });
  expect(resolveName(p, pou, 'P.Z')).toMatchObject({ status: 'other', message: expect.stringMatching(/has no value \.Z/) });
  expect(resolveName(p, pou, 'A[4]')).toMatchObject({ status: 'other', message: expect.stringMatching(/has no value \[4\]/) });
  expect(resolveName(p, pou, 'G[1]')).toMatchObject({ status: 'other', message: expect.stringMatching(/e\.g\. G\[1,0\]/) });
  // Plain names and bits of words are as before.
  expect(resolveName(p, pou, 'N.3')).toEqual({ status: 'declared', type: 'BOOL' });
  expect(describeLiteral('A[3]', 'BOOL')).toBeUndefined();
});

test('completion offers the members that fit after "P."', () => {
  const p = project();
  const pou = p.pous[0]!;
  const contact = rankCandidates('P.', candidatesFor(p, pou, { kind: 'contact' })).map((c) => c.text);
  expect(contact).toEqual(['P.On']);
  const pin = rankCandidates('P.', candidatesFor(p, pou, { kind: 'pin', pinType: 'ANY_INT', direction: 'output' })).map((c) => c.text);
  expect(pin).toEqual(['P.X', 'P.Y']);
  const bits = rankCandidates('A', candidatesFor(p, pou, { kind: 'coil' })).map((c) => c.text);
  expect(bits).toEqual(['A[1]', 'A[2]', 'A[3]']);
});

test('a member operand counts as a use of its variable', () => {
  const p = project();
  const pou = p.pous[0]!;
  const net = pou.networks[0]!;
  const withUse: Project = {
    ...p,
    pous: [{ ...pou, networks: [{ ...net, elements: [{ id: 'e1' as never, kind: 'contact', contact: 'NO', variable: 'A[2]', row: 0, col: 0 }] }] }],
  };
  expect(pouVariableUses(withUse.pous[0]!).get('A')).toHaveLength(1);
});

test("an operand on a user block's pin declared with a data type is declared with that type", () => {
  const p = project();
  const fb = newPou('Plot', { kind: 'FUNCTION_BLOCK', variables: [variable('Pt', 'Point', { varClass: 'input' })] });
  const box = {
    id: 'b1', kind: 'box', blockType: 'Plot', instance: 'Plot1', inputs: { Pt: 'Here' }, outputs: {}, row: 0, col: 1,
  } as unknown as LdElement;
  const main = { ...p.pous[0]!, networks: [newNetwork({ rows: 4, cols: 8, elements: [box] })] };
  const withCall: Project = { ...p, pous: [main, fb] };
  expect(undeclaredVariables(withCall, main).map((v) => `${v.name} : ${v.type}`)).toEqual(['Plot1 : Plot', 'Here : Point']);
  const offered = candidatesFor(withCall, main, pinRole({ name: 'Pt', type: 'ANY', declaredType: 'Point' } as never, 'input'));
  expect(offered.map((c) => c.text)).toEqual(['P']);
});
