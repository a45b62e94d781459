// The editor's block library stays the same object while no block interface changes, so an edit
// redraws only what it changed; a changed interface gives a new library, and a block's body is
// always the newest.
import { describe, expect, it } from 'vitest';
import { bottleFiller } from '../../bench/bottleFiller';
import { variable } from '../../src/model/factory';
import { createDocumentStore, selectLibrary } from '../../src/store/documentStore';

describe('stable block library', () => {
  it('keeps the library through network edits and program declarations, not through an FB interface change', () => {
    const store = createDocumentStore(bottleFiller());
    const main = store.getState().project.pous[0]!;
    const conveyor = store.getState().project.pous.find((p) => p.name === 'Conveyor')!;
    const before = selectLibrary(store.getState());
    store.getState().updateNetwork(main.networks[0]!.id, { title: 'Renamed' });
    store.getState().addVariable(variable('Extra', 'BOOL'), main.id);
    expect(store.getState().project).not.toBe(main);
    expect(selectLibrary(store.getState())).toBe(before);

    // The FB's body edited: same interface, same library, and userPou shows the edit.
    store.getState().updateNetwork(conveyor.networks[0]!.id, { title: 'Jam latch' });
    expect(selectLibrary(store.getState())).toBe(before);
    expect(selectLibrary(store.getState()).userPou('Conveyor')!.networks[0]!.title).toBe('Jam latch');

    // A new input of the FB: a new library whose Conveyor box has the pin.
    store.getState().addVariable(variable('Reset', 'BOOL', { varClass: 'input' }), conveyor.id);
    const after = selectLibrary(store.getState());
    expect(after).not.toBe(before);
    expect(after.signature('Conveyor')!.inputs.map((p) => p.name)).toEqual(['Enable', 'Jam', 'Reset']);
    store.getState().undo();
    expect(selectLibrary(store.getState()).signature('Conveyor')!.inputs.map((p) => p.name)).toEqual(['Enable', 'Jam']);
  });

  it('gives a new library when a library is added to the project, with its blocks', () => {
    const store = createDocumentStore(bottleFiller());
    const conveyor = store.getState().project.pous.find((p) => p.name === 'Conveyor')!;
    const before = selectLibrary(store.getState());
    expect(before.signature('Belt')).toBeUndefined();
    const belt = { ...conveyor, id: 'library:Belts:Belt' as typeof conveyor.id, name: 'Belt' };
    store.getState().updateProject({
      libraries: [{ name: 'Belts', hash: `sha256:${'0'.repeat(64)}`, sourceFile: 'belts.xml', addedAt: '2026-11-28T12:00:00.000Z', origin: 'plcopen', pous: [belt] }],
    });
    const after = selectLibrary(store.getState());
    expect(after).not.toBe(before);
    expect(after.signature('Belt')!.inputs.map((p) => p.name)).toEqual(['Enable', 'Jam']);
  });
});
