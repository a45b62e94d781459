// Comparing a trace of the MATIEC reference (run_oracle.py: `scan,time_ms,<watched>`, STRING cells
// double-quoted, REAL as %.9g) with Rungsmith's `simulate` CSV. Used by tests/plcopen/referenceTraces.test.ts
// and the differential fuzzer (scripts/fuzz.ts).

/** CSV rows (no quoting of commas inside STRING cells is used by the oracle for our cases). */
export function rows(text: string): string[][] {
  return text
    .split('\n')
    .filter((l) => l.trim() !== '' && !l.startsWith('#'))
    .map((l) => parseCsvLine(l));
}

export function parseCsvLine(line: string): string[] {
  const cells: string[] = [];
  let cur = '';
  let quoted = false;
  for (let i = 0; i < line.length; i++) {
    const c = line[i]!;
    if (quoted && c === '"' && line[i + 1] === '"') {
      cur += '"';
      i++;
    } else if (c === '"') quoted = !quoted;
    else if (c === ',' && !quoted) {
      cells.push(cur);
      cur = '';
    } else cur += c;
  }
  cells.push(cur);
  return cells;
}

/** An IEC string literal's text ('a$'b' → a'b); other text unchanged. */
export function iecText(s: string): string {
  if (s.length < 2 || !s.startsWith("'") || !s.endsWith("'")) return s;
  return s
    .slice(1, -1)
    .replace(/\$([0-9A-Fa-f]{2}|.)/g, (_, d: string) =>
      d.length === 2
        ? String.fromCharCode(parseInt(d, 16))
        : (({ $: '$', "'": "'", N: '\n', L: '\n', R: '\r', T: '\t', P: '\f' } as Record<string, string>)[
            d.toUpperCase()
          ] ?? d),
    );
}

/** The oracle's cell and ours are the same value: integers exactly, REAL as 32-bit floats, text as text. */
export function same(expected: string, actual: string): boolean {
  if (expected === actual) return true;
  const num = /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^[-+]?(inf|nan|Infinity|NaN)$/;
  if (num.test(expected) && num.test(actual)) {
    const x = Number(expected.replace(/inf$/, 'Infinity'));
    const y = Number(actual.replace(/inf$/, 'Infinity'));
    if (Number.isNaN(x) && Number.isNaN(y)) return true;
    return Math.fround(x) === Math.fround(y);
  }
  return expected === iecText(actual);
}
