// A small, fast, non-validating XML parser. PLCopen files reach tens of megabytes (10,000-network
// programs) and general DOM parsers take seconds on those. This one checks well-formedness
// (matching tags, quoted attributes, known entities) and reports errors with line and column, but
// builds no object per element: the document is a set of flat typed arrays (names as numbers,
// attribute values and text as offsets into the source), read by index on hot paths (`XmlDoc`)
// and through `XmlElement` views made on demand elsewhere. Namespaces are kept as the raw prefix
// plus the `xmlns` attributes: PLCopen only needs local names and the root namespace.
import { Builder } from './builder';
import { XmlDoc, type XmlElement } from './doc';
import { decodeEntities } from './entities';
import { NameTable, SMI_MASK } from './strings';

export { child, childrenNamed, deepText, descend, XmlDoc, XmlElement } from './doc';

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

const isNameEnd = (c: number): boolean =>
  c === 32 || c === 9 || c === 10 || c === 13 || c === 47 /* / */ || c === 62; /* > */

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
      // Plain unsigned integers (localIds, coordinates) are read as numbers on the way.
      let num = 0;
      let digits = true;
      for (; close < len; close++) {
        const ch = src.charCodeAt(close);
        if (ch === quote) break;
        if (ch === 60) syntaxError(src, `"<" in the value of attribute "${names.name(an)}"`, qp);
        if (ch === 38) amp = 1;
        if (ch >= 48 && ch <= 57 && num < 100_000_000) num = num * 10 + ch - 48;
        else digits = false;
      }
      if (close >= len) syntaxError(src, `unclosed value of attribute "${names.name(an)}"`, qp);
      const n = close - qp - 1;
      // Canonical only ("7", not "07" nor ""), and below 2^31.
      if (!digits || n === 0 || n > 9 || (n > 1 && src.charCodeAt(qp + 1) === 48)) num = -1;
      if (amp) {
        const from = qp + 1;
        decodeEntities(src.slice(qp + 1, close), (m, at) => syntaxError(src, m, from + at));
      }
      for (let a = attrFrom; a < b.attrTotal; a++)
        if (b.attrName[a] === an) syntaxError(src, `attribute "${names.name(an)}" repeated in <${qname}>`, i);
      b.attr(an, qp + 1, close, amp, num);
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
