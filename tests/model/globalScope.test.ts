// Where a global was declared in PLCopen (configuration or resource): an optional field, so project
// files written before it still load; validated like every other field.
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { newPou, newProject, variable } from '../../src/model/factory';
import { loadProject, saveProject } from '../../src/model/load';

describe('global variable scope', () => {
  const project = newProject('Demo', {
    globals: [variable('Lamp', 'BOOL', { location: '%QX0.0', scope: 'resource' }), variable('Limit', 'INT')],
  });

  test('saves and loads back; a file without scope (older format) still loads', () => {
    expect(loadProject(saveProject(project))).toEqual({ ok: true, project });
    const old = JSON.parse(saveProject(project));
    delete old.globals[0].scope;
    expect(loadProject(JSON.stringify(old)).ok).toBe(true);
  });

  test('an unknown scope, or a scope on a POU variable, is refused with its path', () => {
    const bad = JSON.parse(saveProject(project));
    bad.globals[0].scope = 'task';
    const r1 = loadProject(JSON.stringify(bad));
    expect(r1.ok ? [] : r1.errors.map((e) => e.path)).toEqual(['globals[0].scope']);
    const bad2 = JSON.parse(saveProject(project));
    bad2.pous[0].variables = [{ ...bad2.globals[0] }];
    const r2 = loadProject(JSON.stringify(bad2));
    expect(r2.ok ? [] : r2.errors.map((e) => e.path)).toEqual(['pous[0].variables[0].scope']);
  });

  test('a VAR_EXTERNAL with the name of a POU variable is a duplicate (LD-E10)', () => {
    const main = newPou('Main', {
      variables: [variable('Lamp', 'BOOL'), variable('Lamp', 'BOOL', { varClass: 'external' })],
    });
    const p = newProject('Demo', { pous: [main], globals: [variable('Lamp', 'BOOL')] });
    expect(
      checkProject(p)
        .filter((d) => d.rule === 'LD-E10')
        .map((d) => d.message),
    ).toEqual([
      'the VAR_EXTERNAL "Lamp" has the name of a variable of the POU; variable names must be unique (case does not count)',
    ]);
  });
});
