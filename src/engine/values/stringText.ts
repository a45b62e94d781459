// STRING and WSTRING literals (IEC 61131-3 table 6): 'single byte' and "double byte" character
// strings with `$` escapes, and the literal text of a string value for display.
//
// Escapes, as MATIEC reads them: $$ (dollar), $' (quote, in a STRING), $" (quote, in a WSTRING),
// $L (line feed), $N (newline: line feed), $P (form feed), $R (carriage return), $T (tab), each
// letter in either case; $hh (two hex digits, a STRING's byte) and $hhhh (four, a WSTRING's
// character). The other quote stands for itself ("it's" needs no escape). A STRING holds single
// bytes: a character above 255 has to be written in a WSTRING.
import { STRING_MAX_LEN } from '../../model/iecTypes';

export type StringLiteral = { ok: true; value: string; wide: boolean } | { ok: false; message: string };

const CONTROL: Record<string, string> = { L: '\n', N: '\n', P: '\f', R: '\r', T: '\t' };

/** True when the text is written as a string literal (starts with a quote). */
export const looksLikeStringLiteral = (text: string): boolean => text.startsWith("'") || text.startsWith('"');

/**
 * Reads `'...'` (STRING) or `"..."` (WSTRING). Values longer than STRING_MAX_LEN characters are
 * cut there, as MATIEC's STRING holds no more.
 */
export function parseStringLiteral(text: string): StringLiteral {
  const quote = text[0];
  if ((quote !== "'" && quote !== '"') || text.length < 2 || text[text.length - 1] !== quote)
    return { ok: false, message: `${text} is not a string: write a STRING between single quotes ('abc') or a WSTRING between double quotes ("abc")` };
  const wide = quote === '"';
  const type = wide ? 'WSTRING' : 'STRING';
  const body = text.slice(1, -1);
  let out = '';
  for (let i = 0; i < body.length; i++) {
    const c = body[i]!;
    if (c === quote) return { ok: false, message: `${text}: a ${quote} inside a ${type} is written $${quote}` };
    if (c !== '$') {
      if (!wide && c.charCodeAt(0) > 255)
        return { ok: false, message: `${text}: "${c}" is not a single-byte character; a STRING holds bytes (write it in a WSTRING: "...")` };
      out += c;
      continue;
    }
    const next = body[i + 1];
    if (next === undefined) return { ok: false, message: `${text}: a $ at the end of a string is written $$` };
    const upper = next.toUpperCase();
    if (next === '$' || next === "'" || next === '"') {
      out += next;
      i++;
    } else if (CONTROL[upper] !== undefined) {
      out += CONTROL[upper];
      i++;
    } else {
      const digits = wide ? 4 : 2;
      const hex = body.slice(i + 1, i + 1 + digits);
      if (hex.length !== digits || !/^[0-9A-Fa-f]+$/.test(hex))
        return {
          ok: false,
          message: `${text}: "$${next}" is not an escape; use $$, $${quote}, $L, $N, $P, $R, $T or $ and ${digits} hex digits`,
        };
      out += String.fromCharCode(parseInt(hex, 16));
      i += digits;
    }
  }
  return { ok: true, value: out.length > STRING_MAX_LEN ? out.slice(0, STRING_MAX_LEN) : out, wide };
}

const NAMED: Record<string, string> = { '\n': '$N', '\f': '$P', '\r': '$R', '\t': '$T', $: '$$' };

/** The literal of a string value: 'it$'s', "wide", with escapes for $, the quote and control characters. */
export function formatStringLiteral(value: string, wide: boolean): string {
  const quote = wide ? '"' : "'";
  let out = quote;
  for (const c of value) {
    const code = c.charCodeAt(0);
    if (NAMED[c]) out += NAMED[c];
    else if (c === quote) out += `$${quote}`;
    else if (code < 0x20 || code === 0x7f) out += `$${code.toString(16).toUpperCase().padStart(wide ? 4 : 2, '0')}`;
    else out += c;
  }
  return out + quote;
}
