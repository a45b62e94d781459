// A readable, steady canvas at 1280×720 (issue 13): long names drawn whole and clear of the
// rails, coils at the right rail, the diagnostic marker away from the instance name, TRUE and
// FALSE told apart by more than colour, one forced badge on the canvas and in the watch table,
// and nothing moving when Run starts. Checked through the canvas's drawing calls (recorded in the
// page), not screenshots.
import type { Page } from 'playwright-core';
import { afterEach, beforeEach, expect, test } from 'vitest';
import { CELL_W, cellCentre, columnsOf, RAIL_X } from '../../src/editor/canvas/geometry';
import { FORCED_BADGE } from '../../src/editor/theme/monitorStyle';
import type { Project } from '../../src/model/project';
import { ladder, project, vars } from '../engine/ladder';
import { collectPageErrors } from './browser';
import { appUrl, useChromium, waitForApp } from './appPage';
import { SimPage } from './simPage';

const browser = useChromium();
let page: Page;
let errors: string[];
let sim: SimPage;

const SENSOR = 'Conveyor_Infeed_Sensor_1'; // 24 characters
const TIMER = 'Conveyor_Infeed_Timer_01';
const DELAY = 'Infeed_Delay_Setpoint_T'; // a long box pin operand

/** Records fillText / fillRect / strokeRect / stroke / arc calls of every 2D context, in device pixels of its canvas. */
function recordDrawing() {
  interface Call {
    op: string;
    canvas: number;
    m: number[];
    [k: string]: unknown;
  }
  const w = window as unknown as { __calls: Call[] };
  w.__calls = [];
  const ids = new WeakMap<object, number>();
  let next = 1;
  const P = CanvasRenderingContext2D.prototype;
  const base = (ctx: CanvasRenderingContext2D, op: string): Call => {
    let id = ids.get(ctx.canvas);
    if (id === undefined) ids.set(ctx.canvas, (id = next++));
    const t = ctx.getTransform();
    return { op, canvas: id, m: [t.a, t.b, t.c, t.d, t.e, t.f] };
  };
  const style = (ctx: CanvasRenderingContext2D) => ({
    fill: String(ctx.fillStyle),
    stroke: String(ctx.strokeStyle),
    lineWidth: ctx.lineWidth,
    dash: ctx.getLineDash().length > 0,
  });
  const fillText = P.fillText;
  P.fillText = function (this: CanvasRenderingContext2D, text: string, x: number, y: number, maxWidth?: number) {
    const mt = this.measureText(text);
    w.__calls.push({
      ...base(this, 'text'),
      ...style(this),
      text,
      x,
      y,
      maxWidth,
      font: this.font,
      align: this.textAlign,
      width: mt.width,
      ascent: mt.actualBoundingBoxAscent,
      descent: mt.actualBoundingBoxDescent,
      left: mt.actualBoundingBoxLeft,
      right: mt.actualBoundingBoxRight,
    });
    return maxWidth === undefined ? fillText.call(this, text, x, y) : fillText.call(this, text, x, y, maxWidth);
  };
  for (const op of ['fillRect', 'strokeRect'] as const) {
    const orig = P[op];
    P[op] = function (this: CanvasRenderingContext2D, x: number, y: number, rw: number, rh: number) {
      w.__calls.push({ ...base(this, op), ...style(this), x, y, w: rw, h: rh });
      return orig.call(this, x, y, rw, rh);
    };
  }
  const stroke = P.stroke;
  P.stroke = function (this: CanvasRenderingContext2D, ...args: unknown[]) {
    w.__calls.push({ ...base(this, 'stroke'), ...style(this) });
    return (stroke as (...a: unknown[]) => void).apply(this, args);
  } as typeof P.stroke;
  const arc = P.arc;
  P.arc = function (this: CanvasRenderingContext2D, x: number, y: number, r: number, a0: number, a1: number, ccw?: boolean) {
    w.__calls.push({ ...base(this, 'arc'), ...style(this), x, y, r });
    return arc.call(this, x, y, r, a0, a1, ccw);
  };
  const moveTo = P.moveTo;
  const lineTo = P.lineTo;
  const fill = P.fill;
  let path: number[][] = [];
  const point = (ctx: CanvasRenderingContext2D, x: number, y: number) => {
    const t = ctx.getTransform();
    return [t.a * x + t.c * y + t.e, t.b * x + t.d * y + t.f];
  };
  P.moveTo = function (this: CanvasRenderingContext2D, x: number, y: number) {
    path = [point(this, x, y)];
    return moveTo.call(this, x, y);
  };
  P.lineTo = function (this: CanvasRenderingContext2D, x: number, y: number) {
    path.push(point(this, x, y));
    return lineTo.call(this, x, y);
  };
  P.fill = function (this: CanvasRenderingContext2D, ...args: unknown[]) {
    w.__calls.push({ ...base(this, 'fill'), ...style(this), path: [...path] });
    return (fill as (...a: unknown[]) => void).apply(this, args);
  } as typeof P.fill;
}

interface Call {
  op: string;
  canvas: number;
  m: [number, number, number, number, number, number];
  fill: string;
  stroke: string;
  lineWidth: number;
  dash: boolean;
  text?: string;
  x: number;
  y: number;
  w?: number;
  h?: number;
  r?: number;
  maxWidth?: number;
  font?: string;
  align?: CanvasTextAlign;
  width?: number;
  ascent?: number;
  descent?: number;
  left?: number;
  right?: number;
  path?: number[][];
}

interface Box {
  x1: number;
  y1: number;
  x2: number;
  y2: number;
}

const apply = (m: Call['m'], x: number, y: number) => [m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]] as const;

function boxOf(m: Call['m'], x1: number, y1: number, x2: number, y2: number): Box {
  const [ax, ay] = apply(m, x1, y1);
  const [bx, by] = apply(m, x2, y2);
  return { x1: Math.min(ax, bx), y1: Math.min(ay, by), x2: Math.max(ax, bx), y2: Math.max(ay, by) };
}

/** A text call's ink box in its canvas's pixels. */
const textBox = (c: Call): Box => boxOf(c.m, c.x - c.left!, c.y - c.ascent!, c.x + c.right!, c.y + c.descent!);
const intersects = (a: Box, b: Box) => a.x1 < b.x2 && b.x1 < a.x2 && a.y1 < b.y2 && b.y1 < a.y2;

/** The grid of a network's drawing: its background rect (grid x 0..width), the first fillRect of its canvas. */
function gridOf(calls: readonly Call[], canvas: number) {
  const bg = calls.find((c) => c.canvas === canvas && c.op === 'fillRect' && c.x === 0 && c.y === 0)!;
  const scale = bg.m[0];
  return {
    width: bg.w!,
    /** Canvas pixels to grid content pixels. */
    local: (px: number) => (px - bg.m[4]) / scale,
    scale,
  };
}

async function calls(): Promise<Call[]> {
  return page.evaluate(() => (window as unknown as { __calls: Call[] }).__calls);
}

async function clearCalls() {
  await page.evaluate(() => {
    (window as unknown as { __calls: Call[] }).__calls = [];
  });
}

/** Makes every shown network draw again at zoom 1 (a zoom change redraws each network's bitmap). */
async function redraw() {
  await page.evaluate(() => window.rungsmith!.uiStore!.getState().setZoom(1.5));
  await page.waitForTimeout(150);
  await clearCalls();
  await page.evaluate(() => window.rungsmith!.uiStore!.getState().setZoom(1));
  await page.waitForTimeout(200);
}

function plant(declareTimer: boolean): Project {
  return project(
    vars(
      `${SENSOR} BOOL`,
      'Motor BOOL',
      'Always_On BOOL := TRUE',
      'Lamp BOOL',
      'Done BOOL',
      `${DELAY} TIME := T#5s`,
      ...(declareTimer ? [`${TIMER} TON`] : []),
    ),
    [
      ladder([`[${SENSOR}] (Motor)`], { cols: 10 }),
      ladder(['[Always_On] # . (Done)', '. # . .'], {
        cols: 10,
        boxes: [{ row: 0, col: 1, type: 'TON', instance: TIMER, inputs: { PT: DELAY } }],
      }),
      ladder(['[Always_On] (Lamp)'], { cols: 10 }),
    ],
  );
}

async function load(p: Project) {
  await clearCalls();
  await page.evaluate((x) => window.rungsmith!.documentStore!.getState().loadProject(x), p);
  await page.waitForTimeout(300);
}

beforeEach(async () => {
  page = await browser().newPage({ viewport: { width: 1280, height: 720 } });
  errors = collectPageErrors(page);
  await page.addInitScript(recordDrawing);
  await page.goto(appUrl());
  await waitForApp(page);
  sim = new SimPage(page);
});

afterEach(async () => {
  await page.close();
});

test('at 1280×720 long names are drawn whole, clear of the rails, and coils sit at the right rail', async () => {
  await load(plant(true));
  await redraw();
  const all = await calls();
  const texts = all.filter((c) => c.op === 'text');
  // Nothing on the canvas is shortened.
  expect(texts.filter((c) => c.text!.includes('…')).map((c) => c.text)).toEqual([]);
  for (const name of [SENSOR, TIMER, DELAY]) {
    const drawn = texts.find((c) => c.text === name);
    expect(drawn, `${name} drawn`).toBeDefined();
    // Drawn at its own width (not squeezed into a narrower one).
    if (drawn!.maxWidth !== undefined) expect(drawn!.width).toBeLessThanOrEqual(drawn!.maxWidth);
    const grid = gridOf(all, drawn!.canvas);
    const box = textBox(drawn!);
    // Inside the grid: clear of the left rail (x 0, 4 px wide) and of the right rail.
    expect(grid.local(box.x1), `${name} left edge`).toBeGreaterThan(2);
    expect(grid.local(box.x2), `${name} right edge`).toBeLessThan(grid.width - 2);
  }
  // Coils at the right rail: the coil's cell starts one (narrow) column left of the rail.
  for (const coil of ['Motor', 'Lamp']) {
    const name = texts.find((c) => c.text === coil)!;
    const grid = gridOf(all, name.canvas);
    const centre = grid.local(apply(name.m, name.x, name.y)[0]);
    expect(centre - CELL_W / 2).toBeCloseTo(grid.width - CELL_W, 0);
  }
  expect(errors).toEqual([]);
});

test('at 1280×720 a new network of short names fits the canvas without scrolling sideways, its header as wide as the view', async () => {
  await load(project(vars('Start BOOL', 'Stop BOOL', 'Motor BOOL'), [ladder(['[Start] [/Stop] (Motor)'], { cols: 10 })]));
  const widths = await page.getByTestId('ladder-canvas').evaluate((el) => [el.scrollWidth, el.clientWidth]);
  expect(widths[0]).toBeLessThanOrEqual(widths[1]!);
  // Its header is as wide as the view, not only as the grid.
  const edges = await page.evaluate(() => {
    const canvas = document.querySelector('[data-testid="ladder-canvas"]')!;
    const header = document.querySelector('[data-testid="network-header-0"]')!.getBoundingClientRect();
    return { canvasRight: canvas.getBoundingClientRect().left + canvas.clientWidth, headerRight: header.right };
  });
  expect(edges.headerRight).toBeGreaterThan(edges.canvasRight - 30);
  expect(edges.headerRight).toBeLessThanOrEqual(edges.canvasRight);
  expect(errors).toEqual([]);
});

test("the diagnostic marker on a box does not cover its instance name", async () => {
  await load(plant(false)); // the timer instance is not declared: the box is marked
  await expect.poll(() => page.getByTestId('problems-summary').textContent()).toMatch(/[1-9] error/);
  await redraw();
  const all = await calls();
  const name = all.find((c) => c.op === 'text' && c.text === TIMER)!;
  const error = await page.evaluate(() =>
    getComputedStyle(document.documentElement).getPropertyValue('--canvas-error').trim(),
  );
  const mine = all.filter((c) => c.canvas === name.canvas);
  const outline = mine.filter((c) => c.op === 'strokeRect' && c.stroke === error && c.dash);
  const corner = mine.filter((c) => c.op === 'fill' && c.fill === error);
  expect(outline.length).toBeGreaterThan(0);
  expect(corner.length).toBeGreaterThan(0);
  const label = textBox(name);
  for (const r of outline) {
    const b = boxOf(r.m, r.x, r.y, r.x + r.w!, r.y + r.h!);
    // The dashed outline's top edge runs below the name (the outline is a rectangle's border).
    expect(b.y1).toBeGreaterThanOrEqual(label.y2);
  }
  for (const f of corner) {
    const xs = f.path!.map((p) => p[0]!);
    const ys = f.path!.map((p) => p[1]!);
    const b = { x1: Math.min(...xs), y1: Math.min(...ys), x2: Math.max(...xs), y2: Math.max(...ys) };
    expect(intersects(b, label)).toBe(false);
  }
  expect(errors).toEqual([]);
});

test('monitoring: TRUE and FALSE differ in colour and shape; a forced value has one badge on the canvas and in the watch table; nothing moves on Run', async () => {
  await load(plant(true));
  const shapes = () =>
    page.evaluate(() => {
      const k = (window as unknown as { Konva: { stages: { find(s: string): { x(): number; y(): number; width(): number }[] }[] } }).Konva;
      const headers = [...document.querySelectorAll<HTMLElement>('[data-testid^="network-header-"]')].map((h) => {
        const r = h.getBoundingClientRect();
        return [r.left, r.top, r.width, r.height];
      });
      return { grids: k.stages[0]!.find('Shape').map((s) => [s.x(), s.y(), s.width()]), headers };
    });
  const before = await shapes();
  await clearCalls();
  await sim.button('run').click();
  await sim.waitForMode('Running');
  await sim.waitForValue('Lamp', true);
  await page.waitForTimeout(300);
  expect(await shapes()).toEqual(before);

  const colours = await page.evaluate(() => {
    const s = getComputedStyle(document.documentElement);
    return {
      on: s.getPropertyValue('--canvas-energised').trim(),
      off: s.getPropertyValue('--canvas-false').trim(),
      forced: s.getPropertyValue('--forced').trim(),
    };
  });
  await redraw();
  let all = await calls();
  // Value tags: TRUE on a filled tag, FALSE in an outlined one, in different colours.
  const trueTag = all.find((c) => c.op === 'text' && c.text === 'TRUE')!;
  const falseTag = all.find((c) => c.op === 'text' && c.text === 'FALSE')!;
  expect(trueTag).toBeDefined();
  expect(falseTag).toBeDefined();
  const mine = (c: Call) => all.filter((x) => x.canvas === c.canvas);
  expect(mine(trueTag).some((c) => c.op === 'fillRect' && c.fill === colours.on)).toBe(true);
  expect(mine(falseTag).some((c) => c.op === 'strokeRect' && c.stroke === colours.off)).toBe(true);
  expect(trueTag.fill).not.toBe(falseTag.fill);
  // Wires: TRUE thick and solid, FALSE thin, dashed and another colour.
  const onWires = all.filter((c) => c.op === 'stroke' && c.stroke === colours.on && !c.dash);
  const offWires = all.filter((c) => c.op === 'stroke' && c.stroke === colours.off && c.dash);
  expect(onWires.length).toBeGreaterThan(0);
  expect(offWires.length).toBeGreaterThan(0);
  expect(Math.min(...onWires.map((c) => c.lineWidth))).toBeGreaterThan(Math.max(...offWires.map((c) => c.lineWidth)));
  expect(colours.on).not.toBe(colours.off);

  // Forcing Motor: the same badge on the canvas and in the watch table.
  await sim.tab('Watch');
  await page.evaluate(() => {
    const s = (window.rungsmith as unknown as { simStore: { getState(): { addWatch(n: string): void; force(n: string, v: { text: string }): void } } }).simStore.getState();
    s.addWatch('Motor');
    s.force('Motor', { text: 'TRUE' });
  });
  await sim.waitForValue('Motor', true);
  await redraw();
  all = await calls();
  const letter = all.find((c) => c.op === 'text' && c.text === FORCED_BADGE.letter && c.fill === FORCED_BADGE.letterColour)!;
  expect(letter).toBeDefined();
  expect(letter.font).toBe(FORCED_BADGE.font);
  const square = all.find(
    (c) => c.canvas === letter.canvas && c.op === 'fillRect' && c.fill === colours.forced && c.w === c.h,
  )!;
  expect(square.w).toBe(FORCED_BADGE.size);
  const badge = page.getByTestId('watch-row-Motor').getByTestId('forced-badge');
  await badge.waitFor();
  const css = await badge.evaluate((el) => {
    const s = getComputedStyle(el);
    const probe = document.createElement('span');
    probe.style.color = getComputedStyle(document.documentElement).getPropertyValue('--forced');
    document.body.append(probe);
    const forced = getComputedStyle(probe).color;
    probe.remove();
    return { text: el.textContent, width: s.width, height: s.height, bg: s.backgroundColor, colour: s.color, weight: s.fontWeight, size: s.fontSize, forced };
  });
  expect(css).toEqual({
    text: FORCED_BADGE.letter,
    width: `${FORCED_BADGE.size}px`,
    height: `${FORCED_BADGE.size}px`,
    bg: css.forced,
    colour: 'rgb(255, 255, 255)',
    weight: '700',
    size: '11px',
    forced: css.forced,
  });
  expect(errors).toEqual([]);
});

test('a coil drawn at the rail: clicking its wire with a contact puts the contact in series before it', async () => {
  await page.evaluate(() => window.rungsmith!.documentStore!.getState().newProject('Rail'));
  const draw = sim.draw;
  await draw.pickPalette('contact-NO');
  await draw.clickCell(0, 0, 0);
  await draw.typeName('Start');
  await draw.pickPalette('coil-COIL');
  await draw.clickCell(0, 0, 1);
  await draw.typeName('Motor');
  let { networks, layout } = await draw.layout();
  const nc = columnsOf(layout, networks[0]!);
  // The coil sits in the last column; the wire from its cell runs there.
  expect(nc.alignedAt[0]).toBe(1);
  const y = cellCentre(layout, networks, 0, { row: 0, col: 0 }).y;
  const onWire = await draw.screenPoint({ x: RAIL_X + (nc.xs[4]! + nc.xs[5]!) / 2, y });
  await draw.pickPalette('contact-NC');
  await page.mouse.click(onWire.x, onWire.y);
  await draw.typeName('Stop');
  expect(await draw.elements(0)).toEqual([
    { kind: 'contact', row: 0, col: 0, name: 'Start', type: 'NO' },
    { kind: 'contact', row: 0, col: 1, name: 'Stop', type: 'NC' },
    { kind: 'coil', row: 0, col: 2, name: 'Motor', type: 'COIL' },
  ]);
  ({ networks, layout } = await draw.layout());
  expect(columnsOf(layout, networks[0]!).alignedAt[0]).toBe(2);
  // Clicking the coil where it is drawn, at the rail, selects it.
  await draw.pickPalette('select');
  await draw.clickCell(0, 0, 2);
  const selected = await page.evaluate(() => {
    const ui = window.rungsmith!.uiStore!.getState();
    const doc = window.rungsmith!.documentStore!.getState();
    const n = doc.project.pous.find((p) => p.id === doc.activePouId)!.networks[0]!;
    return ui.selection.elements.map((id) => n.elements.find((e) => e.id === id)?.kind);
  });
  expect(selected).toEqual(['coil']);
  expect(errors).toEqual([]);
});

