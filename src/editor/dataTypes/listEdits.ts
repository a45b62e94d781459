// Small list edits the data-type editor's rows share: replace, remove, move one up or down.
export const replaceAt = <T>(list: readonly T[], i: number, item: T): T[] => list.map((x, j) => (j === i ? item : x));
export const removeAt = <T>(list: readonly T[], i: number): T[] => list.filter((_, j) => j !== i);
export function moveBy<T>(list: readonly T[], i: number, delta: number): T[] {
  const j = i + delta;
  if (j < 0 || j >= list.length) return [...list];
  const out = [...list];
  [out[i], out[j]] = [out[j]!, out[i]!];
  return out;
}
/** `base1`, `base2`...: the first name not in the list (ignoring case). */
export function freshName(list: readonly string[], base: string): string {
  const taken = new Set(list.map((n) => n.toUpperCase()));
  for (let i = list.length + 1; ; i++) if (!taken.has(`${base}${i}`.toUpperCase())) return `${base}${i}`;
}
/** A whole number typed in a bound field, or undefined. */
export const wholeNumber = (text: string): number | undefined => (/^\s*-?\d+\s*$/.test(text) ? Number(text) : undefined);
