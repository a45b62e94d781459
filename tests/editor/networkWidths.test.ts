// Networks of different widths in one POU on the canvas: each right rail at its own width, a
// header wide enough for its whole title and comment (a comment shown whole, long lines wrapped),
// a jump's label kept clear of the right rail.
import { describe, expect, it } from 'vitest';
import { JUMP_RAIL_GAP, jumpText, networkColumns, elementSpan } from '../../src/editor/canvas/columns';
import {
  COMMENT_LINE_H,
  COMMENT_W,
  commentLines,
  HEADER_LEFT,
  headerHeight,
  headerNeed,
  layoutNetworks,
  networkWidth,
  TITLEBAR_REST_W,
  titleFieldWidth,
} from '../../src/editor/canvas/geometry';
import { SPEC_MONO_SMALL, textWidth, wrappedLines } from '../../src/editor/canvas/textWidth';
import { newNetwork } from '../../src/model/factory';
import { blockLibrary } from '../../src/model/library';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { fixture } from '../plcopen/fixtures';

function imported(name: string) {
  const r = importPlcopen(fixture(name));
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return r.project;
}

describe('networks of different widths', () => {
  it('each right rail stands at its own network’s width; the canvas is as wide as the widest', () => {
    const p = imported('corpus/godardhi0__dancinglights.xml');
    const nets = p.pous[0]!.networks;
    const lib = blockLibrary(p);
    const widths = nets.map((n) => networkWidth(n, lib));
    expect(new Set(widths).size).toBeGreaterThan(1);
    // A network of 3 columns ends well left of one of 9.
    const narrow = nets.findIndex((n) => n.cols === 3);
    const wide = nets.findIndex((n) => n.cols === 9);
    expect(widths[narrow]!).toBeLessThan(widths[wide]! - 200);
    expect(layoutNetworks(nets, lib).totalWidth).toBeGreaterThanOrEqual(Math.max(...widths));
  });

  it('a jump’s label ends clear of its network’s right rail, with nothing drawn after it', () => {
    const p = imported('jump-label-return.xml');
    let seen = 0;
    for (const n of p.pous[0]!.networks) {
      const nc = networkColumns(n);
      for (const j of n.elements.filter((e) => e.kind === 'jump' || e.kind === 'return')) {
        seen++;
        const span = elementSpan(nc, j, 1);
        const labelEnd = span.x + 10 + textWidth(jumpText(j), SPEC_MONO_SMALL);
        expect(labelEnd + JUMP_RAIL_GAP).toBeLessThanOrEqual(nc.xs[n.cols]! + 0.5);
        expect(n.elements.some((e) => e.row === j.row && e.col > j.col)).toBe(false);
      }
    }
    expect(seen).toBeGreaterThanOrEqual(2);
  });
});

describe('network headers show titles and comments whole', () => {
  const long = 'This program demonstrates how to connect to a remote server using TCP to send and receive messages. '.repeat(4);

  it('every line of a long comment is shown, long lines wrapped', () => {
    const twenty = Array.from({ length: 20 }, (_, i) => `line ${i + 1}`).join('\n');
    expect(commentLines({ comment: twenty })).toBe(20);
    expect(commentLines({ comment: long })).toBeGreaterThanOrEqual(Math.ceil(textWidth(long, { size: 13 }) / COMMENT_W));
    expect(commentLines({ comment: '' })).toBe(1);
    const n = newNetwork({ comment: twenty });
    expect(headerHeight(n)).toBeGreaterThanOrEqual(20 * COMMENT_LINE_H);
  });

  it('the header is wide enough for a long title and for the comment’s longest line', () => {
    const title = 'Start the conveyor when the part sensor and the safety gate agree';
    const n = newNetwork({ title, comment: 'short' });
    expect(titleFieldWidth(n)).toBeGreaterThan(textWidth(title, { size: 13, bold: true }));
    expect(headerNeed(n)).toBeGreaterThanOrEqual(TITLEBAR_REST_W + titleFieldWidth(n));
    const layout = layoutNetworks([n, newNetwork({ comment: long })]);
    expect(layout.totalWidth).toBeGreaterThanOrEqual(HEADER_LEFT + headerNeed(n));
    // A comment longer than the field wraps at it: the header needs the whole field.
    expect(headerNeed(newNetwork({ comment: long }))).toBeGreaterThanOrEqual(COMMENT_W);
  });

  it('wrapping counts lines the way a textarea breaks them', () => {
    const w = textWidth('abc def', { size: 13 });
    expect(wrappedLines('abc def', w, { size: 13 })).toBe(1);
    expect(wrappedLines('abc def', w - 1, { size: 13 })).toBe(2);
    expect(wrappedLines('a\n\nb', 500, { size: 13 })).toBe(3);
    // A word longer than a line fills lines of its own.
    expect(wrappedLines('x'.repeat(100), textWidth('x'.repeat(30), { size: 13 }), { size: 13 })).toBe(4);
  });
});
