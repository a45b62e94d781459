// How a diagnostic reads in the problems list: where it is, in a PLC programmer's words.
import type { Diagnostic } from '../../engine/api';
import { describeElement } from '../../engine/compile/report';
import type { Cell } from '../../model/grid';
import type { LdElement } from '../../model/elements';

/** "network 3 (Start)", "line 12, column 5" in a text body (ST, IL), or "variables" for POU-level diagnostics. */
export function diagnosticNetwork(d: Diagnostic): string {
  if (d.line !== undefined) return `line ${d.line}, column ${d.col ?? 1}`;
  if (d.network < 0) return 'variables';
  return `network ${d.network + 1}${d.networkLabel ? ` (${d.networkLabel})` : ''}`;
}

/**
 * "row 1, column 3" (1-based as shown on the canvas), or empty without a cell. A coil is drawn at
 * the right rail whatever its column: "row 3, at the right rail" (its column would point elsewhere).
 */
export const diagnosticCell = (d: Diagnostic, element?: LdElement): string =>
  d.cell ? cellWords(d.cell, element) : '';

function cellWords(cell: Cell, element: LdElement | undefined): string {
  return element?.kind === 'coil' ? `row ${cell.row + 1}, at the right rail` : `row ${cell.row + 1}, column ${cell.col + 1}`;
}

/**
 * An element where the user finds it in its network: `coil "Y", row 3, at the right rail` (where
 * it is drawn, not its grid column), `contact "Start", row 1, column 2`, "the line at row 2,
 * column 4"; "row 2, column 4" without the element.
 */
export function elementPlace(cell: Cell, element: LdElement | undefined): string {
  if (!element) return cellWords(cell, undefined);
  if (element.kind === 'link') return `the line at ${cellWords(cell, element)}`;
  // describeElement says where an unnamed element is by its cell: its name is enough here.
  const what = describeElement(element).replace(/^the /, '').replace(/ at R\d+C\d+$/, '');
  return `${what}, ${cellWords(cell, element)}`;
}

/** Errors first, then by POU, network, row, column: the order a programmer walks the program. */
export function sortDiagnostics(list: readonly Diagnostic[]): Diagnostic[] {
  const rank = (d: Diagnostic) => (d.severity === 'error' ? 0 : 1);
  return [...list].sort(
    (a, b) =>
      rank(a) - rank(b) ||
      a.pou.localeCompare(b.pou) ||
      a.network - b.network ||
      (a.line ?? 0) - (b.line ?? 0) ||
      (a.col ?? 0) - (b.col ?? 0) ||
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
