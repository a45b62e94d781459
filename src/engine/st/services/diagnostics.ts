// The findings of one ST body, located in its text: exactly what the compiler reports for the POU
// (compile/pou.ts lowerPou, as checkProject runs it for the Problems list, Run and `rungsmith
// check`), for a text that may not be committed to the project yet (the editor's, as typed).
import type { Diagnostic, RuleId } from '../../api';
import { lowerPou } from '../../compile/pou';
import { withLibraries } from '../../../model/libraries';
import type { Pou, Project } from '../../../model/project';
import { textBodyPrefix } from '../body';
import { lineStartsOf, offsetOf, positionOf, readAround, readBody, tokenAt, type BodyText } from './text';

export interface StDiagnostic {
  readonly severity: 'error' | 'warning';
  readonly rule: RuleId;
  readonly pou: string;
  /** 1-based; the end is just past the token found at the start (or the end of its line). */
  readonly line: number;
  readonly col: number;
  readonly endLine: number;
  readonly endCol: number;
  /** As the compiler words it (naming the POU, the language, the line and column). */
  readonly message: string;
  /** The finding alone (`cannot assign to i: …`), for a place that already shows where it is. */
  readonly detail: string;
}

/** The project with the POU's body replaced by `text` (the same project when it is unchanged). */
export function withBody(project: Project, pou: Pou, text: string): { project: Project; pou: Pou } {
  if ((pou.source ?? '') === text) return { project, pou };
  const next: Pou = { ...pou, source: text };
  return { project: { ...project, pous: project.pous.map((p) => (p === pou ? next : p)) }, pou: next };
}

/**
 * The compiler's findings for the body of the POU `pouId` (its text replaced by `text` when given):
 * those located in the text, in text order. Findings about its variables (not in the text) are in
 * `others`.
 */
export function stDiagnostics(
  given: Project,
  pouId: string,
  text?: string,
): { located: StDiagnostic[]; others: Diagnostic[] } {
  const found = given.pous.find((p) => p.id === pouId);
  if (!found) return { located: [], others: [] };
  const { project, pou } = text === undefined ? { project: given, pou: found } : withBody(given, found, text);
  const out: Diagnostic[] = [];
  lowerPou(withLibraries(project), pou, project.profile, out, []);
  const source = pou.source ?? '';
  const lines = { text: source, lineStarts: lineStartsOf(source) };
  // The token at each finding: read around it (a few findings), or the whole text once (many).
  const many = out.filter((d) => d.line !== undefined).length > 16;
  const around = (at: number): BodyText => (many ? readBody(source) : readAround(source, at));
  const prefix = textBodyPrefix(pou);
  const located: StDiagnostic[] = [];
  const others: Diagnostic[] = [];
  for (const d of out) {
    if (d.line === undefined || d.pou !== pou.name) {
      others.push(d);
      continue;
    }
    const col = d.col ?? 1;
    const at = offsetOf(lines, d.line, col);
    const body = around(at);
    const k = tokenAt(body, at);
    const t = k >= 0 ? body.tokens[k] : undefined;
    const lineEnd = body.lineStarts[d.line] !== undefined ? body.lineStarts[d.line]! - 1 : body.text.length;
    const endOffset = t && t.from === at ? t.to : Math.max(at + 1, lineEnd);
    const end = positionOf(body, Math.min(endOffset, body.text.length));
    const detail = d.message.startsWith(prefix)
      ? d.message.slice(prefix.length).replace(/^line \d+ col \d+: /, '')
      : d.message;
    located.push({
      severity: d.severity,
      rule: d.rule,
      pou: pou.name,
      line: d.line,
      col,
      endLine: end.line,
      endCol: end.col,
      message: d.message,
      detail,
    });
  }
  located.sort((a, b) => a.line - b.line || a.col - b.col);
  return { located, others };
}
