// A minimal XML writer: elements with attributes, indented two spaces, into an array of lines.

export type Attrs = Readonly<Record<string, string | number | boolean | undefined>>;

export const escapeText = (s: string): string =>
  !/[&<>]/.test(s) ? s : s.replace(/[&<>]/g, (c) => (c === '&' ? '&amp;' : c === '<' ? '&lt;' : '&gt;'));

const ATTR_SPECIAL = /[&<>"\n\r\t]/;

export const escapeAttr = (s: string): string =>
  !ATTR_SPECIAL.test(s)
    ? s
    : s.replace(/[&<>"\n\r\t]/g, (c) =>
        c === '&'
          ? '&amp;'
          : c === '<'
            ? '&lt;'
            : c === '>'
              ? '&gt;'
              : c === '"'
                ? '&quot;'
                : c === '\n'
                  ? '&#10;'
                  : c === '\r'
                    ? '&#13;'
                    : '&#9;',
      );

/** CDATA text; a `]]>` inside is split across two sections. */
export const cdata = (s: string): string => `<![CDATA[${s.replace(/]]>/g, ']]]]><![CDATA[>')}]]>`;

function attrText(attrs: Attrs | undefined): string {
  if (!attrs) return '';
  let out = '';
  for (const k in attrs) {
    const v = attrs[k];
    if (v === undefined) continue;
    out += ` ${k}="${typeof v === 'string' ? escapeAttr(v) : String(v)}"`;
  }
  return out;
}

/**
 * For each line of `xml` after the first: whether it starts inside text that is part of the
 * document (a CDATA section, a comment, or element text holding more than whitespace, e.g. the
 * lines of an ST body in `<xhtml:p>`), where indentation must be kept as written; the other lines
 * start in the whitespace between tags, which may be re-indented.
 */
export function textLineStarts(xml: string): boolean[] {
  const out: boolean[] = [];
  let i = 0;
  const n = xml.length;
  const newlines = (from: number, to: number, inText: boolean) => {
    for (let k = xml.indexOf('\n', from); k >= 0 && k < to; k = xml.indexOf('\n', k + 1)) out.push(inText);
  };
  while (i < n) {
    if (xml.startsWith('<![CDATA[', i)) {
      const e = xml.indexOf(']]>', i);
      const end = e < 0 ? n : e + 3;
      newlines(i, end, true);
      i = end;
    } else if (xml.startsWith('<!--', i)) {
      const e = xml.indexOf('-->', i);
      const end = e < 0 ? n : e + 3;
      newlines(i, end, true);
      i = end;
    } else if (xml[i] === '<') {
      const e = xml.indexOf('>', i);
      const end = e < 0 ? n : e + 1;
      newlines(i, end, false);
      i = end;
    } else {
      let end = xml.indexOf('<', i);
      if (end < 0) end = n;
      // Element text: significant when it holds more than whitespace, or when it runs into a CDATA
      // section (the text of `<xhtml:p>  <![CDATA[`... stays as it is).
      const own = !/^\s*$/.test(xml.slice(i, end));
      newlines(i, end, own);
      i = end;
    }
  }
  return out;
}

const PADS = Array.from({ length: 32 }, (_, i) => '  '.repeat(i));

/** Lines per flattened chunk: a big export would otherwise hold every line as a tree of string pieces. */
const CHUNK_LINES = 2048;

export class XmlWriter {
  /** Finished text, one flat string per CHUNK_LINES lines. */
  private readonly chunks: string[] = [];
  private lines: string[] = [];
  private depth = 0;
  /** While writing one line (see line()), the text so far; null otherwise. */
  private buf: string | null = null;

  private pad(): string {
    return PADS[this.depth] ?? '  '.repeat(this.depth);
  }

  private push(text: string): void {
    if (this.buf !== null) this.buf += text;
    else this.add(this.pad() + text);
  }

  private add(line: string): void {
    this.lines.push(line);
    if (this.lines.length >= CHUNK_LINES) {
      this.chunks.push(this.lines.join('\n'));
      this.lines = [];
    }
  }

  /** Everything body() writes goes on one line (compact pins and wires keep big files small). */
  line(body: () => void): this {
    if (this.buf !== null) {
      body();
      return this;
    }
    this.buf = '';
    body();
    this.add(this.pad() + this.buf);
    this.buf = null;
    return this;
  }

  /** `<name attrs/>` */
  empty(name: string, attrs?: Attrs): this {
    this.push(`<${name}${attrText(attrs)}/>`);
    return this;
  }

  /** `<name attrs>text</name>` on one line (text escaped). */
  leaf(name: string, text: string, attrs?: Attrs): this {
    this.push(`<${name}${attrText(attrs)}>${escapeText(text)}</${name}>`);
    return this;
  }

  /** `<name attrs>` ... `</name>` around body(). */
  open(name: string, attrs: Attrs | undefined, body: () => void): this {
    this.push(`<${name}${attrText(attrs)}>`);
    this.depth++;
    body();
    this.depth--;
    this.push(`</${name}>`);
    return this;
  }

  /** One pre-formed line of XML (no newline inside) at the current depth. */
  text(line: string): this {
    this.push(line);
    return this;
  }

  /** Pre-formed XML, e.g. preserved vendor data, re-indented at the current depth. */
  raw(xml: string): this {
    if (this.buf !== null) {
      this.buf += xml;
      return this;
    }
    const pad = this.pad();
    // Lines inside text (an ST body's CDATA) are written as they are: re-indenting them would
    // change the text.
    const inText = xml.includes('\n') ? textLineStarts(xml) : [];
    xml.split('\n').forEach((line, i) => this.add(i > 0 && inText[i - 1] ? line : pad + line));
    return this;
  }

  /** Formatted text as PLCopen writes it: `<name><xhtml:p><![CDATA[..]]></xhtml:p></name>`. */
  formatted(name: string, text: string, attrs?: Attrs): this {
    this.push(`<${name}${attrText(attrs)}><xhtml:p>${cdata(text)}</xhtml:p></${name}>`);
    return this;
  }

  toString(): string {
    if (this.lines.length) {
      this.chunks.push(this.lines.join('\n'));
      this.lines = [];
    }
    return `${this.chunks.join('\n')}\n`;
  }
}
