import { describe, expect, test } from 'vitest';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { NetworkId } from '../../src/model/ids';
import type { Project } from '../../src/model/project';
import { createDocumentStore } from '../../src/store/documentStore';
import { makeAutosaveRecord } from '../../src/editor/files/autosaveRecord';
import {
  applyPatch,
  decideRecoveryFrom,
  makeJournal,
  projectPatch,
  type Slot,
} from '../../src/editor/files/autosaveJournal';

const bigProject = (networks: number): Project =>
  newProject('Big', {
    globals: [variable('Start', 'BOOL', { location: '%IX0.0' })],
    pous: [
      newPou('Main', { networks: Array.from({ length: networks }, (_, i) => newNetwork({ title: `N${i}` })) }),
      newPou('Other'),
    ],
  });

/** IndexedDB and localStorage as the browser would hold them after these writes. */
function stored(slots: Partial<Record<Slot, unknown>>, journal?: unknown) {
  const clone = (v: unknown) => (v === undefined ? undefined : JSON.parse(JSON.stringify(v)));
  return {
    slots: { a: clone(slots.a), b: clone(slots.b) },
    journal: journal === undefined ? null : JSON.stringify(journal),
  };
}

const restored = (r: ReturnType<typeof decideRecoveryFrom>) => {
  if (r.decision.action !== 'restore') throw new Error(`expected a restore, got ${r.decision.action}`);
  return r.decision;
};

describe('autosave journal', () => {
  test('a change to one network of 10,000 journals that network only; applied, it gives the project back', () => {
    const store = createDocumentStore(bigProject(10_000));
    const base = store.getState().project;
    const target = base.pous[0]!.networks[4321]!.id;
    store.getState().updateNetwork(target, { title: 'Changed' });
    const current = store.getState().project;
    const { patch, inlineNetworks } = projectPatch(base, current);
    expect(inlineNetworks).toBe(1);
    // Runs of untouched networks, not 10,000 entries: the journal stays small.
    expect(JSON.stringify(patch).length).toBeLessThan(2_000);
    expect(applyPatch(JSON.parse(JSON.stringify(base)), patch)).toEqual(JSON.parse(JSON.stringify(current)));
  });

  test('a network edit or a new declaration in a POU of 4,000 variables journals the change, not the 4,000 variables', () => {
    const variables = Array.from({ length: 4000 }, (_, i) => variable(`V${i}`, 'BOOL', { comment: `Variable ${i}` }));
    const store = createDocumentStore(
      newProject('Vars', { pous: [newPou('Main', { variables, networks: [newNetwork(), newNetwork()] })] }),
    );
    const base = store.getState().project;
    const baseData = JSON.parse(JSON.stringify(base));
    store.getState().updateNetwork(base.pous[0]!.networks[1]!.id, { title: 'Changed' });
    const edited = store.getState().project;
    const { patch } = projectPatch(base, edited);
    expect(JSON.stringify(patch).length).toBeLessThan(2_000);
    expect(applyPatch(baseData, patch)).toEqual(JSON.parse(JSON.stringify(edited)));
    store.getState().addVariable(variable('Added', 'INT'), base.pous[0]!.id);
    const declared = store.getState().project;
    const second = projectPatch(base, declared).patch;
    expect(JSON.stringify(second).length).toBeLessThan(2_000);
    expect(applyPatch(baseData, second)).toEqual(JSON.parse(JSON.stringify(declared)));
    expect((applyPatch(baseData, second) as Project).pous[0]!.variables).toHaveLength(4001);
  });

  test('added, deleted and moved networks, a renamed project and a new global come back as they are', () => {
    const store = createDocumentStore(bigProject(50));
    const base = store.getState().project;
    const s = store.getState();
    s.insertNetwork(10, { title: 'Inserted' });
    s.deleteNetwork(base.pous[0]!.networks[30]!.id);
    s.moveNetwork(0, 40);
    s.updateProject({ name: 'Renamed' });
    s.addVariable(variable('Motor', 'BOOL', { location: '%QX0.0' }));
    const current = store.getState().project;
    const { patch } = projectPatch(base, current);
    expect(applyPatch(JSON.parse(JSON.stringify(base)), patch)).toEqual(JSON.parse(JSON.stringify(current)));
  });

  test('with no snapshot yet the journal holds the whole project', () => {
    const p = bigProject(3);
    const { patch, inlineNetworks } = projectPatch(undefined, p);
    expect(inlineNetworks).toBe(4);
    expect(applyPatch(undefined, patch)).toEqual(JSON.parse(JSON.stringify(p)));
  });

  test('recovery takes the journal on top of its snapshot: the last change and an undo survive', () => {
    const store = createDocumentStore(bigProject(20));
    const base = store.getState().project;
    const snapshot = { ...makeAutosaveRecord(base, false, 100, 'snap-1') };
    const net = base.pous[0]!.networks[0]!.id as NetworkId;
    store.getState().placeElement(net, { row: 0, col: 0 }, { kind: 'contact', contact: 'NO', variable: 'Start' });
    const placed = store.getState().project;
    const j1 = makeJournal({ slot: 'a', id: 'snap-1' }, projectPatch(base, placed).patch, true, 200);
    const r1 = restored(decideRecoveryFrom(stored({ a: snapshot }, j1)));
    expect(r1.project.pous[0]!.networks[0]!.elements.map((e) => e.kind)).toEqual(['contact']);
    expect(r1.unsavedChanges).toBe(true);

    store.getState().undo();
    const undone = store.getState().project;
    const j2 = makeJournal({ slot: 'a', id: 'snap-1' }, projectPatch(base, undone).patch, true, 300);
    const r2 = restored(decideRecoveryFrom(stored({ a: snapshot }, j2)));
    expect(r2.project.pous[0]!.networks[0]!.elements).toEqual([]);
  });

  test('a journal based on a snapshot that was since replaced is not applied; the newest snapshot is', () => {
    const p1 = bigProject(2);
    const p2 = { ...p1, name: 'Second' };
    const j = makeJournal({ slot: 'a', id: 'old' }, projectPatch(p1, { ...p1, name: 'Journal' }).patch, true, 150);
    const r = decideRecoveryFrom(
      stored({ a: makeAutosaveRecord(p1, false, 100, 'replaced'), b: makeAutosaveRecord(p2, true, 120, 'b1') }, j),
    );
    expect(restored(r).project.name).toBe('Second');
    expect(r.keepSlot).toBe('b');
  });

  test('a snapshot newer than the journal wins over it', () => {
    const p1 = bigProject(2);
    const j = makeJournal({ slot: 'a', id: 'a1' }, projectPatch(p1, { ...p1, name: 'Journal' }).patch, true, 150);
    const r = decideRecoveryFrom(
      stored({ a: makeAutosaveRecord(p1, false, 100, 'a1'), b: makeAutosaveRecord({ ...p1, name: 'Newer' }, true, 160, 'b1') }, j),
    );
    expect(restored(r).project.name).toBe('Newer');
  });

  test('a damaged journal is ignored and the snapshot restored', () => {
    const p1 = bigProject(2);
    const r = decideRecoveryFrom({ slots: { a: makeAutosaveRecord(p1, false, 100, 'a1'), b: undefined }, journal: '{"format":' });
    expect(restored(r).project.name).toBe('Big');
    expect(decideRecoveryFrom({ slots: { a: undefined, b: undefined }, journal: null }).decision.action).toBe('start-fresh');
  });
});
