// Value representation and typing rules for the elementary IEC types (LD-SEMANTICS.md section 8).
// Representation (see model/iecTypes.ts): BOOL -> boolean; LINT/ULINT/LWORD -> bigint;
// other integers and bit strings -> number; REAL/LREAL -> number; TIME -> integer milliseconds;
// STRING/WSTRING -> string (at most STRING_MAX_LEN characters).
import {
  INT_INFO,
  STRING_MAX_LEN,
  type BitStringType,
  type DateType,
  type ElementaryType,
  type IntegerType,
  type StringType,
  type Value,
} from '../../model/iecTypes';

export type SizedType = IntegerType | Exclude<BitStringType, 'BOOL'>;

export const isSizedType = (t: ElementaryType): t is SizedType => t in INT_INFO;
export const isBigIntType = (t: ElementaryType): boolean => t === 'LINT' || t === 'ULINT' || t === 'LWORD';
export const isIntegerType = (t: ElementaryType): t is IntegerType =>
  t === 'SINT' || t === 'INT' || t === 'DINT' || t === 'LINT' || t === 'USINT' || t === 'UINT' || t === 'UDINT' || t === 'ULINT';
export const isBitStringType = (t: ElementaryType): t is BitStringType =>
  t === 'BOOL' || t === 'BYTE' || t === 'WORD' || t === 'DWORD' || t === 'LWORD';
export const isRealType = (t: ElementaryType): t is 'REAL' | 'LREAL' => t === 'REAL' || t === 'LREAL';
export const isStringType = (t: string): t is StringType => t === 'STRING' || t === 'WSTRING';
export const isDateType = (t: string): t is DateType => t === 'DATE' || t === 'TOD' || t === 'DT';
/** TIME and the date types: whole milliseconds held as numbers. */
export const isTimeLike = (t: string): boolean => t === 'TIME' || isDateType(t);
export const isSignedType = (t: ElementaryType): boolean =>
  t === 'SINT' || t === 'INT' || t === 'DINT' || t === 'LINT' || t === 'REAL' || t === 'LREAL' || t === 'TIME';

/** Initial value of a variable of this type when its declaration gives none. */
export function defaultValue(type: ElementaryType): Value {
  if (type === 'BOOL') return false;
  if (isStringType(type)) return '';
  return isBigIntType(type) ? 0n : 0;
}

/** Smallest and largest value of an integer or bit-string type. */
export function typeRange(type: SizedType): { min: bigint; max: bigint } {
  const { bits, signed } = INT_INFO[type];
  const b = BigInt(bits);
  return signed ? { min: -(1n << (b - 1n)), max: (1n << (b - 1n)) - 1n } : { min: 0n, max: (1n << b) - 1n };
}

/**
 * The same ranges as numbers for the types held as numbers (8, 16 and 32 bits), made once: a check
 * of a value written every scan (an input from the I/O, a machine's sensor) needs no BigInt (with
 * them, a check of an INT took some 70 ns).
 */
const NUMBER_RANGES = new Map<ElementaryType, { readonly min: number; readonly max: number }>(
  (Object.keys(INT_INFO) as SizedType[])
    .filter((t) => !isBigIntType(t))
    .map((t) => {
      const { min, max } = typeRange(t);
      return [t, { min: Number(min), max: Number(max) }];
    }),
);

/** The range of a type held as a number (8, 16 or 32 bits) as numbers; undefined for any other type. */
export const numberRange = (type: ElementaryType): { readonly min: number; readonly max: number } | undefined =>
  NUMBER_RANGES.get(type);

const toNumber = (v: Value): number =>
  typeof v === 'boolean' ? (v ? 1 : 0) : typeof v === 'bigint' ? Number(v) : typeof v === 'string' ? Number.NaN : v;

/** A string cut to the most characters a STRING holds (MATIEC cuts every result there). */
export const clipString = (s: string): string => (s.length > STRING_MAX_LEN ? s.slice(0, STRING_MAX_LEN) : s);

/** Truncates toward zero; NaN and infinities (no integer meaning) become 0. */
const toInteger = (v: number): number => (Number.isFinite(v) ? Math.trunc(v) : 0);

const toBigInt = (v: Value): bigint => {
  if (typeof v === 'bigint') return v;
  if (typeof v === 'boolean') return v ? 1n : 0n;
  return BigInt(toInteger(toNumber(v)));
};

/**
 * Brings a value into the representation and range of `type` the way a PLC stores it:
 * integers wrap at their width (two's complement), REAL is rounded to 32 bits, TIME to whole ms.
 */
export function normalize(type: ElementaryType, v: Value): Value {
  switch (type) {
    case 'STRING':
    case 'WSTRING':
      return clipString(typeof v === 'string' ? v : String(v));
    case 'BOOL':
      return typeof v === 'boolean' ? v : typeof v === 'bigint' ? v !== 0n : typeof v === 'string' ? v !== '' : v !== 0 && !Number.isNaN(v);
    case 'REAL':
      return Math.fround(toNumber(v));
    case 'LREAL':
      return toNumber(v);
    case 'TIME':
    case 'DATE':
    case 'TOD':
    case 'DT': {
      const n = toNumber(v);
      return Number.isFinite(n) ? Math.round(n) || 0 : 0;
    }
    case 'LINT':
      return BigInt.asIntN(64, toBigInt(v));
    case 'ULINT':
    case 'LWORD':
      return BigInt.asUintN(64, toBigInt(v));
    default: {
      // 8/16/32-bit: JS bit operators apply ToInt32, which is exact modulo 2^32 for any finite number.
      const n = typeof v === 'bigint' ? Number(BigInt.asIntN(32, v)) : toInteger(toNumber(v));
      switch (type) {
        case 'SINT':
          return (n << 24) >> 24;
        case 'INT':
          return (n << 16) >> 16;
        case 'DINT':
          return n | 0;
        case 'USINT':
        case 'BYTE':
          return n & 0xff;
        case 'UINT':
        case 'WORD':
          return n & 0xffff;
        case 'UDINT':
        case 'DWORD':
          return n >>> 0;
      }
    }
  }
}

/** True when `v` is exactly a value of `type` in the engine's representation. */
export function isValueOfType(type: ElementaryType, v: Value): boolean {
  if (type === 'BOOL') return typeof v === 'boolean';
  if (type === 'STRING') return typeof v === 'string' && v.length <= STRING_MAX_LEN && isSingleByte(v);
  if (type === 'WSTRING') return typeof v === 'string' && v.length <= STRING_MAX_LEN;
  if (type === 'LREAL') return typeof v === 'number';
  if (type === 'REAL') return typeof v === 'number' && (Number.isNaN(v) || Math.fround(v) === v);
  if (isTimeLike(type)) return typeof v === 'number' && Number.isInteger(v);
  if (isBigIntType(type)) {
    if (typeof v !== 'bigint') return false;
    const { min, max } = typeRange(type as SizedType);
    return v >= min && v <= max;
  }
  if (typeof v !== 'number' || !Number.isInteger(v)) return false;
  const range = NUMBER_RANGES.get(type);
  return range !== undefined && v >= range.min && v <= range.max;
}

/** True when every character is one byte (code 0-255), as a STRING holds them. */
export function isSingleByte(s: string): boolean {
  for (let i = 0; i < s.length; i++) if (s.charCodeAt(i) > 0xff) return false;
  return true;
}

/** True when the text holds a control character (codes 0-31 and 127). */
export function hasControlCharacter(s: string): boolean {
  for (let i = 0; i < s.length; i++) {
    const c = s.charCodeAt(i);
    if (c < 0x20 || c === 0x7f) return true;
  }
  return false;
}

/**
 * IEC 61131-3 (3rd ed.) implicit conversions, figure 11 "implicit type conversion", closed transitively.
 * A conversion is implicit only where every value of the source is represented exactly:
 *
 *   from \ to | wider integers                 | REAL | LREAL | bit strings
 *   SINT      | INT DINT LINT                  | yes  | yes   |
 *   INT       | DINT LINT                      | yes  | yes   |
 *   DINT      | LINT                           |      | yes   |
 *   LINT      |                                |      |       |
 *   USINT     | UINT UDINT ULINT INT DINT LINT | yes  | yes   |
 *   UINT      | UDINT ULINT DINT LINT          | yes  | yes   |
 *   UDINT     | ULINT LINT                     |      | yes   |
 *   ULINT     |                                |      |       |
 *   BYTE      |                                |      |       | WORD DWORD LWORD
 *   WORD      |                                |      |       | DWORD LWORD
 *   DWORD     |                                |      |       | LWORD
 *   REAL      |                                |      | yes   |
 *
 * BOOL, LWORD, LREAL and TIME widen to nothing; bit strings never become numbers implicitly
 * (use WORD_TO_INT etc.), as the standard keeps ANY_BIT and ANY_NUM apart.
 */
const WIDENINGS: Partial<Record<ElementaryType, readonly ElementaryType[]>> = {
  SINT: ['INT', 'DINT', 'LINT', 'REAL', 'LREAL'],
  INT: ['DINT', 'LINT', 'REAL', 'LREAL'],
  DINT: ['LINT', 'LREAL'],
  USINT: ['UINT', 'UDINT', 'ULINT', 'INT', 'DINT', 'LINT', 'REAL', 'LREAL'],
  UINT: ['UDINT', 'ULINT', 'DINT', 'LINT', 'REAL', 'LREAL'],
  UDINT: ['ULINT', 'LINT', 'LREAL'],
  BYTE: ['WORD', 'DWORD', 'LWORD'],
  WORD: ['DWORD', 'LWORD'],
  DWORD: ['LWORD'],
  REAL: ['LREAL'],
};

/** True when a `from` value may be used where `to` is expected without an explicit conversion (from === to included). */
export function canWiden(from: ElementaryType, to: ElementaryType): boolean {
  return from === to || (WIDENINGS[from]?.includes(to) ?? false);
}

/** Converts a value of `from` to `to` along an implicit widening (canWiden(from, to) must hold). */
export function widen(from: ElementaryType, to: ElementaryType, v: Value): Value {
  if (from === to) return v;
  return normalize(to, v);
}

/** Order used to pick the narrowest common type when no argument's own type fits all. */
const RANK: readonly ElementaryType[] = ['SINT', 'USINT', 'INT', 'UINT', 'DINT', 'UDINT', 'LINT', 'ULINT', 'REAL', 'LREAL', 'BYTE', 'WORD', 'DWORD', 'LWORD'];

/**
 * The type every given type widens to: the widest argument type when it covers the others
 * (INT and DINT -> DINT), else the narrowest type covering all (INT and UINT -> DINT);
 * undefined when there is none (INT and WORD).
 */
export function commonType(types: readonly ElementaryType[]): ElementaryType | undefined {
  for (const candidate of types) if (types.every((t) => canWiden(t, candidate))) return candidate;
  return RANK.find((c) => types.every((t) => canWiden(t, c)));
}
