// How a diagnostic reads in the problems list: where it is, in a PLC programmer's words.
import type { Diagnostic } from '../../engine/api';

/** "network 3 (Start)", or "variables" for POU-level diagnostics. */
export function diagnosticNetwork(d: Diagnostic): string {
  if (d.network < 0) return 'variables';
  return `network ${d.network + 1}${d.networkLabel ? ` (${d.networkLabel})` : ''}`;
}

/** "row 1, column 3" (1-based as shown on the canvas), or empty without a cell. */
export const diagnosticCell = (d: Diagnostic): string =>
  d.cell ? `row ${d.cell.row + 1}, column ${d.cell.col + 1}` : '';

/** Errors first, then by POU, network, row, column: the order a programmer walks the program. */
export function sortDiagnostics(list: readonly Diagnostic[]): Diagnostic[] {
  const rank = (d: Diagnostic) => (d.severity === 'error' ? 0 : 1);
  return [...list].sort(
    (a, b) =>
      rank(a) - rank(b) ||
      a.pou.localeCompare(b.pou) ||
      a.network - b.network ||
      (a.cell?.row ?? -1) - (b.cell?.row ?? -1) ||
      (a.cell?.col ?? -1) - (b.cell?.col ?? -1) ||
      a.rule.localeCompare(b.rule),
  );
}

export function countBySeverity(list: readonly Diagnostic[]): { errors: number; warnings: number } {
  let errors = 0;
  for (const d of list) if (d.severity === 'error') errors++;
  return { errors, warnings: list.length - errors };
}
