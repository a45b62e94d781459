// Diagnostics as cell markers: each located diagnostic marks its cell (or its element's cell).
import type { Diagnostic } from '../../engine/api';
import type { Network } from '../../model/project';
import type { CellMarker } from './drawNetwork';

export interface NetworkMarkers {
  readonly markers: readonly CellMarker[];
  readonly errors: number;
  readonly warnings: number;
}

export function markersByNetwork(
  networks: readonly Network[],
  byNetwork: ReadonlyMap<number, readonly Diagnostic[]>,
): Map<number, NetworkMarkers> {
  const out = new Map<number, NetworkMarkers>();
  for (const [index, list] of byNetwork) {
    const n = networks[index];
    if (!n) continue;
    const markers: CellMarker[] = [];
    let errors = 0;
    let warnings = 0;
    for (const d of list) {
      if (d.severity === 'error') errors++;
      else warnings++;
      const el = d.elementId ? n.elements.find((e) => e.id === d.elementId) : undefined;
      const cell = d.cell ?? (el ? { row: el.row, col: el.col } : undefined);
      if (cell) markers.push({ cell, severity: d.severity, text: `${d.rule}: ${d.message}` });
    }
    out.set(index, { markers, errors, warnings });
  }
  return out;
}
