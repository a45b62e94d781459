// The trend as a PNG: the chart's canvas as shown (lanes, cursors, trigger mark) with a legend
// under it that names every signal in full in its colour.
import type uPlot from 'uplot';
import { signalColour } from './trendChart';

const FONT_PX = 13;

/** A canvas with the chart and its legend (full names, wrapped to the width), on the panel's background. */
export function trendImage(chart: uPlot, names: readonly string[], heading: string, colours: { background: string; text: string }): HTMLCanvasElement {
  const source = chart.ctx.canvas;
  const ratio = source.width / Math.max(1, source.clientWidth || chart.width);
  const width = source.width;
  const measure = document.createElement('canvas').getContext('2d')!;
  const font = `${FONT_PX * ratio}px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif`;
  measure.font = font;
  const pad = 8 * ratio;
  const line = (FONT_PX + 6) * ratio;
  const swatch = 12 * ratio;
  // Lay the legend out: entries left to right, a new line when the next would not fit; a name
  // wider than the image wraps by characters (never cut).
  type Piece = { text: string; x: number; y: number; colour?: string };
  const pieces: Piece[] = [{ text: heading, x: pad, y: 0 }];
  let x = pad;
  let y = line;
  names.forEach((name, i) => {
    const entry = measure.measureText(name).width + swatch + 16 * ratio;
    if (x > pad && x + entry > width - pad) {
      x = pad;
      y += line;
    }
    pieces.push({ text: '', x, y, colour: signalColour(i) });
    let rest = name;
    let tx = x + swatch + 4 * ratio;
    while (rest) {
      let n = rest.length;
      while (n > 1 && tx + measure.measureText(rest.slice(0, n)).width > width - pad) n--;
      const chunk = rest.slice(0, n);
      pieces.push({ text: chunk, x: tx, y, colour: signalColour(i) });
      rest = rest.slice(n);
      if (rest) {
        y += line;
        tx = pad + swatch + 4 * ratio;
      } else x = tx + measure.measureText(chunk).width + 16 * ratio;
    }
  });
  const legendHeight = y + line + pad;
  const out = document.createElement('canvas');
  out.width = width;
  out.height = source.height + legendHeight;
  const ctx = out.getContext('2d')!;
  ctx.fillStyle = colours.background;
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.drawImage(source, 0, 0);
  ctx.font = font;
  ctx.textBaseline = 'top';
  const top = source.height + pad;
  for (const p of pieces) {
    if (p.text === '' && p.colour) {
      ctx.fillStyle = p.colour;
      ctx.fillRect(p.x, top + p.y + 2 * ratio, swatch, swatch);
      continue;
    }
    ctx.fillStyle = p.colour ?? colours.text;
    ctx.fillText(p.text, p.x, top + p.y);
  }
  return out;
}
