// The syntax of an operand path (`Motor1.T1.Q`, `Line.Pts[2].X`, `Grid[1, 2]`): its names and
// constant index lists, before SymbolTable.resolve (symbols.ts) looks them up.

/**
 * `A.B[1, 2].C` -> ['A', 'B', [1, 2], 'C'] (names, and constant index lists); undefined when the
 * text is not such a path (an index that is not an integer literal, unbalanced brackets).
 */
export function splitPath(text: string): (string | number[])[] | undefined {
  const out: (string | number[])[] = [];
  let i = 0;
  const s = text.trim();
  const ident = /^[A-Za-z_0-9]+/;
  while (i < s.length) {
    if (out.length > 0) {
      if (s[i] === '.') i++;
      else if (s[i] !== '[') return undefined;
    }
    if (s[i] === '[') {
      const end = s.indexOf(']', i);
      if (end < 0) return undefined;
      const parts = s.slice(i + 1, end).split(',').map((x) => x.trim());
      if (!parts.every((x) => /^[+-]?\d+$/.test(x))) return undefined;
      out.push(parts.map(Number));
      i = end + 1;
      continue;
    }
    const m = ident.exec(s.slice(i));
    if (!m) return undefined;
    out.push(m[0]);
    i += m[0].length;
  }
  return out;
}
