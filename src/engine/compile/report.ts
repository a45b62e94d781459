// Located diagnostics worded for a PLC programmer: rule id, POU, network, cell, element.
import type { Cell } from '../../model/grid';
import type { ElementId } from '../../model/ids';
import type { LdElement } from '../../model/elements';
import type { Diagnostic, RuleId } from '../api';

/** R1C4: 1-based row and column as the editor shows them. */
export const cellName = (row: number, col: number): string => `R${row + 1}C${col + 1}`;

const CONTACT_WORDS = {
  NO: 'contact',
  NC: 'normally closed contact',
  P: 'rising-edge contact',
  N: 'falling-edge contact',
  NOT: 'inverting contact',
} as const;
const COIL_WORDS = {
  COIL: 'coil',
  NEG: 'negated coil',
  SET: 'set coil',
  RESET: 'reset coil',
  M: 'retentive coil',
  SM: 'retentive set coil',
  RM: 'retentive reset coil',
  P: 'rising-edge coil',
  N: 'falling-edge coil',
} as const;

/** "the contact "Start"", "the TON block "T1"", "the line at R2C3". */
export function describeElement(el: LdElement): string {
  const at = cellName(el.row, el.col);
  switch (el.kind) {
    case 'contact':
      return el.contact === 'NOT' || el.variable.trim() === ''
        ? `the ${CONTACT_WORDS[el.contact]} at ${at}`
        : `the ${CONTACT_WORDS[el.contact]} "${el.variable}"`;
    case 'coil':
      return el.variable.trim() === ''
        ? `the ${COIL_WORDS[el.coil]} at ${at}`
        : `the ${COIL_WORDS[el.coil]} "${el.variable}"`;
    case 'jump':
      return el.target.trim() === '' ? `the jump at ${at}` : `the jump to "${el.target}"`;
    case 'return':
      return `the RETURN at ${at}`;
    case 'box':
      return el.instance
        ? `the ${el.blockType} block "${el.instance}"`
        : `the ${el.blockType} block at ${at}`;
    case 'link':
      return `the line at ${at}`;
    case 'connector':
      return el.name.trim() === '' ? `the connector at ${at}` : `the connector ">${el.name}>"`;
    case 'continuation':
      return el.name.trim() === '' ? `the continuation at ${at}` : `the continuation ">${el.name}>" at ${at}`;
  }
}

export interface Located {
  readonly id?: ElementId;
  readonly row: number;
  readonly col: number;
}

/** Collects the diagnostics of one network (or of the POU's variable table when network = -1). */
export class Reporter {
  constructor(
    private readonly out: Diagnostic[],
    readonly pou: string,
    readonly network: number,
    readonly networkLabel?: string,
  ) {}

  /** Errors reported through this reporter so far. */
  errors = 0;

  error(rule: RuleId, message: string, at?: Located): void {
    this.errors++;
    this.add('error', rule, message, at);
  }

  warning(rule: RuleId, message: string, at?: Located): void {
    this.add('warning', rule, message, at);
  }

  /** A finding in a text body (ST, IL) at a 1-based line and column of its text. */
  inText(severity: Diagnostic['severity'], rule: RuleId, message: string, pos: { line: number; col: number }): void {
    if (severity === 'error') this.errors++;
    this.add(severity, rule, message, undefined, pos);
  }

  private add(severity: Diagnostic['severity'], rule: RuleId, message: string, at?: Located, text?: { line: number; col: number }): void {
    const cell: Cell | undefined = at ? { row: at.row, col: at.col } : undefined;
    this.out.push({
      severity,
      rule,
      pou: this.pou,
      network: this.network,
      ...(this.networkLabel !== undefined && this.networkLabel !== ''
        ? { networkLabel: this.networkLabel }
        : {}),
      ...(cell ? { cell } : {}),
      ...(at?.id !== undefined ? { elementId: at.id } : {}),
      ...(text ? { line: text.line, col: text.col } : {}),
      message,
    });
  }
}

/**
 * One line for terminals and logs: `error LD-R03 Main/network 2:R1C4 the contact ...`; in a text
 * body, `error LD-E50 Scale/line 3 col 7 the ST body of Scale does not compile: ...`.
 */
export function formatDiagnostic(d: Diagnostic): string {
  const where =
    d.line !== undefined
      ? `${d.pou}/line ${d.line} col ${d.col ?? 1}`
      : d.network < 0
      ? `${d.pou}/variables`
      : `${d.pou}/network ${d.network + 1}${d.networkLabel ? ` (${d.networkLabel})` : ''}${d.cell ? `:${cellName(d.cell.row, d.cell.col)}` : ''}`;
  return `${d.severity} ${d.rule} ${where} ${d.message}`;
}
