// Shortest decimal text for floating-point values.

/**
 * Shortest decimal digits that read back (as a 32-bit float) to the same REAL. A number that is not
 * a 32-bit float yet (a machine's quantity, computed in 64 bits, read as a REAL) is taken as the REAL
 * it would be stored as: 60.00000000000001 is 60, not 17 digits of noise.
 */
export function shortestReal(value: number): string {
  const v = Math.fround(value);
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return Object.is(v, -0) ? '-0' : '0';
  for (let digits = 1; digits <= 9; digits++) {
    const text = v.toPrecision(digits);
    if (Math.fround(Number(text)) === v) return String(Number(text));
  }
  return String(v);
}

/** Shortest decimal digits that read back (as a 64-bit float) to the same LREAL: JavaScript's own rule. */
export const shortestLreal = (v: number): string => (Object.is(v, -0) ? '-0' : String(v));

/** Display form of a real: always shows it is a real (2 -> "2.0", 1e21 -> "1.0e+21"). */
export function realDisplay(text: string): string {
  if (!/^-?\d/.test(text) || text.includes('.')) return text;
  const e = text.indexOf('e');
  return e < 0 ? `${text}.0` : `${text.slice(0, e)}.0${text.slice(e)}`;
}
