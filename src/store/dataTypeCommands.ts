// The data-type commands (add, rename, duplicate, delete, update) and the pure edits behind them:
// names, where a data type is used, and the changes that make references follow a rename (variable
// types in every POU and the globals, function return types, other data types' members, bases and
// element types, inline `ARRAY[..] OF Name`). Each command is one undo step: the project's
// `dataTypes` list is replaced by one 'project.update' change, plus the follow-up variable and POU
// changes. See the list at the top of documentStore.ts.
import { blockSignature } from '../model/blocks';
import { isElementaryType } from '../model/iecTypes';
import type { DataType, DataTypeDef, Project, Variable } from '../model/project';
import type { Change, VariableScope } from './changes';

export type DataTypeKind = DataTypeDef['kind'];

export const DATA_TYPE_KIND_WORDS: Record<DataTypeKind, string> = {
  enum: 'enumeration',
  struct: 'structure',
  array: 'array',
  subrange: 'subrange',
  alias: 'alias',
};

const same = (a: string, b: string) => a.trim().toUpperCase() === b.trim().toUpperCase();
const IDENTIFIER = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** Why `name` cannot name a data type of the project (another one than `except`), or undefined. */
export function dataTypeNameProblem(project: Project, name: string, except?: string): string | undefined {
  const n = name.trim();
  if (n === '') return 'A data type needs a name.';
  if (!IDENTIFIER.test(n) || n.includes('__') || n.endsWith('_'))
    return `"${n}" is not an IEC identifier (letters, digits and single underscores, not starting with a digit).`;
  const upper = n.toUpperCase();
  if (isElementaryType(upper) || upper === 'STRING' || upper === 'WSTRING' || upper === 'ARRAY' || upper === 'STRUCT')
    return `"${n}" is the name of the type ${upper}.`;
  if (blockSignature(n)) return `"${n}" is the name of the standard block ${upper}.`;
  const pou = project.pous.find((p) => same(p.name, n));
  if (pou) return `The project already has a POU named ${pou.name}.`;
  const other = (project.dataTypes ?? []).find((t) => same(t.name, n) && (except === undefined || !same(t.name, except)));
  if (other) return `The project already has a data type named ${other.name}.`;
  return undefined;
}

/** `base`, or `base2`, `base3`... the first name free for a data type. */
export function freshDataTypeName(project: Project, base: string): string {
  if (!dataTypeNameProblem(project, base)) return base;
  for (let i = 2; ; i++) if (!dataTypeNameProblem(project, `${base}${i}`)) return `${base}${i}`;
}

/** What a new data type of each kind starts as. */
export function newDataTypeDef(kind: DataTypeKind): DataTypeDef {
  switch (kind) {
    case 'enum':
      return { kind, values: ['VALUE1', 'VALUE2'] };
    case 'struct':
      return { kind, members: [{ name: 'Member1', type: 'INT' }] };
    case 'array':
      return { kind, dims: [{ lower: 1, upper: 10 }], of: 'INT' };
    case 'subrange':
      return { kind, base: 'INT', lower: 0, upper: 100 };
    case 'alias':
      return { kind, base: 'INT' };
  }
}

const DEFAULT_NAMES: Record<DataTypeKind, string> = {
  enum: 'Enum',
  struct: 'Struct',
  array: 'ArrayType',
  subrange: 'Subrange',
  alias: 'Alias',
};

/** `text` with every whole-word occurrence of identifier `from` (any case) replaced by `to`. */
export function renameTypeInText(text: string, from: string, to: string): string {
  const escaped = from.replace(/[^A-Za-z0-9_]/g, '');
  if (escaped === '') return text;
  return text.replace(new RegExp(`(?<![A-Za-z0-9_])${escaped}(?![A-Za-z0-9_])`, 'gi'), to);
}

/** True when the type text names `name` (`Point`, `ARRAY[1..3] OF Point`). */
export const typeTextUses = (text: string, name: string): boolean => renameTypeInText(text, name, '\u0000') !== text;

/** The type names a definition refers to (members' types, base, element type). */
export function defTypeTexts(def: DataTypeDef): string[] {
  switch (def.kind) {
    case 'enum':
      return [];
    case 'struct':
      return def.members.map((m) => m.type);
    case 'array':
      return [def.of];
    case 'subrange':
    case 'alias':
      return [def.base];
  }
}

function retypeDef(def: DataTypeDef, from: string, to: string): DataTypeDef {
  const r = (t: string) => renameTypeInText(t, from, to);
  switch (def.kind) {
    case 'enum':
      return def;
    case 'struct':
      return { ...def, members: def.members.map((m) => (typeTextUses(m.type, from) ? { ...m, type: r(m.type) } : m)) };
    case 'array':
      return typeTextUses(def.of, from) ? { ...def, of: r(def.of) } : def;
    case 'subrange':
    case 'alias':
      return typeTextUses(def.base, from) ? { ...def, base: r(def.base) } : def;
  }
}

/** One place that uses a data type. */
export type DataTypeUse =
  | { readonly kind: 'variable'; readonly scope: VariableScope; readonly owner: string; readonly variable: string }
  | { readonly kind: 'return'; readonly pou: string }
  | { readonly kind: 'type'; readonly type: string };

/** Every variable declaration, function return type and other data type naming the data type `name`. */
export function dataTypeUsages(project: Project, name: string): DataTypeUse[] {
  const out: DataTypeUse[] = [];
  for (const pou of project.pous) {
    if (pou.returnType && typeTextUses(pou.returnType, name)) out.push({ kind: 'return', pou: pou.name });
    for (const v of pou.variables)
      if (typeTextUses(v.type, name)) out.push({ kind: 'variable', scope: pou.id, owner: pou.name, variable: v.name });
  }
  for (const v of project.globals)
    if (typeTextUses(v.type, name))
      out.push({ kind: 'variable', scope: 'globals', owner: 'global variables', variable: v.name });
  for (const t of project.dataTypes ?? [])
    if (!same(t.name, name) && defTypeTexts(t.def).some((x) => typeTextUses(x, name)))
      out.push({ kind: 'type', type: t.name });
  return out;
}

/** "Main: variable P", "function Dist: return type", "data type Line". */
export function describeDataTypeUse(u: DataTypeUse): string {
  switch (u.kind) {
    case 'variable':
      return `${u.owner}: variable ${u.variable}`;
    case 'return':
      return `function ${u.pou}: return type`;
    case 'type':
      return `data type ${u.type}`;
  }
}

const setTypes = (project: Project, dataTypes: readonly DataType[]): Change => ({
  type: 'project.update',
  before: { dataTypes: project.dataTypes },
  after: { dataTypes },
});

/** The changes renaming data type `from` to `to`: the type, and every declaration naming it. */
export function renameDataTypeChanges(project: Project, from: string, to: string): Change[] {
  const types = (project.dataTypes ?? []).map((t) => {
    const renamed = same(t.name, from) ? { ...t, name: to } : t;
    const def = retypeDef(renamed.def, from, to);
    return def === renamed.def ? renamed : { ...renamed, def };
  });
  const changes: Change[] = [setTypes(project, types)];
  const scan = (scope: VariableScope, vars: readonly Variable[]) =>
    vars.forEach((v, index) => {
      if (typeTextUses(v.type, from))
        changes.push({
          type: 'variable.update',
          scope,
          index,
          before: v,
          after: { ...v, type: renameTypeInText(v.type, from, to) },
        });
    });
  for (const pou of project.pous) {
    scan(pou.id, pou.variables);
    if (pou.returnType && typeTextUses(pou.returnType, from))
      changes.push({
        type: 'pou.update',
        pou: pou.id,
        before: { returnType: pou.returnType },
        after: { returnType: renameTypeInText(pou.returnType, from, to) },
      });
  }
  scan('globals', project.globals);
  return changes;
}

/** Editable parts of a data type; `initial`/`comment` '' or undefined remove the field. */
export type DataTypePatch = Partial<Pick<DataType, 'def' | 'initial' | 'comment'>>;

export interface DataTypeCommandOps {
  project(): Project;
  commit(name: string, changes: readonly Change[]): void;
}

export interface DataTypeCommands {
  /** Adds a data type of that kind (a fresh name unless given); returns its name. */
  addDataType(kind: DataTypeKind, name?: string): string | undefined;
  renameDataType(name: string, to: string): boolean;
  /** A copy "<name>_copy" right after it; returns the copy's name. */
  duplicateDataType(name: string): string | undefined;
  /** Removes it; declarations naming it stay (the checks report them). */
  deleteDataType(name: string): boolean;
  updateDataType(name: string, patch: DataTypePatch): boolean;
}

export function dataTypeCommands({ project, commit }: DataTypeCommandOps): DataTypeCommands {
  const list = () => project().dataTypes ?? [];
  const indexOf = (name: string) => list().findIndex((t) => same(t.name, name));
  return {
    addDataType: (kind, name) => {
      const p = project();
      const chosen = name?.trim() || freshDataTypeName(p, DEFAULT_NAMES[kind]);
      if (dataTypeNameProblem(p, chosen)) return undefined;
      commit('addDataType', [setTypes(p, [...list(), { name: chosen, def: newDataTypeDef(kind) }])]);
      return chosen;
    },
    renameDataType: (name, to) => {
      const p = project();
      const t = list()[indexOf(name)];
      const target = to.trim();
      if (!t || dataTypeNameProblem(p, target, t.name)) return false;
      if (target === t.name) return true;
      commit('renameDataType', renameDataTypeChanges(p, t.name, target));
      return true;
    },
    duplicateDataType: (name) => {
      const p = project();
      const i = indexOf(name);
      const t = list()[i];
      if (!t) return undefined;
      const copy = { ...t, name: freshDataTypeName(p, `${t.name}_copy`) };
      const types = [...list()];
      types.splice(i + 1, 0, copy);
      commit('duplicateDataType', [setTypes(p, types)]);
      return copy.name;
    },
    deleteDataType: (name) => {
      const p = project();
      const i = indexOf(name);
      if (i < 0) return false;
      commit('deleteDataType', [setTypes(p, list().filter((_, j) => j !== i))]);
      return true;
    },
    updateDataType: (name, patch) => {
      const p = project();
      const i = indexOf(name);
      const t = list()[i];
      if (!t) return false;
      const next: Record<string, unknown> = { ...t };
      if (patch.def) next.def = patch.def;
      for (const k of ['initial', 'comment'] as const)
        if (k in patch) {
          const v = patch[k]?.trim();
          if (v) next[k] = v;
          else delete next[k];
        }
      const updated = next as unknown as DataType;
      if (JSON.stringify(updated) === JSON.stringify(t)) return false;
      commit('updateDataType', [setTypes(p, list().map((x, j) => (j === i ? updated : x)))]);
      return true;
    },
  };
}
