// The change list an online change applied on request shows (issue 24): running document against
// the shown one, networks by id, variables by name; titles and comments are no change.
import { describe, expect, test } from 'vitest';
import { variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { changedNetworkIds, changeList, describeChanges } from '../../src/sim/changeList';
import { ladder, project, vars } from '../engine/ladder';

function plant(): Project {
  return project(vars('Start BOOL', 'Stop BOOL', 'Motor BOOL', 'Lamp BOOL', 'T1 TON'), [ladder(['[Start] (Motor)']), ladder(['[Stop] (Lamp)']), ladder(['[Motor] (Lamp)'])]);
}

const editPou = (p: Project, f: (pou: Project['pous'][number]) => Project['pous'][number]): Project => ({ ...p, pous: [f(p.pous[0]!), ...p.pous.slice(1)] });

describe('changeList', () => {
  test('the same document, or one with only a title and a comment changed, has no changes', () => {
    const p = plant();
    expect(changeList(p, p).count).toBe(0);
    const commented = editPou(p, (pou) => ({ ...pou, networks: pou.networks.map((n, i) => (i === 1 ? { ...n, title: 'Stop lamp', comment: 'why' } : n)) }));
    expect(changeList(p, commented).count).toBe(0);
    expect(changedNetworkIds(p, commented).size).toBe(0);
  });

  test('a changed network, an added one, a removed one and a new variable, numbered as the user sees them', () => {
    const p = plant();
    const nets = p.pous[0]!.networks;
    const changed = { ...nets[0]!, elements: nets[0]!.elements.map((e) => (e.kind === 'contact' ? { ...e, variable: 'Stop' } : e)) };
    const added = ladder(['[Start] (Horn)']);
    const after = editPou(p, (pou) => ({ ...pou, variables: [...pou.variables, variable('Horn', 'BOOL')], networks: [changed, nets[1]!, added] }));
    const c = changeList(p, after);
    expect(c.pous).toHaveLength(1);
    expect(c.pous[0]).toMatchObject({ changed: [1], added: [3], removed: [3], newVariables: ['Horn'], removedVariables: [], changedVariables: [] });
    expect(c.count).toBe(4);
    expect(describeChanges(c)).toEqual([`${p.pous[0]!.name}: network changed: 1; network added: 3; network removed: 3; new variables: Horn`]);
    expect([...changedNetworkIds(p, after)].sort()).toEqual([changed.id, added.id].sort());
  });

  test('a retyped variable, a global added and networks swapped are changes', () => {
    const p = plant();
    const nets = p.pous[0]!.networks;
    const after: Project = {
      ...editPou(p, (pou) => ({ ...pou, variables: pou.variables.map((v) => (v.name === 'T1' ? { ...v, type: 'TOF' } : v)), networks: [nets[1]!, nets[0]!, nets[2]!] })),
      globals: [variable('Alarm', 'BOOL')],
    };
    const c = changeList(p, after);
    expect(c.pous[0]!.changedVariables).toEqual(['T1: TON → TOF']);
    expect(c.pous[0]!.changed).toEqual([1, 2]);
    expect(c.globals.newVariables).toEqual(['Alarm']);
    expect(describeChanges(c)).toContain('Global variables: new: Alarm');
  });
});
