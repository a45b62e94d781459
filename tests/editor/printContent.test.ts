// What a print contains: networks drawn as SVG by the canvas's drawing code, the variable lists,
// the cross-reference; and the SVG drawing context those drawings go through.
import { expect, test } from 'vitest';
import { EXAMPLES } from '../../src/model/examples';
import { newNetwork, newPou, newProject, variable } from '../../src/model/factory';
import type { ElementId } from '../../src/model/ids';
import { blockLibrary } from '../../src/model/library';
import { parsePanels } from '../../src/editor/layout/panelSizes';
import { networkSvg } from '../../src/editor/print/networkSvg';
import { printItems, usesText } from '../../src/editor/print/printModel';
import { SvgContext } from '../../src/editor/print/svgContext';
import type { CanvasTheme } from '../../src/editor/theme/canvasTheme';
import { DEFAULT_PANELS } from '../../src/store/uiStore';
import { crossReference, projectCrossReference } from '../../src/store/xref';

const measure = (font: string, text: string) => text.length * (font.includes('11px') ? 6 : 6.5);
const THEME: CanvasTheme = {
  bg: '#fff', grid: '#eee', rail: '#222', wire: '#222', symbol: '#111', text: '#111', operand: '#05a',
  muted: '#888', selection: '#00f', selectionFill: '#00f2', cursor: '#f80', hover: '#00f1', error: '#d00',
  warning: '#e80', energised: '#1a4', falseState: '#789', boxFill: '#f7f9fc', networkBg: '#fbfcfd', forced: '#b19',
};

const texts = (svg: string) => [...svg.matchAll(/<text[^>]*>([^<]*)<\/text>/g)].map((m) => m[1]);

test('every example network draws as one well-formed SVG showing its operands', () => {
  for (const example of EXAMPLES) {
    const project = example.build();
    const lib = blockLibrary(project);
    for (const pou of project.pous)
      for (const network of pou.networks) {
        const d = networkSvg(network, THEME, measure, lib);
        expect(d.svg.match(/<svg/g)).toHaveLength(1);
        expect(d.svg.endsWith('</svg>')).toBe(true);
        expect(d.svg).not.toMatch(/NaN|undefined/);
        expect(d.frame).toMatch(/^<svg[^>]*><\/svg>$/);
        expect(d.width).toBeGreaterThan(0);
        // The rails at least, and every contact's and coil's variable (elided like on the canvas).
        expect(d.svg.match(/<path/g)?.length).toBeGreaterThanOrEqual(2);
        const shown = texts(d.svg).join(' ');
        for (const el of network.elements)
          if ((el.kind === 'contact' || el.kind === 'coil') && el.variable)
            expect(shown).toContain(el.variable.replace(/&/g, '&amp;').slice(0, 4));
      }
  }
});

test('the SVG context follows the canvas: transforms, saved state, arcs, squeezed text, dashes', () => {
  const ctx = new SvgContext(measure);
  ctx.save();
  ctx.translate(10, 20);
  ctx.strokeStyle = '#123';
  ctx.lineWidth = 2;
  ctx.setLineDash([4, 2]);
  ctx.strokeRect(1, 2, 30, 40);
  ctx.restore();
  ctx.strokeRect(0, 0, 5, 5);
  ctx.beginPath();
  ctx.arc(50, 50, 10, 0, Math.PI * 2);
  ctx.fill();
  ctx.font = '12px sans-serif';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText('A & <B>', 5, 6, 20);
  const svg = ctx.toSvg(100, 80);
  expect(svg).toContain('<rect x="11" y="22" width="30" height="40" fill="none" stroke="#123" stroke-width="2" stroke-dasharray="4 2"/>');
  // Restored: no translation, default stroke, no dash.
  expect(svg).toContain('<rect x="0" y="0" width="5" height="5" fill="none" stroke="#000" stroke-width="1"/>');
  // A full circle: two half arcs back to the start.
  expect(svg).toMatch(/<path d="M60 50A10 10 0 0 1 40 50A10 10 0 0 1 60 50" fill="#000"\/>/);
  // Text escaped, centred, squeezed to its maxWidth as the canvas does.
  expect(svg).toContain('text-anchor="middle" dominant-baseline="central" textLength="20" lengthAdjust="spacingAndGlyphs"');
  expect(texts(svg)).toEqual(['A &amp; &lt;B&gt;']);
});

test('a POU prints its heading, networks, variable list; the cross-reference lists each use by network', () => {
  const id = (s: string) => s as ElementId;
  const main = newPou('Main', {
    variables: [
      variable('Start', 'BOOL', { location: '%IX0.0' }),
      variable('Motor', 'BOOL', { location: '%QX0.0', retain: true }),
      variable('Count', 'INT', { varClass: 'input' }),
    ],
    networks: [
      newNetwork({
        title: 'Seal-in',
        rows: 2,
        cols: 4,
        elements: [
          { id: id('a'), kind: 'contact', contact: 'NO', variable: 'Start', row: 0, col: 0 },
          { id: id('q'), kind: 'coil', coil: 'COIL', variable: 'Motor', row: 0, col: 3 },
          { id: id('m'), kind: 'contact', contact: 'NO', variable: 'Motor', row: 1, col: 0 },
          { id: id('g'), kind: 'contact', contact: 'NO', variable: 'Alarm', row: 1, col: 1 },
        ],
      }),
      newNetwork({
        rows: 1,
        cols: 4,
        elements: [{ id: id('q2'), kind: 'coil', coil: 'SET', variable: 'Motor', row: 0, col: 3 }],
      }),
    ],
  });
  const other = newPou('Other', { networks: [newNetwork()] });
  const project = newProject('Plant', {
    pous: [main, other],
    globals: [variable('Alarm', 'BOOL'), variable('Spare', 'BOOL')],
  });

  const one = printItems(project, { scope: { kind: 'pou', pou: main.id }, variables: true, crossReference: true, orientation: 'landscape' });
  expect(one.map((i) => i.kind)).toEqual([
    'pou', 'network', 'network', 'heading', 'var', 'var', 'var', 'heading', 'xref', 'xref', 'xref', 'xref',
  ]);
  // The interface first in the variable list, as the table sorts it.
  expect(one.filter((i) => i.kind === 'var').map((i) => (i.kind === 'var' ? i.variable.name : ''))).toEqual(['Count', 'Start', 'Motor']);
  // Printing one POU: the globals it uses (Alarm), not the others (Spare); sorted by name.
  const rows = one.flatMap((i) => (i.kind === 'xref' ? [i.row] : []));
  expect(rows.map((r) => [r.name, r.declaredIn, r.uses, r.count])).toEqual([
    ['Alarm', 'Global', 'Main: N1 R', 1],
    ['Count', 'Main', '—', 0],
    ['Motor', 'Main', 'Main: N1 W, N1 R, N2 W', 3],
    ['Start', 'Main', 'Main: N1 R', 1],
  ]);
  expect(one.every((i) => i.section === 'Main' || (i.kind === 'heading' || i.kind === 'xref' ? i.section === 'Cross-reference' : false))).toBe(true);

  const all = printItems(project, { scope: { kind: 'project' }, variables: true, crossReference: false, orientation: 'portrait' });
  expect(all.filter((i) => i.kind === 'pou').map((i) => i.section)).toEqual(['Main', 'Other']);
  expect(all.filter((i) => i.kind === 'var' && i.global).map((i) => i.section)).toEqual(['Global variables', 'Global variables']);
  expect(all.some((i) => i.kind === 'xref')).toBe(false);

  // The one-pass cross-reference agrees with the per-variable one.
  const bulk = projectCrossReference(project);
  expect(bulk.get(main.id)?.get('MOTOR')).toEqual(crossReference(project, main.id, 'Motor'));
  expect(bulk.get('globals')?.get('ALARM')).toEqual(crossReference(project, 'globals', 'Alarm'));
  expect(usesText(crossReference(project, main.id, 'Motor'))).toBe('Main: N1 W, N1 R, N2 W');
});

test('remembered panel sizes are read back checked: garbage gives the defaults, sizes stay within limits', () => {
  expect(parsePanels(null)).toEqual(DEFAULT_PANELS);
  expect(parsePanels('{not json')).toEqual(DEFAULT_PANELS);
  expect(parsePanels('[1,2]')).toMatchObject({ left: DEFAULT_PANELS.left });
  expect(parsePanels(JSON.stringify({ left: 5000, right: 12, bottom: 'x', leftCollapsed: true, variablesDock: 'bottom' }))).toEqual({
    ...DEFAULT_PANELS,
    left: 560,
    right: 240,
    leftCollapsed: true,
    variablesDock: 'bottom',
  });
});
