// The typed arrays of an XML document while the parser fills them (see parse.ts and doc.ts).
import type { XmlDoc } from './doc';

function grown<T extends Int32Array | Uint8Array>(a: T, need: number): T {
  if (need <= a.length) return a;
  const b = new (a.constructor as new (n: number) => T)(Math.max(need, a.length * 2));
  b.set(a);
  return b;
}

/** The arrays of a document while it is read (grown by doubling when short). */
export class Builder {
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
  valNum: Int32Array;
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
    this.valNum = new Int32Array(cap * 2);
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

  attr(name: number, from: number, to: number, amp: number, num: number): void {
    const k = this.attrTotal;
    if (k === this.attrName.length) {
      this.attrName = grown(this.attrName, k * 2);
      this.valStart = grown(this.valStart, k * 2);
      this.valEnd = grown(this.valEnd, k * 2);
      this.valAmp = grown(this.valAmp, k * 2);
      this.valNum = grown(this.valNum, k * 2);
    }
    this.attrName[k] = name;
    this.valStart[k] = from;
    this.valEnd[k] = to;
    this.valAmp[k] = amp;
    this.valNum[k] = num;
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
    doc.valNum = this.valNum;
    doc.attrTotal = this.attrTotal;
    doc.segStart = this.segStart;
    doc.segEnd = this.segEnd;
    doc.segCdata = this.segCdata;
    doc.segNext = this.segNext;
    doc.segTotal = this.segTotal;
    return doc;
  }
}
