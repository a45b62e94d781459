// Issue 22, section 2 item 16: while simulating, a TON drew `???` beside its ET output (an output
// nothing reads is optional, not a missing operand). Editing, the `???` cue stays; an unassigned
// input keeps it while running too.
import { expect, test } from 'vitest';
import type { BoxElement } from '../../src/model/elements';
import type { ElementId } from '../../src/model/ids';
import { newNetwork } from '../../src/model/factory';
import { drawElement } from '../../src/editor/canvas/drawSymbols';
import { openPins } from '../../src/editor/canvas/pinOperands';
import { SvgContext } from '../../src/editor/print/svgContext';
import type { CanvasTheme } from '../../src/editor/theme/canvasTheme';

const measure = (_font: string, text: string) => text.length * 6.5;
const THEME: CanvasTheme = {
  bg: '#fff', grid: '#eee', rail: '#222', wire: '#222', symbol: '#111', text: '#111', operand: '#05a',
  muted: '#888', selection: '#00f', selectionFill: '#00f2', cursor: '#f80', hover: '#00f1', error: '#d00',
  warning: '#e80', energised: '#1a4', falseState: '#789', boxFill: '#f7f9fc', networkBg: '#fbfcfd', forced: '#b19',
};
const texts = (svg: string) => [...svg.matchAll(/<text[^>]*>([^<]*)<\/text>/g)].map((m) => m[1]);

function drawn(box: BoxElement, power: number | undefined): string[] {
  const network = newNetwork({ rows: 3, cols: 6, elements: [box], vlinks: [] });
  const ctx = new SvgContext(measure);
  drawElement(ctx as unknown as CanvasRenderingContext2D, THEME, box, {
    width: 200,
    openPins: openPins(network, box),
    ...(power !== undefined ? { power } : {}),
  });
  return texts(ctx.toSvg(220, 120));
}

const ton = (inputs: Record<string, string>): BoxElement => ({ id: 'b1' as ElementId, kind: 'box', row: 0, col: 1, blockType: 'TON', instance: 'T1', inputs, outputs: {} });

test('editing, an unread ET is drawn with ???; while simulating it is not', () => {
  const box = ton({ PT: 'T#5s' });
  expect(drawn(box, undefined).filter((t) => t === '???')).toHaveLength(2); // IN (unwired) and ET
  const running = drawn(box, 0b111);
  expect(running).toContain('ET');
  expect(running.filter((t) => t === '???')).toHaveLength(1); // IN only: an input with nothing is still missing
});

test('an input with no operand keeps its ??? while simulating', () => {
  const running = drawn(ton({}), 0b101);
  expect(running.filter((t) => t === '???').length).toBeGreaterThanOrEqual(2); // IN and PT
});
