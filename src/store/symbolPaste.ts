// Pasting a symbol table from a spreadsheet (Excel, LibreOffice, Google Sheets: TSV; a CSV file's
// text: comma or semicolon separated) into a variable list: the POU's variables or the globals.
// Columns name, type, address, initial value, comment, in that order when there is no header row;
// with a header, the columns are found by name in the usual spellings (CODESYS's "Scope", "Data
// type", "Initialization"; TIA Portal's PLC tag table "Data Type", "Logical Address"; German
// "Datentyp", "Adresse", "Kommentar"), and columns this table does not hold (TIA's "Path", "Hmi
// Visible") are ignored. TIA/S7 addresses (%I0.0, %Q4.1, %IW64, %MD10, E0.0/A0.0) become IEC
// addresses (%IX0.0 ...); those without an IEC equivalent (DB1.DBX0.0, T5, C3, %IW64:P) are refused
// with the reason. planSymbolPaste says per row what a paste would do (add, rename, replace or
// refuse, with the reason) before anything changes; applySymbolPaste makes it one undo step.
import { parse } from 'csv-parse/browser/esm/sync';
import { variable } from '../model/factory';
import { ELEMENTARY_TYPES, locationText, parseLocation, parseSizedString } from '../model/iecTypes';
import { blockLibrary } from '../model/library';
import type { Project, VarClass, Variable } from '../model/project';
import { identifierProblem, validateVariables, type VariableField } from '../editor/variables/validation';
import type { VariableScope } from './changes';

export type SymbolColumn =
  'name' | 'type' | 'address' | 'initial' | 'comment' | 'class' | 'retain' | 'constant';

/** One data row of the pasted text, cells by column (trimmed; absent when the table has no such column). */
export interface SymbolRow {
  /** 1-based line of the row in the pasted text. */
  readonly line: number;
  readonly cells: Partial<Record<SymbolColumn, string>>;
}

export interface SymbolTable {
  readonly delimiter: '\t' | ',' | ';';
  /** The first row named the columns. */
  readonly header: boolean;
  /** Which column of the text each field came from (0-based); columns the table ignores are left out. */
  readonly columns: Partial<Record<SymbolColumn, number>>;
  readonly rows: readonly SymbolRow[];
  /** The text could not be read as a table (an unclosed quote): the reason, with the line. */
  readonly error?: string;
}

/** Header words (lower case, letters and digits only) and the column each names. */
const HEADER_WORDS: Record<string, SymbolColumn> = {};
const words = (column: SymbolColumn, list: string) =>
  list.split(' ').forEach((w) => (HEADER_WORDS[w] = column));
words(
  'name',
  'name names symbol symbolname symbols tag tagname variable variablename varname identifier bezeichner',
);
words('type', 'type datatype datentyp typ vartype variabletype');
words('address', 'address logicaladdress location adresse operand at ioaddress absoluteaddress');
words(
  'initial',
  'initial initialvalue init initvalue initialization initialisation default defaultvalue startvalue startwert anfangswert value',
);
words('comment', 'comment comments description kommentar remark remarks');
words('class', 'class scope section varclass kind');
words('retain', 'retain retentive remanent remanence');
words('constant', 'constant const');

const headerColumn = (cell: string): SymbolColumn | undefined =>
  HEADER_WORDS[cell.toLowerCase().replace(/[^a-z0-9]/g, '')];

/** Columns of a table without header: name, type, address, initial value, comment. */
const POSITIONAL: readonly SymbolColumn[] = ['name', 'type', 'address', 'initial', 'comment'];

/** Tab when the first line has one (a spreadsheet's copy); otherwise the commoner of ';' and ','. */
function guessDelimiter(text: string): SymbolTable['delimiter'] {
  const first = text.split(/\r?\n/).find((l) => l.trim() !== '') ?? '';
  if (first.includes('\t')) return '\t';
  const outside = first.replace(/"[^"]*"/g, '');
  const count = (c: string) => outside.split(c).length - 1;
  return count(';') > count(',') ? ';' : ',';
}

/** Reads pasted spreadsheet text (see the file comment). Never throws: an unreadable text gives `error`. */
export function parseSymbolTable(text: string): SymbolTable {
  const clean = text.replace(/^\uFEFF/, '');
  const delimiter = guessDelimiter(clean);
  let records: { record: string[]; info: { lines: number } }[];
  try {
    records = parse(clean, {
      delimiter,
      info: true,
      relax_column_count: true,
      relax_quotes: true,
      skip_empty_lines: true,
      trim: true,
    }) as unknown as { record: string[]; info: { lines: number } }[];
  } catch (e) {
    return {
      delimiter,
      header: false,
      columns: {},
      rows: [],
      error: e instanceof Error ? e.message : String(e),
    };
  }
  // A row of blanks only (a spreadsheet's empty row copied with its tabs) is no row.
  const data = records.filter((r) => r.record.some((c) => c !== ''));
  const first = data[0]?.record ?? [];
  const named = first.map(headerColumn);
  const header = named.includes('name') && named.filter((c) => c !== undefined).length >= 2;
  const columns: Partial<Record<SymbolColumn, number>> = {};
  if (header) named.forEach((c, i) => c !== undefined && columns[c] === undefined && (columns[c] = i));
  else POSITIONAL.forEach((c, i) => (columns[c] = i));
  const rows = (header ? data.slice(1) : data).map(({ record, info }) => {
    const cells: Partial<Record<SymbolColumn, string>> = {};
    for (const [column, index] of Object.entries(columns) as [SymbolColumn, number][]) {
      const cell = record[index];
      if (cell !== undefined) cells[column] = cell;
    }
    // info.lines is the line the record ends on; a record spanning lines (a quoted comment with a
    // line break) starts earlier, but its first line is what the user finds in the sheet.
    return { line: info.lines, cells };
  });
  return { delimiter, header, columns, rows };
}

export type AddressResult =
  { readonly address: string; readonly note?: string } | { readonly refused: string };

/**
 * An address as a PLC programmer pastes it, in IEC spelling: `%IX0.0` as is; TIA/S7 `%I0.0`, `I0.0`,
 * `%Q4.1`, `%M10.3` become `%IX0.0`, `%QX4.1`, `%MX10.3`; `%IW64`, `%QB3`, `%MD10` keep their size;
 * German E/A (Eingang/Ausgang) are I/Q. Refused with the reason: S7 data block, timer and counter
 * addresses, peripheral access (`:P`), a bit address without its bit.
 */
export function importAddress(text: string): AddressResult {
  const raw = text.trim();
  const t = raw.replace(/\s+/g, '').toUpperCase();
  if (/:P$/.test(t))
    return {
      refused: `"${raw}" is an S7 peripheral access (:P), which IEC 61131-3 has no address for: use the address without :P`,
    };
  if (/^%?DB\d+/.test(t) || /^%?D[IB][XBWD]\d/.test(t))
    return {
      refused: `"${raw}" is an S7 data block address, which has no IEC equivalent: declare the variable without an address`,
    };
  if (/^%?[TCZ]\d+$/.test(t))
    return {
      refused: `"${raw}" is an S7 timer or counter, which is no memory address in IEC 61131-3: declare a TON/CTU instance instead`,
    };
  const m = /^%?([IQMEA])([XBWDL]?)(\d+)(?:\.(\d+))?$/.exec(t);
  if (!m)
    return {
      refused: `"${raw}" is not an address: write e.g. %IX0.0 or %I0.0 (input bit), %QX0.1, %IW64, %MW10, %MD4`,
    };
  const area = m[1] === 'E' ? 'I' : m[1] === 'A' ? 'Q' : m[1]!;
  const size = m[2] || 'X';
  const index = Number(m[3]);
  const bit = m[4];
  if (size === 'X' && bit === undefined)
    return {
      refused: `"${raw}" names no bit: write ${`%${area}X${index}.0`} for a bit or %${area}W${index} for a word`,
    };
  if (size === 'X' && Number(bit) > 7) return { refused: `"${raw}": a byte has bits 0 to 7` };
  if (size !== 'X' && bit !== undefined)
    return {
      refused: `"${raw}": a ${size === 'B' ? 'byte' : 'word'} address has no bit: write %${area}${size}${index}`,
    };
  const address = `%${area}${size}${index}${size === 'X' ? `.${bit}` : ''}`;
  const written = raw.toUpperCase();
  return written === address ? { address } : { address, note: `address ${raw} read as ${address}` };
}

/**
 * The type as the project spells it: an elementary type in capitals (TIA's "Bool", "DInt"), a
 * project data type or FB as declared, a standard FB in capitals; other text as written (the
 * checks decide).
 */
export function importType(project: Project, text: string): string {
  const t = text.trim();
  const upper = t.toUpperCase();
  if ((ELEMENTARY_TYPES as readonly string[]).includes(upper)) return upper;
  if (upper === 'TIME_OF_DAY' || upper === 'DATE_AND_TIME') return upper;
  const sized = parseSizedString(upper.replace(/\s+/g, ''));
  if (sized) return `${sized.type}[${sized.length}]`;
  const own = project.dataTypes?.find((d) => d.name.toUpperCase() === upper);
  if (own) return own.name;
  const lib = blockLibrary(project);
  const pou = lib.userPou(t);
  if (pou) return pou.name;
  const sig = lib.signature(t);
  if (sig) return sig.name;
  return t;
}

const CLASS_WORDS: Record<string, VarClass | 'global'> = {
  VAR: 'local',
  LOCAL: 'local',
  STATIC: 'local',
  VAR_STAT: 'local',
  VAR_INPUT: 'input',
  INPUT: 'input',
  IN: 'input',
  VAR_OUTPUT: 'output',
  OUTPUT: 'output',
  OUT: 'output',
  VAR_IN_OUT: 'inOut',
  IN_OUT: 'inOut',
  INOUT: 'inOut',
  VAR_EXTERNAL: 'external',
  EXTERNAL: 'external',
  VAR_TEMP: 'temp',
  TEMP: 'temp',
  VAR_GLOBAL: 'global',
  GLOBAL: 'global',
};

/** `VAR_INPUT`, `VAR_GLOBAL RETAIN`, `VAR CONSTANT`, `Input`, `Static`... : class and attributes. */
function importClass(
  text: string,
  globals: boolean,
): { varClass?: VarClass; retain?: boolean; constant?: boolean } | { refused: string } {
  const parts = text.trim().toUpperCase().split(/\s+/).filter(Boolean);
  const out: { varClass?: VarClass; retain?: boolean; constant?: boolean } = {};
  for (const p of parts) {
    if (p === 'RETAIN' || p === 'PERSISTENT') out.retain = true;
    else if (p === 'CONSTANT') out.constant = true;
    else if (p === 'NON_RETAIN') out.retain = false;
    else {
      const c = CLASS_WORDS[p];
      if (!c)
        return {
          refused: `class "${text.trim()}" is not one of VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR_EXTERNAL, VAR_TEMP, VAR_GLOBAL`,
        };
      if (globals && c !== 'global')
        return { refused: `class ${text.trim()} belongs in a POU, not in the global variables` };
      if (!globals && c === 'global')
        return { refused: `a VAR_GLOBAL belongs in the global variables: paste it there` };
      if (c !== 'global') out.varClass = c;
    }
  }
  return out;
}

const truthy = (text: string | undefined): boolean =>
  /^(true|x|yes|y|ja|1|on|retain|constant|\u2713|\u2714)$/i.test((text ?? '').trim());

export type PasteAction = 'add' | 'rename' | 'replace' | 'refuse' | 'skip';

/** What the user chose for a row whose name is taken: a free name (the default), replace the existing variable, or skip. */
export type ClashChoice = 'rename' | 'replace' | 'skip';

export interface PastePlanRow {
  readonly line: number;
  /** The name as pasted. */
  readonly given: string;
  readonly action: PasteAction;
  /** What the row writes (add, rename, replace); for a refused row what it would have been, when it got that far. */
  readonly variable?: Variable;
  /** The name of the variable it clashes with (rename, replace, or skip after a clash). */
  readonly clash?: string;
  /** The clash is with a variable already in the list (replace possible), not with an earlier pasted row. */
  readonly canReplace: boolean;
  /** Why the row is refused (refuse only). */
  readonly reasons: readonly string[];
  /** What was read differently from the text (an S7 address in IEC spelling, the type's spelling). */
  readonly notes: readonly string[];
}

const FIELD_WORDS: Record<VariableField, string> = {
  name: 'name',
  type: 'type',
  varClass: 'class',
  location: 'address',
  initial: 'initial value',
  retain: 'RETAIN',
  constant: 'CONSTANT',
};

/** The list a scope holds in the project (empty for a POU that does not exist). */
export function scopeVariables(project: Project, scope: VariableScope): readonly Variable[] {
  return scope === 'globals' ? project.globals : (project.pous.find((p) => p.id === scope)?.variables ?? []);
}

/** `Start_2`, `Start_3`, ... the first not in `taken` (upper-case names). */
function freeName(base: string, taken: ReadonlySet<string>): string {
  for (let i = 2; ; i++) {
    const candidate = `${base}_${i}`;
    if (!taken.has(candidate.toUpperCase())) return candidate;
  }
}

/**
 * What pasting `table` into `scope` does, row by row (nothing changes yet). A name already in the
 * list is renamed to a free name unless `choices` says replace (or skip) for that row (by its index
 * in table.rows); a name pasted twice keeps its first row and renames the later ones. A row is
 * refused with every reason found: bad name, no or unknown type, an address that is not one or
 * does not fit the type or is used already (in the project or by an earlier row), a bad initial
 * value, a class the list cannot hold.
 */
export function planSymbolPaste(
  project: Project,
  scope: VariableScope,
  table: Pick<SymbolTable, 'rows'>,
  choices: ReadonlyMap<number, ClashChoice> = new Map(),
): PastePlanRow[] {
  const globals = scope === 'globals';
  const pou = globals ? undefined : project.pous.find((p) => p.id === scope);
  const existing = scopeVariables(project, scope);
  /** Addresses of the list as it will be after the rows accepted so far (canonical spelling), by holder. */
  const addresses = new Map<string, string>();
  for (const w of existing) {
    const loc = w.location ? parseLocation(w.location) : undefined;
    if (loc && !addresses.has(locationText(loc))) addresses.set(locationText(loc), w.name);
  }
  const taken = new Set(existing.map((v) => v.name.toUpperCase()));
  // Free names avoid every pasted name too, so a rename never takes the name a later row brings.
  for (const row of table.rows) if (row.cells.name) taken.add(row.cells.name.trim().toUpperCase());
  const pastedNames = new Set<string>();
  const replaced = new Set<string>();

  return table.rows.map((row, index): PastePlanRow => {
    const given = (row.cells.name ?? '').trim();
    const reasons: string[] = [];
    const notes: string[] = [];
    const base = { line: row.line, given, canReplace: false, reasons, notes };
    const nameProblem = identifierProblem(given);
    if (nameProblem) reasons.push(given === '' ? 'no name' : nameProblem);
    const typeText = (row.cells.type ?? '').trim();
    const type = typeText === '' ? '' : importType(project, typeText);
    if (typeText === '') reasons.push('no type');
    else if (type !== typeText && type.toUpperCase() !== typeText.toUpperCase().replace(/\s+/g, ''))
      notes.push(`type ${typeText} read as ${type}`);
    let location: string | undefined;
    const addressText = (row.cells.address ?? '').trim();
    if (addressText !== '') {
      const a = importAddress(addressText);
      if ('refused' in a) reasons.push(a.refused);
      else {
        location = a.address;
        if (a.note) notes.push(a.note);
      }
    }
    const cls = importClass(row.cells.class ?? '', globals);
    if ('refused' in cls) reasons.push(cls.refused);
    const initial = (row.cells.initial ?? '').trim();
    const retain = truthy(row.cells.retain) || (!('refused' in cls) && cls.retain === true);
    const constant = truthy(row.cells.constant) || (!('refused' in cls) && cls.constant === true);
    const v = variable(given, type, {
      ...(!('refused' in cls) && cls.varClass ? { varClass: cls.varClass } : {}),
      ...(location ? { location } : {}),
      ...(initial ? { initial } : {}),
      ...(retain ? { retain } : {}),
      ...(constant ? { constant } : {}),
      comment: (row.cells.comment ?? '').trim(),
    });
    if (reasons.length) return { ...base, action: 'refuse', ...(given && type ? { variable: v } : {}) };

    // The name: free, taken by the list (rename or replace), or by an earlier row (rename).
    const key = given.toUpperCase();
    const inList = existing.find((w) => w.name.toUpperCase() === key);
    const clashesRow = pastedNames.has(key);
    pastedNames.add(key);
    let action: PasteAction = 'add';
    let written = v;
    let clash: string | undefined;
    const canReplace = !!inList && !clashesRow && !replaced.has(key);
    if (inList || clashesRow) {
      clash = inList?.name ?? given;
      const choice = choices.get(index) ?? 'rename';
      if (choice === 'skip') return { ...base, action: 'skip', variable: v, clash, canReplace };
      if (choice === 'replace' && canReplace) {
        action = 'replace';
        // No class in the paste: the variable keeps its own (an input stays an input).
        const keep = row.cells.class?.trim() ? {} : { varClass: inList.varClass };
        written = { ...v, ...keep, name: inList.name, ...(inList.scope ? { scope: inList.scope } : {}) };
      } else {
        action = 'rename';
        const name = freeName(given, taken);
        taken.add(name.toUpperCase());
        written = { ...v, name };
      }
    }

    // Every other check of the table (unknown type, address fit, an address of another list,
    // initial value...), then the address against this list as the rows accepted so far leave it.
    const reasonsFound = validateVariables([written], { project, ...(pou ? { pou: pou.name } : {}) }).map(
      (i) => `${FIELD_WORDS[i.field]}: ${i.message}`,
    );
    const loc = written.location ? parseLocation(written.location) : undefined;
    const where = loc ? locationText(loc) : undefined;
    const holder = where ? addresses.get(where) : undefined;
    if (where && holder && holder.toUpperCase() !== key)
      reasonsFound.push(`address: ${where} is already used by "${holder}"`);
    if (reasonsFound.length) return { ...base, action: 'refuse', variable: written, reasons: reasonsFound };
    if (action === 'replace') {
      replaced.add(key);
      const old = existing.find((w) => w.name.toUpperCase() === key)?.location;
      const oldLoc = old ? parseLocation(old) : undefined;
      if (oldLoc && addresses.get(locationText(oldLoc))?.toUpperCase() === key)
        addresses.delete(locationText(oldLoc));
    }
    if (where) addresses.set(where, written.name);
    return { ...base, action, variable: written, canReplace, ...(clash !== undefined ? { clash } : {}) };
  });
}

/** How many rows of a plan do each thing. */
export function planCounts(plan: readonly PastePlanRow[]): Record<PasteAction, number> {
  const out: Record<PasteAction, number> = { add: 0, rename: 0, replace: 0, refuse: 0, skip: 0 };
  for (const row of plan) out[row.action] += 1;
  return out;
}

/** The store commands a paste uses. */
export interface SymbolPasteTarget {
  batch<T>(name: string, fn: () => T): T;
  addVariable(v: Variable, scope?: VariableScope): boolean;
  updateVariable(name: string, patch: Partial<Variable>, scope?: VariableScope): boolean;
}

/** Writes the added, renamed and replaced rows of `plan` into `scope` as one undo step; returns how many. */
export function applySymbolPaste(
  target: SymbolPasteTarget,
  scope: VariableScope,
  plan: readonly PastePlanRow[],
): number {
  return target.batch('pasteSymbols', () => {
    let done = 0;
    for (const row of plan) {
      const v = row.variable;
      if (!v) continue;
      if (row.action === 'add' || row.action === 'rename') done += target.addVariable(v, scope) ? 1 : 0;
      else if (row.action === 'replace') {
        // The existing variable keeps its place and its references; its fields become the pasted ones.
        const patch: Partial<Variable> = {
          type: v.type,
          varClass: v.varClass,
          location: v.location,
          initial: v.initial,
          retain: v.retain,
          constant: v.constant,
          comment: v.comment,
        };
        done += target.updateVariable(v.name, patch, scope) ? 1 : 0;
      }
    }
    return done;
  });
}
