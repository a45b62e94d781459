import { expect, test } from 'vitest';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Project, Variable } from '../../src/model/project';
import { createDocumentStore } from '../../src/store/documentStore';
import { applyReplacements, findInProject, planReplace, type FindHit } from '../../src/store/find';
import { crossReference, unusedVariables, writtenInSeveralPlaces } from '../../src/store/xref';

const v = (name: string, type: string): Variable => ({ name, type, varClass: 'local', retain: false, comment: '' });
let k = 0;
const id = () => `f${k++}` as ElementId;
const contact = (variable: string, col = 0, row = 0): LdElement => ({ kind: 'contact', contact: 'NO', variable, id: id(), row, col });
const coil = (variable: string, c: 'COIL' | 'SET' = 'COIL', row = 0): LdElement => ({ kind: 'coil', coil: c, variable, id: id(), row, col: 6 });

function plant(): Project {
  const main = newPou('Main');
  const aux = newPou('Aux');
  return newProject('p', {
    globals: [v('Alarm', 'BOOL')],
    pous: [
      {
        ...main,
        variables: [v('Start', 'BOOL'), v('Motor', 'BOOL'), v('Timer1', 'TON'), v('Spare', 'INT'), v('Timer10', 'TON')],
        networks: [
          newNetwork({
            title: 'Start the motor',
            comment: 'Timer1 delays the start',
            elements: [
              contact('Start'),
              { kind: 'box', blockType: 'TON', instance: 'Timer1', id: id(), row: 0, col: 1, inputs: { PT: 'T#5s' }, outputs: {} },
              coil('Motor'),
            ],
          }),
          newNetwork({ title: 'Hold', label: 'Hold', elements: [contact('Timer1.Q'), coil('Motor', 'SET'), contact('Timer10.Q', 0, 1), coil('Alarm', 'COIL', 1)] }),
        ],
      },
      { ...aux, networks: [newNetwork({ title: 'Alarm lamp', elements: [contact('Alarm'), coil('Alarm', 'SET')] })] },
    ],
  });
}

const hits = (p: Project, q: Parameters<typeof findInProject>[1]) => findInProject(p, q) as FindHit[];

test('find covers variables, literals, comments and titles in every POU, with network and element', () => {
  const p = plant();
  const h = hits(p, { text: 'timer1', mode: 'text' });
  // comment, box instance, Timer1.Q contact, and Timer10.Q (substring)
  expect(h.map((x) => [x.pouName, x.networkIndex, x.field, x.elementKind ?? '-'])).toEqual([
    ['Main', 0, 'comment', '-'],
    ['Main', 0, 'variable', 'box'],
    ['Main', 1, 'variable', 'contact'],
    ['Main', 1, 'variable', 'contact'],
  ]);
  expect(hits(p, { text: 'Timer1', mode: 'word' })).toHaveLength(3);
  expect(hits(p, { text: 'T#5s', mode: 'text' }).map((x) => [x.field, x.pin])).toEqual([['literal', 'PT']]);
  expect(hits(p, { text: 'alarm', mode: 'text' }).map((x) => x.pouName)).toEqual(['Main', 'Aux', 'Aux', 'Aux']);
  expect(hits(p, { text: 'Alarm', mode: 'text', caseSensitive: true, fields: ['title'] })).toHaveLength(1);
  expect(findInProject(p, { text: '(', mode: 'regex' })).toMatch(/Not a valid pattern/);
});

test('replace a whole name: preview lists every place, applying is one undo step', () => {
  const store = createDocumentStore(plant());
  const p = store.getState().project;
  const plan = planReplace(p, { text: 'Timer1', mode: 'word' }, 'Delay1');
  if (typeof plan === 'string') throw new Error(plan);
  expect(plan.map((r) => `${r.before} -> ${r.after}`)).toEqual([
    'Timer1 delays the start -> Delay1 delays the start',
    'Timer1 -> Delay1',
    'Timer1.Q -> Delay1.Q',
  ]);
  store.getState().replaceNetworks('replace', applyReplacements(p, plan));
  expect(hits(store.getState().project, { text: 'Timer1', mode: 'word' })).toHaveLength(0);
  expect(hits(store.getState().project, { text: 'Timer10', mode: 'word' })).toHaveLength(1);
  store.getState().undo();
  expect(hits(store.getState().project, { text: 'Timer1', mode: 'word' })).toHaveLength(3);
  // A pattern with a group.
  const re = planReplace(p, { text: 'Timer(\\d+)\\.Q', mode: 'regex' }, 'T$1.Q');
  expect(typeof re !== 'string' && re.map((r) => r.after)).toEqual(['T1.Q', 'T10.Q']);
});

test('cross-reference lists every use with POU, network, element kind and access', () => {
  const p = plant();
  const main = p.pous[0]!;
  expect(crossReference(p, main.id, 'Timer1').map((u) => [u.networkIndex, u.elementKind, u.pin ?? '', u.access])).toEqual([
    [0, 'box', 'instance', 'call'],
    [1, 'contact', '', 'read'],
  ]);
  expect(crossReference(p, main.id, 'Motor').map((u) => [u.detail, u.access])).toEqual([
    ['COIL', 'write'],
    ['SET', 'write'],
  ]);
  // A global is used in every POU that does not shadow it.
  expect(crossReference(p, 'globals', 'Alarm').map((u) => [u.pouName, u.access])).toEqual([
    ['Main', 'write'],
    ['Aux', 'read'],
    ['Aux', 'write'],
  ]);
  expect(unusedVariables(p).map((s) => s.variable.name)).toEqual(['Spare']);
  expect(writtenInSeveralPlaces(p).map((s) => `${s.variable.name}:${s.writers}`)).toEqual(['Alarm:2', 'Motor:2']);
});
