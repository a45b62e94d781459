// A network is as tall as the rows its rung uses (at least one); room to place into is shown while
// placing: one empty row under every rung (armed tool, drag), or down to the keyboard cursor.
import { expect, test } from 'vitest';
import { roomFor } from '../../src/editor/canvas/canvasLayout';
import { CELL_H, GRID_PAD_BOTTOM, hitTest, cellCentre, layoutNetworks, shownRows } from '../../src/editor/canvas/geometry';
import { networkSvg } from '../../src/editor/print/networkSvg';
import type { LdElement } from '../../src/model/elements';
import { newNetwork } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import type { Network } from '../../src/model/project';
import { usedRows } from '../../src/store/networkEdits';
import type { CanvasTheme } from '../../src/editor/theme/canvasTheme';

const contact = (variable: string, row: number, col: number): LdElement => ({
  id: `${variable}` as ElementId,
  kind: 'contact',
  contact: 'NO',
  variable,
  row,
  col,
});
const ton: LdElement = { id: 'T' as ElementId, kind: 'box', blockType: 'TON', instance: 'T1', row: 0, col: 1, inputs: {}, outputs: {} };

test('used rows: one for an empty network, the rows elements, boxes and vertical links reach; memoised per network', () => {
  expect(usedRows(newNetwork({ rows: 3 }))).toBe(1);
  expect(usedRows(newNetwork({ rows: 3, elements: [contact('A', 0, 0)] }))).toBe(1);
  expect(usedRows(newNetwork({ rows: 5, elements: [ton] }))).toBe(2);
  expect(usedRows(newNetwork({ rows: 4, elements: [contact('A', 0, 0)], vlinks: [{ row: 1, boundary: 1 }] }))).toBe(3);
  const n = newNetwork({ rows: 4, elements: [contact('A', 0, 0), contact('B', 2, 0)] });
  expect(usedRows(n)).toBe(3);
  expect(usedRows(n)).toBe(3);
});

test('shown rows and the layout: used rows, one more for every network while placing, down to the cursor in its network', () => {
  const a: Network = newNetwork({ rows: 3, elements: [contact('A', 0, 0)] });
  const b: Network = newNetwork({ rows: 1, elements: [contact('B', 0, 0)] });
  expect(shownRows(a)).toBe(1);
  expect(shownRows(a, undefined, { all: true })).toBe(2);
  expect(shownRows(b, undefined, { all: true })).toBe(2); // beyond the model's rows: placing there grows it
  expect(shownRows(a, undefined, { network: a.id, rows: 2 })).toBe(2);
  expect(shownRows(b, undefined, { network: a.id, rows: 2 })).toBe(1);

  const plain = layoutNetworks([a, b]);
  const placing = layoutNetworks([a, b], undefined, undefined, { all: true });
  expect(plain.heights[0]! - placing.heights[0]!).toBe(-CELL_H);
  expect(placing.tops[1]! - plain.tops[1]!).toBe(CELL_H);
  // The room row is a grid row to hit while placing, and not there otherwise.
  const p = cellCentre(placing, [a, b], 0, { row: 1, col: 0 });
  expect(hitTest(placing, [a, b], p)).toMatchObject({ area: 'grid', index: 0, cell: { row: 1, col: 0 } });
  expect(hitTest(plain, [a, b], p)).not.toMatchObject({ area: 'grid', index: 0 });
});

test('room: an armed tool or a drag gives every network a row; the cursor below the rung gives its network rows down to it', () => {
  const a: Network = newNetwork({ rows: 3, elements: [contact('A', 0, 0)] });
  const select = { kind: 'select' } as const;
  expect(roomFor({ tool: select, cursor: undefined, dragging: false }, [a])).toBeUndefined();
  expect(roomFor({ tool: select, cursor: undefined, dragging: true }, [a])).toEqual({ all: true });
  expect(roomFor({ tool: { kind: 'vlink' }, cursor: undefined, dragging: false }, [a])).toEqual({ all: true });
  expect(roomFor({ tool: select, cursor: { network: a.id, row: 0, col: 0 }, dragging: false }, [a])).toBeUndefined();
  expect(roomFor({ tool: select, cursor: { network: a.id, row: 1, col: 0 }, dragging: false }, [a])).toEqual({
    network: a.id,
    rows: 2,
  });
});

test('print draws a network as tall as the rows its rung uses', () => {
  const theme = new Proxy({}, { get: () => '#000' }) as CanvasTheme;
  const d = networkSvg(newNetwork({ rows: 3, elements: [contact('A', 0, 0)] }), theme, (_f, t) => t.length * 6);
  expect(d.rows).toBe(1);
  expect(d.height).toBe(CELL_H + GRID_PAD_BOTTOM);
});
