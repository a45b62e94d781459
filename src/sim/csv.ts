// A small CSV reader and writer for scenarios and traces (runs in the browser and in Node):
// comma separated, double quotes around cells with commas or quotes ("" inside), `#` comment lines.

export interface CsvLine {
  /** 1-based line number in the text. */
  readonly line: number;
  readonly cells: string[];
}

/** Lines with their cells (trimmed); blank lines are skipped, `#` lines come back as comments. */
export function readCsv(text: string): { rows: CsvLine[]; comments: CsvLine[] } {
  const rows: CsvLine[] = [];
  const comments: CsvLine[] = [];
  text.split(/\r?\n/).forEach((raw, i) => {
    const line = i + 1;
    const t = raw.trim();
    if (t === '') return;
    if (t.startsWith('#')) {
      comments.push({ line, cells: [t.slice(1).trim()] });
      return;
    }
    rows.push({ line, cells: splitCells(raw, line) });
  });
  return { rows, comments };
}

function splitCells(raw: string, line: number): string[] {
  const cells: string[] = [];
  let cur = '';
  let quoted = false;
  for (let i = 0; i < raw.length; i++) {
    const c = raw[i]!;
    if (quoted) {
      if (c === '"' && raw[i + 1] === '"') {
        cur += '"';
        i++;
      } else if (c === '"') quoted = false;
      else cur += c;
    } else if (c === '"' && cur.trim() === '') {
      quoted = true;
      cur = '';
    } else if (c === ',') {
      cells.push(cur.trim());
      cur = '';
    } else cur += c;
  }
  if (quoted) throw new Error(`line ${line}: a quoted cell is not closed`);
  cells.push(cur.trim());
  return cells;
}

export function csvCell(text: string): string {
  return /[",\n]/.test(text) ? `"${text.replace(/"/g, '""')}"` : text;
}

export const csvRow = (cells: readonly string[]): string => cells.map(csvCell).join(',');
