// Type texts as the editor shows and offers them, over the model's resolution
// (src/model/dataTypes.ts): whether a type text is known, the choices of a type field, and a data
// type written as IEC text.
import { resolveType } from '../../model/dataTypes';
import { ELEMENTARY_TYPES } from '../../model/iecTypes';
import { blockLibrary } from '../../model/library';
import type { DataType, Project } from '../../model/project';

/** Why the type text is not a type of the project (src/model/dataTypes.ts resolveType), or undefined. */
export function typeTextProblem(project: Project, text: string): string | undefined {
  if (text.trim() === '') return 'choose a type';
  const r = resolveType(project, text);
  return r.ok ? undefined : r.message;
}

/** Integer types a subrange may narrow. */
export const SUBRANGE_BASES = ['SINT', 'INT', 'DINT', 'LINT', 'USINT', 'UINT', 'UDINT', 'ULINT'] as const;

/** The data type as IEC text: `TYPE Point : STRUCT X : INT; Y : INT; END_STRUCT; END_TYPE`. */
export function declarationText(t: DataType): string {
  const init = (v: string | undefined) => (v ? ` := ${v}` : '');
  const def = t.def;
  let body: string;
  switch (def.kind) {
    case 'enum':
      body = `(${def.values.join(', ')})${init(t.initial)};`;
      break;
    case 'struct':
      body = `STRUCT\n${def.members.map((m) => `    ${m.name} : ${m.type}${init(m.initial)};${m.comment ? ` (* ${m.comment} *)` : ''}\n`).join('')}  END_STRUCT${init(t.initial)};`;
      break;
    case 'array':
      body = `ARRAY[${def.dims.map((d) => `${d.lower}..${d.upper}`).join(', ')}] OF ${def.of}${init(t.initial)};`;
      break;
    case 'subrange':
      body = `${def.base} (${def.lower}..${def.upper})${init(t.initial)};`;
      break;
    case 'alias':
      body = `${def.base}${init(t.initial)};`;
      break;
  }
  return `TYPE\n  ${t.name} : ${body}\nEND_TYPE`;
}

/** Type names the editor offers in a type field: elementary types, then the project's data types and FBs. */
export function typeChoices(project: Project): { elementary: readonly string[]; dataTypes: string[]; fbs: string[] } {
  const lib = blockLibrary(project);
  return {
    elementary: ELEMENTARY_TYPES,
    dataTypes: (project.dataTypes ?? []).map((t) => t.name),
    fbs: lib.all().filter((s) => s.kind === 'fb').map((s) => s.name),
  };
}
