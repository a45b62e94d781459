// A parsed XML document (see parse.ts): element names as ids, attribute values and text as offsets
// into the source, all in typed arrays; read by index on hot paths, or through element views.
import { checked, decodeEntities } from './entities';
import { type NameTable, StringTable } from './strings';

/** Values up to this length are shared through the string table (numbers, flags, pin names). */
const SHORT_VALUE = 12;

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
  /** The value as a number when it is a plain unsigned integer below 2^31 (else -1). */
  valNum: Int32Array = new Int32Array(0);
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
    // A plain integer is written exactly as its number: no need to go back to the text.
    const n = this.valNum[a]!;
    if (n !== -1) return String(n);
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
    // Plain unsigned integers (nearly all PLCopen numbers) were read while parsing.
    const n = this.valNum[a]!;
    if (n !== -1) return n;
    const v = +this.attrValue(a);
    return v === v && v !== Infinity && v !== -Infinity ? v : 0;
  }
  /** An attribute that is a plain unsigned integer below 2^31 (localIds): its value, else -1. */
  attrIndexNumber(i: number, nameId: number): number {
    const a = this.attrIndex(i, nameId);
    return a === -1 ? -1 : this.valNum[a]!;
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
