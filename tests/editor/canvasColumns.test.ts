// The canvas's columns: as wide as the longest name drawn in them, coils drawn at the right rail,
// and every cell found again under its own drawn middle (clicks land where things are drawn).
import { describe, expect, it } from 'vitest';
import {
  boxMetrics,
  CELL_W,
  colAtX,
  displayCol,
  LABEL_PAD,
  nameWidth,
  networkColumns,
  operandWidth,
} from '../../src/editor/canvas/columns';
import { wireStyle } from '../../src/editor/canvas/drawSymbols';
import {
  cellCentre,
  cellRect,
  columnsOf,
  hitTest,
  layoutNetworks,
  networkWidth,
  RAIL_X,
} from '../../src/editor/canvas/geometry';
import { SPEC_BOLD, textWidth } from '../../src/editor/canvas/textWidth';
import type { CanvasTheme } from '../../src/editor/theme/canvasTheme';
import { boolState, WIRE_FALSE, WIRE_TRUE } from '../../src/editor/theme/monitorStyle';
import { boxLayout } from '../../src/model/boxLayout';
import type { BoxElement } from '../../src/model/elements';
import type { Network } from '../../src/model/project';
import { ladder } from '../engine/ladder';

const LONG = 'Conveyor_Infeed_Sensor_1'; // 24 characters

describe('column widths', () => {
  it('a column grows to the longest name in it; the others keep the narrow width', () => {
    const n = ladder([`[${LONG}] [B] (Out)`]);
    const nc = networkColumns(n);
    const first = nc.xs[1]! - nc.xs[0]!;
    expect(first).toBeGreaterThanOrEqual(nameWidth(LONG) + LABEL_PAD);
    expect(nc.xs[2]! - nc.xs[1]!).toBe(CELL_W);
    expect(networkWidth(n)).toBe(2 * RAIL_X + (n.cols - 1) * CELL_W + first);
  });

  it('a network of short names keeps the narrow grid (a default network fits the window)', () => {
    const n = ladder(['[Start] [/Stop] (Motor)'], { cols: 10 });
    expect(networkWidth(n)).toBe(2 * RAIL_X + 10 * CELL_W);
  });

  it('the estimate is at least what the canvas draws in DejaVu Sans, the widest usual UI font', () => {
    // Measured in Chromium on this machine (12px DejaVu Sans): 161.7 px, and 179.6 px bold.
    expect(textWidth(LONG)).toBeGreaterThanOrEqual(161.7);
    expect(textWidth(LONG, SPEC_BOLD)).toBeGreaterThanOrEqual(179.6);
    expect(textWidth(LONG)).toBeLessThan(170);
  });

  it("a box's columns hold its instance name and its pin operands beside the body", () => {
    const n = ladder(['[Go] # .', '. # .'], {
      boxes: [
        {
          row: 0,
          col: 1,
          type: 'TON',
          instance: 'Conveyor_Infeed_Timer_01',
          inputs: { PT: 'Infeed_Delay_Setpoint_Time' },
          outputs: { ET: 'Infeed_Elapsed_Time_Value' },
        },
      ],
    });
    const box = n.elements.find((e): e is BoxElement => e.kind === 'box')!;
    const nc = networkColumns(n);
    const span = cellRect(nc, box, 2).width;
    const m = boxMetrics(box, boxLayout(box)!);
    expect(span).toBeGreaterThanOrEqual(nameWidth('Conveyor_Infeed_Timer_01') + 8);
    expect(m.left).toBeGreaterThanOrEqual(operandWidth('Infeed_Delay_Setpoint_Time') + 6);
    expect(m.rightMargin).toBeGreaterThanOrEqual(operandWidth('Infeed_Elapsed_Time_Value') + 6);
    expect(span).toBeGreaterThanOrEqual(m.left + m.body + m.rightMargin);
    // The operands sit inside the box's own columns, not over the rail or the column before.
    expect(cellRect(nc, box).x).toBe(nc.xs[1]);
  });
});

describe('coils at the right rail', () => {
  it('a coil that ends its rung is drawn in the last column, with the wire drawn on from its cell', () => {
    const n = ladder(['[A] (Q) . . .'], { cols: 6 });
    const nc = networkColumns(n);
    expect(nc.alignedAt[0]).toBe(1);
    expect(displayCol(nc, 0, 1)).toBe(5);
    // The coil's x is the right rail minus one column.
    expect(cellRect(nc, { row: 0, col: 1 }).x).toBe(nc.xs[6]! - CELL_W);
  });

  it('coils in parallel both go to the rail; a coil before another element (LD-R04) stays', () => {
    const parallel = ladder(['[A] + (Q1) . .', '. + (Q2) . .'], { cols: 5 });
    const p = networkColumns(parallel);
    expect([p.alignedAt[0], p.alignedAt[1]]).toEqual([1, 1]);
    const series = ladder(['[A] (Q) [B] (R) .'], { cols: 5 });
    const s = networkColumns(series);
    expect(displayCol(s, 0, 1)).toBe(1);
    expect(displayCol(s, 0, 3)).toBe(4);
  });

  it('a coil whose right side is joined by a vertical link stays in its cell', () => {
    const n = ladder(['[A] (Q) . .', '[B] (R) . .'], { cols: 4, vlinks: [{ row: 0, boundary: 2 }] });
    const nc = networkColumns(n);
    expect([nc.alignedAt[0], nc.alignedAt[1]]).toEqual([-1, -1]);
  });
});

describe('hit testing', () => {
  const networks: Network[] = [
    ladder([`[${LONG}] [B] (Out_Motor_Running_Lamp) . . .`, '[C] # . . . .'], {
      cols: 8,
      boxes: [{ row: 1, col: 1, type: 'TON', instance: 'Conveyor_Infeed_Timer_01', inputs: { PT: 'T#5s' } }],
    }),
    ladder(['[X] . (Y) . . .'], { cols: 6 }),
  ];
  const layout = layoutNetworks(networks);

  it('every cell is found under its own drawn middle (cell -> pixel -> cell)', () => {
    networks.forEach((n, index) => {
      for (let row = 0; row < layout.rows[index]!; row++)
        for (let col = 0; col < n.cols; col++) {
          // Empty cells right of a rail-aligned coil lie under the coil's drawn wire (next test).
          const k = columnsOf(layout, n).alignedAt[row]!;
          if (k >= 0 && col > k) continue;
          const hit = hitTest(layout, networks, cellCentre(layout, networks, index, { row, col }));
          expect(hit).toMatchObject({ area: 'grid', index, cell: { row, col } });
        }
    });
  });

  it('the wire drawn on to a rail-aligned coil belongs to the coil (a contact placed there goes before it)', () => {
    const n = networks[1]!;
    const nc = columnsOf(layout, n);
    const top = layout.tops[1]! + 80;
    for (const col of [2, 3, 4, 5]) {
      const x = RAIL_X + (nc.xs[col]! + nc.xs[col + 1]!) / 2;
      const hit = hitTest(layout, networks, { x, y: top });
      expect(hit).toMatchObject({ area: 'grid', cell: { row: 0, col: 2 } });
    }
  });

  it('a click right of the grid still counts columns of the narrow width (placing there grows it)', () => {
    const n = networks[0]!;
    const nc = columnsOf(layout, n);
    expect(colAtX(nc, nc.xs[n.cols]! + CELL_W / 2)).toBe(n.cols);
    expect(colAtX(nc, nc.xs[n.cols]! + CELL_W * 1.5)).toBe(n.cols + 1);
  });
});

describe('monitoring styles', () => {
  const theme = { wire: '#222', energised: '#0a0', falseState: '#789' } as CanvasTheme;
  const styleOf = (simulating: boolean, on: boolean) => {
    const ctx = { strokeStyle: '', lineWidth: 0, dash: [] as number[], setLineDash(d: number[]) { this.dash = d; } };
    wireStyle(ctx as unknown as CanvasRenderingContext2D, theme, simulating, on);
    return { colour: ctx.strokeStyle, width: ctx.lineWidth, dashed: ctx.dash.length > 0 };
  };

  it('TRUE and FALSE wires differ in colour, width and dash (readable without colour)', () => {
    const on = styleOf(true, true);
    const off = styleOf(true, false);
    expect(on).toEqual({ colour: '#0a0', width: WIRE_TRUE, dashed: false });
    expect(off).toEqual({ colour: '#789', width: WIRE_FALSE, dashed: true });
    expect(styleOf(false, false)).toEqual({ colour: '#222', width: 1.5, dashed: false });
  });

  it('live texts read as TRUE, FALSE or a neutral value', () => {
    expect(boolState('TRUE')).toBe('TRUE');
    expect(boolState('FALSE [F]')).toBe('FALSE');
    expect(boolState('T#1s')).toBeUndefined();
    expect(boolState('Q=TRUE ET=T#1s')).toBeUndefined();
  });
});
