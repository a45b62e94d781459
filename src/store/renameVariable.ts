// Renaming a declared variable everywhere it is named, as one undo step: its declaration and every
// use (updateVariable), and the columns of the test scenarios that name it. The watch list and the
// trend (not part of the document) follow through `renameInNames`. Used by the Find/Replace panel
// when the text replaced is a declared variable's whole name.
import { findVariable } from '../model/factory';
import type { Pou, Project, Scenario } from '../model/project';
import { csvRow, readCsv } from '../sim/csv';
import type { VariableScope } from './changes';
import type { DocumentStore } from './documentStore';
import { declaresLocally, renameOperand } from './variableEdits';
import { applyReplacements, planReplace, type FindQuery, type Replacement } from './find';

const EXPECT = /^(expect[:\s]\s*)(.+?)(\s*~\s*.+)?$/i;
const IDENT = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** Where a variable named `name` is declared: 'globals' and/or the POUs declaring it. */
export function declarationsOf(project: Project, name: string, caseSensitive = false): VariableScope[] {
  const same = (v: { name: string }) => (caseSensitive ? v.name === name : v.name.toUpperCase() === name.toUpperCase());
  const out: VariableScope[] = [];
  if (project.globals.some(same)) out.push('globals');
  for (const pou of project.pous) if (pou.variables.some(same)) out.push(pou.id);
  return out;
}

/** The scenario text with header columns naming `from` (`Motor`, `expect Motor`, `expect T1.ET ~ 5ms`) renamed. */
export function renameInScenarioCsv(csv: string, from: string, to: string): string {
  let header: { line: number; cells: string[] } | undefined;
  try {
    header = readCsv(csv).rows[0];
  } catch {
    return csv;
  }
  if (!header || header.cells[0]?.toLowerCase() !== 'scan') return csv;
  const cells = header.cells.map((cell, i) => {
    if (i === 0) return cell;
    const m = EXPECT.exec(cell);
    if (m) return `${m[1]}${renameOperand(m[2]!, from, to)}${m[3] ?? ''}`;
    return renameOperand(cell, from, to);
  });
  if (cells.every((c, i) => c === header.cells[i])) return csv;
  const lines = csv.split(/(\r?\n)/);
  // split with a capture group keeps the line breaks at odd indexes: line n is at index 2(n-1).
  lines[2 * (header.line - 1)] = csvRow(cells);
  return lines.join('');
}

/** The POU a scenario runs (`# pou: NAME`), or undefined for the default program. */
function scenarioPou(csv: string): string | undefined {
  const m = /^\s*#\s*pou\s*:\s*(.+?)\s*$/im.exec(csv);
  return m?.[1];
}

function renameInScenarios(project: Project, scope: VariableScope, from: string, to: string): Scenario[] | undefined {
  const list = project.scenarios ?? [];
  const pou = scope === 'globals' ? undefined : project.pous.find((p) => p.id === scope);
  const concerns = (s: Scenario) => {
    const target = scenarioPou(s.csv);
    const runs: Pou | undefined = target
      ? project.pous.find((p) => p.name.toUpperCase() === target.toUpperCase())
      : project.pous.find((p) => p.kind === 'PROGRAM');
    if (scope === 'globals') return !runs || !declaresLocally(runs, from);
    return runs === pou;
  };
  let changed = false;
  const next = list.map((s) => {
    if (!concerns(s)) return s;
    const csv = renameInScenarioCsv(s.csv, from, to);
    if (csv === s.csv) return s;
    changed = true;
    return { ...s, csv };
  });
  return changed ? next : undefined;
}

/** `names` (watch, trend) with those naming `from` renamed to `to`; the same array when none. */
export function renameInNames(names: readonly string[], from: string, to: string): readonly string[] {
  const next = names.map((n) => {
    // `Main.Motor` (an instance path) or `Motor`, `Motor.Q`.
    const direct = renameOperand(n, from, to);
    if (direct !== n) return direct;
    const dot = n.indexOf('.');
    if (dot < 0) return n;
    const tail = renameOperand(n.slice(dot + 1), from, to);
    return tail === n.slice(dot + 1) ? n : `${n.slice(0, dot + 1)}${tail}`;
  });
  return next.every((n, i) => n === names[i]) ? names : next;
}

/**
 * Renames the variable `from` to `to` in every scope that declares it (the globals and/or POUs),
 * with every use and the scenarios' columns, as one undo step named `stepName`. Returns the scopes
 * renamed, or a reason when it cannot (not an identifier, the name taken in one of the scopes).
 */
export function renameVariable(
  doc: DocumentStore,
  from: string,
  to: string,
  scopes: readonly VariableScope[],
  stepName = `Rename ${from} → ${to}`,
): { ok: true } | { ok: false; reason: string } {
  if (!IDENT.test(to)) return { ok: false, reason: `"${to}" is not a valid name (a letter or _, then letters, digits, _)` };
  const project = doc.getState().project;
  for (const sc of scopes) {
    const vars = sc === 'globals' ? project.globals : (project.pous.find((p) => p.id === sc)?.variables ?? []);
    const taken = vars.find((v) => v.name.toUpperCase() === to.toUpperCase() && v.name.toUpperCase() !== from.toUpperCase());
    if (taken) {
      const where = sc === 'globals' ? 'the globals' : `POU ${project.pous.find((p) => p.id === sc)?.name}`;
      return { ok: false, reason: `"${to}" is already declared in ${where}` };
    }
  }
  // A global's VAR_EXTERNAL declarations are renamed with it (updateVariable): the new name must be free there too.
  if (scopes.includes('globals')) {
    const same = (a: string, b: string) => a.toUpperCase() === b.toUpperCase();
    const blocked = project.pous.find(
      (p) => p.variables.some((v) => v.varClass === 'external' && same(v.name, from)) && p.variables.some((v) => same(v.name, to) && !same(v.name, from)),
    );
    if (blocked) return { ok: false, reason: `"${to}" is already declared in POU ${blocked.name}, which uses the global ${from} as VAR_EXTERNAL` };
  }
  doc.getState().batch(stepName, () => {
    for (const sc of scopes) {
      const declared =
        sc === 'globals' ? project.globals : (project.pous.find((p) => p.id === sc)?.variables ?? []);
      const v = declared.find((d) => d.name.toUpperCase() === from.toUpperCase());
      if (!v) continue;
      doc.getState().updateVariable(v.name, { name: to }, sc);
      const scenarios = renameInScenarios(doc.getState().project, sc, v.name, to);
      if (scenarios) doc.getState().updateProject({ scenarios });
    }
  });
  return { ok: true };
}

/** A name a replacement leaves in a variable field that nothing declares, and where. */
export interface Undeclared {
  readonly name: string;
  readonly replacement: Replacement;
}

/**
 * Names the replacements would leave undeclared: the new text of a variable field whose name
 * (before any `.member`) no declaration in scope has, not counting names `declaredToo` adds.
 */
export function undeclaredAfter(
  project: Project,
  replacements: readonly Replacement[],
  declaredToo: readonly string[] = [],
): Undeclared[] {
  const extra = new Set(declaredToo.map((n) => n.toUpperCase()));
  const out: Undeclared[] = [];
  for (const r of replacements) {
    if (r.place.field !== 'variable') continue;
    const head = r.after.trim().split('.')[0] ?? '';
    if (!head || extra.has(head.toUpperCase())) continue;
    const pou = project.pous.find((p) => p.id === r.place.pou);
    if (!pou || findVariable(project, pou, head)) continue;
    // A direct address (%IX0.0) needs no declaration.
    if (head.startsWith('%')) continue;
    out.push({ name: head, replacement: r });
  }
  return out;
}

/** What a Find/Replace does: a rename of the declared variable the query names whole, and/or text replacements. */
export interface ReplacePlan {
  /** The query names a declared variable whole: renamed (declaration, uses, scenarios) to `to`. */
  readonly rename?: { readonly from: string; readonly to: string; readonly scopes: readonly VariableScope[] };
  /** The uses the rename rewrites (shown in the preview). */
  readonly renamedUses: readonly Replacement[];
  /** Text replacements besides the rename. */
  readonly replacements: readonly Replacement[];
  /** Names the replacements would leave undeclared (the user is asked before they apply). */
  readonly undeclared: readonly Undeclared[];
}

/**
 * The plan of a replace-all. When the query (text or whole-name mode) is exactly the name of a
 * declared variable and the replacement is a name, the references to it become a rename.
 */
export function planFindReplace(project: Project, q: FindQuery, by: string): ReplacePlan | string {
  const all = planReplace(project, q, by);
  if (typeof all === 'string') return all;
  const from = q.text.trim();
  const scopes =
    q.mode !== 'regex' && IDENT.test(from) && IDENT.test(by.trim())
      ? declarationsOf(project, from, q.caseSensitive)
      : [];
  if (scopes.length === 0)
    return { renamedUses: [], replacements: all, undeclared: undeclaredAfter(project, all) };
  const to = by.trim();
  const renamedUses: Replacement[] = [];
  const replacements: Replacement[] = [];
  for (const r of all) {
    const pou = project.pous.find((p) => p.id === r.place.pou);
    const head = r.before.trim().split('.')[0] ?? '';
    const isUse =
      r.place.field === 'variable' &&
      head.toUpperCase() === from.toUpperCase() &&
      pou !== undefined &&
      findVariable(project, pou, head) !== undefined &&
      renameOperand(r.before, from, to) === r.after;
    (isUse ? renamedUses : replacements).push(r);
  }
  return {
    rename: { from, to, scopes },
    renamedUses,
    replacements,
    undeclared: undeclaredAfter(project, replacements, [to]),
  };
}

/** Applies a plan as one undo step; returns a reason when the rename cannot apply. */
export function applyFindReplace(doc: DocumentStore, plan: ReplacePlan): { ok: true } | { ok: false; reason: string } {
  let result: { ok: true } | { ok: false; reason: string } = { ok: true };
  const name = plan.rename ? `Rename ${plan.rename.from} → ${plan.rename.to}` : 'replace';
  doc.getState().batch(name, () => {
    if (plan.rename) {
      result = renameVariable(doc, plan.rename.from, plan.rename.to, plan.rename.scopes, name);
      if (!result.ok) return;
    }
    if (plan.replacements.length)
      doc.getState().replaceNetworks(name, applyReplacements(doc.getState().project, plan.replacements));
  });
  return result;
}
