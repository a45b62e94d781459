// Page breaking of the print view, from measured heights: blocks (a network, a heading, a row of a
// table) are placed on pages of a given height in order. A block that fits on a page is never
// split: it moves to the next page instead. A block taller than a page starts on a new page and is
// cut where it allows (its `breaks`, e.g. between two rungs' rows), each piece but the first
// marked "continued" and each but the last "continues", with room kept for those marks. Rows of a
// table (same `group`) repeat the table's header at the top of every page they are on. Pure.

export interface PrintBlock {
  readonly height: number;
  /** Offsets from the block's top where it may be cut if it must be split, ascending. */
  readonly breaks?: readonly number[];
  /** Keep on the same page as (the start of) the next block: a heading. */
  readonly keepWithNext?: boolean;
  /** Consecutive blocks of one group are rows of a table whose header (groupHead high) is
   * repeated on each page the table reaches. */
  readonly group?: string;
  readonly groupHead?: number;
}

export interface PagePiece {
  readonly block: number;
  /** Part of the block on this page: [from, to) from its top; the whole block is [0, height). */
  readonly from: number;
  readonly to: number;
  /** The block started on an earlier page. */
  readonly continued: boolean;
  /** The block goes on on the next page. */
  readonly continues: boolean;
  /** The table header of the block's group is drawn above this piece. */
  readonly groupHead: boolean;
}

export interface PrintPage {
  readonly pieces: readonly PagePiece[];
}

export interface PaginateOptions {
  /** Height of a page's body (below its title block). */
  readonly pageHeight: number;
  /** Height of one "continued" mark, kept free above or below each piece of a split block. */
  readonly markHeight?: number;
}

export function paginate(blocks: readonly PrintBlock[], options: PaginateOptions): PrintPage[] {
  const { pageHeight } = options;
  const mark = options.markHeight ?? 0;
  const pages: PrintPage[] = [];
  let pieces: PagePiece[] = [];
  let used = 0;
  let group: string | undefined;

  const newPage = () => {
    if (pieces.length) pages.push({ pieces });
    pieces = [];
    used = 0;
    group = undefined;
  };
  const headOf = (b: PrintBlock, afterGroup: string | undefined) =>
    b.group !== undefined && b.group !== afterGroup ? (b.groupHead ?? 0) : 0;
  const place = (block: number, from: number, to: number, continued: boolean, continues: boolean) => {
    const b = blocks[block]!;
    const head = headOf(b, group);
    pieces.push({ block, from, to, continued, continues, groupHead: head > 0 });
    used += head + (to - from) + (continued ? mark : 0) + (continues ? mark : 0);
    group = b.group;
  };
  /** Room a block needs on the current page if it is to go there whole (with what it keeps with). */
  const needs = (i: number): number => {
    const b = blocks[i]!;
    let need = headOf(b, group) + b.height;
    // A heading keeps its next block's start (a whole block, or its first piece) on its page.
    for (let j = i; blocks[j]?.keepWithNext && j + 1 < blocks.length; j++) {
      const next = blocks[j + 1]!;
      const first = next.height <= pageHeight ? next.height : (next.breaks?.[0] ?? 0) + mark;
      need += headOf(next, blocks[j]!.group) + first;
      if (next.height > pageHeight) break;
    }
    return need;
  };

  blocks.forEach((b, i) => {
    const need = needs(i);
    if (used > 0 && used + need > pageHeight) newPage();
    if (used + headOf(b, group) + b.height <= pageHeight) {
      place(i, 0, b.height, false, false);
      return;
    }
    // Taller than a page: cut it, from a page of its own.
    if (used > 0) newPage();
    let offset = 0;
    for (;;) {
      const top = offset > 0 ? mark : 0;
      const room = pageHeight - used - headOf(b, group) - top;
      if (b.height - offset <= room) {
        place(i, offset, b.height, offset > 0, false);
        return;
      }
      const limit = offset + room - mark;
      const cut = b.breaks?.filter((x) => x > offset && x <= limit).pop() ?? limit;
      // However small the page, each piece moves on.
      const to = Math.min(b.height, Math.max(cut, offset + 1));
      place(i, offset, to, offset > 0, true);
      newPage();
      offset = to;
    }
  });
  newPage();
  return pages;
}
