import { expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Network, Project, Variable } from '../../src/model/project';
import { createDocumentStore } from '../../src/store/documentStore';
import {
  copyNetworks,
  networkClipText,
  nextFreeName,
  parseNetworkClip,
} from '../../src/store/networkUnits';

const v = (name: string, type: string): Variable => ({ name, type, varClass: 'local', retain: false, comment: '' });
let k = 0;
const id = () => `t${k++}` as ElementId;
const contact = (variable: string, col = 0): LdElement => ({ kind: 'contact', contact: 'NO', variable, id: id(), row: 0, col });
const coil = (variable: string, col = 6): LdElement => ({ kind: 'coil', coil: 'COIL', variable, id: id(), row: 0, col });
const ton = (instance: string): LdElement => ({
  kind: 'box',
  blockType: 'TON',
  instance,
  id: id(),
  row: 0,
  col: 1,
  inputs: { PT: 'T#2s' },
  outputs: { Q: 'Lamp' },
});
const jump = (target: string): LdElement => ({ kind: 'jump', target, id: id(), row: 0, col: 1 });

/** A 3-network program: a timer call, a jump back to a label, a coil. */
function machine(): Project {
  const main = newPou('Main');
  const networks: Network[] = [
    newNetwork({ title: 'Start delay', comment: 'waits 2 s', elements: [contact('Start'), ton('Timer1')] }),
    newNetwork({ title: 'Loop', label: 'Again', collapsed: true, elements: [contact('Run'), jump('Again')] }),
    newNetwork({ title: 'Motor', elements: [contact('Lamp'), coil('Motor')] }),
  ];
  return newProject('m', {
    pous: [
      {
        ...main,
        variables: [v('Start', 'BOOL'), v('Run', 'BOOL'), v('Lamp', 'BOOL'), v('Motor', 'BOOL'), v('Timer1', 'TON')],
        networks,
      },
      { ...newPou('Other'), networks: [newNetwork()] },
    ],
  });
}

const ids = (p: Project, pou = 0) => p.pous[pou]!.networks.map((n) => n.id);

test('next free names count on from a trailing number', () => {
  expect(nextFreeName('Timer1', new Set(['TIMER1']))).toBe('Timer2');
  expect(nextFreeName('Timer1', new Set(['TIMER1', 'TIMER2']))).toBe('Timer3');
  expect(nextFreeName('Loop', new Set(['LOOP']))).toBe('Loop2');
  expect(nextFreeName('10', new Set(['10']))).toBe('11');
});

test('copied networks keep title, comment, label and collapsed state through clipboard text', () => {
  const p = machine();
  const clip = copyNetworks(p.pous[0]!, ids(p))!;
  const back = parseNetworkClip(networkClipText(clip))!;
  expect(back.networks.map((n) => [n.title, n.comment, n.label, n.collapsed ?? false])).toEqual([
    ['Start delay', 'waits 2 s', undefined, false],
    ['Loop', '', 'Again', true],
    ['Motor', '', undefined, false],
  ]);
  expect(back.variables.map((x) => x.name).sort()).toEqual(['Lamp', 'Motor', 'Run', 'Start', 'Timer1']);
  expect(parseNetworkClip('{"format":"rungsmith-networks","version":1,"networks":[{"id":1}]}')).toBeUndefined();
  expect(parseNetworkClip('plain text')).toBeUndefined();
});

test('pasting into the same POU with new instances: Timer2 declared, label renamed, jump follows, one undo', () => {
  const store = createDocumentStore(machine());
  const p0 = store.getState().project;
  const clip = copyNetworks(p0.pous[0]!, ids(p0))!;
  const pasted = store.getState().pasteNetworks(p0.pous[0]!.id, 3, clip, 'new');
  const pou = store.getState().project.pous[0]!;
  expect(pasted).toHaveLength(3);
  expect(pou.networks).toHaveLength(6);
  const box = pou.networks[3]!.elements.find((e) => e.kind === 'box');
  expect(box && box.kind === 'box' && box.instance).toBe('Timer2');
  expect(pou.variables.find((x) => x.name === 'Timer2')?.type).toBe('TON');
  expect(pou.networks[4]!.label).toBe('Again2');
  const j = pou.networks[4]!.elements.find((e) => e.kind === 'jump');
  expect(j && j.kind === 'jump' && j.target).toBe('Again2');
  expect(pou.networks[4]!.collapsed).toBe(true);
  // The original keeps its label and jump.
  expect(pou.networks[1]!.label).toBe('Again');
  expect(checkProject(store.getState().project).filter((d) => d.severity === 'error')).toEqual([]);
  store.getState().undo();
  expect(store.getState().project.pous[0]!.networks).toHaveLength(3);
  expect(store.getState().project.pous[0]!.variables.some((x) => x.name === 'Timer2')).toBe(false);
});

test('keeping the instance calls it twice: a warning (LD-R10), not an error', () => {
  const store = createDocumentStore(machine());
  const p0 = store.getState().project;
  const clip = copyNetworks(p0.pous[0]!, [p0.pous[0]!.networks[0]!.id])!;
  store.getState().pasteNetworks(p0.pous[0]!.id, 1, clip, 'keep');
  const pou = store.getState().project.pous[0]!;
  const boxes = pou.networks.flatMap((n) => n.elements).filter((e) => e.kind === 'box');
  expect(boxes.map((b) => b.kind === 'box' && b.instance)).toEqual(['Timer1', 'Timer1']);
  const diags = checkProject(store.getState().project);
  expect(diags.filter((d) => d.severity === 'error')).toEqual([]);
  expect(diags.some((d) => d.rule === 'LD-R10' && d.severity === 'warning')).toBe(true);
});

test('pasting into another POU declares what it uses; a jump to a label left behind keeps its text', () => {
  const store = createDocumentStore(machine());
  const p0 = store.getState().project;
  const clip = copyNetworks(p0.pous[0]!, [p0.pous[0]!.networks[0]!.id, p0.pous[0]!.networks[1]!.id])!;
  const text = networkClipText(clip);
  // another project, through text
  const other = createDocumentStore(newProject('other'));
  const target = other.getState().project.pous[0]!;
  other.getState().pasteNetworks(target.id, 0, parseNetworkClip(text)!, 'new');
  const pou = other.getState().project.pous[0]!;
  expect(pou.networks.map((n) => n.title)).toEqual(['Start delay', 'Loop', '']);
  expect(pou.variables.map((x) => x.name).sort()).toEqual(['Lamp', 'Run', 'Start', 'Timer1']);
  // Only network 2 (the jump) without its label's network: the jump keeps "Again".
  const clip2 = copyNetworks(p0.pous[0]!, [p0.pous[0]!.networks[1]!.id])!;
  const cut = { ...clip2, networks: clip2.networks.map((n) => ({ ...n, label: undefined })) };
  const otherPou = p0.pous[1]!;
  store.getState().pasteNetworks(otherPou.id, 0, cut, 'new');
  const j = store.getState().project.pous[1]!.networks[0]!.elements.find((e) => e.kind === 'jump');
  expect(j && j.kind === 'jump' && j.target).toBe('Again');
});

test('duplicate, delete, move up/down and move to a place act on sets of networks, one undo step each', () => {
  const store = createDocumentStore(machine());
  const s = () => store.getState();
  const titles = () => s().project.pous[0]!.networks.map((n) => n.title);
  const [a, b, c] = ids(s().project);
  s().duplicateNetworks([a!, b!], 'new');
  expect(titles()).toEqual(['Start delay', 'Loop', 'Start delay', 'Loop', 'Motor']);
  s().undo();
  expect(s().moveNetworks([b!, c!], -1)).toBe(true);
  expect(titles()).toEqual(['Loop', 'Motor', 'Start delay']);
  expect(s().moveNetworks([b!], -1)).toBe(false);
  s().undo();
  expect(titles()).toEqual(['Start delay', 'Loop', 'Motor']);
  expect(s().moveNetworks([a!, b!], 1)).toBe(true);
  expect(titles()).toEqual(['Motor', 'Start delay', 'Loop']);
  s().undo();
  expect(s().moveNetworksTo([a!, b!], 0)).toBe(false);
  expect(s().moveNetworksTo([a!, c!], 0)).toBe(true);
  expect(titles()).toEqual(['Start delay', 'Motor', 'Loop']);
  s().undo();
  expect(s().moveNetworksTo([c!], 0)).toBe(true);
  expect(titles()).toEqual(['Motor', 'Start delay', 'Loop']);
  s().undo();
  s().deleteNetworks([a!, c!]);
  expect(titles()).toEqual(['Loop']);
  s().undo();
  expect(titles()).toEqual(['Start delay', 'Loop', 'Motor']);
  s().setCollapsed('all', true);
  expect(s().project.pous[0]!.networks.every((n) => n.collapsed)).toBe(true);
  s().setCollapsed('all', false);
  expect(s().project.pous[0]!.networks.some((n) => n.collapsed)).toBe(false);
});

test("a pasted copy of an imported network drops Beremiz's turns (its elements are new; it must not join the original's group)", () => {
  const p = machine();
  const motor = p.pous[0]!.networks[2]!;
  const turned = { ...motor, turns: { [motor.elements[1]!.id]: 4 } };
  const store = createDocumentStore({ ...p, pous: [{ ...p.pous[0]!, networks: [...p.pous[0]!.networks.slice(0, 2), turned] }, p.pous[1]!] });
  const p0 = store.getState().project;
  store.getState().pasteNetworks(p0.pous[0]!.id, 3, copyNetworks(p0.pous[0]!, [turned.id])!, 'new');
  const nets = store.getState().project.pous[0]!.networks;
  expect(nets).toHaveLength(4);
  expect(nets[2]!.turns).toEqual(turned.turns);
  expect(nets[3]!.turns).toBeUndefined();
});
