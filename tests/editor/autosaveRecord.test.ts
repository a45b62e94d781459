import { describe, expect, test } from 'vitest';
import { newProject, variable } from '../../src/model/factory';
import { decideRecovery, makeAutosaveRecord, recoveryNotice } from '../../src/editor/files/autosaveRecord';

const time = (ms: number) => new Date(ms).toISOString();

describe('autosave recovery', () => {
  test('nothing stored: start with a new project and say nothing', () => {
    const decision = decideRecovery(undefined);
    expect(decision).toEqual({ action: 'start-fresh' });
    expect(recoveryNotice(decision, time)).toBeUndefined();
  });
  test('a saved record restores the same project and whether it had unsaved changes', () => {
    const project = newProject('Conveyor', { globals: [variable('Run', 'BOOL', { location: '%QX0.0' })] });
    const record = makeAutosaveRecord(project, true, 1_700_000_000_000);
    // IndexedDB keeps a structured clone: a JSON round trip shows the record holds plain data only.
    const decision = decideRecovery(JSON.parse(JSON.stringify(record)));
    expect(decision).toMatchObject({ action: 'restore', unsavedChanges: true, savedAt: 1_700_000_000_000 });
    if (decision.action !== 'restore') throw new Error('expected a restore');
    expect(decision.project).toEqual(project);
    expect(recoveryNotice(decision, time)).toMatch(
      /Restored "Conveyor" .*2023-11-14.*not yet saved to a file/,
    );
  });
  test('restoring a project with nothing in it yet says nothing', () => {
    const decision = decideRecovery(makeAutosaveRecord(newProject('Untitled'), false, 5));
    expect(decision.action).toBe('restore');
    expect(recoveryNotice(decision, time)).toBeUndefined();
  });
  test('a damaged record is discarded with the located reason', () => {
    const record = {
      ...makeAutosaveRecord(newProject('x'), false, 1),
      projectText: '{"format":"rungsmith-project","version":1}',
    };
    const decision = decideRecovery(record);
    expect(decision.action).toBe('discard');
    expect(recoveryNotice(decision, time)).toMatch(/could not be restored: .*validation \(name: /);
  });
  test('a record from another format version is discarded, not misread', () => {
    expect(
      decideRecovery({ format: 'rungsmith-autosave', version: 99, savedAt: 1, projectText: '' }),
    ).toMatchObject({ action: 'discard' });
    expect(decideRecovery('text')).toMatchObject({ action: 'discard' });
  });
});
