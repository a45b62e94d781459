// The watch list kept per project (issue 24): saved in the project (file and autosave) without an
// undo step or an online change, read back by the loader, and the names `W` adds from the canvas.
import { describe, expect, test } from 'vitest';
import { watchNamesOf } from '../../src/editor/sim/watchFromCanvas';
import { blockLibrary } from '../../src/model/library';
import { loadProject, saveProject, validateProject } from '../../src/model/load';
import { programFingerprint } from '../../src/sim/layout';
import { createDocumentStore } from '../../src/store/documentStore';
import { createSimStore } from '../../src/store/simStore';
import { ladder, project, vars } from '../engine/ladder';
import { loopback } from './loopback';
import { motorProject } from './monitorPrograms';

describe('the watch list in the project', () => {
  test('is kept in the project without an undo step, and is no change of the program', () => {
    const doc = createDocumentStore(project(vars('Start BOOL'), [ladder(['[Start] (Start)'])]));
    const before = doc.getState().project;
    doc.getState().setWatchList(['Start', 'T1.ET']);
    const after = doc.getState().project;
    expect(after.watch).toEqual(['Start', 'T1.ET']);
    expect(doc.getState().dirty).toBe(true);
    expect(doc.getState().canUndo).toBe(false);
    expect(programFingerprint(after)).toBe(programFingerprint(before));
    doc.getState().setWatchList([]);
    expect('watch' in doc.getState().project).toBe(false);
  });

  test('a saved project with a watch list loads back; a bad one is refused with its path', () => {
    const p = { ...project(vars('Start BOOL'), []), watch: ['Start', 'Conv1.Motor'] };
    const ok = loadProject(saveProject(p));
    expect(ok.ok && ok.project.watch).toEqual(['Start', 'Conv1.Motor']);
    const bad = validateProject({ ...JSON.parse(saveProject(p)), watch: ['Start', 3] });
    expect(bad.ok).toBe(false);
    expect(!bad.ok && bad.errors[0]!.path).toBe('watch[1]');
  });
});

describe('W: the names an element adds to the watch list', () => {
  test('a contact its variable, an FB its instance, a function its named operands (not literals); read in the monitored instance', () => {
    const { transport, scheduler } = loopback();
    const sim = createSimStore(transport);
    const p = motorProject();
    const lib = blockLibrary(p);
    const main = p.pous[0]!.networks[0]!;
    const contact = main.elements.find((e) => e.kind === 'contact')!;
    const call = main.elements.find((e) => e.kind === 'box')!;
    expect(watchNamesOf(sim.getState(), contact, lib)).toEqual(['Start1']);
    expect(watchNamesOf(sim.getState(), call, lib)).toEqual(['Motor1']);
    const add = { id: 'x', kind: 'box', row: 0, col: 0, blockType: 'ADD', inputs: { IN1: 'Count', IN2: '16#10' }, outputs: { OUT: 'Total' } } as const;
    expect(watchNamesOf(sim.getState(), add as never, lib)).toEqual(['Count', 'Total']);
    // Inside the FB's body, on its picked instance: the instance's own variable.
    sim.getState().run(p);
    scheduler.advance(30);
    sim.getState().showPou({ name: 'Motor', kind: 'FUNCTION_BLOCK' });
    scheduler.advance(30);
    const coil = p.pous[1]!.networks[0]!.elements.find((e) => e.kind === 'coil')!;
    expect(watchNamesOf(sim.getState(), coil, lib)).toEqual(['Motor1.Run']);
  });
});
