// Figures for the editing-habits pieces (issue 13) that run on every frame or draw: the trend's
// lanes and lane data for a full window, and the `???` pin check of a network of boxes.
// Run: `npx tsx bench/editingHabits.bench.ts`.
import { trendData, trendLayout } from '../src/editor/sim/trendChart';
import { openPins } from '../src/editor/canvas/pinOperands';
import type { BoxElement, LdElement } from '../src/model/elements';
import { newNetwork } from '../src/model/factory';
import type { ElementId } from '../src/model/ids';
import type { TrendBuffer } from '../src/sim/trendBuffer';
import { median } from './median';

// Trend: 4 BOOL and 4 numeric signals, a 10,000-scan window (what one frame redraws).
const SAMPLES = 10_000;
const names = ['B1', 'B2', 'B3', 'B4', 'N1', 'N2', 'N3', 'N4'];
const signals = names.map((name) => ({ name, type: name.startsWith('B') ? 'BOOL' : 'INT' }));
const buffer: TrendBuffer = {
  names,
  scans: Array.from({ length: SAMPLES }, (_, i) => i + 1),
  timesMs: Array.from({ length: SAMPLES }, (_, i) => (i + 1) * 10),
  series: names.map((n, k) =>
    Array.from({ length: SAMPLES }, (_, i) => (n.startsWith('B') ? ((i >> (k + 3)) & 1) : (i * (k + 1)) % 1000)),
  ),
};
const trend = median(21, () => trendData(trendLayout(signals, buffer), buffer));
console.log(`trend lanes + data, 8 signals x ${SAMPLES} scans: ${trend.toFixed(2)} ms (median of 21)`);

// Pin check: a network of 40 TON boxes in a column (row 2k), each fed by a contact, Q to a coil.
const elements: LdElement[] = [];
for (let k = 0; k < 40; k++) {
  const row = k * 2;
  elements.push({ kind: 'contact', contact: 'NO', variable: `S${k}`, id: `c${k}` as ElementId, row, col: 0 });
  elements.push({ kind: 'box', blockType: 'TON', instance: `T${k}`, inputs: {}, outputs: {}, id: `b${k}` as ElementId, row, col: 1 });
  elements.push({ kind: 'coil', coil: 'COIL', variable: `L${k}`, id: `o${k}` as ElementId, row, col: 3 });
}
const net = newNetwork({ rows: 80, cols: 4, elements });
const boxes = elements.filter((e): e is BoxElement => e.kind === 'box');
const pins = median(21, () => {
  for (const b of boxes) openPins(net, b);
});
console.log(`??? pin check, 40 boxes / 120 elements in one network: ${pins.toFixed(2)} ms per draw (median of 21)`);
