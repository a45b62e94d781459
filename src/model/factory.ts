// Small pure helpers to build and query projects.
import { boxLayout } from './boxLayout';
import type { LdElement } from './elements';
import type { BlockLibrary } from './library';
import { newId, type NetworkId, type PouId } from './ids';
import { PROJECT_FORMAT, PROJECT_VERSION, type Network, type Pou, type Project, type Variable } from './project';

export const DEFAULT_COLS = 10;
export const DEFAULT_ROWS = 3;

export function newNetwork(partial: Partial<Network> = {}): Network {
  return {
    id: newId<'NetworkId'>('n') as NetworkId,
    title: '',
    comment: '',
    rows: DEFAULT_ROWS,
    cols: DEFAULT_COLS,
    elements: [],
    vlinks: [],
    ...partial,
  };
}

export function newPou(name = 'Main', partial: Partial<Pou> = {}): Pou {
  return {
    id: newId<'PouId'>('p') as PouId,
    name,
    kind: 'PROGRAM',
    language: 'LD',
    comment: '',
    variables: [],
    networks: [newNetwork()],
    ...partial,
  };
}

export function newProject(name = 'Untitled', partial: Partial<Project> = {}): Project {
  const main = newPou('Main');
  return {
    format: PROJECT_FORMAT,
    version: PROJECT_VERSION,
    name,
    description: '',
    profile: 'iec',
    pous: [main],
    globals: [],
    tasks: [{ name: 'MainTask', cycleMs: 10, priority: 1, programs: [{ instance: 'MainInstance', pou: main.name }] }],
    ...partial,
  };
}

export const variable = (name: string, type: string, extra: Partial<Variable> = {}): Variable => ({
  name,
  type,
  varClass: 'local',
  retain: false,
  comment: '',
  ...extra,
});

/** Rows and columns an element covers: 1x1, or the box's layout size (1x1 for an unknown block). */
export function elementSize(el: LdElement, library?: BlockLibrary): { rows: number; cols: number } {
  if (el.kind !== 'box') return { rows: 1, cols: 1 };
  const layout = boxLayout(el, library);
  return layout ? { rows: layout.rows, cols: layout.cols } : { rows: 1, cols: 1 };
}

/** Every cell an element covers. */
export function elementCells(el: LdElement, library?: BlockLibrary): { row: number; col: number }[] {
  const { rows, cols } = elementSize(el, library);
  const out: { row: number; col: number }[] = [];
  for (let r = 0; r < rows; r++) for (let c = 0; c < cols; c++) out.push({ row: el.row + r, col: el.col + c });
  return out;
}

/** The POU variable (or global) with this name, case-insensitively as IEC identifiers are. */
export function findVariable(project: Project, pou: Pou, name: string): Variable | undefined {
  const key = name.toUpperCase();
  return byName(pou.variables).get(key) ?? byName(project.globals).get(key);
}

/**
 * Variables by upper-case name (the first of a name wins, as a linear search would find it), kept
 * per list: documents are immutable, so a list is indexed once, not once per operand (a compile of
 * 650 networks looked names up ~10,000 times). The length guards a list grown in place by a caller.
 */
const nameIndexes = new WeakMap<readonly Variable[], { readonly length: number; readonly map: Map<string, Variable> }>();
function byName(variables: readonly Variable[]): Map<string, Variable> {
  const cached = nameIndexes.get(variables);
  if (cached && cached.length === variables.length) return cached.map;
  const map = new Map<string, Variable>();
  for (const v of variables) {
    const key = v.name.toUpperCase();
    if (!map.has(key)) map.set(key, v);
  }
  nameIndexes.set(variables, { length: variables.length, map });
  return map;
}
