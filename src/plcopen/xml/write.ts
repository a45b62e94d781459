// A minimal XML writer: elements with attributes, indented two spaces, into an array of lines.

export type Attrs = Readonly<Record<string, string | number | boolean | undefined>>;

export const escapeText = (s: string): string =>
  s.replace(/[&<>]/g, (c) => (c === '&' ? '&amp;' : c === '<' ? '&lt;' : '&gt;'));

export const escapeAttr = (s: string): string =>
  s.replace(/[&<>"\n\r\t]/g, (c) =>
    c === '&' ? '&amp;' : c === '<' ? '&lt;' : c === '>' ? '&gt;' : c === '"' ? '&quot;' : c === '\n' ? '&#10;' : c === '\r' ? '&#13;' : '&#9;',
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

export class XmlWriter {
  private readonly lines: string[] = [];
  private depth = 0;

  private pad(): string {
    return '  '.repeat(this.depth);
  }

  /** `<name attrs/>` */
  empty(name: string, attrs?: Attrs): this {
    this.lines.push(`${this.pad()}<${name}${attrText(attrs)}/>`);
    return this;
  }

  /** `<name attrs>text</name>` on one line (text escaped). */
  leaf(name: string, text: string, attrs?: Attrs): this {
    this.lines.push(`${this.pad()}<${name}${attrText(attrs)}>${escapeText(text)}</${name}>`);
    return this;
  }

  /** `<name attrs>` ... `</name>` around body(). */
  open(name: string, attrs: Attrs | undefined, body: () => void): this {
    this.lines.push(`${this.pad()}<${name}${attrText(attrs)}>`);
    this.depth++;
    body();
    this.depth--;
    this.lines.push(`${this.pad()}</${name}>`);
    return this;
  }

  /** Pre-formed XML, e.g. preserved vendor data, re-indented at the current depth. */
  raw(xml: string): this {
    const pad = this.pad();
    for (const line of xml.split('\n')) this.lines.push(pad + line);
    return this;
  }

  /** Formatted text as PLCopen writes it: `<name><xhtml:p><![CDATA[..]]></xhtml:p></name>`. */
  formatted(name: string, text: string, attrs?: Attrs): this {
    this.lines.push(`${this.pad()}<${name}${attrText(attrs)}><xhtml:p>${cdata(text)}</xhtml:p></${name}>`);
    return this;
  }

  toString(): string {
    return `${this.lines.join('\n')}\n`;
  }
}
