// Checks one data type the way the editor shows it: each problem names the field it belongs to
// (a member's row, a dimension, the base) so the editor marks that field and lists the message.
import { checkDataTypes, resolveType } from '../../model/dataTypes';
import { IDENTIFIER_RE, INT_INFO } from '../../model/iecTypes';
import type { DataType, Project } from '../../model/project';
import { SUBRANGE_BASES, typeTextProblem } from './typeText';

/**
 * Where a problem sits: 'value:2', 'member:1:name', 'member:0:type', 'dim:0', 'of', 'base',
 * 'bounds', 'initial', 'type' (the type as a whole: it contains itself).
 */
export interface DataTypeProblem {
  readonly field: string;
  readonly message: string;
}

const identifierWords = (what: string, name: string): string | undefined =>
  IDENTIFIER_RE.test(name.trim()) && !name.includes('__')
    ? undefined
    : `${what} "${name}" is not an IEC identifier (letters, digits and single underscores)`;

/** Duplicates in a list of names (ignoring case): one problem for each later copy. */
function duplicates(names: readonly string[], field: (i: number) => string, what: string): DataTypeProblem[] {
  const first = new Map<string, number>();
  const out: DataTypeProblem[] = [];
  names.forEach((n, i) => {
    const key = n.trim().toUpperCase();
    const at = first.get(key);
    if (at === undefined) first.set(key, i);
    else out.push({ field: field(i), message: `${what} ${n} is already in row ${at + 1}` });
  });
  return out;
}

/** The range a subrange base holds, for checking the bounds. */
function baseRange(base: string): { min: bigint; max: bigint } | undefined {
  const info = INT_INFO[base.trim().toUpperCase() as keyof typeof INT_INFO];
  if (!info) return undefined;
  const bits = BigInt(info.bits);
  return info.signed
    ? { min: -(1n << (bits - 1n)), max: (1n << (bits - 1n)) - 1n }
    : { min: 0n, max: (1n << bits) - 1n };
}

export function dataTypeProblems(project: Project, t: DataType): DataTypeProblem[] {
  const out: DataTypeProblem[] = [];
  const typeField = (field: string, text: string, what: string) => {
    const problem = typeTextProblem(project, text);
    if (problem) out.push({ field, message: `${what}: ${problem}` });
  };
  const def = t.def;
  switch (def.kind) {
    case 'enum':
      if (def.values.length === 0) out.push({ field: 'values', message: 'an enumeration needs at least one value' });
      def.values.forEach((v, i) => {
        const bad = identifierWords('value', v);
        if (bad) out.push({ field: `value:${i}`, message: bad });
      });
      out.push(...duplicates(def.values, (i) => `value:${i}`, 'value'));
      break;
    case 'struct':
      if (def.members.length === 0) out.push({ field: 'members', message: 'a structure needs at least one member' });
      def.members.forEach((m, i) => {
        const bad = identifierWords('member', m.name);
        if (bad) out.push({ field: `member:${i}:name`, message: bad });
        typeField(`member:${i}:type`, m.type, `member ${m.name}`);
      });
      out.push(...duplicates(def.members.map((m) => m.name), (i) => `member:${i}:name`, 'member'));
      break;
    case 'array':
      if (def.dims.length === 0) out.push({ field: 'dims', message: 'an array needs at least one dimension' });
      def.dims.forEach((d, i) => {
        if (!Number.isInteger(d.lower) || !Number.isInteger(d.upper))
          out.push({ field: `dim:${i}`, message: `dimension ${i + 1}: bounds are whole numbers` });
        else if (d.lower > d.upper)
          out.push({ field: `dim:${i}`, message: `dimension ${i + 1}: lower bound ${d.lower} is above upper bound ${d.upper}` });
      });
      typeField('of', def.of, 'element type');
      break;
    case 'subrange': {
      if (!(SUBRANGE_BASES as readonly string[]).includes(def.base.trim().toUpperCase()))
        out.push({ field: 'base', message: `a subrange narrows an integer type (${SUBRANGE_BASES.join(', ')}), not ${def.base}` });
      if (def.lower > def.upper)
        out.push({ field: 'bounds', message: `lower bound ${def.lower} is above upper bound ${def.upper}` });
      const range = baseRange(def.base);
      if (range && (BigInt(def.lower) < range.min || BigInt(def.upper) > range.max))
        out.push({ field: 'bounds', message: `${def.lower}..${def.upper} does not fit ${def.base.toUpperCase()} (${range.min}..${range.max})` });
      break;
    }
    case 'alias':
      typeField('base', def.base, 'base type');
      break;
  }
  // What the fields do not show: the type containing itself, and initial values (the model's
  // checks, src/model/dataTypes.ts, whose initial-value messages start with the type's path).
  const whole = resolveType(project, t.name);
  if (!whole.ok && out.length === 0) out.push({ field: 'type', message: whole.message });
  if (whole.ok) {
    const path = new RegExp(`^${t.name}[.[:]`, 'i');
    for (const c of checkDataTypes(project))
      if (c.name === t.name && path.test(c.message)) out.push({ field: 'initial', message: c.message });
  }
  return out;
}
