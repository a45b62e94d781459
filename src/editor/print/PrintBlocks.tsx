// The printed blocks: a POU heading, a network (its header and its grid as drawn by the canvas
// code), source text, headings and notes, a row of the variable list or of the cross-reference,
// and those tables' headers. Rows are grids of fixed columns, so a row's height does not depend on
// the other rows and each can be measured on its own.
import type { ReactNode } from 'react';
import { classLabel, pouTitle, type PrintItem } from './printModel';
import type { NetworkDrawing } from './networkSvg';

const VAR_COLUMNS = ['Class', 'Name', 'Type', 'Address', 'Initial', 'Attributes', 'Comment'] as const;
const XREF_COLUMNS = ['Name', 'Declared in', 'Type', 'Address', 'Uses', 'Count'] as const;

function Row(props: { readonly cells: readonly ReactNode[]; readonly className: string; readonly head?: boolean }) {
  return (
    <div className={`rs-print-row ${props.className}`} role="row">
      {props.cells.map((c, i) => (
        <span key={i} role={props.head ? 'columnheader' : 'cell'}>
          {c}
        </span>
      ))}
    </div>
  );
}

const columnsOf = (table: string) => (table === 'xref' ? XREF_COLUMNS : VAR_COLUMNS);
const tableClass = (table: string) => (table === 'xref' ? 'rs-print-xref' : 'rs-print-var');

/** The header of the table a row belongs to, repeated on each page the table reaches. */
export function TableHead({ table }: { readonly table: string }) {
  return <Row className={`rs-print-head ${tableClass(table)}`} cells={columnsOf(table)} head />;
}

/** A one-line row of the table: measured once, it gives the height of every row whose cells all fit. */
export function SampleRow({ table }: { readonly table: string }) {
  return <Row className={`rs-print-sample ${tableClass(table)}`} cells={columnsOf(table).map(() => 'X')} />;
}

export function PrintBlockView({
  item,
  drawing,
  frameOnly,
}: {
  readonly item: PrintItem;
  readonly drawing?: NetworkDrawing;
  /** Measuring: the grid's room without its drawing. */
  readonly frameOnly?: boolean;
}) {
  switch (item.kind) {
    case 'pou':
      return (
        <div className="rs-print-pou">
          <h2>{pouTitle(item.pou)}</h2>
          {item.pou.comment && <p>{item.pou.comment}</p>}
        </div>
      );
    case 'network': {
      const n = item.network;
      return (
        <div className="rs-print-network" data-testid="print-network">
          <div className="rs-print-net-head">
            <strong>Network {item.index + 1}</strong>
            {n.label && <code>{n.label}:</code>}
            <span>{n.title}</span>
          </div>
          {n.comment && <p className="rs-print-net-comment">{n.comment}</p>}
          <div
            className="rs-print-net-grid"
            role="img"
            aria-label={`Network ${item.index + 1} of ${item.pou.name}`}
            dangerouslySetInnerHTML={{ __html: (frameOnly ? drawing?.frame : drawing?.svg) ?? '' }}
          />
        </div>
      );
    }
    case 'source':
      return <pre className="rs-print-source">{item.text || '(empty)'}</pre>;
    case 'heading':
      return (
        <div className="rs-print-heading">
          <h3>{item.text}</h3>
          {item.note && <p>{item.note}</p>}
        </div>
      );
    case 'note':
      return <p className="rs-print-note">{item.text}</p>;
    case 'var':
    case 'xref':
      return <Row className={tableClass(item.table)} cells={rowCells(item)} />;
  }
}

/** The cells' texts of a table row (empty for other blocks). */
export function rowCells(item: PrintItem): string[] {
  if (item.kind === 'xref') {
    const r = item.row;
    return [r.name, r.declaredIn, r.type, r.address, r.uses, String(r.count)];
  }
  if (item.kind !== 'var') return [];
  const v = item.variable;
  const attributes = [v.retain ? 'RETAIN' : '', v.constant ? 'CONSTANT' : ''].filter(Boolean).join(' ');
  return [classLabel(v, item.global), v.name, v.type, v.location ?? '', v.initial ?? '', attributes, v.comment];
}

/** The table a block is a row of, if it is one. */
export const tableOf = (item: PrintItem): string | undefined =>
  item.kind === 'var' || item.kind === 'xref' ? item.table : undefined;
