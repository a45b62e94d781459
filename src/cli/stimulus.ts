// Stimulus CSV: header `scan,<var>,<var>…`; a row sets those variables just before the input read
// of that scan (1-based); an empty cell leaves the value as it is.
import { parse } from 'csv-parse/sync';
import { UsageError } from './io';

export interface StimulusRow {
  readonly scan: number;
  readonly line: number;
  /** Variable name → text (only non-empty cells). */
  readonly values: ReadonlyMap<string, string>;
}

export interface Stimulus {
  readonly columns: readonly string[];
  readonly rows: readonly StimulusRow[];
}

export function parseStimulus(text: string, file: string): Stimulus {
  let records: { record: string[]; info: { lines: number } }[];
  try {
    records = parse(text, {
      skip_empty_lines: true,
      trim: true,
      info: true,
      relax_column_count: true,
      comment: '#',
    }) as unknown as typeof records;
  } catch (e) {
    throw new UsageError(`${file}: not a valid CSV file: ${(e as Error).message}`);
  }
  const head = records[0];
  if (!head || head.record[0]?.toLowerCase() !== 'scan')
    throw new UsageError(`${file}: the first line must be the header scan,<variable>,<variable>...`);
  const columns = head.record.slice(1);
  columns.forEach((c, i) => {
    if (!c) throw new UsageError(`${file} line ${head.info.lines}: column ${i + 2} has no variable name`);
  });
  const rows: StimulusRow[] = [];
  let last = 0;
  for (const { record, info } of records.slice(1)) {
    const scanText = record[0] ?? '';
    const scan = Number(scanText);
    if (!Number.isInteger(scan) || scan < 1)
      throw new UsageError(
        `${file} line ${info.lines}: scan "${scanText}" is not a scan number (1, 2, 3...)`,
      );
    if (scan < last)
      throw new UsageError(
        `${file} line ${info.lines}: scan ${scan} comes after scan ${last}; sort the rows by scan`,
      );
    if (record.length > columns.length + 1)
      throw new UsageError(`${file} line ${info.lines}: more cells than header columns`);
    last = scan;
    const values = new Map<string, string>();
    columns.forEach((c, i) => {
      const cell = record[i + 1];
      if (cell !== undefined && cell !== '') values.set(c, cell);
    });
    rows.push({ scan, line: info.lines, values });
  }
  return { columns, rows };
}
