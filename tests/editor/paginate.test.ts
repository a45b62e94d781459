// Page breaking of the print view: networks are never split when they fit on a page, a network
// taller than a page is cut between rows with "continued" marks, headings stay with what follows,
// table headers repeat on every page.
import { expect, test } from 'vitest';
import { paginate, type PrintBlock, type PrintPage } from '../../src/editor/print/paginate';

const PAGE = 700;

/** Every block appears, in order, each piece following on from the previous one. */
function expectComplete(blocks: readonly PrintBlock[], pages: readonly PrintPage[]) {
  let block = 0;
  let at = 0;
  for (const piece of pages.flatMap((p) => p.pieces)) {
    if (at === blocks[block]!.height) {
      block += 1;
      at = 0;
    }
    expect([piece.block, piece.from]).toEqual([block, at]);
    expect(piece.to).toBeGreaterThan(piece.from);
    at = piece.to;
  }
  expect([block, at]).toEqual([blocks.length - 1, blocks[blocks.length - 1]!.height]);
}

/** Height each page uses (pieces, table heads, continued marks). */
const used = (blocks: readonly PrintBlock[], page: PrintPage, mark = 0) =>
  page.pieces.reduce(
    (sum, p) =>
      sum +
      (p.to - p.from) +
      (p.groupHead ? (blocks[p.block]!.groupHead ?? 0) : 0) +
      (p.continued ? mark : 0) +
      (p.continues ? mark : 0),
    0,
  );

test('100 networks of 150 px: four to a 700 px page, 25 pages, none split', () => {
  const blocks = Array.from({ length: 100 }, () => ({ height: 150 }));
  const pages = paginate(blocks, { pageHeight: PAGE });
  expect(pages).toHaveLength(25);
  expect(pages.every((p) => p.pieces.length === 4)).toBe(true);
  expect(pages.flatMap((p) => p.pieces).every((p) => p.from === 0 && !p.continued && !p.continues)).toBe(true);
  expectComplete(blocks, pages);
});

test('networks of mixed heights: a network that does not fit moves whole to the next page', () => {
  // 100 networks of 120, 250 and 400 px in turn.
  const heights = [120, 250, 400];
  const blocks = Array.from({ length: 100 }, (_, i) => ({ height: heights[i % 3]! }));
  const pages = paginate(blocks, { pageHeight: PAGE });
  // Each cycle of three (770 px) overflows a page: the pages hold 120+250, then 400+120 (ends the
  // next cycle's first), then 250+400, then 120+250 ... computed greedily:
  let expected = 1;
  let fill = 0;
  for (const b of blocks) {
    if (fill + b.height > PAGE) {
      expected += 1;
      fill = 0;
    }
    fill += b.height;
  }
  expect(pages).toHaveLength(expected);
  expect(pages.flatMap((p) => p.pieces).some((p) => p.continued || p.continues)).toBe(false);
  for (const page of pages) expect(used(blocks, page)).toBeLessThanOrEqual(PAGE);
  // Moving to the next page only when the next network really did not fit.
  for (let k = 0; k + 1 < pages.length; k++) {
    const next = blocks[pages[k + 1]!.pieces[0]!.block]!;
    expect(used(blocks, pages[k]!) + next.height).toBeGreaterThan(PAGE);
  }
  expectComplete(blocks, pages);
});

test('a network taller than a page starts a new page and is cut between rows, with continued marks', () => {
  const rows = 30;
  // Header 60 px, then 30 rows of 64 px: 1980 px, cut only at row boundaries.
  const tall: PrintBlock = {
    height: 60 + rows * 64,
    breaks: Array.from({ length: rows - 1 }, (_, r) => 60 + (r + 1) * 64),
  };
  const blocks = [{ height: 300 }, tall, { height: 200 }];
  const mark = 18;
  const pages = paginate(blocks, { pageHeight: PAGE, markHeight: mark });
  const pieces = pages.map((p) => p.pieces.map((x) => ({ ...x })));
  // Page 1: the short network alone (the tall one does not start in its remaining room).
  expect(pieces[0]!.map((p) => p.block)).toEqual([0]);
  const tallPieces = pages.flatMap((p) => p.pieces).filter((p) => p.block === 1);
  // 636 px (9 rows below the header) on the first page, then 10 rows a page, less the marks.
  expect(tallPieces.map((p) => [p.from, p.to, p.continued, p.continues])).toEqual([
    [0, 636, false, true],
    [636, 1276, true, true],
    [1276, 1916, true, true],
    [1916, 1980, true, false],
  ]);
  // Every cut is between two rows.
  for (const p of tallPieces.slice(0, -1)) expect(tall.breaks).toContain(p.to);
  for (const page of pages) expect(used(blocks, page, mark)).toBeLessThanOrEqual(PAGE);
  // The network after it follows on the last piece's page when it fits there.
  expect(pages[pages.length - 1]!.pieces.map((p) => p.block)).toEqual([1, 2]);
  expectComplete(blocks, pages);
});

test('a block with no place to cut is cut at the page height', () => {
  const blocks = [{ height: 1500 }];
  const pages = paginate(blocks, { pageHeight: PAGE, markHeight: 20 });
  expect(pages.map((p) => p.pieces[0]!.to - p.pieces[0]!.from)).toEqual([680, 660, 160]);
  expectComplete(blocks, pages);
});

test('a heading is never left alone at the bottom of a page', () => {
  const blocks: PrintBlock[] = [{ height: 600 }, { height: 40, keepWithNext: true }, { height: 200 }];
  const pages = paginate(blocks, { pageHeight: PAGE });
  expect(pages.map((p) => p.pieces.map((x) => x.block))).toEqual([[0], [1, 2]]);
});

test('rows of a table repeat its header on each page', () => {
  const rows: PrintBlock[] = Array.from({ length: 50 }, () => ({ height: 30, group: 'vars', groupHead: 40 }));
  const blocks: PrintBlock[] = [{ height: 500 }, ...rows];
  const pages = paginate(blocks, { pageHeight: PAGE });
  // Page 1: 500 + head 40 + 5 rows (150) = 690. Then 40 + 22 rows = 700 per page: 45 rows left -> 3 pages.
  expect(pages.map((p) => p.pieces.length)).toEqual([6, 22, 22, 1]);
  expect(pages.map((p) => p.pieces.filter((x) => x.groupHead).length)).toEqual([1, 1, 1, 1]);
  for (const page of pages) expect(used(blocks, page)).toBeLessThanOrEqual(PAGE);
  expectComplete(blocks, pages);
});
