// What a print contains, in order, before any layout: per POU a heading, its networks (or its
// source text for a POU kept in ST), its variable list; the global variables; the cross-reference
// at the end. Each item names its section (shown in the page's title block) and, for table rows,
// its table (the header repeated on each page). Pure over the project.
import type { Network, Pou, Project, Variable } from '../../model/project';
import type { VariableScope } from '../../store/changes';
import { projectCrossReference, type Access, type XrefUse } from '../../store/xref';
import { CLASS_LABELS, CLASS_ORDER } from '../variables/VariableRow';
import type { PrintOptions } from './printState';

interface Base {
  readonly key: string;
  /** The POU (or "Global variables", "Cross-reference") the title block names. */
  readonly section: string;
}

export type PrintItem =
  | (Base & { readonly kind: 'pou'; readonly pou: Pou })
  | (Base & { readonly kind: 'network'; readonly pou: Pou; readonly index: number; readonly network: Network })
  | (Base & { readonly kind: 'source'; readonly pou: Pou; readonly text: string })
  | (Base & { readonly kind: 'heading'; readonly text: string; readonly note?: string })
  | (Base & { readonly kind: 'note'; readonly text: string })
  | (Base & { readonly kind: 'var'; readonly table: string; readonly variable: Variable; readonly global: boolean })
  | (Base & { readonly kind: 'xref'; readonly table: 'xref'; readonly row: XrefRow });

export interface XrefRow {
  readonly name: string;
  readonly declaredIn: string;
  readonly type: string;
  readonly address: string;
  /** "Main: N1 R, N4 W · Sub: N2 R" */
  readonly uses: string;
  readonly count: number;
}

export const ACCESS_MARK: Readonly<Record<Access, string>> = { read: 'R', write: 'W', 'read/write': 'RW', call: 'C' };

const KIND_WORDS: Readonly<Record<Pou['kind'], string>> = {
  PROGRAM: 'PROGRAM',
  FUNCTION_BLOCK: 'FUNCTION_BLOCK',
  FUNCTION: 'FUNCTION',
};

export const pouTitle = (pou: Pou) =>
  `${KIND_WORDS[pou.kind]} ${pou.name}${pou.kind === 'FUNCTION' && pou.returnType ? ` : ${pou.returnType}` : ''}`;

/** A POU's variables, its interface first (as the variable table sorts them). */
const byClass = (vars: readonly Variable[]) =>
  [...vars].sort((a, b) => CLASS_ORDER.indexOf(a.varClass) - CLASS_ORDER.indexOf(b.varClass));

export const classLabel = (v: Variable, global: boolean) =>
  global ? (v.scope === 'resource' ? 'Resource' : 'Configuration') : CLASS_LABELS[v.varClass];

/** "Main: N1 R, N4 W · Sub: N2 R": each network once per kind of access, POU by POU. */
export function usesText(uses: readonly XrefUse[]): string {
  const perPou = new Map<string, string[]>();
  for (const u of uses) {
    const list = perPou.get(u.pouName) ?? [];
    const text = `N${u.networkIndex + 1} ${ACCESS_MARK[u.access]}`;
    if (!list.includes(text)) list.push(text);
    perPou.set(u.pouName, list);
  }
  return [...perPou].map(([pou, list]) => `${pou}: ${list.join(', ')}`).join(' · ');
}

function xrefRows(project: Project, pous: readonly Pou[], whole: boolean): XrefRow[] {
  const all = projectCrossReference(project);
  const only = new Set(pous.map((p) => p.id));
  const row = (scope: VariableScope, v: Variable, declaredIn: string): XrefRow => {
    const uses = (all.get(scope)?.get(v.name.toUpperCase()) ?? []).filter((u) => only.has(u.pou));
    return {
      name: v.name,
      declaredIn,
      type: v.type,
      address: v.location ?? '',
      uses: uses.length ? usesText(uses) : '—',
      count: uses.length,
    };
  };
  const rows: XrefRow[] = [];
  for (const pou of pous) for (const v of byClass(pou.variables)) rows.push(row(pou.id, v, pou.name));
  // Printing one POU: the globals it uses; the whole project: every global.
  for (const v of project.globals) {
    const r = row('globals', v, 'Global');
    if (whole || r.count > 0) rows.push(r);
  }
  return rows.sort((a, b) => a.name.localeCompare(b.name, 'en', { sensitivity: 'base', numeric: true }) || a.declaredIn.localeCompare(b.declaredIn));
}

/** The POUs the options print: the chosen one, or all of them in project order. */
export function printedPous(project: Project, options: PrintOptions): Pou[] {
  const { scope } = options;
  if (scope.kind === 'project') return [...project.pous];
  const pou = project.pous.find((p) => p.id === scope.pou);
  return pou ? [pou] : [];
}

export function printItems(project: Project, options: PrintOptions): PrintItem[] {
  const whole = options.scope.kind === 'project';
  const pous = printedPous(project, options);
  const items: PrintItem[] = [];
  for (const pou of pous) {
    const section = pou.name;
    items.push({ kind: 'pou', key: `pou:${pou.id}`, section, pou });
    if (pou.language !== 'LD') {
      items.push({ kind: 'source', key: `src:${pou.id}`, section, pou, text: pou.source ?? '' });
    } else if (pou.networks.length === 0) {
      items.push({ kind: 'note', key: `none:${pou.id}`, section, text: 'No networks.' });
    }
    if (pou.language === 'LD')
      pou.networks.forEach((network, index) =>
        items.push({ kind: 'network', key: `net:${network.id}`, section, pou, index, network }),
      );
    if (options.variables) {
      const table = `vars:${pou.id}`;
      items.push({ kind: 'heading', key: `${table}:h`, section, text: `Variables of ${pou.name}` });
      if (pou.variables.length === 0)
        items.push({ kind: 'note', key: `${table}:none`, section, text: 'No variables.' });
      for (const [i, variable] of byClass(pou.variables).entries())
        items.push({ kind: 'var', key: `${table}:${i}`, section, table, variable, global: false });
    }
  }
  if (options.variables && whole && project.globals.length > 0) {
    const section = 'Global variables';
    items.push({ kind: 'heading', key: 'globals:h', section, text: 'Global variables' });
    for (const [i, variable] of project.globals.entries())
      items.push({ kind: 'var', key: `globals:${i}`, section, table: 'globals', variable, global: true });
  }
  if (options.crossReference) {
    const section = 'Cross-reference';
    items.push({
      kind: 'heading',
      key: 'xref:h',
      section,
      text: 'Cross-reference',
      note: 'Uses per POU by network: N3 = network 3; R read, W write, RW read/write (VAR_IN_OUT), C call of an instance.',
    });
    for (const [i, row] of xrefRows(project, pous, whole).entries())
      items.push({ kind: 'xref', key: `xref:${i}`, section, table: 'xref', row });
  }
  return items;
}
