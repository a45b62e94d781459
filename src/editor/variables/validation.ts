// Checks a variable table the way a PLC programmer expects to be told about mistakes: per row and
// per field, in plain words. Pure functions: the table shows the result inline.
import { IEC_DECLARATION_WORDS, ST_OPERATOR_WORDS, ST_STATEMENT_WORDS } from '../../engine/st/lexer';
import { blockSignature } from '../../model/blocks';
import { anonymousType, leafPaths, resolveType } from '../../model/dataTypes';
import { blockLibrary, STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import {
  IDENTIFIER_RE,
  isElementaryType,
  locationAdmits,
  parseLocation,
  locationText,
  parseSizedString,
  type ElementaryType,
  type ParsedLocation,
} from '../../model/iecTypes';
import type { Project, Variable } from '../../model/project';
import { checkInitialValue } from './initialValue';

export type VariableField = 'name' | 'type' | 'varClass' | 'location' | 'initial' | 'retain' | 'constant';

export interface VariableIssue {
  /** Row in the checked list. */
  readonly index: number;
  readonly field: VariableField;
  readonly message: string;
}

/** Words IEC 61131-3 reserves, which cannot name a variable (types and block names are added below). */
const KEYWORDS = [
  ...ST_OPERATOR_WORDS,
  // CONTINUE (IEC 3rd edition) is not reserved for variable names: older projects use it as one.
  ...ST_STATEMENT_WORDS.filter((w) => w !== 'CONTINUE'),
  ...IEC_DECLARATION_WORDS,
  ...[
    'DATE',
    'TIME_OF_DAY',
    'TOD',
    'DATE_AND_TIME',
    'DT',
    'EN',
    'ENO',
    'CONFIGURATION',
    'RESOURCE',
    'TASK',
    'WITH',
    'ON',
  ],
];
const RESERVED = new Set(KEYWORDS);

/** Why `name` cannot be an IEC variable name, or undefined when it can. */
export function identifierProblem(name: string): string | undefined {
  const trimmed = name.trim();
  if (trimmed === '') return 'a variable needs a name';
  if (!IDENTIFIER_RE.test(trimmed)) {
    return `"${trimmed}" is not an IEC identifier: use letters, digits and underscores, starting with a letter or underscore`;
  }
  if (trimmed.includes('__'))
    return `"${trimmed}" has two underscores in a row, which IEC identifiers do not allow`;
  if (trimmed.endsWith('_'))
    return `"${trimmed}" ends with an underscore, which IEC identifiers do not allow`;
  const upper = trimmed.toUpperCase();
  if (RESERVED.has(upper) || isElementaryType(upper)) return `"${trimmed}" is a reserved word in IEC 61131-3`;
  if (blockSignature(upper)) return `"${trimmed}" is the name of the standard block ${upper}`;
  return undefined;
}

export const isKnownVariableType = (type: string, lib: BlockLibrary = STANDARD_LIBRARY): boolean =>
  isElementaryType(type.toUpperCase()) || parseSizedString(type) !== undefined || lib.isFbType(type);

/** An address in one canonical spelling, so %ix0.0 and %IX0.0 compare equal. */
export const canonicalLocation = (loc: ParsedLocation): string => locationText(loc);

/** Every located variable of the project, by canonical address, with who holds it. */
export function addressOwners(project: Project): Map<string, { pou: string | undefined; name: string }[]> {
  const owners = new Map<string, { pou: string | undefined; name: string }[]>();
  const add = (pou: string | undefined, v: Variable) => {
    const loc = v.location ? parseLocation(v.location) : undefined;
    if (!loc) return;
    const key = canonicalLocation(loc);
    owners.set(key, [...(owners.get(key) ?? []), { pou, name: v.name }]);
  };
  project.globals.forEach((v) => add(undefined, v));
  project.pous.forEach((pou) => pou.variables.forEach((v) => add(pou.name, v)));
  return owners;
}

function checkLocation(
  v: Variable,
  index: number,
  issues: VariableIssue[],
  lib: BlockLibrary,
): ParsedLocation | undefined {
  const text = v.location?.trim();
  if (!text) return undefined;
  const loc = parseLocation(text);
  if (!loc) {
    issues.push({
      index,
      field: 'location',
      message: `"${text}" is not an IEC address: write e.g. %IX0.0 (input bit), %QX0.1 (output bit), %MX2.3, %IW0, %QW1, %MW10, %MD4`,
    });
    return undefined;
  }
  const type = v.type.trim().toUpperCase();
  if (lib.isFbType(type)) {
    issues.push({
      index,
      field: 'location',
      message: `a ${lib.signature(type)?.name ?? type} instance cannot sit at an address`,
    });
  } else if (isElementaryType(type) && !locationAdmits(loc, type)) {
    const sizeWords = {
      X: 'a bit (BOOL)',
      B: 'a byte',
      W: 'a 16-bit word',
      D: 'a 32-bit double word',
      L: 'a 64-bit long word',
    };
    issues.push({
      index,
      field: 'location',
      message: `${canonicalLocation(loc)} holds ${sizeWords[loc.size]}, which does not fit type ${type}`,
    });
  }
  if (v.varClass === 'temp' || v.varClass === 'inOut' || v.varClass === 'external') {
    issues.push({
      index,
      field: 'location',
      message: `a ${CLASS_WORDS[v.varClass]} variable cannot be given an address`,
    });
  }
  return loc;
}

export const CLASS_WORDS: Record<Variable['varClass'], string> = {
  local: 'local',
  input: 'input',
  output: 'output',
  inOut: 'in-out',
  external: 'external',
  temp: 'temporary',
};

export interface ValidationScope {
  /** The whole project, to find addresses used elsewhere. */
  readonly project?: Project;
  /** Name of the POU owning `variables` (undefined for the global list). */
  readonly pou?: string;
}

/** Checks one variable list (a POU's variables or the globals). */
export function validateVariables(
  variables: readonly Variable[],
  scope: ValidationScope = {},
): VariableIssue[] {
  const issues: VariableIssue[] = [];
  const byName = new Map<string, number>();
  const localAddresses = new Map<string, number>();
  const owners = scope.project ? addressOwners(scope.project) : undefined;
  const lib = blockLibrary(scope.project);
  const owner = scope.pou === undefined ? undefined : scope.project?.pous.find((p) => p.name === scope.pou);
  variables.forEach((v, index) => {
    const nameProblem = identifierProblem(v.name);
    if (nameProblem) issues.push({ index, field: 'name', message: nameProblem });
    else {
      const key = v.name.trim().toUpperCase();
      const first = byName.get(key);
      if (first !== undefined) {
        issues.push({
          index,
          field: 'name',
          message: `"${v.name}" is already declared in row ${first + 1} (names ignore upper/lower case)`,
        });
      } else byName.set(key, index);
    }
    const type = v.type.trim().toUpperCase();
    if (type === '') issues.push({ index, field: 'type', message: 'choose a type' });
    else if (!isKnownVariableType(type, lib)) {
      // A data type of the project or an anonymous type written in place: ARRAY[..] OF, STRUCT ..
      // END_STRUCT, (A, B), INT (0..100) (src/model/dataTypes.ts).
      const resolved = scope.project ? resolveType(scope.project, v.type) : undefined;
      const written = /^ARRAY\b/i.test(v.type.trim()) || anonymousType(v.type) !== undefined;
      if (!resolved?.ok)
        issues.push({
          index,
          field: 'type',
          message: resolved && written ? resolved.message : `unknown type "${v.type}"`,
        });
    } else if (owner?.kind === 'FUNCTION' && lib.isFbType(type))
      issues.push({
        index,
        field: 'type',
        message: `a FUNCTION cannot declare a ${lib.signature(type)?.name ?? type} instance: its state would be lost between calls`,
      });

    const loc = checkLocation(v, index, issues, lib);
    if (loc) {
      const key = canonicalLocation(loc);
      const first = localAddresses.get(key);
      if (first !== undefined) {
        issues.push({
          index,
          field: 'location',
          message: `${key} is already used by "${variables[first]?.name ?? ''}" in row ${first + 1}`,
        });
      } else {
        localAddresses.set(key, index);
        const elsewhere = (owners?.get(key) ?? []).find((o) => o.pou !== scope.pou);
        if (elsewhere) {
          const where = elsewhere.pou === undefined ? 'the global variables' : `POU ${elsewhere.pou}`;
          issues.push({
            index,
            field: 'location',
            message: `${key} is already used by "${elsewhere.name}" in ${where}`,
          });
        }
      }
    }

    if (v.initial !== undefined && v.initial.trim() !== '') {
      if (lib.isFbType(type))
        issues.push({
          index,
          field: 'initial',
          message: `a ${lib.signature(type)?.name ?? type} instance takes no initial value`,
        });
      else if (isElementaryType(type) || parseSizedString(type)) {
        const problem = checkInitialValue(
          v.initial,
          parseSizedString(type)?.type ?? (type as ElementaryType),
        );
        if (problem) issues.push({ index, field: 'initial', message: problem });
      } else if (scope.project && resolveType(scope.project, v.type).ok) {
        const leaves = leafPaths(scope.project, v);
        if (!leaves.ok) issues.push({ index, field: 'initial', message: leaves.message });
      }
    }
    if (v.constant && v.retain)
      issues.push({ index, field: 'retain', message: 'a CONSTANT cannot also be RETAIN' });
    if (v.constant && (v.initial === undefined || v.initial.trim() === '')) {
      issues.push({ index, field: 'initial', message: 'a CONSTANT needs an initial value' });
    }
  });
  return issues;
}

/** The issues of one row, grouped by field (first message per field). */
export function issuesByField(
  issues: readonly VariableIssue[],
  index: number,
): Partial<Record<VariableField, string>> {
  const out: Partial<Record<VariableField, string>> = {};
  for (const issue of issues)
    if (issue.index === index && out[issue.field] === undefined) out[issue.field] = issue.message;
  return out;
}
