// The print view: the print laid out on A4 pages, shown as sheets on screen and printed as they
// are (print.css). The pages are computed here, not left to the browser, so each page carries a
// title block with its number out of the total: every block is first rendered once at the page
// body's width and measured, paginate() places the blocks on pages (never splitting a network that
// fits on a page), then the pages are rendered, each with its title block. A table row whose
// cells all fit their columns (checked with the canvas's text measure) is one line high and is
// not rendered for measuring: large variable lists lay out in a fraction of the time.
import { useLayoutEffect, useMemo, useRef, useState, type ReactNode } from 'react';
import { createPortal } from 'react-dom';
import { blockLibrary } from '../../model/library';
import type { Pou, Project } from '../../model/project';
import type { SymbolComments } from '../canvas/geometry';
import { symbolCommentLookup } from '../canvas/symbolComments';
import { useModal } from '../layout/useModal';
import { readCanvasTheme } from '../theme/canvasTheme';
import { networkSvg, type NetworkDrawing } from './networkSvg';
import { paginate, type PagePiece, type PrintBlock, type PrintPage } from './paginate';
import { PrintBlockView, rowCells, SampleRow, TableHead, tableOf } from './PrintBlocks';
import { printItems, type PrintItem } from './printModel';
import type { PrintOptions } from './printState';
import { canvasMeasure } from './svgContext';
import './print.css';

/** Height of a "continued" mark (print.css .rs-print-mark). */
const MARK_H = 18;
/** Kept free at the bottom of each page against rounding in the printer's layout. */
const SLACK = 2;

/** The canvas colours of the light theme, whatever the editor shows. */
function lightTheme() {
  const probe = document.createElement('div');
  probe.dataset.theme = 'light';
  document.body.append(probe);
  const theme = readCanvasTheme(probe);
  probe.remove();
  return theme;
}

const formatDate = (d: Date) => {
  const p = (n: number) => String(n).padStart(2, '0');
  return `${d.getFullYear()}-${p(d.getMonth() + 1)}-${p(d.getDate())} ${p(d.getHours())}:${p(d.getMinutes())}`;
};

/** Where a block may be cut if it is taller than a page: between rows of a rung, lines of text. */
function breaksOf(el: HTMLElement, item: PrintItem, drawing: NetworkDrawing | undefined): number[] {
  const top = el.getBoundingClientRect().top;
  if (item.kind === 'network' && drawing) {
    const grid = el.querySelector('svg')?.getBoundingClientRect();
    if (!grid) return [];
    const scale = grid.height / drawing.height;
    return Array.from({ length: drawing.rows - 1 }, (_, r) => grid.top - top + (r + 1) * drawing.pitch * scale);
  }
  if (item.kind === 'source') {
    const pre = el.querySelector('pre') ?? el;
    const style = getComputedStyle(pre);
    const line = parseFloat(style.lineHeight) || 15;
    const first = pre.getBoundingClientRect().top - top + parseFloat(style.paddingTop);
    const lines = item.text.split('\n').length;
    return Array.from({ length: lines - 1 }, (_, k) => first + (k + 1) * line);
  }
  return [];
}

function TitleBlock(props: { project: string; section: string; date: string; page: number; pages: number }) {
  return (
    <header className="rs-print-title">
      <span className="rs-print-project">{props.project}</span>
      <span className="rs-print-section">{props.section}</span>
      <span className="rs-print-date">{props.date}</span>
      <span className="rs-print-pageno" data-testid="print-page-number">
        Page {props.page} / {props.pages}
      </span>
    </header>
  );
}

function Piece({ piece, item, drawing }: { piece: PagePiece; item: PrintItem; drawing: NetworkDrawing | undefined }) {
  const block = (
    <div className="rs-print-block">
      <PrintBlockView item={item} {...(drawing ? { drawing } : {})} />
    </div>
  );
  const what = item.kind === 'network' ? `Network ${item.index + 1}` : 'Continued';
  const content: ReactNode =
    piece.continued || piece.continues ? (
      <>
        {piece.continued && <div className="rs-print-mark">{what} (continued)</div>}
        <div className="rs-print-slice" style={{ height: piece.to - piece.from }}>
          <div style={{ marginTop: -piece.from }}>{block}</div>
        </div>
        {piece.continues && <div className="rs-print-mark">continued on the next page ↓</div>}
      </>
    ) : (
      block
    );
  return (
    <>
      {piece.groupHead && <TableHead table={tableOf(item)!} />}
      {content}
    </>
  );
}

export function PrintView({
  project,
  options,
  onClose,
  symbolComments = false,
}: {
  readonly project: Project;
  readonly options: PrintOptions;
  readonly onClose: () => void;
  /** The editor's "Show symbol comments" option: printed as shown. */
  readonly symbolComments?: boolean;
}) {
  const items = useMemo(() => printItems(project, options), [project, options]);
  const measure = useMemo(() => canvasMeasure(), []);
  const drawings = useMemo(() => {
    const theme = lightTheme();
    const library = blockLibrary(project);
    const lookups = new Map<Pou, SymbolComments>();
    const symbolsOf = (pou: Pou) => {
      if (!symbolComments) return undefined;
      let s = lookups.get(pou);
      if (!s) lookups.set(pou, (s = symbolCommentLookup(pou.variables, project.globals)));
      return s;
    };
    return items.map((item) =>
      item.kind === 'network' ? networkSvg(item.network, theme, measure, library, symbolsOf(item.pou)) : undefined,
    );
  }, [items, project, measure, symbolComments]);
  /** Table rows to render and measure (a cell wraps); the others are one line high. */
  const [wrapping, setWrapping] = useState<ReadonlySet<number> | undefined>(undefined);
  const [pages, setPages] = useState<PrintPage[] | undefined>(undefined);
  const measureRef = useRef<HTMLDivElement>(null);
  const printButton = useRef<HTMLButtonElement>(null);
  const date = useMemo(() => formatDate(new Date()), []);

  // First the tables' columns: which rows have a cell wider than its column, so they wrap.
  useLayoutEffect(() => {
    const root = measureRef.current;
    if (!root || wrapping) return;
    const columns = new Map(
      [...root.querySelectorAll<HTMLElement>('[data-head]')].map((el) => {
        const cells = [...el.querySelectorAll<HTMLElement>('.rs-print-head > span')];
        const style = getComputedStyle(el.querySelector('.rs-print-sample > span')!);
        const font = `${style.fontStyle} ${style.fontWeight} ${style.fontSize} ${style.fontFamily}`;
        return [el.dataset.head!, { font, widths: cells.map((c) => c.clientWidth) }];
      }),
    );
    const rows = new Set<number>();
    items.forEach((item, i) => {
      const table = tableOf(item);
      if (!table) return;
      const { font, widths } = columns.get(table === 'xref' ? 'xref' : 'vars')!;
      if (rowCells(item).some((text, c) => text && measure(font, text) > (widths[c] ?? 0) - 1)) rows.add(i);
    });
    setWrapping(rows);
  }, [items, measure, wrapping]);

  // Then every block at the page body's width, and the pages.
  useLayoutEffect(() => {
    const root = measureRef.current;
    if (!root || !wrapping || pages) return;
    const body = root.querySelector<HTMLElement>('.rs-print-body')!;
    const heads = new Map(
      [...root.querySelectorAll<HTMLElement>('[data-head]')].map((el) => [
        el.dataset.head!,
        {
          head: el.querySelector('.rs-print-head')!.getBoundingClientRect().height,
          line: el.querySelector('.rs-print-sample')!.getBoundingClientRect().height,
        },
      ]),
    );
    const heights = new Map<number, HTMLElement>();
    for (const el of root.querySelectorAll<HTMLElement>('[data-block]')) heights.set(Number(el.dataset.block), el);
    const blocks: PrintBlock[] = items.map((item, i) => {
      const table = tableOf(item);
      const head = table ? heads.get(table === 'xref' ? 'xref' : 'vars')! : undefined;
      const el = heights.get(i);
      const breaks = el ? breaksOf(el, item, drawings[i]) : [];
      return {
        height: el ? el.getBoundingClientRect().height : (head?.line ?? 0),
        ...(breaks.length ? { breaks } : {}),
        ...(item.kind === 'pou' || item.kind === 'heading' ? { keepWithNext: true } : {}),
        ...(table ? { group: table, groupHead: head?.head ?? 0 } : {}),
      };
    });
    setPages(paginate(blocks, { pageHeight: body.clientHeight - SLACK, markHeight: MARK_H }));
  }, [items, drawings, wrapping, pages]);

  useLayoutEffect(() => {
    document.body.classList.add('rs-printing');
    return () => document.body.classList.remove('rs-printing');
  }, []);
  const modal = useModal(onClose);
  useLayoutEffect(() => {
    if (pages) printButton.current?.focus();
  }, [pages]);

  const sectionOf = (page: PrintPage) => items[page.pieces[0]?.block ?? 0]?.section ?? '';
  const paper = options.orientation;

  return createPortal(
    <div
      className={`rs-print-view rs-paper-${paper}`}
      data-theme="light"
      role="dialog"
      aria-label="Print preview"
      data-testid="print-view"
      aria-modal="true"
      data-ready={pages ? 'true' : 'false'}
      {...modal}
    >
      <style>{`@page { size: A4 ${paper}; margin: 10mm; }`}</style>
      <div className="rs-print-toolbar">
        <strong>Print preview</strong>
        <span data-testid="print-summary">
          {pages ? `${pages.length} page${pages.length === 1 ? '' : 's'}` : 'Laying out…'} · A4 {paper}
        </span>
        <span className="rs-print-hint">To export a PDF, choose “Save as PDF” as the printer in the print dialog.</span>
        <span className="rs-spacer" />
        <button
          ref={printButton}
          type="button"
          className="rs-button rs-primary"
          disabled={!pages}
          onClick={() => window.print()}
          data-testid="print-now"
        >
          Print… / Save as PDF
        </button>
        <button type="button" className="rs-button" onClick={onClose} data-testid="print-close">
          Close
        </button>
      </div>
      {!pages ? (
        <div ref={measureRef} className="rs-print-measure" aria-hidden="true">
          <section className="rs-print-page">
            <TitleBlock project={project.name} section="" date={date} page={1} pages={1} />
            <div className="rs-print-body">
              {['vars', 'xref'].map((table) => (
                <div key={table} data-head={table}>
                  <TableHead table={table} />
                  <SampleRow table={table} />
                </div>
              ))}
              {items.map((item, i) =>
                tableOf(item) && !wrapping?.has(i) ? null : (
                  <div key={item.key} data-block={i} className="rs-print-block">
                    <PrintBlockView item={item} {...(drawings[i] ? { drawing: drawings[i] } : {})} frameOnly />
                  </div>
                ),
              )}
            </div>
          </section>
        </div>
      ) : (
        <div className="rs-print-pages">
          {pages.map((page, n) => (
            <section key={n} className="rs-print-page" data-testid="print-page">
              <TitleBlock project={project.name} section={sectionOf(page)} date={date} page={n + 1} pages={pages.length} />
              <div className="rs-print-body">
                {page.pieces.map((piece) => (
                  <Piece
                    key={`${piece.block}:${piece.from}`}
                    piece={piece}
                    item={items[piece.block]!}
                    drawing={drawings[piece.block]}
                  />
                ))}
              </div>
            </section>
          ))}
        </div>
      )}
    </div>,
    document.body,
  );
}
