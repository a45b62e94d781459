import { describe, expect, test } from 'vitest';
import { checkedDiagnostics, onChecked, requestCheck } from '../../src/editor/problems/checker';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';

const withCoil = (name: string, declared: boolean) =>
  newProject('p', {
    pous: [
      newPou('Main', {
        variables: declared
          ? [variable('Start', 'BOOL'), variable(name, 'BOOL')]
          : [variable('Start', 'BOOL')],
        networks: [
          newNetwork({
            rows: 1,
            cols: 2,
            elements: [
              { id: 'c' as ElementId, kind: 'contact', contact: 'NO', variable: 'Start', row: 0, col: 0 },
              { id: 'k' as ElementId, kind: 'coil', coil: 'COIL', variable: name, row: 0, col: 1 },
            ],
          }),
        ],
      }),
    ],
  });

describe('the live checker (in the page when no Web Worker exists, as in Node)', () => {
  test('checks a project version once and tells subscribers', () => {
    const project = withCoil('Motor', false);
    let heard = 0;
    const stop = onChecked(() => heard++);
    expect(checkedDiagnostics(project)).toBeUndefined();
    requestCheck(project);
    const found = checkedDiagnostics(project);
    expect(found?.map((d) => `${d.rule} ${d.cell?.col}`)).toEqual(['LD-R08 1']);
    requestCheck(project);
    expect(checkedDiagnostics(project)).toBe(found);
    expect(heard).toBe(1);
    stop();
  });
  test('each version has its own result: declaring the variable clears the problem', () => {
    const fixed = withCoil('Motor', true);
    requestCheck(fixed);
    expect(checkedDiagnostics(fixed)).toEqual([]);
  });
});
