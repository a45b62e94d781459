// Pure helpers behind the canvas drag between networks, the variable table's row window and the
// timing of the live checks.
import { expect, test } from 'vitest';
import { dropInto } from '../../src/editor/canvas/dragTargets';
import { hoverText } from '../../src/editor/canvas/hoverText';
import { checkTiming, CHECK_DELAY_MS, LARGE_CHECK_DELAY_MS } from '../../src/editor/problems/useDiagnostics';
import { rowOffsets, WINDOW_THRESHOLD, windowFor } from '../../src/editor/variables/rowWindow';
import type { LdElement } from '../../src/model/elements';
import { newNetwork, newPou, newProject } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';

const contact = (name: string, row: number, col: number): LdElement => ({
  kind: 'contact',
  contact: 'NO',
  variable: name,
  id: name as ElementId,
  row,
  col,
});

test('a drop into another network keeps the grabbed element under the pointer', () => {
  const source = newNetwork({ rows: 2, cols: 4, elements: [contact('A', 0, 1), contact('B', 1, 2)] });
  const target = newNetwork({ rows: 2, cols: 4, elements: [contact('X', 1, 3)] });
  // B was grabbed; the pointer is over target cell (1, 2): B lands there, A one up and one left.
  const d = dropInto(source, target, ['A', 'B'] as ElementId[], { row: 1, col: 2 }, { row: 1, col: 2 })!;
  expect(d.at).toEqual({ row: 0, col: 1 });
  expect(d.ghost.map((e) => [e.id, e.row, e.col])).toEqual([
    ['A', 0, 1],
    ['B', 1, 2],
  ]);
  expect(d.blocked).toBe(false);
  // Over X's cell: blocked.
  expect(
    dropInto(source, target, ['A', 'B'] as ElementId[], { row: 1, col: 2 }, { row: 1, col: 3 })!.blocked,
  ).toBe(true);
});

test('the row window renders every row of a short table and a slice of a long one', () => {
  const short = rowOffsets(new Array<boolean>(WINDOW_THRESHOLD).fill(false), { row: 28, issue: 24 });
  expect(windowFor(short, 5000, 400)).toEqual({ first: 0, last: WINDOW_THRESHOLD - 1 });

  const issues = Array.from({ length: 5000 }, (_, i) => i % 10 === 0);
  const offsets = rowOffsets(issues, { row: 28, issue: 24 });
  expect(offsets[10]).toBe(10 * 28 + 24);
  const top = offsets[2500]!;
  const w = windowFor(offsets, top, 400);
  // The visible rows are inside the window, and far fewer rows than the table holds are rendered.
  expect(w.first).toBeLessThanOrEqual(2500);
  expect(offsets[w.last + 1]).toBeGreaterThanOrEqual(top + 400);
  expect(w.last - w.first).toBeLessThan(100);
  // The end of the table is reachable.
  const end = windowFor(offsets, offsets[5000]! - 400, 400);
  expect(end.last).toBe(4999);
});

test('checks start sooner for projects drawn by hand than for very large ones', () => {
  const small = newProject('s');
  expect(checkTiming(small).delayMs).toBe(CHECK_DELAY_MS);
  const networks = Array.from({ length: 300 }, (_, i) =>
    newNetwork({
      rows: 1,
      cols: 10,
      elements: Array.from({ length: 10 }, (_, c) => contact(`V${i}_${c}`, 0, c)),
    }),
  );
  const large = newProject('l', { pous: [newPou('Main', { networks })] });
  expect(checkTiming(large).delayMs).toBe(LARGE_CHECK_DELAY_MS);
  expect(CHECK_DELAY_MS).toBeLessThan(LARGE_CHECK_DELAY_MS);
});

test('the tooltip of a cell names its element in full and lists the problems marked there', () => {
  const el = contact('ConveyorRunningFeedback', 0, 0);
  expect(hoverText(el, [])).toBe('ConveyorRunningFeedback: Normally open contact  -| |-');
  const problem = { cell: { row: 0, col: 0 }, severity: 'error' as const, text: 'LD-R08: not declared' };
  expect(hoverText(el, [problem])).toBe(
    'ConveyorRunningFeedback: Normally open contact  -| |-\nLD-R08: not declared',
  );
  expect(hoverText({ kind: 'link', id: 'l' as ElementId, row: 0, col: 1 }, [])).toBeUndefined();
  expect(hoverText(undefined, [])).toBeUndefined();
});
