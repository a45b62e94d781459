// A small, fast, non-validating XML parser. PLCopen files reach tens of megabytes (10,000-network
// programs) and general DOM parsers take seconds on those. This one checks well-formedness
// (matching tags, quoted attributes, known entities) and reports errors with line and column, but
// builds no object per element: the document is a set of flat typed arrays (names as numbers,
// attribute values and text as offsets into the source), read by index on hot paths (`XmlDoc`)
// and through `XmlElement` views made on demand elsewhere. Namespaces are kept as the raw prefix
// plus the `xmlns` attributes: PLCopen only needs local names and the root namespace.
import { NameTable, SMI_MASK, StringTable } from './strings';

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

const ENTITIES: Record<string, string> = { lt: '<', gt: '>', amp: '&', quot: '"', apos: "'" };

/** Decodes entity and character references; `fail` gets the offset in `s` of the bad reference. */
function decodeEntities(s: string, fail: (msg: string, at: number) => never): string {
  if (s.indexOf('&') === -1) return s;
  return s.replace(/&([^;&\s]*);?/g, (m, body: string, at: number) => {
    if (!m.endsWith(';')) fail(`"&" must start an entity such as &amp;`, at);
    if (body.startsWith('#x') || body.startsWith('#X')) {
      const n = parseInt(body.slice(2), 16);
      if (Number.isNaN(n)) fail(`bad character reference "${m}"`, at);
      return String.fromCodePoint(n);
    }
    if (body.startsWith('#')) {
      const n = parseInt(body.slice(1), 10);
      if (Number.isNaN(n)) fail(`bad character reference "${m}"`, at);
      return String.fromCodePoint(n);
    }
    const e = ENTITIES[body];
    if (e === undefined) fail(`unknown entity "${m}"`, at);
    return e;
  });
}

/** Entities were checked while parsing: decoding again cannot fail. */
const checked = (msg: string): never => {
  throw new Error(`internal: ${msg}`);
};

const isNameEnd = (c: number): boolean =>
  c === 32 || c === 9 || c === 10 || c === 13 || c === 47 /* / */ || c === 62; /* > */

/** Values up to this length are shared through the string table (numbers, flags, pin names). */
const SHORT_VALUE = 12;

function grown<T extends Int32Array | Uint8Array>(a: T, need: number): T {
  if (need <= a.length) return a;
  const b = new (a.constructor as new (n: number) => T)(Math.max(need, a.length * 2));
  b.set(a);
  return b;
}

/**
 * A parsed document: element `i` (0 is the root) has a name, attributes, child elements and
 * character data, all stored in typed arrays. `-1` means "none" for every index.
 */
export class XmlDoc {
  /** Number of elements. */
  count = 0;
  /** Per element: qualified and local name ids (see `names`). */
  qid: Int32Array = new Int32Array(0);
  lid: Int32Array = new Int32Array(0);
  firstChild: Int32Array = new Int32Array(0);
  nextSibling: Int32Array = new Int32Array(0);
  /** Offset of the `<` of the start tag, and just past the end of the element. */
  start: Int32Array = new Int32Array(0);
  end: Int32Array = new Int32Array(0);
  /** First attribute and attribute count. */
  attrFirst: Int32Array = new Int32Array(0);
  attrCount: Int32Array = new Int32Array(0);
  /** First text segment (-1 if none). */
  textFirst: Int32Array = new Int32Array(0);
  /** Per attribute: name id, value span in the source, whether the value holds entities. */
  attrName: Int32Array = new Int32Array(0);
  valStart: Int32Array = new Int32Array(0);
  valEnd: Int32Array = new Int32Array(0);
  valAmp: Uint8Array = new Uint8Array(0);
  attrTotal = 0;
  /** Text segments: span, kind (0 text with entities decoded, 1 CDATA verbatim), next of the same element. */
  segStart: Int32Array = new Int32Array(0);
  segEnd: Int32Array = new Int32Array(0);
  segCdata: Uint8Array = new Uint8Array(0);
  segNext: Int32Array = new Int32Array(0);
  segTotal = 0;

  private readonly values: StringTable;
  private views: (XmlElement | undefined)[] = [];

  constructor(
    readonly src: string,
    readonly names: NameTable,
  ) {
    this.values = new StringTable(src);
  }

  /** Id of a name as written in this document (element local/qualified name or attribute name), or -1. */
  id(name: string): number {
    return this.names.lookup(name);
  }
  name(i: number): string {
    return this.names.name(this.lid[i]!);
  }
  qname(i: number): string {
    return this.names.name(this.qid[i]!);
  }
  /** First child element with this local-name id, or -1. */
  childById(i: number, lid: number): number {
    for (let c = this.firstChild[i]!; c !== -1; c = this.nextSibling[c]!) if (this.lid[c] === lid) return c;
    return -1;
  }
  /** Index of the attribute with this name id on element i, or -1. */
  attrIndex(i: number, nameId: number): number {
    const from = this.attrFirst[i]!;
    const to = from + this.attrCount[i]!;
    for (let a = from; a < to; a++) if (this.attrName[a] === nameId) return a;
    return -1;
  }
  /** Value of attribute `a` (an index from attrIndex). */
  attrValue(a: number): string {
    const s = this.valStart[a]!;
    const e = this.valEnd[a]!;
    if (this.valAmp[a]) return decodeEntities(this.src.slice(s, e), checked);
    return e - s <= SHORT_VALUE ? this.values.get(s, e, this.values.hashOf(s, e)) : this.src.slice(s, e);
  }
  /** Value of an attribute by name id, or undefined. */
  attr(i: number, nameId: number): string | undefined {
    const a = this.attrIndex(i, nameId);
    return a === -1 ? undefined : this.attrValue(a);
  }
  /** An attribute read as a number: 0 when absent or not a finite number. */
  attrNumber(i: number, nameId: number): number {
    const a = this.attrIndex(i, nameId);
    if (a === -1) return 0;
    const s = this.valStart[a]!;
    const e = this.valEnd[a]!;
    // Plain unsigned integers (nearly all PLCopen numbers) without making a string.
    let n = 0;
    let k = s;
    for (; k < e; k++) {
      const c = this.src.charCodeAt(k) - 48;
      if (c < 0 || c > 9) break;
      n = n * 10 + c;
    }
    if (k === e && e > s && e - s < 16) return n;
    const v = +this.attrValue(a);
    return v === v && v !== Infinity && v !== -Infinity ? v : 0;
  }
  /** An attribute that is a plain unsigned integer below 2^31 (localIds): its value, else -1. */
  attrIndexNumber(i: number, nameId: number): number {
    const a = this.attrIndex(i, nameId);
    if (a === -1) return -1;
    const s = this.valStart[a]!;
    const e = this.valEnd[a]!;
    if (e === s || e - s > 9) return -1;
    let n = 0;
    for (let k = s; k < e; k++) {
      const c = this.src.charCodeAt(k) - 48;
      if (c < 0 || c > 9) return -1;
      n = n * 10 + c;
    }
    // "007" is not "7": only canonical numbers stand for their text.
    return e - s > 1 && this.src.charCodeAt(s) === 48 ? -1 : n;
  }
  /** Character data directly inside element i (text with entities decoded, and CDATA). */
  text(i: number): string {
    let seg = this.textFirst[i]!;
    if (seg === -1) return '';
    let out = '';
    for (; seg !== -1; seg = this.segNext[seg]!) {
      const chunk = this.src.slice(this.segStart[seg]!, this.segEnd[seg]!);
      out += this.segCdata[seg] ? chunk : decodeEntities(chunk, checked);
    }
    return out;
  }
  /** The element view of index i (one per index). */
  element(i: number): XmlElement {
    return (this.views[i] ??= new XmlElement(this, i));
  }
}

/** A view of one element of an XmlDoc, for code that walks the tree by name rather than by index. */
export class XmlElement {
  private attrsMemo?: Readonly<Record<string, string>>;
  private childrenMemo?: readonly XmlElement[];
  constructor(
    readonly doc: XmlDoc,
    readonly index: number,
  ) {}
  /** Local name (prefix removed). */
  get name(): string {
    return this.doc.name(this.index);
  }
  /** Qualified name as written. */
  get qname(): string {
    return this.doc.qname(this.index);
  }
  get attrs(): Readonly<Record<string, string>> {
    if (this.attrsMemo) return this.attrsMemo;
    const d = this.doc;
    const out: Record<string, string> = {};
    const from = d.attrFirst[this.index]!;
    for (let a = from; a < from + d.attrCount[this.index]!; a++)
      out[d.names.name(d.attrName[a]!)] = d.attrValue(a);
    return (this.attrsMemo = out);
  }
  get children(): readonly XmlElement[] {
    if (this.childrenMemo) return this.childrenMemo;
    const d = this.doc;
    const out: XmlElement[] = [];
    for (let c = d.firstChild[this.index]!; c !== -1; c = d.nextSibling[c]!) out.push(d.element(c));
    return (this.childrenMemo = out);
  }
  /** Character data directly inside this element (text and CDATA, entities decoded; whitespace-only runs are dropped). */
  get text(): string {
    return this.doc.text(this.index);
  }
  /** Offset of the `<` of the start tag in the source text. */
  get offset(): number {
    return this.doc.start[this.index]!;
  }
  /** End of the element in the source (just past its end tag), for verbatim copies. */
  get end(): number {
    return this.doc.end[this.index]!;
  }
}

export interface ParseOptions {
  /**
   * Elements (with everything inside them) that are checked like the rest but left out of the
   * document, by local names of the parent and of the element: a reader that never looks at them
   * saves storing hundreds of thousands of entries. Their text stays in the source.
   */
  readonly skip?: (parentName: string, name: string) => boolean;
}

function syntaxError(src: string, msg: string, at: number): never {
  const { line, column } = lineColumn(src, at);
  throw new XmlSyntaxError(msg, line, column);
}

/** The arrays of a document while it is read (grown by doubling when short). */
class Builder {
  count = 0;
  qid: Int32Array;
  lid: Int32Array;
  firstChild: Int32Array;
  nextSibling: Int32Array;
  start: Int32Array;
  end: Int32Array;
  attrFirst: Int32Array;
  attrCount: Int32Array;
  textFirst: Int32Array;
  attrTotal = 0;
  attrName: Int32Array;
  valStart: Int32Array;
  valEnd: Int32Array;
  valAmp: Uint8Array;
  segTotal = 0;
  segStart: Int32Array;
  segEnd: Int32Array;
  segCdata: Uint8Array;
  segNext: Int32Array;
  // Open elements, innermost at depth - 1: name id (for end tags), element index (-1 inside a
  // skipped element), last child and last text segment so far.
  depth = 0;
  openQ = new Int32Array(64);
  openEl = new Int32Array(64);
  openLastChild = new Int32Array(64);
  openLastSeg = new Int32Array(64);

  constructor(size: number) {
    const cap = Math.max(64, size >> 6);
    this.qid = new Int32Array(cap);
    this.lid = new Int32Array(cap);
    this.firstChild = new Int32Array(cap);
    this.nextSibling = new Int32Array(cap);
    this.start = new Int32Array(cap);
    this.end = new Int32Array(cap);
    this.attrFirst = new Int32Array(cap);
    this.attrCount = new Int32Array(cap);
    this.textFirst = new Int32Array(cap);
    this.attrName = new Int32Array(cap * 2);
    this.valStart = new Int32Array(cap * 2);
    this.valEnd = new Int32Array(cap * 2);
    this.valAmp = new Uint8Array(cap * 2);
    const scap = Math.max(64, cap >> 2);
    this.segStart = new Int32Array(scap);
    this.segEnd = new Int32Array(scap);
    this.segCdata = new Uint8Array(scap);
    this.segNext = new Int32Array(scap);
  }

  /** A new element under the innermost open one; returns its index. */
  element(q: number, l: number, at: number): number {
    if (this.count === this.qid.length) {
      const n = this.count * 2;
      this.qid = grown(this.qid, n);
      this.lid = grown(this.lid, n);
      this.firstChild = grown(this.firstChild, n);
      this.nextSibling = grown(this.nextSibling, n);
      this.start = grown(this.start, n);
      this.end = grown(this.end, n);
      this.attrFirst = grown(this.attrFirst, n);
      this.attrCount = grown(this.attrCount, n);
      this.textFirst = grown(this.textFirst, n);
    }
    const el = this.count++;
    this.qid[el] = q;
    this.lid[el] = l;
    this.firstChild[el] = -1;
    this.nextSibling[el] = -1;
    this.start[el] = at;
    this.textFirst[el] = -1;
    this.attrFirst[el] = this.attrTotal;
    this.attrCount[el] = 0;
    const d = this.depth;
    if (d) {
      const last = this.openLastChild[d - 1]!;
      if (last === -1) this.firstChild[this.openEl[d - 1]!] = el;
      else this.nextSibling[last] = el;
      this.openLastChild[d - 1] = el;
    }
    return el;
  }

  attr(name: number, from: number, to: number, amp: number): void {
    const k = this.attrTotal;
    if (k === this.attrName.length) {
      this.attrName = grown(this.attrName, k * 2);
      this.valStart = grown(this.valStart, k * 2);
      this.valEnd = grown(this.valEnd, k * 2);
      this.valAmp = grown(this.valAmp, k * 2);
    }
    this.attrName[k] = name;
    this.valStart[k] = from;
    this.valEnd[k] = to;
    this.valAmp[k] = amp;
    this.attrTotal = k + 1;
  }

  open(q: number, el: number): void {
    const d = this.depth;
    if (d === this.openQ.length) {
      this.openQ = grown(this.openQ, d * 2);
      this.openEl = grown(this.openEl, d * 2);
      this.openLastChild = grown(this.openLastChild, d * 2);
      this.openLastSeg = grown(this.openLastSeg, d * 2);
    }
    this.openQ[d] = q;
    this.openEl[d] = el;
    this.openLastChild[d] = -1;
    this.openLastSeg[d] = -1;
    this.depth = d + 1;
  }

  /** Character data of the innermost open element (nothing inside a skipped element). */
  text(from: number, to: number, cdata: number): void {
    const d = this.depth;
    const el = this.openEl[d - 1]!;
    if (el === -1) return;
    const k = this.segTotal;
    if (k === this.segStart.length) {
      this.segStart = grown(this.segStart, k * 2);
      this.segEnd = grown(this.segEnd, k * 2);
      this.segCdata = grown(this.segCdata, k * 2);
      this.segNext = grown(this.segNext, k * 2);
    }
    this.segStart[k] = from;
    this.segEnd[k] = to;
    this.segCdata[k] = cdata;
    this.segNext[k] = -1;
    const last = this.openLastSeg[d - 1]!;
    if (last === -1) this.textFirst[el] = k;
    else this.segNext[last] = k;
    this.openLastSeg[d - 1] = k;
    this.segTotal = k + 1;
  }

  finish(doc: XmlDoc): XmlDoc {
    doc.count = this.count;
    doc.qid = this.qid;
    doc.lid = this.lid;
    doc.firstChild = this.firstChild;
    doc.nextSibling = this.nextSibling;
    doc.start = this.start;
    doc.end = this.end;
    doc.attrFirst = this.attrFirst;
    doc.attrCount = this.attrCount;
    doc.textFirst = this.textFirst;
    doc.attrName = this.attrName;
    doc.valStart = this.valStart;
    doc.valEnd = this.valEnd;
    doc.valAmp = this.valAmp;
    doc.attrTotal = this.attrTotal;
    doc.segStart = this.segStart;
    doc.segEnd = this.segEnd;
    doc.segCdata = this.segCdata;
    doc.segNext = this.segNext;
    doc.segTotal = this.segTotal;
    return doc;
  }
}

/** Parses XML text into a document. Throws XmlSyntaxError with a location. */
export function parseXmlDoc(src: string, options: ParseOptions = {}): XmlDoc {
  const skip = options.skip;
  let pos = 0;
  const len = src.length;
  if (src.charCodeAt(0) === 0xfeff) pos = 1;
  const names = new NameTable(src);
  const b = new Builder(len);
  /** Depth of the outermost skipped element being read (0: none). */
  let skipFrom = 0;
  let hasRoot = false;

  while (pos < len) {
    const lt = src.indexOf('<', pos);
    if (lt === -1) {
      if (b.depth) syntaxError(src, `the file ends inside <${names.name(b.openQ[b.depth - 1]!)}>`, len);
      for (let i = pos; i < len; i++) {
        const c = src.charCodeAt(i);
        if (c !== 32 && c !== 10 && c !== 13 && c !== 9)
          syntaxError(
            src,
            hasRoot ? 'text after the end of the document' : 'this is not XML: no element found',
            pos,
          );
      }
      break;
    }
    if (lt > pos) {
      // Indentation between elements is most of the text in PLCopen files: skip it without slicing.
      let k = pos;
      for (; k < lt; k++) {
        const c = src.charCodeAt(k);
        if (c !== 32 && c !== 10 && c !== 13 && c !== 9) break;
      }
      if (k < lt) {
        if (!b.depth)
          syntaxError(
            src,
            hasRoot ? 'text after the end of the document' : 'this is not XML: text before the first element',
            pos,
          );
        let amp = false;
        for (; k < lt && !amp; k++) amp = src.charCodeAt(k) === 38;
        if (amp) {
          const from = pos;
          decodeEntities(src.slice(pos, lt), (m, at) => syntaxError(src, m, from + at));
        }
        b.text(pos, lt, 0);
      }
    }
    pos = lt;
    const c1 = src.charCodeAt(pos + 1);
    if (c1 === 33 /* ! */) {
      if (src.startsWith('<!--', pos)) {
        const e = src.indexOf('-->', pos + 4);
        if (e === -1) syntaxError(src, 'unclosed comment', pos);
        pos = e + 3;
      } else if (src.startsWith('<![CDATA[', pos)) {
        const e = src.indexOf(']]>', pos + 9);
        if (e === -1) syntaxError(src, 'unclosed CDATA section', pos);
        if (!b.depth) syntaxError(src, 'CDATA outside the root element', pos);
        b.text(pos + 9, e, 1);
        pos = e + 3;
      } else if (src.startsWith('<!DOCTYPE', pos)) {
        if (hasRoot || b.depth) syntaxError(src, 'DOCTYPE inside the document', pos);
        // Skip an optional internal subset; entity declarations are not supported (PLCopen never uses them).
        let nesting = 0;
        let i = pos + 9;
        for (; i < len; i++) {
          const ch = src[i];
          if (ch === '[') nesting++;
          else if (ch === ']') nesting--;
          else if (ch === '>' && nesting <= 0) break;
        }
        if (i >= len) syntaxError(src, 'unclosed DOCTYPE', pos);
        pos = i + 1;
      } else syntaxError(src, 'unexpected "<!"', pos);
      continue;
    }
    if (c1 === 63 /* ? */) {
      const e = src.indexOf('?>', pos + 2);
      if (e === -1) syntaxError(src, 'unclosed processing instruction', pos);
      pos = e + 2;
      continue;
    }
    if (c1 === 47 /* / */) {
      const e = src.indexOf('>', pos + 2);
      if (e === -1) syntaxError(src, 'unclosed end tag', pos);
      if (!b.depth) syntaxError(src, `end tag </${src.slice(pos + 2, e).trim()}> without a start tag`, pos);
      const depth = --b.depth;
      // Fast path: `</name>` exactly as opened.
      const q = names.name(b.openQ[depth]!);
      const el = b.openEl[depth]!;
      if (e !== pos + 2 + q.length || !src.startsWith(q, pos + 2)) {
        const name = src.slice(pos + 2, e).trim();
        if (q !== name) {
          const at = el === -1 ? '' : ` (line ${lineColumn(src, b.start[el]!).line})`;
          syntaxError(src, `end tag </${name}> does not match <${q}>${at}`, pos);
        }
      }
      if (el !== -1) b.end[el] = e + 1;
      if (skipFrom > depth) skipFrom = 0;
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
    const q = names.get(pos + 1, i, (h + Math.imul(i - pos - 1, 0x9e3779b1)) & SMI_MASK);
    const qname = names.name(q);
    const first = qname.charCodeAt(0);
    const nameStart =
      (first >= 65 && first <= 90) || (first >= 97 && first <= 122) || first === 95 || first >= 0xc0;
    const depth = b.depth;
    if (!nameStart)
      syntaxError(src, hasRoot || depth ? 'bad element name' : 'this is not XML: expected an element', pos);
    if (!depth && hasRoot) syntaxError(src, 'more than one root element', start);
    const l = colon === -1 ? q : names.get(colon + 1, i, names.hashOf(colon + 1, i));
    // A skipped element is checked just as strictly, but not stored.
    if (!skipFrom && depth && skip && skip(names.name(b.lid[b.openEl[depth - 1]!]!), names.name(l)))
      skipFrom = depth + 1;
    const el = skipFrom ? -1 : b.element(q, l, start);
    const attrFrom = b.attrTotal;
    let selfClosing = false;
    for (;;) {
      while (i < len) {
        const c = src.charCodeAt(i);
        if (c === 32 || c === 9 || c === 10 || c === 13) i++;
        else break;
      }
      if (i >= len) syntaxError(src, `unclosed start tag <${qname}>`, start);
      const c = src.charCodeAt(i);
      if (c === 62) {
        i++;
        break;
      }
      if (c === 47) {
        if (src.charCodeAt(i + 1) !== 62) syntaxError(src, 'expected "/>"', i);
        selfClosing = true;
        i += 2;
        break;
      }
      const eq = src.indexOf('=', i);
      if (eq === -1) syntaxError(src, `attribute without a value in <${qname}>`, i);
      let ae = eq;
      while (ae > i && src.charCodeAt(ae - 1) <= 32) ae--;
      if (ae === i) syntaxError(src, `bad attribute in <${qname}>`, i);
      let ah = 0;
      for (let k = i; k < ae; k++) {
        const ch = src.charCodeAt(k);
        if (ch <= 32 || ch === 60 || ch === 62 || ch === 34 || ch === 39)
          syntaxError(src, `bad attribute in <${qname}>`, i);
        ah = (Math.imul(ah, 31) + ch) | 0;
      }
      const an = names.get(i, ae, (ah + Math.imul(ae - i, 0x9e3779b1)) & SMI_MASK);
      let qp = eq + 1;
      while (qp < len && src.charCodeAt(qp) <= 32) qp++;
      const quote = src.charCodeAt(qp);
      if (quote !== 34 && quote !== 39)
        syntaxError(src, `the value of attribute "${names.name(an)}" must be quoted`, qp);
      let close = qp + 1;
      let amp = 0;
      for (; close < len; close++) {
        const ch = src.charCodeAt(close);
        if (ch === quote) break;
        if (ch === 60) syntaxError(src, `"<" in the value of attribute "${names.name(an)}"`, qp);
        if (ch === 38) amp = 1;
      }
      if (close >= len) syntaxError(src, `unclosed value of attribute "${names.name(an)}"`, qp);
      if (amp) {
        const from = qp + 1;
        decodeEntities(src.slice(qp + 1, close), (m, at) => syntaxError(src, m, from + at));
      }
      for (let a = attrFrom; a < b.attrTotal; a++)
        if (b.attrName[a] === an) syntaxError(src, `attribute "${names.name(an)}" repeated in <${qname}>`, i);
      b.attr(an, qp + 1, close, amp);
      i = close + 1;
    }
    if (el !== -1) {
      b.attrCount[el] = b.attrTotal - attrFrom;
      b.end[el] = i;
      if (!depth) hasRoot = true;
    } else b.attrTotal = attrFrom; // a skipped element keeps its attributes only for the repeat check
    if (!selfClosing) b.open(q, el);
    else if (skipFrom > depth) skipFrom = 0;
    pos = i;
  }
  if (b.depth) syntaxError(src, `the file ends inside <${names.name(b.openQ[b.depth - 1]!)}>`, len);
  if (!hasRoot) syntaxError(src, 'this is not XML: no element found', 0);
  return b.finish(new XmlDoc(src, names));
}

/** Parses XML text into its root element. Throws XmlSyntaxError with a location. */
export function parseXml(src: string, options: ParseOptions = {}): XmlElement {
  return parseXmlDoc(src, options).element(0);
}

/** First child element with this local name. */
export function child(el: XmlElement, name: string): XmlElement | undefined {
  const d = el.doc;
  const id = d.id(name);
  if (id === -1) return undefined;
  const c = d.childById(el.index, id);
  return c === -1 ? undefined : d.element(c);
}
/** Child elements with this local name. */
export function childrenNamed(el: XmlElement, name: string): XmlElement[] {
  const out: XmlElement[] = [];
  const d = el.doc;
  const id = d.id(name);
  if (id === -1) return out;
  for (let c = d.firstChild[el.index]!; c !== -1; c = d.nextSibling[c]!)
    if (d.lid[c] === id) out.push(d.element(c));
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
