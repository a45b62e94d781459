// Issue 22, section 2 item 16, the small things a user reads: where an element is (a coil drawn at
// the right rail is not "R3C1"), the Why? lines without a second bullet, execution time in one
// stable unit.
import { describe, expect, test } from 'vitest';
import type { Diagnostic } from '../../src/engine/api';
import { diagnosticCell, elementPlace } from '../../src/editor/problems/describe';
import { whyLineText } from '../../src/editor/history/WhyPanel';
import { formatExec } from '../../src/editor/sim/SimToolbar';
import { exportBehaviour } from '../../src/plcopen/exportBehaviour';
import { ladder, project, vars } from '../engine/ladder';

describe('where an element is, in words', () => {
  const net = ladder(['[B] + (R:B)', '. + (Y)', '[A] - (Y)']);
  const el = (kind: string, row: number) => net.elements.find((e) => e.kind === kind && e.row === row)!;

  test('a coil is placed by its row, at the right rail where it is drawn (not by its grid column)', () => {
    expect(elementPlace({ row: 1, col: 1 }, el('coil', 1))).toBe('coil "Y", row 2, at the right rail');
    expect(elementPlace({ row: 0, col: 1 }, el('coil', 0))).toBe('reset coil "B", row 1, at the right rail');
    expect(elementPlace({ row: 2, col: 0 }, el('contact', 2))).toBe('contact "A", row 3, column 1');
    expect(elementPlace({ row: 2, col: 1 }, el('link', 2))).toBe('the line at row 3, column 2');
    expect(elementPlace({ row: 2, col: 1 }, undefined)).toBe('row 3, column 2');
  });

  test('the Problems row says the same of a coil', () => {
    const d: Diagnostic = { severity: 'warning', rule: 'LD-R12', pou: 'Main', network: 2, cell: { row: 1, col: 1 }, message: 'm' };
    expect(diagnosticCell(d, el('coil', 1))).toBe('row 2, at the right rail');
    expect(diagnosticCell(d)).toBe('row 2, column 2');
  });

  test('the export review places its LD-X05 warning on the element it names, without R1C1', () => {
    const shared = ladder(['[B] + (R:B)', '. + (Y)']);
    const [w] = exportBehaviour(project(vars('B BOOL', 'Y BOOL'), [shared])).filter((x) => x.rule === 'LD-X05');
    const target = shared.elements.find((e) => e.id === w!.elementId);
    expect(elementPlace(w!.cell!, target)).toBe('contact "B", row 1, column 1');
  });
});

test('a Why? sub-line loses its own bullet: the list draws one', () => {
  expect(whyLineText('  • |/| Stop: open')).toBe('|/| Stop: open');
  expect(whyLineText('Motor is TRUE')).toBe('Motor is TRUE');
  expect(whyLineText('  - the line')).toBe('the line');
});

test('execution time keeps one unit and three decimals, small or large', () => {
  expect(formatExec(0.012, 0.0104, 0.3)).toBe('0.012 / 0.010 / 0.300 ms');
  expect(formatExec(0.02, 0.5, 1.5)).toBe('0.020 / 0.500 / 1.500 ms');
  expect(formatExec(12.25, 11, 40)).toBe('12.250 / 11.000 / 40.000 ms');
  expect(formatExec(Number.NaN, 0, 0)).toBe('0.000 / 0.000 / 0.000 ms');
});
