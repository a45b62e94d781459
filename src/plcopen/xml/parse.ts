// A small, fast, non-validating XML parser producing a light element tree with source offsets.
// PLCopen files reach tens of megabytes (10,000-network programs); general DOM parsers take seconds
// on those, this one a fraction of that. It checks well-formedness (matching tags, quoted
// attributes, known entities) and reports errors with line and column. Namespaces are kept as
// the raw prefix plus the `xmlns` attributes: PLCopen only needs local names and the root namespace.
import { SMI_MASK, StringTable } from './strings';

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

/** Shared by every element without child elements (most of a PLCopen file: positions, pins); never written. */
const NO_CHILDREN: XmlElement[] = Object.freeze([]) as unknown as XmlElement[];
/** Shared by every element without attributes; never written. */
const NO_ATTRS: Readonly<Record<string, string>> = Object.freeze({});

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

const isNameEnd = (c: number): boolean =>
  c === 32 || c === 9 || c === 10 || c === 13 || c === 47 /* / */ || c === 62; /* > */

/** Values up to this length are shared through the string table (numbers, flags, pin names). */
const SHORT_VALUE = 12;

export interface ParseOptions {
  /**
   * Elements (with everything inside them) that are checked like the rest but left out of the
   * tree: a reader that never looks at them saves building hundreds of thousands of nodes.
   * Their text stays available through the offsets of their parent.
   */
  readonly skip?: (parent: XmlElement, name: string) => boolean;
}

/** Parses XML text into its root element. Throws XmlSyntaxError with a location. */
export function parseXml(src: string, options: ParseOptions = {}): XmlElement {
  const skip = options.skip;
  let pos = 0;
  const len = src.length;
  const fail: (msg: string, at?: number) => never = (msg, at = pos) => {
    const { line, column } = lineColumn(src, at);
    throw new XmlSyntaxError(msg, line, column);
  };
  if (src.charCodeAt(0) === 0xfeff) pos = 1;
  const strings = new StringTable(src);
  // Open elements, innermost at depth - 1 (indexed, not push/pop: those reallocate as depth swings).
  const stack: XmlElement[] = [];
  let depth = 0;
  // Children of the open elements, innermost last: each element gets an exact-size array when it
  // closes (a growing array per element would hold mostly empty slots).
  const kids: XmlElement[] = [];
  const kidsFrom: number[] = [];
  // Used up to kidsTop / skippedCount: truncating with `length =` would shrink and regrow the
  // arrays' storage for every element.
  let kidsTop = 0;
  const skippedNames: string[] = [];
  let skippedCount = 0;
  let root: XmlElement | undefined;

  while (pos < len) {
    const lt = src.indexOf('<', pos);
    if (lt === -1) {
      const rest = src.slice(pos);
      if (depth) fail(`the file ends inside <${stack[depth - 1]!.qname}>`, len);
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
      if (!blank) {
        const top = stack[depth - 1];
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
        const top = stack[depth - 1];
        if (!top) fail('CDATA outside the root element');
        top.text += src.slice(pos + 9, e);
        pos = e + 3;
      } else if (src.startsWith('<!DOCTYPE', pos)) {
        if (root || depth) fail('DOCTYPE inside the document');
        // Skip an optional internal subset; entity declarations are not supported (PLCopen never uses them).
        let nesting = 0;
        let i = pos + 9;
        for (; i < len; i++) {
          const ch = src[i];
          if (ch === '[') nesting++;
          else if (ch === ']') nesting--;
          else if (ch === '>' && nesting <= 0) break;
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
      const top = depth > 0 ? stack[--depth] : undefined;
      // Fast path: `</name>` exactly as opened.
      const q = top?.qname ?? '';
      if (!top || e !== pos + 2 + q.length || !src.startsWith(q, pos + 2)) {
        const name = src.slice(pos + 2, e).trim();
        if (!top) fail(`end tag </${name}> without a start tag`);
        if (top.qname !== name)
          fail(`end tag </${name}> does not match <${top.qname}> (line ${lineColumn(src, top.offset).line})`);
      }
      const from = kidsFrom[depth]!;
      if (kidsTop > from) {
        (top as { children: XmlElement[] }).children = kids.slice(from, kidsTop);
        kidsTop = from;
      }
      top!.end = e + 1;
      pos = e + 1;
      continue;
    }
    // Start tag.
    const start = pos;
    let i = pos + 1;
    let h = 0;
    let colon = -1;
    for (; i < len; i++) {
      const c = src.charCodeAt(i);
      if (isNameEnd(c)) break;
      if (c === 58 /* : */ && colon === -1) colon = i;
      h = (Math.imul(h, 31) + c) | 0;
    }
    const qname = strings.get(pos + 1, i, (h + Math.imul(i - pos - 1, 0x9e3779b1)) & SMI_MASK);
    const first = qname.charCodeAt(0);
    const nameStart =
      (first >= 65 && first <= 90) || (first >= 97 && first <= 122) || first === 95 || first >= 0xc0;
    if (!nameStart) fail(root || depth ? 'bad element name' : 'this is not XML: expected an element');
    const name =
      colon === -1
        ? qname
        : strings.get(
            colon + 1,
            start + 1 + qname.length,
            strings.hashOf(colon + 1, start + 1 + qname.length),
          );
    // A skipped element is checked just as strictly, but its attributes are not kept.
    const kept = !skip || !depth || !skip(stack[depth - 1]!, name);
    skippedCount = 0;
    let attrs = NO_ATTRS as Record<string, string>;
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
      if (ae === i) fail(`bad attribute in <${qname}>`, i);
      let ah = 0;
      for (let k = i; k < ae; k++) {
        const ch = src.charCodeAt(k);
        if (ch <= 32 || ch === 60 || ch === 62 || ch === 34 || ch === 39)
          fail(`bad attribute in <${qname}>`, i);
        ah = (Math.imul(ah, 31) + ch) | 0;
      }
      const an = strings.get(i, ae, (ah + Math.imul(ae - i, 0x9e3779b1)) & SMI_MASK);
      let q = eq + 1;
      while (q < len && src.charCodeAt(q) <= 32) q++;
      const quote = src.charCodeAt(q);
      if (quote !== 34 && quote !== 39) fail(`the value of attribute "${an}" must be quoted`, q);
      if (!kept) {
        const close = src.indexOf(quote === 34 ? '"' : "'", q + 1);
        if (close === -1) fail(`unclosed value of attribute "${an}"`, q);
        let amp = false;
        for (let k = q + 1; k < close; k++) {
          const ch = src.charCodeAt(k);
          if (ch === 60) fail(`"<" in the value of attribute "${an}"`, q);
          if (ch === 38) amp = true;
        }
        for (let k = 0; k < skippedCount; k++)
          if (skippedNames[k] === an) fail(`attribute "${an}" repeated in <${qname}>`, i);
        skippedNames[skippedCount++] = an;
        if (amp) decodeEntities(src.slice(q + 1, close), (m) => fail(m, q));
        i = close + 1;
        continue;
      }
      let close = q + 1;
      let vh = 0;
      let special = false;
      // Short values are hashed while looking for the closing quote; long ones are found with indexOf.
      for (; close < len && close - q <= SHORT_VALUE + 1; close++) {
        const ch = src.charCodeAt(close);
        if (ch === quote) break;
        if (ch === 60 || ch === 38) special = true;
        vh = (Math.imul(vh, 31) + ch) | 0;
      }
      let raw: string;
      if (close < len && src.charCodeAt(close) === quote && !special) {
        raw = strings.get(q + 1, close, (vh + Math.imul(close - q - 1, 0x9e3779b1)) & SMI_MASK);
      } else {
        close = src.indexOf(quote === 34 ? '"' : "'", q + 1);
        if (close === -1) fail(`unclosed value of attribute "${an}"`, q);
        raw = src.slice(q + 1, close);
        if (raw.indexOf('<') !== -1) fail(`"<" in the value of attribute "${an}"`, q);
      }
      if (attrs === NO_ATTRS) attrs = {};
      else if (an in attrs) fail(`attribute "${an}" repeated in <${qname}>`, i);
      attrs[an] = raw.indexOf('&') === -1 ? raw : decodeEntities(raw, (m) => fail(m, q));
      i = close + 1;
    }
    const el: XmlElement = {
      name,
      qname,
      attrs,
      children: NO_CHILDREN,
      text: '',
      offset: start,
      end: i,
    };
    if (depth) {
      if (kept) kids[kidsTop++] = el;
    } else if (root) fail('more than one root element', start);
    else root = el;
    if (!selfClosing) {
      kidsFrom[depth] = kidsTop;
      stack[depth++] = el;
    }
    pos = i;
  }
  if (depth) fail(`the file ends inside <${stack[depth - 1]!.qname}>`, len);
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
