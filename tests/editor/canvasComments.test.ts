// Comments under operands and compact collapsed networks: the canvas layout makes room for what it
// draws (a comment band under each row of a network that shows one), element comments are kept in
// the project file and in PLCopen (TC6 <documentation> of the contact, coil or block).
import { describe, expect, it } from 'vitest';
import {
  CELL_H,
  cellCentre,
  COLLAPSED_HEADER_H,
  COMMENT_PITCH,
  HEADER_TITLE_H,
  hitTest,
  layoutNetworks,
  NETWORK_GAP,
  rowPitch,
} from '../../src/editor/canvas/geometry';
import { wrapLines } from '../../src/editor/canvas/elementPaint';
import { symbolCommentLookup } from '../../src/editor/canvas/symbolComments';
import type { LdElement } from '../../src/model/elements';
import { newNetwork } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { loadProject, saveProject } from '../../src/model/load';
import type { Network, Project, Variable } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { fitRows } from '../../src/store/networkEdits';
import { blocks } from '../plcopen/samples';
import { schemaErrors } from '../plcopen/xsd';

const contact = (variable: string, col: number, comment?: string): LdElement => ({
  id: `e${col}` as ElementId,
  kind: 'contact',
  contact: 'NO',
  variable,
  row: 0,
  col,
  ...(comment ? { comment } : {}),
});
const v = (name: string, comment = ''): Variable => ({ name, type: 'BOOL', varClass: 'local', retain: false, comment });

describe('collapsed networks', () => {
  it('a collapsed network is one header line, whatever its comment and rows', () => {
    const open = newNetwork({ rows: 3, comment: 'two\nlines' });
    const closed = { ...open, collapsed: true };
    const l = layoutNetworks([closed, open]);
    expect(l.heights[0]).toBeLessThanOrEqual(COLLAPSED_HEADER_H + 4);
    expect(COLLAPSED_HEADER_H).toBe(HEADER_TITLE_H);
    // Before: a collapsed network took 72 px (title bar, one comment line, gap).
    expect(l.heights[0]).toBeLessThan(72);
    expect(l.tops[1]! - l.tops[0]!).toBe(l.heights[0]);
    // An empty open network shows one row to draw in.
    expect(l.heights[1]).toBeGreaterThan(CELL_H);
  });
});

describe('fit rows to rungs', () => {
  it('a one-row rung in a three-row network is one row high in the layout; fitRows trims the model alike', () => {
    const n: Network = newNetwork({ rows: 3, elements: [contact('Start', 0)] });
    const fitted = fitRows(n);
    expect(fitted.rows).toBe(1);
    expect(fitted.elements).toBe(n.elements);
    const l = layoutNetworks([fitted]);
    // The canvas no longer shows the empty model rows: both are one row high.
    expect(l.heights[0]).toBe(layoutNetworks([n]).heights[0]);
    expect(l.rows[0]).toBe(1);
  });
  it('keeps the rows a branch or a box reaches, and leaves an empty network and a fitted one as they are', () => {
    const branch: Network = newNetwork({ rows: 4, elements: [contact('A', 0), { ...contact('B', 1), row: 1 }], vlinks: [{ row: 0, boundary: 1 }] });
    expect(fitRows(branch).rows).toBe(2);
    const ton: Network = newNetwork({
      rows: 5,
      elements: [{ id: 'x' as ElementId, kind: 'box', blockType: 'TON', instance: 'T1', row: 0, col: 1, inputs: {}, outputs: {} }],
    });
    expect(fitRows(ton).rows).toBe(2);
    const empty = newNetwork({ rows: 3 });
    expect(fitRows(empty)).toBe(empty);
    const one = fitRows(newNetwork({ rows: 3, elements: [contact('A', 0)] }));
    expect(fitRows(one)).toBe(one);
  });
});

describe('comment rows', () => {
  const lookup = symbolCommentLookup([v('Start', 'Start push button, green, on the front panel'), v('Stop')], [v('Lamp', 'global lamp')]);

  it('rows are CELL_H high without comments, taller where a comment is shown', () => {
    const plain: Network = newNetwork({ rows: 2, elements: [contact('Start', 0)] });
    expect(rowPitch(plain)).toBe(CELL_H);
    expect(rowPitch(plain, lookup)).toBe(COMMENT_PITCH);
    const stopOnly: Network = newNetwork({ rows: 2, elements: [contact('Stop', 0)] });
    expect(rowPitch(stopOnly, lookup)).toBe(CELL_H);
    const own: Network = newNetwork({ rows: 2, elements: [contact('Stop', 0, 'jog only')] });
    expect(rowPitch(own)).toBe(COMMENT_PITCH);
  });

  it('the layout gives each row of a commented network its band, and hit tests follow it', () => {
    const n: Network = newNetwork({ rows: 2, elements: [contact('Start', 0), { ...contact('Stop', 1), row: 1 }] });
    const off = layoutNetworks([n, n]);
    const on = layoutNetworks([n, { ...n }], undefined, lookup);
    expect(on.heights[0]! - off.heights[0]!).toBe(2 * (COMMENT_PITCH - CELL_H));
    expect(on.pitches[0]).toBe(COMMENT_PITCH);
    // The centre of row 1 hits row 1, not the band of row 0.
    const p = cellCentre(on, [n, n], 0, { row: 1, col: 0 });
    const hit = hitTest(on, [n, n], p);
    expect(hit).toMatchObject({ area: 'grid', index: 0, cell: { row: 1, col: 0 } });
    // A point in row 0's comment band still belongs to row 0.
    const band = { x: p.x, y: cellCentre(on, [n, n], 0, { row: 0, col: 0 }).y + CELL_H / 2 + 5 };
    expect(hitTest(on, [n, n], band)).toMatchObject({ cell: { row: 0 } });
    expect(on.tops[1]! - on.tops[0]!).toBe(on.heights[0]);
    expect(NETWORK_GAP).toBeGreaterThan(0);
  });

  it('names are looked up case-insensitively; a local hides a global; Word.3 shows Word', () => {
    expect(lookup('start')).toMatch(/^Start push/);
    expect(lookup('Lamp')).toBe('global lamp');
    expect(lookup('Stop')).toBeUndefined();
    const shadow = symbolCommentLookup([v('Lamp')], [v('Lamp', 'global lamp'), v('Word', 'status word')]);
    expect(shadow('Lamp')).toBeUndefined();
    expect(shadow('Word.3')).toBe('status word');
    expect(shadow('T#5s')).toBeUndefined();
  });
});

describe('wrapping a comment into its cell', () => {
  // 6 px per character: a stand-in for the canvas's measureText.
  const ctx = { measureText: (t: string) => ({ width: t.length * 6 }) } as unknown as CanvasRenderingContext2D;
  it('wraps at words into two lines at most, the second cut with an ellipsis', () => {
    const lines = wrapLines(ctx, 'Start push button green on the front panel', 60, 2);
    expect(lines).toHaveLength(2);
    for (const l of lines) expect(l.length * 6).toBeLessThanOrEqual(60);
    expect(lines[0]).toBe('Start push');
    expect(lines[1]!.endsWith('…')).toBe(true);
  });
  it('keeps a short comment whole and breaks a word longer than a line', () => {
    expect(wrapLines(ctx, 'short', 60, 2)).toEqual(['short']);
    const long = wrapLines(ctx, 'Supercalifragilistic', 60, 2);
    expect(long[0]).toBe('Supercalif');
    expect(long[1]!.length * 6).toBeLessThanOrEqual(60);
  });
});

describe('element comments in files', () => {
  const withComments = (): Project => {
    const p = blocks();
    const pou = p.pous[0]!;
    const networks = pou.networks.map((n) => ({
      ...n,
      elements: n.elements.map((e) =>
        e.kind === 'contact' || e.kind === 'coil' || e.kind === 'box' ? { ...e, comment: `note on ${e.kind} ${e.id}` } : e,
      ),
    }));
    return { ...p, pous: [{ ...pou, networks }, ...p.pous.slice(1)] };
  };
  const notes = (p: Project) =>
    p.pous[0]!.networks.flatMap((n) => n.elements.filter((e) => e.comment).map((e) => `${e.kind}:${e.comment!.replace(/ \S+$/, '')}`)).sort();

  it('are saved and loaded with the project', () => {
    const p = withComments();
    const back = loadProject(saveProject(p));
    if (!back.ok) throw new Error(JSON.stringify(back));
    expect(notes(back.project)).toEqual(notes(p));
    expect(notes(p).length).toBeGreaterThan(2);
  });

  it('go to PLCopen as <documentation> of the element (schema-valid) and come back on import', async () => {
    const p = withComments();
    const xml = exportPlcopen(p);
    expect(await schemaErrors(xml)).toEqual([]);
    expect(xml).toMatch(/<contact[^>]*>[\s\S]*?<documentation>[\s\S]*?note on contact[\s\S]*?<\/contact>/);
    const back = importPlcopen(xml);
    if (!back.ok) throw new Error(JSON.stringify(back.errors));
    expect(notes(back.project)).toEqual(notes(p));
  });
});
