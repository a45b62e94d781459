// The elementary IEC 61131-3 types Rungsmith supports (LD-SEMANTICS.md section 8).

export const ELEMENTARY_TYPES = [
  'BOOL',
  'SINT',
  'INT',
  'DINT',
  'LINT',
  'USINT',
  'UINT',
  'UDINT',
  'ULINT',
  'BYTE',
  'WORD',
  'DWORD',
  'LWORD',
  'REAL',
  'LREAL',
  'TIME',
  'DATE',
  'TOD',
  'DT',
  'STRING',
  'WSTRING',
] as const;
export type ElementaryType = (typeof ELEMENTARY_TYPES)[number];

export const isElementaryType = (t: string): t is ElementaryType =>
  (ELEMENTARY_TYPES as readonly string[]).includes(t);

export type IntegerType = 'SINT' | 'INT' | 'DINT' | 'LINT' | 'USINT' | 'UINT' | 'UDINT' | 'ULINT';
export type BitStringType = 'BOOL' | 'BYTE' | 'WORD' | 'DWORD' | 'LWORD';
export type RealType = 'REAL' | 'LREAL';
export type StringType = 'STRING' | 'WSTRING';
export type DateType = 'DATE' | 'TOD' | 'DT';

/** The long names IEC also gives TOD and DT. */
export const DATE_TYPE_ALIASES: Readonly<Record<string, DateType>> = { TIME_OF_DAY: 'TOD', DATE_AND_TIME: 'DT' };

/**
 * Most characters a STRING or WSTRING holds: MATIEC's STR_MAX_LEN (lib/C/iec_types.h), the body of
 * its C STRING. Longer results are cut there, as MATIEC's string functions cut them.
 */
export const STRING_MAX_LEN = 126;

const SIZED_STRING = /^(W?STRING)\s*[[(]\s*(\d+)\s*[\])]$/i;

/** `STRING[20]`, `WSTRING(8)`: a string type with a declared length (not checked against STRING_MAX_LEN). */
export function parseSizedString(text: string): { type: StringType; length: number } | undefined {
  const m = SIZED_STRING.exec(text.trim());
  return m ? { type: m[1]!.toUpperCase() as StringType, length: Number(m[2]) } : undefined;
}

/** Bit width and signedness of integer and bit-string types. */
export const INT_INFO: Record<IntegerType | Exclude<BitStringType, 'BOOL'>, { bits: 8 | 16 | 32 | 64; signed: boolean }> = {
  SINT: { bits: 8, signed: true },
  INT: { bits: 16, signed: true },
  DINT: { bits: 32, signed: true },
  LINT: { bits: 64, signed: true },
  USINT: { bits: 8, signed: false },
  UINT: { bits: 16, signed: false },
  UDINT: { bits: 32, signed: false },
  ULINT: { bits: 64, signed: false },
  BYTE: { bits: 8, signed: false },
  WORD: { bits: 16, signed: false },
  DWORD: { bits: 32, signed: false },
  LWORD: { bits: 64, signed: false },
};

/** Generic type classes used in block signatures (IEC 61131-3 table 11). */
export type GenericType =
  | 'ANY'
  | 'ANY_ELEMENTARY'
  | 'ANY_MAGNITUDE'
  | 'ANY_NUM'
  | 'ANY_INT'
  | 'ANY_REAL'
  | 'ANY_BIT'
  | 'ANY_STRING';
export type PinType = ElementaryType | GenericType;

const INTS: readonly ElementaryType[] = ['SINT', 'INT', 'DINT', 'LINT', 'USINT', 'UINT', 'UDINT', 'ULINT'];
const REALS: readonly ElementaryType[] = ['REAL', 'LREAL'];
const BITS: readonly ElementaryType[] = ['BOOL', 'BYTE', 'WORD', 'DWORD', 'LWORD'];

/** The concrete types a generic type admits. */
export const GENERIC_MEMBERS: Record<GenericType, readonly ElementaryType[]> = {
  ANY: ELEMENTARY_TYPES,
  ANY_ELEMENTARY: ELEMENTARY_TYPES,
  ANY_MAGNITUDE: [...INTS, ...REALS, 'TIME'],
  ANY_NUM: [...INTS, ...REALS],
  ANY_INT: INTS,
  ANY_REAL: REALS,
  ANY_BIT: BITS,
  ANY_STRING: ['STRING', 'WSTRING'],
};

/**
 * Value representation shared by engine, simulator, CLI and UI:
 * BOOL -> boolean; 64-bit integer and bit-string types (LINT, ULINT, LWORD) -> bigint;
 * other integers and bit strings -> number; REAL/LREAL -> number (REAL held rounded to 32 bits);
 * TIME -> number of milliseconds (signed); DATE, TOD (TIME_OF_DAY), DT (DATE_AND_TIME) -> number of
 * milliseconds since 1970-01-01 (DATE, DT; UTC) or since midnight (TOD); STRING -> a JavaScript string of single-byte characters
 * (codes 0-255, one character per byte); WSTRING -> a JavaScript string (UTF-16 code units).
 */
export type Value = boolean | number | bigint | string;

/** IEC directly represented variable: %IX0.0, %QX1.7, %MX2.3, %IW0, %QW3, %MW10, %ID.., %MD... */
export const LOCATION_RE = /^%([IQM])([XBWDL]?)(\d+)((?:\.\d+)*)$/;

export interface ParsedLocation {
  area: 'I' | 'Q' | 'M';
  size: 'X' | 'B' | 'W' | 'D' | 'L';
  index: number;
  bit?: number;
  /**
   * Further fields of a hierarchical address, as MATIEC reads them (`%IW0.0` → index 0, levels [0];
   * `%IB0.0.32.24576.1` from CANopen configurations): a location of its own, not the flat `%IW0`.
   */
  levels?: readonly number[];
}

/** An address in one canonical spelling, so %ix0.0 and %IX0.0 compare equal. */
export const locationText = (loc: ParsedLocation): string =>
  `%${loc.area}${loc.size}${loc.index}${loc.bit !== undefined ? `.${loc.bit}` : ''}${(loc.levels ?? []).map((l) => `.${l}`).join('')}`;

/** Parses an IEC location; returns undefined when the text is not a valid location. */
export function parseLocation(text: string): ParsedLocation | undefined {
  const m = LOCATION_RE.exec(text.trim().toUpperCase());
  if (!m) return undefined;
  const size = (m[2] || 'X') as ParsedLocation['size'];
  const index = Number(m[3]);
  // Fields after the index: a bit address's bit, then (any size) the levels of a hierarchical address.
  const rest = m[4] ? m[4].slice(1).split('.').map(Number) : [];
  const bit = size === 'X' ? rest.shift() : undefined;
  if (size === 'X') {
    if (m[2] === '' && bit === undefined) return undefined; // "%I3" is ambiguous; require %IX3.0 style
    // No upper bound on the bit (IEC 61131-3 2.4.1.1 gives none, and MATIEC compiles %IX0.12): a
    // bit address is a location of its own; %IX0.12 is not %IX1.4.
  }
  return { area: m[1] as ParsedLocation['area'], size, index, ...(bit !== undefined ? { bit } : {}), ...(rest.length ? { levels: rest } : {}) };
}

/** The IEC types a location can hold: X -> BOOL, B -> 8 bit, W -> 16 bit, D -> 32 bit, L -> 64 bit. */
export function locationAdmits(loc: ParsedLocation, type: string): boolean {
  switch (loc.size) {
    case 'X':
      return type === 'BOOL';
    case 'B':
      return ['BYTE', 'SINT', 'USINT'].includes(type);
    case 'W':
      return ['WORD', 'INT', 'UINT'].includes(type);
    case 'D':
      return ['DWORD', 'DINT', 'UDINT', 'REAL', 'TIME'].includes(type);
    case 'L':
      return ['LWORD', 'LINT', 'ULINT', 'LREAL'].includes(type);
  }
}

/** IEC identifier: letter or underscore, then letters, digits, single underscores. */
export const IDENTIFIER_RE = /^[A-Za-z_][A-Za-z0-9_]*$/;
