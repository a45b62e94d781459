// Widths of canvas texts without a canvas: the grid's column widths are worked out from the names
// the network holds (columns.ts), the same in the browser, in Node tests and in print. The glyph
// widths are DejaVu Sans's (one of the widest UI fonts; Segoe UI, Roboto and SF are narrower), so
// an estimate is at least the drawn width; drawing still checks and never cuts a name.

/** The canvas fonts (drawSymbols.ts draws with these). */
export const FONT = '12px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
export const FONT_BOLD = 'bold 12px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
export const FONT_SMALL = '11px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
export const FONT_SMALL_BOLD = 'bold 11px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
export const MONO_SMALL_BOLD = 'bold 11px ui-monospace, "SF Mono", Menlo, Consolas, monospace';

/** Advance widths of ASCII 32..126 in hundredths of an em: regular, then bold. */
const REGULAR = decode(
  '32,41,46,84,64,95,78,28,39,39,50,84,32,37,32,34,64,64,64,64,64,64,64,64,64,64,34,34,84,84,84,54,100,69,69,70,77,64,58,78,76,30,30,66,56,87,75,79,61,79,70,64,62,74,69,99,69,62,69,39,34,39,84,50,50,62,64,55,64,62,36,64,64,28,28,58,28,98,64,62,64,64,42,53,40,64,60,82,60,60,53,64,34,64,84',
);
const BOLD = decode(
  '35,46,53,84,70,101,88,31,46,46,53,84,38,42,38,37,70,70,70,70,70,70,70,70,70,70,40,40,84,84,84,58,100,78,77,74,84,69,69,83,84,38,38,78,64,100,84,85,74,85,77,72,69,82,78,111,78,73,73,46,37,46,84,50,50,68,72,60,72,68,44,72,72,35,35,67,35,105,72,69,72,72,50,60,48,72,66,93,65,66,59,72,37,72,84',
);
/** Monospace fonts (jump labels): DejaVu Sans Mono's advance. */
const MONO_EM = 0.61;

function decode(list: string): Uint8Array {
  return Uint8Array.from(list.split(','), Number);
}

export interface FontSpec {
  readonly size: number;
  readonly bold?: boolean;
  readonly mono?: boolean;
}

export const SPEC_FONT: FontSpec = { size: 12 };
export const SPEC_BOLD: FontSpec = { size: 12, bold: true };
export const SPEC_SMALL: FontSpec = { size: 11 };
export const SPEC_SMALL_BOLD: FontSpec = { size: 11, bold: true };
export const SPEC_MONO_SMALL: FontSpec = { size: 11, bold: true, mono: true };

/** Estimated width in pixels of `text` in a font (at least what DejaVu Sans draws). */
export function textWidth(text: string, font: FontSpec = SPEC_FONT): number {
  if (font.mono) return text.length * MONO_EM * font.size;
  const table = font.bold ? BOLD : REGULAR;
  let hundredths = 0;
  for (const ch of text) {
    const code = ch.codePointAt(0)!;
    // Outside ASCII: a full em (wide letters, CJK); an estimate too wide only costs a few pixels.
    hundredths += code >= 32 && code < 127 ? table[code - 32]! : 100;
  }
  return (hundredths / 100) * font.size;
}

/**
 * Lines `text` takes wrapped at `width` pixels the way a textarea wraps it: at spaces, a word
 * longer than a line broken inside it, every newline a new line. Measured with the estimates
 * above, so at least as many lines as the browser draws.
 */
export function wrappedLines(text: string, width: number, font: FontSpec = SPEC_FONT): number {
  const space = textWidth(' ', font);
  let lines = 0;
  for (const paragraph of text.split('\n')) {
    lines++;
    let x = 0;
    for (const word of paragraph.split(' ')) {
      const w = textWidth(word, font);
      if (x > 0 && x + space + w <= width) {
        x += space + w;
        continue;
      }
      if (x > 0) lines++;
      // A word wider than a line fills whole lines and goes on in the next.
      const full = w > width ? Math.ceil(w / width) - 1 : 0;
      lines += full;
      x = w - full * width;
    }
  }
  return lines;
}
