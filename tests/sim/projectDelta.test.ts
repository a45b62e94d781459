// The document goes to the worker as a difference from the one sent before (issue 24): an edit of
// one network sends that network only, and the worker rebuilds a document with the same program id.
import { describe, expect, test } from 'vitest';
import { variable } from '../../src/model/factory';
import type { Project } from '../../src/model/project';
import { programId } from '../../src/sim/programId';
import { applyDelta, diffProject } from '../../src/sim/projectDelta';
import { ladder, project, vars } from '../engine/ladder';

const base = (): Project => project(vars('A BOOL', 'B BOOL', 'Q BOOL'), Array.from({ length: 50 }, (_, i) => ladder([i % 2 ? '[A] (Q)' : '[B] (Q)'])));

describe('project deltas', () => {
  test('one network edited: only it travels; the rebuilt document is the edited one, unchanged networks shared', () => {
    const before = base();
    const main = before.pous[0]!;
    const edited = { ...main.networks[7]!, elements: main.networks[7]!.elements.map((e) => (e.kind === 'contact' ? { ...e, variable: 'B' } : e)) };
    const after: Project = { ...before, pous: [{ ...main, variables: [...main.variables, variable('C', 'BOOL')], networks: main.networks.map((n, i) => (i === 7 ? edited : n)) }] };
    const delta = diffProject(before, 3, after);
    expect(delta.base).toBe(3);
    const pou = delta.pous[0]!;
    expect(typeof pou === 'object' && 'networks' in pou ? pou.networks.filter((n) => typeof n !== 'number') : []).toEqual([edited]);
    // The worker's copy of the base is a structured clone: rebuilt from it, the document is equal.
    const copy = structuredClone(before);
    const rebuilt = applyDelta(copy, structuredClone(delta));
    expect(rebuilt).toEqual(after);
    expect(programId(rebuilt)).toBe(programId(after));
    expect(rebuilt.pous[0]!.networks[8]).toBe(copy.pous[0]!.networks[8]);
  });

  test('unchanged POUs travel as an index; a new POU and reordered networks come through', () => {
    const before = base();
    const main = before.pous[0]!;
    const same = diffProject(before, 1, { ...before, name: 'renamed' });
    expect(same.pous).toEqual([0]);
    const reordered: Project = { ...before, pous: [{ ...main, networks: [...main.networks].reverse() }, { ...main, id: 'pou-x' as typeof main.id, name: 'Other' }] };
    const rebuilt = applyDelta(structuredClone(before), structuredClone(diffProject(before, 1, reordered)));
    expect(rebuilt).toEqual(reordered);
  });
});
