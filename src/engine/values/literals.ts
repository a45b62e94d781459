// IEC 61131-3 literals (tables 5-8) and the text forms of values for display and CSV.
//
// Decisions (tests in tests/engine/values/literals.test.ts):
// - An untyped integer adopts `expected` (range-checked); without one it is the smallest of
//   INT, DINT, LINT, ULINT that holds it.
// - An untyped real is REAL (rounded to 32 bits) unless LREAL is expected.
// - With `expected`, the result always has type `expected`: a typed literal (INT#5) must widen
//   to it (canWiden), else it is refused.
// - Based literals (16#FF) have no sign and must fit the type as numbers: SINT#16#FF is refused.
// - TIME literals are held in whole milliseconds (finer parts rounded to the nearest ms).
// - 'abc' is a STRING and "abc" a WSTRING (stringText.ts); neither converts to the other or to a
//   number implicitly. D#, TOD#, DT# (and DATE#, TIME_OF_DAY#, DATE_AND_TIME#) are dates and times
//   of day in ms (dateText.ts); a CSV or watch value may also give them as a number of ms.
import { ELEMENTARY_TYPES, isElementaryType, type ElementaryType, type Value } from '../../model/iecTypes';
import {
  canWiden,
  hasControlCharacter,
  isDateType,
  isRealType,
  isSingleByte,
  isSizedType,
  isStringType,
  normalize,
  typeRange,
  widen,
  type SizedType,
} from './types';
import { formatStringLiteral, looksLikeStringLiteral, parseStringLiteral } from './stringText';
import { datePrefix, formatDate, parseDateBody, type DateKind } from './dateText';
import { formatTime, parseTimeBody } from './time';
import { realDisplay, shortestLreal, shortestReal } from './realText';

export type LiteralResult = { ok: true; value: Value; type: ElementaryType } | { ok: false; message: string };
export type ValueResult = { ok: true; value: Value } | { ok: false; message: string };

type Raw =
  | { kind: 'bool'; value: boolean }
  | { kind: 'int'; value: bigint }
  | { kind: 'real'; value: number }
  | { kind: 'time'; ms: number }
  | { kind: 'string'; value: string; wide: boolean }
  | { kind: 'date'; type: DateKind; ms: number }
  | { kind: 'error'; message: string };

const DECIMAL = /^[+-]?\d(?:_?\d)*$/;
const BASED = /^(2|8|16)#([0-9A-Fa-f](?:_?[0-9A-Fa-f])*)$/;
const REAL_TEXT = /^[+-]?\d(?:_?\d)*(?:\.\d(?:_?\d)*)?(?:[eE][+-]?\d(?:_?\d)*)?$/;
const BASE_DIGITS: Record<string, RegExp> = { '2': /^[01_]+$/, '8': /^[0-7_]+$/, '16': /^[0-9A-Fa-f_]+$/ };
const TIME_PREFIX = /^(?:T|TIME)#/i;
const UNSUPPORTED_PREFIX = /^(LTIME|LT)#/i;

function parseInteger(text: string): Raw | undefined {
  if (DECIMAL.test(text)) return { kind: 'int', value: BigInt(text.replaceAll('_', '')) };
  const based = BASED.exec(text);
  if (based) {
    const base = based[1]!;
    if (!BASE_DIGITS[base]!.test(based[2]!)) return { kind: 'error', message: `"${text}" has digits that base ${base} does not allow` };
    const prefix = base === '16' ? '0x' : base === '8' ? '0o' : '0b';
    return { kind: 'int', value: BigInt(prefix + based[2]!.replaceAll('_', '')) };
  }
  if (/^[+-]\d+#/.test(text)) return { kind: 'error', message: `"${text}": a based number (16#.., 8#.., 2#..) cannot have a sign` };
  return undefined;
}

/** Reads the literal's own form, before any type is applied. */
function parseRaw(text: string): Raw {
  if (looksLikeStringLiteral(text)) {
    const s = parseStringLiteral(text);
    return s.ok ? { kind: 'string', value: s.value, wide: s.wide } : { kind: 'error', message: s.message };
  }
  const dateKind = datePrefix(text);
  if (dateKind) {
    const d = parseDateBody(dateKind, text.slice(text.indexOf('#') + 1));
    return d.ok ? { kind: 'date', type: dateKind, ms: d.ms } : { kind: 'error', message: d.message };
  }
  const upper = text.toUpperCase();
  if (upper === 'TRUE') return { kind: 'bool', value: true };
  if (upper === 'FALSE') return { kind: 'bool', value: false };
  if (TIME_PREFIX.test(text)) {
    const t = parseTimeBody(text.slice(text.indexOf('#') + 1));
    return t.ok ? { kind: 'time', ms: t.ms } : { kind: 'error', message: t.message };
  }
  const int = parseInteger(text);
  if (int) return int;
  if (REAL_TEXT.test(text)) return { kind: 'real', value: Number(text.replaceAll('_', '')) };
  return {
    kind: 'error',
    message: `"${text}" is not a value: write TRUE/FALSE, a number (42, -7, 16#FF, 1.5), a TIME (T#1s500ms) or a STRING ('text')`,
  };
}

const describe = (raw: Raw, text: string): string => {
  switch (raw.kind) {
    case 'bool':
      return `${text} is a BOOL`;
    case 'int':
      return `${text} is an integer`;
    case 'real':
      return `${text} is a real number`;
    case 'time':
      return `${text} is a TIME`;
    case 'string':
      return `${text} is a ${raw.wide ? 'WSTRING' : 'STRING'}`;
    case 'date':
      return `${text} is a ${raw.type}`;
    case 'error':
      return raw.message;
  }
};

const rangeText = (t: SizedType): string => {
  const { min, max } = typeRange(t);
  return `${min}..${max}`;
};

/** Gives an untyped literal the type `type`, or says in plain words why it cannot have it. */
function applyType(raw: Raw, type: ElementaryType, text: string): LiteralResult {
  if (raw.kind === 'error') return { ok: false, message: raw.message };
  if (isStringType(type)) {
    const wide = type === 'WSTRING';
    if (raw.kind === 'string' && raw.wide === wide) return { ok: true, value: raw.value, type };
    if (raw.kind === 'string')
      return { ok: false, message: `${text} is a ${raw.wide ? 'WSTRING' : 'STRING'}, not a ${type} (write a ${type} between ${wide ? 'double quotes: "abc"' : "single quotes: 'abc'"})` };
    return { ok: false, message: `${describe(raw, text)}, not a ${type} (write a ${type} between ${wide ? 'double quotes: "abc"' : "single quotes: 'abc'"})` };
  }
  if (raw.kind === 'string') return { ok: false, message: `${describe(raw, text)}, not ${article(type)} ${type}` };
  if (isDateType(type)) {
    if (raw.kind === 'date' && raw.type === type) return { ok: true, value: raw.ms, type };
    return { ok: false, message: `${describe(raw, text)}, not ${article(type)} ${type} (write ${DATE_EXAMPLE[type]})` };
  }
  if (raw.kind === 'date') return { ok: false, message: `${describe(raw, text)}, not ${article(type)} ${type}` };
  if (type === 'BOOL') {
    if (raw.kind === 'bool') return { ok: true, value: raw.value, type };
    if (raw.kind === 'int' && (raw.value === 0n || raw.value === 1n)) return { ok: true, value: raw.value === 1n, type };
    return { ok: false, message: `${describe(raw, text)}, not a BOOL (use TRUE, FALSE, 1 or 0)` };
  }
  if (type === 'TIME') {
    if (raw.kind === 'time') return { ok: true, value: raw.ms, type };
    return { ok: false, message: `${describe(raw, text)}, not a TIME (write a TIME as T#5s, T#500ms or T#1m30s)` };
  }
  if (isRealType(type)) {
    if (raw.kind === 'int') return { ok: true, value: normalize(type, Number(raw.value)), type };
    if (raw.kind === 'real') {
      const value = normalize(type, raw.value) as number;
      if (!Number.isFinite(value)) return { ok: false, message: `${text} is too large for ${type}` };
      return { ok: true, value, type };
    }
    return { ok: false, message: `${describe(raw, text)}, not a ${type} number` };
  }
  if (isSizedType(type)) {
    if (raw.kind !== 'int') {
      const hint = raw.kind === 'real' ? `; ${type} needs a whole number` : '';
      return { ok: false, message: `${describe(raw, text)}, not ${article(type)} ${type}${hint}` };
    }
    const { min, max } = typeRange(type);
    if (raw.value < min || raw.value > max) return { ok: false, message: `${text} does not fit ${type} (${rangeText(type)})` };
    return { ok: true, value: normalize(type, raw.value), type };
  }
  return { ok: false, message: `${type} values cannot be written as literals` };
}

const article = (type: string): string => (/^[AEIOU]/.test(type) ? 'an' : 'a');

const DATE_EXAMPLE: Record<DateKind, string> = { DATE: 'D#2024-01-31', TOD: 'TOD#12:30:15', DT: 'DT#2024-01-31-12:30:15' };

/** Type an untyped literal takes when nothing is expected of it. */
function naturalType(raw: Raw): ElementaryType | undefined {
  switch (raw.kind) {
    case 'bool':
      return 'BOOL';
    case 'time':
      return 'TIME';
    case 'real':
      return 'REAL';
    case 'string':
      return raw.wide ? 'WSTRING' : 'STRING';
    case 'date':
      return raw.type;
    case 'int':
      return (['INT', 'DINT', 'LINT', 'ULINT'] as const).find((t) => raw.value >= typeRange(t).min && raw.value <= typeRange(t).max);
    case 'error':
      return undefined;
  }
}

/**
 * Parses an IEC literal: TRUE, 0, 1, -5, 1_000, 16#FF, 8#17, 2#1010_1010, INT#-5, UINT#16#FF, BOOL#1,
 * 1.5, -2.0E3, REAL#1.5, T#1s500ms, TIME#-2h, t#1.5s, 'text$N', "wide", STRING#'abc'.
 */
export function parseLiteral(text: string, expected?: ElementaryType): LiteralResult {
  const trimmed = text.trim();
  if (trimmed === '') return { ok: false, message: 'the value is empty' };
  if (UNSUPPORTED_PREFIX.test(trimmed)) {
    return { ok: false, message: `"${trimmed}": ${trimmed.slice(0, trimmed.indexOf('#')).toUpperCase()} values are not supported (types: ${ELEMENTARY_TYPES.join(', ')})` };
  }
  const typed = /^([A-Za-z_][A-Za-z0-9_]*)#(.+)$/.exec(trimmed);
  let result: LiteralResult;
  if (typed && !TIME_PREFIX.test(trimmed) && !datePrefix(trimmed)) {
    const typeName = typed[1]!.toUpperCase();
    if (!isElementaryType(typeName)) return { ok: false, message: `"${typed[1]}" in "${trimmed}" is not a known type` };
    const body = typed[2]!;
    const raw = parseRaw(body);
    if (raw.kind === 'bool' && typeName !== 'BOOL') return { ok: false, message: `${trimmed}: TRUE/FALSE are BOOL values, not ${typeName}` };
    result = applyType(raw, typeName, trimmed);
  } else {
    const raw = parseRaw(trimmed);
    if (expected) return applyType(raw, expected, trimmed);
    const natural = naturalType(raw);
    if (!natural) return { ok: false, message: raw.kind === 'error' ? raw.message : `${trimmed} is too large for any integer type` };
    result = applyType(raw, natural, trimmed);
  }
  if (!result.ok || !expected || result.type === expected) return result;
  if (!canWiden(result.type, expected)) return { ok: false, message: `${trimmed} is ${article(result.type)} ${result.type}, but ${expected} is needed here` };
  return { ok: true, value: widen(result.type, expected, result.value), type: expected };
}

/**
 * True for literals that take their type from where they are used: plain and based integers
 * (42, 16#FF, 2#1010) and reals (1.5). Typed literals (INT#5, T#1s) and TRUE/FALSE carry their own type.
 */
export function isUntypedLiteral(text: string): boolean {
  const t = text.trim();
  const raw = parseRaw(t);
  return (raw.kind === 'int' || raw.kind === 'real') && !/^[A-Za-z_]/.test(t);
}

/**
 * Text for the user: TRUE/FALSE, decimal integers, REAL in the shortest form that reads back exactly
 * (2.0, 0.1), T#1s500ms, a STRING as its literal ('it$'s').
 */
export function formatValue(type: ElementaryType, v: Value): string {
  if (isStringType(type)) return formatStringLiteral(String(v), type === 'WSTRING');
  if (isDateType(type)) return formatDate(type, Number(v));
  if (type === 'BOOL') return v === true || v === 1 || v === 1n ? 'TRUE' : 'FALSE';
  if (type === 'TIME') return formatTime(Number(v));
  if (type === 'REAL') return realDisplay(shortestReal(Number(v)));
  if (type === 'LREAL') return realDisplay(shortestLreal(Number(v)));
  return String(v);
}

/**
 * Text for CSV traces: BOOL 0/1, integers in decimal, REAL/LREAL in the shortest digits that read
 * back exactly, TIME in ms, a STRING as its text (as its literal when the plain text would read back
 * otherwise: empty, spaces around it, control characters, or a leading quote). The CSV writer
 * quotes the cell (RFC 4180) where it has to.
 */
export function csvValue(type: ElementaryType, v: Value): string {
  if (isDateType(type)) return formatDate(type, Number(v));
  if (isStringType(type)) {
    const s = String(v);
    const plain = s !== '' && s.trim() === s && !hasControlCharacter(s) && !looksLikeStringLiteral(s);
    return plain ? s : formatStringLiteral(s, type === 'WSTRING');
  }
  if (type === 'BOOL') return v === true || v === 1 || v === 1n ? '1' : '0';
  if (type === 'REAL') return shortestReal(Number(v));
  if (type === 'LREAL') return shortestLreal(Number(v));
  return String(v);
}

/**
 * Reads a value typed by a user or found in a CSV stimulus file: 0/1/true/false/on/off for BOOL,
 * plain numbers (a TIME as a number of ms), or any IEC literal that fits the type. A STRING is its
 * literal ('a$Nb', '' for empty) or, when the text does not start with a quote, the text itself.
 */
export function parseValueText(type: ElementaryType, text: string): ValueResult {
  const trimmed = text.trim();
  if (isStringType(type) && !looksLikeStringLiteral(trimmed)) {
    const value = normalize(type, text);
    if (type === 'STRING' && !isSingleByte(text))
      return { ok: false, message: `"${text}" has characters a STRING cannot hold (it holds single bytes); use a WSTRING` };
    return { ok: true, value };
  }
  if (type === 'BOOL') {
    const lower = trimmed.toLowerCase();
    if (lower === 'on') return { ok: true, value: true };
    if (lower === 'off') return { ok: true, value: false };
  }
  if ((type === 'TIME' || isDateType(type)) && /^[+-]?\d+(?:\.\d+)?$/.test(trimmed)) return { ok: true, value: normalize(type, Number(trimmed)) };
  if (isSizedType(type) && /^[+-]?\d+\.0*$/.test(trimmed)) return parseValueText(type, trimmed.replace(/\.0*$/, ''));
  const r = parseLiteral(trimmed, type);
  return r.ok ? { ok: true, value: r.value } : { ok: false, message: r.message };
}
