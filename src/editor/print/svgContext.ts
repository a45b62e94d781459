// A 2D drawing context that writes SVG: the canvas's own drawing code (drawNetworkGrid and the
// symbols) draws into it, so a printed network is the network as the editor draws it, in vector
// form (sharp at any zoom and in a PDF). It covers what a ladder drawing uses: rectangles, paths
// (lines, arcs, curves), text with alignment, dashes, alpha, save/restore, translate and scale.
// Text widths come from a measuring function (a real canvas in the browser).

export type MeasureText = (font: string, text: string) => number;

interface State {
  fillStyle: string;
  strokeStyle: string;
  lineWidth: number;
  lineCap: CanvasLineCap;
  lineJoin: CanvasLineJoin;
  font: string;
  textAlign: CanvasTextAlign;
  textBaseline: CanvasTextBaseline;
  globalAlpha: number;
  dash: number[];
  /** Translation and (uniform) scale: device = user * scale + (x, y). */
  x: number;
  y: number;
  scale: number;
}

const ANCHOR: Record<CanvasTextAlign, string> = {
  left: 'start',
  start: 'start',
  center: 'middle',
  right: 'end',
  end: 'end',
};

const BASELINE: Record<CanvasTextBaseline, string | undefined> = {
  alphabetic: undefined,
  ideographic: 'ideographic',
  bottom: 'text-after-edge',
  top: 'text-before-edge',
  hanging: 'hanging',
  middle: 'central',
};

const num = (n: number) => String(Math.round(n * 100) / 100);

export const escapeXml = (s: string) =>
  s.replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]!);

const colour = (style: unknown) => (typeof style === 'string' ? style : '#000');

/** An <svg> element of the given size around `content` (empty: a frame that takes the room only). */
export const svgFrame = (width: number, height: number, attrs = '', content = '') =>
  `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${num(width)} ${num(height)}" width="${num(width)}" height="${num(height)}"${attrs ? ` ${attrs}` : ''}>${content}</svg>`;

export class SvgContext {
  private state: State = {
    fillStyle: '#000',
    strokeStyle: '#000',
    lineWidth: 1,
    lineCap: 'butt',
    lineJoin: 'miter',
    font: '10px sans-serif',
    textAlign: 'start',
    textBaseline: 'alphabetic',
    globalAlpha: 1,
    dash: [],
    x: 0,
    y: 0,
    scale: 1,
  };
  private readonly stack: State[] = [];
  private readonly out: string[] = [];
  private path = '';
  /** The current point of the path (device coordinates), for arcs joining it. */
  private hasPoint = false;

  constructor(private readonly measure: MeasureText) {}

  get fillStyle() { return this.state.fillStyle; }
  set fillStyle(v: string) { this.state.fillStyle = colour(v); }
  get strokeStyle() { return this.state.strokeStyle; }
  set strokeStyle(v: string) { this.state.strokeStyle = colour(v); }
  get lineWidth() { return this.state.lineWidth; }
  set lineWidth(v: number) { this.state.lineWidth = v; }
  get lineCap() { return this.state.lineCap; }
  set lineCap(v: CanvasLineCap) { this.state.lineCap = v; }
  get lineJoin() { return this.state.lineJoin; }
  set lineJoin(v: CanvasLineJoin) { this.state.lineJoin = v; }
  get font() { return this.state.font; }
  set font(v: string) { this.state.font = v; }
  get textAlign() { return this.state.textAlign; }
  set textAlign(v: CanvasTextAlign) { this.state.textAlign = v; }
  get textBaseline() { return this.state.textBaseline; }
  set textBaseline(v: CanvasTextBaseline) { this.state.textBaseline = v; }
  get globalAlpha() { return this.state.globalAlpha; }
  set globalAlpha(v: number) { this.state.globalAlpha = v; }

  save() { this.stack.push({ ...this.state, dash: [...this.state.dash] }); }
  restore() { const s = this.stack.pop(); if (s) this.state = s; }
  translate(x: number, y: number) {
    this.state.x += x * this.state.scale;
    this.state.y += y * this.state.scale;
  }
  scale(x: number, y: number = x) { this.state.scale *= Math.sqrt(Math.abs(x * y)); }
  setLineDash(d: readonly number[]) { this.state.dash = [...d]; }
  getLineDash() { return [...this.state.dash]; }
  measureText(text: string): TextMetrics {
    return { width: this.measure(this.state.font, text) } as TextMetrics;
  }

  private px(x: number) { return num(this.state.x + x * this.state.scale); }
  private py(y: number) { return num(this.state.y + y * this.state.scale); }
  private len(n: number) { return num(n * this.state.scale); }

  private paintAttrs(kind: 'fill' | 'stroke'): string {
    const s = this.state;
    const alpha = s.globalAlpha < 1 ? ` opacity="${num(s.globalAlpha)}"` : '';
    if (kind === 'fill') return `fill="${escapeXml(s.fillStyle)}"${alpha}`;
    const dash = s.dash.length ? ` stroke-dasharray="${s.dash.map((d) => this.len(d)).join(' ')}"` : '';
    const cap = s.lineCap !== 'butt' ? ` stroke-linecap="${s.lineCap}"` : '';
    const join = s.lineJoin !== 'miter' ? ` stroke-linejoin="${s.lineJoin}"` : '';
    return `fill="none" stroke="${escapeXml(s.strokeStyle)}" stroke-width="${this.len(s.lineWidth)}"${dash}${cap}${join}${alpha}`;
  }

  private rectPath(x: number, y: number, w: number, h: number) {
    return `x="${this.px(Math.min(x, x + w))}" y="${this.py(Math.min(y, y + h))}" width="${this.len(Math.abs(w))}" height="${this.len(Math.abs(h))}"`;
  }

  fillRect(x: number, y: number, w: number, h: number) {
    this.out.push(`<rect ${this.rectPath(x, y, w, h)} ${this.paintAttrs('fill')}/>`);
  }
  strokeRect(x: number, y: number, w: number, h: number) {
    this.out.push(`<rect ${this.rectPath(x, y, w, h)} ${this.paintAttrs('stroke')}/>`);
  }
  /** A printed page has no pixels to clear: nothing is drawn. */
  clearRect() {}

  beginPath() {
    this.path = '';
    this.hasPoint = false;
  }
  moveTo(x: number, y: number) {
    this.path += `M${this.px(x)} ${this.py(y)}`;
    this.hasPoint = true;
  }
  lineTo(x: number, y: number) {
    this.path += `${this.hasPoint ? 'L' : 'M'}${this.px(x)} ${this.py(y)}`;
    this.hasPoint = true;
  }
  closePath() {
    if (this.path) this.path += 'Z';
  }
  rect(x: number, y: number, w: number, h: number) {
    this.moveTo(x, y);
    this.lineTo(x + w, y);
    this.lineTo(x + w, y + h);
    this.lineTo(x, y + h);
    this.closePath();
  }
  quadraticCurveTo(cx: number, cy: number, x: number, y: number) {
    this.path += `Q${this.px(cx)} ${this.py(cy)} ${this.px(x)} ${this.py(y)}`;
    this.hasPoint = true;
  }
  bezierCurveTo(c1x: number, c1y: number, c2x: number, c2y: number, x: number, y: number) {
    this.path += `C${this.px(c1x)} ${this.py(c1y)} ${this.px(c2x)} ${this.py(c2y)} ${this.px(x)} ${this.py(y)}`;
    this.hasPoint = true;
  }
  arc(x: number, y: number, r: number, start: number, end: number, ccw = false) {
    this.ellipse(x, y, r, r, 0, start, end, ccw);
  }
  ellipse(x: number, y: number, rx: number, ry: number, _rotation: number, start: number, end: number, ccw = false) {
    const at = (a: number) => [x + rx * Math.cos(a), y + ry * Math.sin(a)] as const;
    let sweep = ccw ? start - end : end - start;
    if (sweep < 0) sweep = (sweep % (2 * Math.PI)) + 2 * Math.PI;
    const full = sweep >= 2 * Math.PI - 1e-9 || Math.abs(end - start) >= 2 * Math.PI - 1e-9;
    const [sx, sy] = at(start);
    this.path += `${this.hasPoint ? 'L' : 'M'}${this.px(sx)} ${this.py(sy)}`;
    this.hasPoint = true;
    const a = `A${this.len(rx)} ${this.len(ry)} 0`;
    const dir = ccw ? 0 : 1;
    if (full) {
      // Two half turns: one SVG arc cannot end where it starts.
      const [mx, my] = at(start + (ccw ? -Math.PI : Math.PI));
      this.path += `${a} 0 ${dir} ${this.px(mx)} ${this.py(my)}${a} 0 ${dir} ${this.px(sx)} ${this.py(sy)}`;
      return;
    }
    const [ex, ey] = at(ccw ? start - sweep : start + sweep);
    this.path += `${a} ${sweep > Math.PI ? 1 : 0} ${dir} ${this.px(ex)} ${this.py(ey)}`;
  }
  roundRect(x: number, y: number, w: number, h: number, radii: number | readonly number[] = 0) {
    const r0 = typeof radii === 'number' ? radii : (radii[0] ?? 0);
    const r = Math.max(0, Math.min(r0, Math.abs(w) / 2, Math.abs(h) / 2));
    this.moveTo(x + r, y);
    this.lineTo(x + w - r, y);
    this.quadraticCurveTo(x + w, y, x + w, y + r);
    this.lineTo(x + w, y + h - r);
    this.quadraticCurveTo(x + w, y + h, x + w - r, y + h);
    this.lineTo(x + r, y + h);
    this.quadraticCurveTo(x, y + h, x, y + h - r);
    this.lineTo(x, y + r);
    this.quadraticCurveTo(x, y, x + r, y);
    this.closePath();
  }
  fill() {
    if (this.path) this.out.push(`<path d="${this.path}" ${this.paintAttrs('fill')}/>`);
  }
  stroke() {
    if (this.path) this.out.push(`<path d="${this.path}" ${this.paintAttrs('stroke')}/>`);
  }
  /** Printing keeps whatever a clip would cut: the drawing code clips only its own margins. */
  clip() {}

  private text(text: string, x: number, y: number, maxWidth: number | undefined, paint: 'fill' | 'stroke') {
    const s = this.state;
    const baseline = BASELINE[s.textBaseline];
    const width = this.measure(s.font, text);
    // Like the canvas, squeeze text wider than maxWidth.
    const squeeze =
      maxWidth !== undefined && width > maxWidth && maxWidth > 0
        ? ` textLength="${this.len(maxWidth)}" lengthAdjust="spacingAndGlyphs"`
        : '';
    const scale = s.scale !== 1 ? ` transform="translate(${this.px(x)} ${this.py(y)}) scale(${num(s.scale)})"` : '';
    const pos = s.scale !== 1 ? 'x="0" y="0"' : `x="${this.px(x)}" y="${this.py(y)}"`;
    this.out.push(
      `<text ${pos}${scale} style="font:${escapeXml(s.font)}" text-anchor="${ANCHOR[s.textAlign]}"${baseline ? ` dominant-baseline="${baseline}"` : ''}${squeeze} ${this.paintAttrs(paint)}>${escapeXml(text)}</text>`,
    );
  }
  fillText(text: string, x: number, y: number, maxWidth?: number) {
    this.text(text, x, y, maxWidth, 'fill');
  }
  strokeText(text: string, x: number, y: number, maxWidth?: number) {
    this.text(text, x, y, maxWidth, 'stroke');
  }

  /** The drawing as SVG markup of the given size (user units = CSS px). */
  toSvg(width: number, height: number, attrs = ''): string {
    return svgFrame(width, height, attrs, this.out.join(''));
  }
}

/** Text widths from a real (never shown) canvas, cached per font and text. */
export function canvasMeasure(): MeasureText {
  const ctx = document.createElement('canvas').getContext('2d');
  const cache = new Map<string, number>();
  return (font, text) => {
    const key = `${font}\u0000${text}`;
    let w = cache.get(key);
    if (w === undefined) {
      if (!ctx) return text.length * 7;
      ctx.font = font;
      w = ctx.measureText(text).width;
      cache.set(key, w);
    }
    return w;
  };
}
