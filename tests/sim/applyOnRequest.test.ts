// Online change applied on request (issue 24), as the UI sees it (store + session over the loopback
// transport): an edit while running changes nothing until Apply; Apply asks with the change list;
// Cancel keeps the running program; Run goes on with the running program; Apply + confirm swaps it in.
import { describe, expect, test } from 'vitest';
import { variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { programId } from '../../src/sim/programId';
import { createSimStore } from '../../src/store/simStore';
import { ladder, project, vars } from '../engine/ladder';
import { loopback } from './loopback';

const running = (): Project => project(vars('Start BOOL', 'Motor BOOL', 'Lamp BOOL'), [ladder(['[Start] (Motor)'])]);
const edited = (p: Project): Project => {
  const main = p.pous[0]!;
  return { ...p, pous: [{ ...main, variables: [...main.variables, variable('Horn', 'BOOL')], networks: [...main.networks, ladder(['[Start] (Horn)'])] }] };
};

describe('apply on request in the store', () => {
  test('nothing changes until Apply; Apply lists the change and asks; Cancel keeps the program; confirm applies it', () => {
    const { transport, scheduler } = loopback();
    const store = createSimStore(transport);
    const s = () => store.getState();
    s().setOnlineMode('request');
    const doc = running();
    s().run(doc);
    scheduler.advance(50);
    expect(s().runningProgram).toBe(programId(doc));
    expect(s().runningProject).toBe(doc);
    const next = edited(doc);
    // Run again with the edited document on screen: the running program goes on (only Apply changes it).
    s().pause();
    scheduler.advance(20);
    s().run(next);
    scheduler.advance(50);
    expect(s().mode).toBe('running');
    expect(s().runningProgram).toBe(programId(doc));
    expect(s().variableIndex.has('HORN')).toBe(false);

    s().applyChanges(next);
    scheduler.advance(30);
    const asked = s().onlineChange;
    expect(asked?.kind).toBe('confirm');
    if (asked?.kind !== 'confirm') return;
    expect(asked.changes?.pous[0]).toMatchObject({ added: [2], newVariables: ['Horn'] });
    expect(s().runningProgram).toBe(programId(doc));
    s().answerOnlineChange(false);
    scheduler.advance(30);
    expect(s().onlineChange?.kind).toBe('cancelled');
    expect(s().runningProgram).toBe(programId(doc));

    s().applyChanges(next);
    scheduler.advance(30);
    expect(s().onlineChange?.kind).toBe('confirm');
    s().answerOnlineChange(true);
    scheduler.advance(50);
    expect(s().onlineChange?.kind).toBe('applied');
    expect(s().runningProgram).toBe(programId(next));
    expect(s().runningProject).toBe(next);
    s().write('Start', { value: true });
    scheduler.advance(50);
    expect(s().values[s().variableIndex.get('HORN')!]).toBe(true);
    expect(s().mode).toBe('running');
  });
});
