import { describe, expect, test } from 'vitest';
import { loadProject, saveProject } from '../../src/model/load';
import { newProject } from '../../src/model/factory';
import { ladder, project, vars } from '../engine/ladder';

describe('project files', () => {
  test('a new project saves and loads back unchanged', () => {
    const project = newProject('Demo');
    const result = loadProject(saveProject(project));
    expect(result).toEqual({ ok: true, project });
  });

  test('a project with a connector/continuation pair saves and loads back unchanged (they were refused by the file schema)', () => {
    const p = project(vars('A BOOL', 'X BOOL'), [ladder(['[A] >C1>| .', '|>C1> - (X)'])]);
    const result = loadProject(saveProject(p));
    expect(result).toEqual({ ok: true, project: p });
  });

  test('text that is not JSON is refused with a reason', () => {
    const result = loadProject('{ nope');
    expect(result.ok).toBe(false);
    if (!result.ok) expect(result.errors[0]!.message).toMatch(/not valid JSON/);
  });

  test('a wrong field is refused with its path', () => {
    const project = newProject('Demo');
    const bad = JSON.parse(saveProject(project));
    bad.pous[0].networks[0].rows = -1;
    const result = loadProject(JSON.stringify(bad));
    expect(result.ok).toBe(false);
    if (!result.ok) expect(result.errors[0]!.path).toBe('pous[0].networks[0].rows');
  });

  test('two elements in one cell are refused, naming the cell', () => {
    const project = newProject('Demo');
    const bad = JSON.parse(saveProject(project));
    bad.pous[0].networks[0].elements = [
      { id: 'a', kind: 'link', row: 0, col: 1 },
      { id: 'b', kind: 'contact', contact: 'NO', variable: 'X', row: 0, col: 1 },
    ];
    const result = loadProject(JSON.stringify(bad));
    expect(result.ok).toBe(false);
    if (!result.ok) expect(result.errors[0]!.message).toMatch(/row 0, column 1 already holds/);
  });

  test('a file from a newer Rungsmith is refused politely', () => {
    const bad = { ...newProject('Demo'), version: 99 };
    const result = loadProject(JSON.stringify(bad));
    expect(result.ok).toBe(false);
    if (!result.ok) expect(result.errors[0]!.message).toMatch(/newer/);
  });
});
