import { describe, expect, test } from 'vitest';
import type { Diagnostic } from '../../src/engine/api';
import {
  countBySeverity,
  diagnosticCell,
  diagnosticNetwork,
  sortDiagnostics,
} from '../../src/editor/problems/describe';
import { labelProblem } from '../../src/editor/inspector/networkLabel';
import { projectFileName } from '../../src/editor/files/projectFile';
import { newProject } from '../../src/model/factory';

const d = (partial: Partial<Diagnostic>): Diagnostic => ({
  severity: 'error',
  rule: 'LD-R03',
  pou: 'Main',
  network: 0,
  message: 'm',
  ...partial,
});

describe('problems list wording', () => {
  test('networks are shown 1-based with their label; POU-level problems point at the variables', () => {
    expect(diagnosticNetwork(d({ network: 2, networkLabel: 'Start' }))).toBe('network 3 (Start)');
    expect(diagnosticNetwork(d({ network: 0 }))).toBe('network 1');
    expect(diagnosticNetwork(d({ network: -1 }))).toBe('variables');
    // A finding in an ST body is where it is in the text.
    expect(diagnosticNetwork(d({ network: 0, line: 12, col: 5 }))).toBe('line 12, column 5');
    expect(diagnosticCell(d({ cell: { row: 0, col: 4 } }))).toBe('row 1, column 5');
    expect(diagnosticCell(d({}))).toBe('');
  });
  test('errors come first, then the order of the program', () => {
    const sorted = sortDiagnostics([
      d({ severity: 'warning', rule: 'LD-R12', network: 0 }),
      d({ network: 3, cell: { row: 0, col: 1 } }),
      d({ network: 1, cell: { row: 2, col: 0 } }),
      d({ network: 1, cell: { row: 0, col: 5 } }),
    ]);
    expect(sorted.map((x) => `${x.severity} ${x.network} ${x.cell?.row ?? '-'}`)).toEqual([
      'error 1 0',
      'error 1 2',
      'error 3 0',
      'warning 0 -',
    ]);
    expect(countBySeverity(sorted)).toEqual({ errors: 3, warnings: 1 });
  });
});

describe('network labels', () => {
  test('identifiers and unsigned integers are labels; duplicates are refused ignoring case', () => {
    expect(labelProblem('Start_Motor', [])).toBeUndefined();
    expect(labelProblem('100', [])).toBeUndefined();
    expect(labelProblem('', ['X'])).toBeUndefined();
    expect(labelProblem('-5', [])).toMatch(/identifier .* or an unsigned integer/);
    expect(labelProblem('loop', ['LOOP'])).toMatch(/already labelled loop/);
  });
});

describe('project file names', () => {
  test('come from the project name with unsafe characters replaced', () => {
    expect(projectFileName(newProject('Motor start/stop'))).toBe('Motor_start_stop.json');
    expect(projectFileName(newProject('  '))).toBe('project.json');
  });
});
