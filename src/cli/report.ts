// Plain-text lines for import findings.
import type { ImportIssue } from '../plcopen/types';

/** `line 12 <contact localId="7"> (POU Main): message` */
export function formatIssue(i: ImportIssue): string {
  const where = [
    i.line !== undefined ? `line ${i.line}` : '',
    i.element ? `<${i.element}${i.localId ? ` localId="${i.localId}"` : ''}>` : '',
    i.pou ? `(POU ${i.pou})` : '',
  ]
    .filter(Boolean)
    .join(' ');
  return where ? `${where}: ${i.message}` : i.message;
}
