// A small, fast, non-validating XML parser producing a light element tree with source offsets.
// PLCopen files reach tens of megabytes (10,000-network programs); general DOM parsers take seconds
// on those, this one a fraction of that. It checks well-formedness (matching tags, quoted
// attributes, known entities) and reports errors with line and column. Namespaces are kept as
// the raw prefix plus the `xmlns` attributes: PLCopen only needs local names and the root namespace.

export interface XmlElement {
  /** Local name (prefix removed). */
  readonly name: string;
  /** Qualified name as written. */
  readonly qname: string;
  readonly attrs: Readonly<Record<string, string>>;
  readonly children: XmlElement[];
  /** Character data directly inside this element (text and CDATA, entities decoded; whitespace-only runs are dropped). */
  text: string;
  /** Offset of the `<` of the start tag in the source text. */
  readonly offset: number;
  /** Offsets of the whole element in the source (start tag `<` to end of end tag), for verbatim copies. */
  end: number;
}

export class XmlSyntaxError extends Error {
  constructor(
    message: string,
    readonly line: number,
    readonly column: number,
  ) {
    super(`line ${line}, column ${column}: ${message}`);
  }
}

/** 1-based line and column of an offset. */
export function lineColumn(text: string, offset: number): { line: number; column: number } {
  let line = 1;
  let lineStart = 0;
  for (let i = text.indexOf('\n'); i !== -1 && i < offset; i = text.indexOf('\n', i + 1)) {
    line++;
    lineStart = i + 1;
  }
  return { line, column: offset - lineStart + 1 };
}

/** Shared by every self-closing element (most of a PLCopen file: positions, pins); never written. */
const NO_CHILDREN: XmlElement[] = Object.freeze([]) as unknown as XmlElement[];

const ENTITIES: Record<string, string> = { lt: '<', gt: '>', amp: '&', quot: '"', apos: "'" };

function decodeEntities(s: string, fail: (msg: string) => never): string {
  if (s.indexOf('&') === -1) return s;
  return s.replace(/&([^;&\s]*);?/g, (m, body: string) => {
    if (!m.endsWith(';')) fail(`"&" must start an entity such as &amp;`);
    if (body.startsWith('#x') || body.startsWith('#X')) {
      const n = parseInt(body.slice(2), 16);
      if (Number.isNaN(n)) fail(`bad character reference "${m}"`);
      return String.fromCodePoint(n);
    }
    if (body.startsWith('#')) {
      const n = parseInt(body.slice(1), 10);
      if (Number.isNaN(n)) fail(`bad character reference "${m}"`);
      return String.fromCodePoint(n);
    }
    const e = ENTITIES[body];
    if (e === undefined) fail(`unknown entity "${m}"`);
    return e;
  });
}

const localName = (qname: string): string => {
  const i = qname.indexOf(':');
  return i === -1 ? qname : qname.slice(i + 1);
};

const isNameEnd = (c: number): boolean =>
  c === 32 || c === 9 || c === 10 || c === 13 || c === 47 /* / */ || c === 62; /* > */

/** Parses XML text into its root element. Throws XmlSyntaxError with a location. */
export function parseXml(src: string): XmlElement {
  let pos = 0;
  const len = src.length;
  const fail: (msg: string, at?: number) => never = (msg, at = pos) => {
    const { line, column } = lineColumn(src, at);
    throw new XmlSyntaxError(msg, line, column);
  };
  if (src.charCodeAt(0) === 0xfeff) pos = 1;
  const stack: XmlElement[] = [];
  let root: XmlElement | undefined;

  while (pos < len) {
    const lt = src.indexOf('<', pos);
    if (lt === -1) {
      const rest = src.slice(pos);
      if (stack.length) fail(`the file ends inside <${stack[stack.length - 1]!.qname}>`, len);
      if (rest.trim())
        fail(root ? 'text after the end of the document' : 'this is not XML: no element found');
      break;
    }
    if (lt > pos) {
      // Indentation between elements is most of the text in PLCopen files: skip it without slicing.
      let blank = true;
      for (let i = pos; i < lt; i++) {
        const c = src.charCodeAt(i);
        if (c !== 32 && c !== 10 && c !== 13 && c !== 9) {
          blank = false;
          break;
        }
      }
      const top = stack[stack.length - 1];
      if (!blank) {
        const chunk = src.slice(pos, lt);
        if (top) top.text += decodeEntities(chunk, (m) => fail(m, pos));
        else
          fail(
            root ? 'text after the end of the document' : 'this is not XML: text before the first element',
          );
      }
    }
    pos = lt;
    const c1 = src.charCodeAt(pos + 1);
    if (c1 === 33 /* ! */) {
      if (src.startsWith('<!--', pos)) {
        const e = src.indexOf('-->', pos + 4);
        if (e === -1) fail('unclosed comment');
        pos = e + 3;
      } else if (src.startsWith('<![CDATA[', pos)) {
        const e = src.indexOf(']]>', pos + 9);
        if (e === -1) fail('unclosed CDATA section');
        const top = stack[stack.length - 1];
        if (!top) fail('CDATA outside the root element');
        top.text += src.slice(pos + 9, e);
        pos = e + 3;
      } else if (src.startsWith('<!DOCTYPE', pos)) {
        if (root || stack.length) fail('DOCTYPE inside the document');
        // Skip an optional internal subset; entity declarations are not supported (PLCopen never uses them).
        let depth = 0;
        let i = pos + 9;
        for (; i < len; i++) {
          const ch = src[i];
          if (ch === '[') depth++;
          else if (ch === ']') depth--;
          else if (ch === '>' && depth <= 0) break;
        }
        if (i >= len) fail('unclosed DOCTYPE');
        pos = i + 1;
      } else fail('unexpected "<!"');
      continue;
    }
    if (c1 === 63 /* ? */) {
      const e = src.indexOf('?>', pos + 2);
      if (e === -1) fail('unclosed processing instruction');
      pos = e + 2;
      continue;
    }
    if (c1 === 47 /* / */) {
      const e = src.indexOf('>', pos + 2);
      if (e === -1) fail('unclosed end tag');
      const name = src.slice(pos + 2, e).trim();
      const top = stack.pop();
      if (!top) fail(`end tag </${name}> without a start tag`);
      if (top.qname !== name)
        fail(`end tag </${name}> does not match <${top.qname}> (line ${lineColumn(src, top.offset).line})`);
      top.end = e + 1;
      pos = e + 1;
      continue;
    }
    // Start tag.
    const start = pos;
    let i = pos + 1;
    while (i < len && !isNameEnd(src.charCodeAt(i))) i++;
    const qname = src.slice(pos + 1, i);
    const first = qname.charCodeAt(0);
    const nameStart =
      (first >= 65 && first <= 90) || (first >= 97 && first <= 122) || first === 95 || first >= 0xc0;
    if (!nameStart) fail(root || stack.length ? 'bad element name' : 'this is not XML: expected an element');
    const attrs: Record<string, string> = {};
    let selfClosing = false;
    for (;;) {
      while (i < len) {
        const c = src.charCodeAt(i);
        if (c === 32 || c === 9 || c === 10 || c === 13) i++;
        else break;
      }
      if (i >= len) fail(`unclosed start tag <${qname}>`, start);
      const c = src.charCodeAt(i);
      if (c === 62) {
        i++;
        break;
      }
      if (c === 47) {
        if (src.charCodeAt(i + 1) !== 62) fail('expected "/>"', i);
        selfClosing = true;
        i += 2;
        break;
      }
      const eq = src.indexOf('=', i);
      if (eq === -1) fail(`attribute without a value in <${qname}>`, i);
      let ae = eq;
      while (ae > i && src.charCodeAt(ae - 1) <= 32) ae--;
      const an = src.slice(i, ae);
      for (let k = 0; k < an.length; k++) {
        const c = an.charCodeAt(k);
        if (c <= 32 || c === 60 || c === 62 || c === 34 || c === 39) fail(`bad attribute in <${qname}>`, i);
      }
      if (!an) fail(`bad attribute in <${qname}>`, i);
      let q = eq + 1;
      while (q < len && src.charCodeAt(q) <= 32) q++;
      const quote = src[q] ?? '';
      if (quote !== '"' && quote !== "'") fail(`the value of attribute "${an}" must be quoted`, q);
      const close = src.indexOf(quote, q + 1);
      if (close === -1) fail(`unclosed value of attribute "${an}"`, q);
      const raw = src.slice(q + 1, close);
      if (raw.indexOf('<') !== -1) fail(`"<" in the value of attribute "${an}"`, q);
      if (an in attrs) fail(`attribute "${an}" repeated in <${qname}>`, i);
      attrs[an] = raw.indexOf('&') === -1 ? raw : decodeEntities(raw, (m) => fail(m, q));
      i = close + 1;
    }
    const el: XmlElement = {
      name: qname.indexOf(':') === -1 ? qname : localName(qname),
      qname,
      attrs,
      children: selfClosing ? NO_CHILDREN : [],
      text: '',
      offset: start,
      end: i,
    };
    const parent = stack[stack.length - 1];
    if (parent) parent.children.push(el);
    else if (root) fail('more than one root element', start);
    else root = el;
    if (!selfClosing) stack.push(el);
    pos = i;
  }
  if (stack.length) fail(`the file ends inside <${stack[stack.length - 1]!.qname}>`, len);
  if (!root) fail('this is not XML: no element found', 0);
  return root!;
}

/** First child element with this local name. */
export function child(el: XmlElement, name: string): XmlElement | undefined {
  const cs = el.children;
  for (let i = 0; i < cs.length; i++) if (cs[i]!.name === name) return cs[i];
  return undefined;
}
/** Child elements with this local name. */
export function childrenNamed(el: XmlElement, name: string): XmlElement[] {
  const out: XmlElement[] = [];
  const cs = el.children;
  for (let i = 0; i < cs.length; i++) if (cs[i]!.name === name) out.push(cs[i]!);
  return out;
}
/** Path of child names: `child(child(el, a), b)`. */
export function descend(el: XmlElement | undefined, ...names: string[]): XmlElement | undefined {
  let cur = el;
  for (const n of names) {
    if (!cur) return undefined;
    cur = child(cur, n);
  }
  return cur;
}

/** All text inside an element (its own and its descendants'), for xhtml formatted text. */
export function deepText(el: XmlElement): string {
  if (!el.children.length) return el.text;
  let out = el.text;
  for (const c of el.children) {
    const t = deepText(c);
    if (out && t && (c.name === 'p' || c.name === 'br' || c.name === 'div')) out += '\n';
    out += t;
  }
  return out;
}

/** Fast offset → line lookups for many findings in one file. */
export function lineLocator(text: string): (offset: number) => number {
  const starts: number[] = [0];
  for (let i = text.indexOf('\n'); i !== -1; i = text.indexOf('\n', i + 1)) starts.push(i + 1);
  return (offset) => {
    let lo = 0;
    let hi = starts.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (starts[mid]! <= offset) lo = mid;
      else hi = mid - 1;
    }
    return lo + 1;
  };
}
