// The string table of the XML parser (see parse.ts).

const TABLE_MASK = 4095;
/** Hashes are kept to small integers: larger ones would be boxed when passed to the table. */
export const SMI_MASK = 0x3fffffff;

/** A hash of the text between start and end, for the tables below. */
export function hashRange(src: string, start: number, end: number): number {
  let h = end - start;
  for (let k = start; k < end; k++) h = (Math.imul(h, 31) + src.charCodeAt(k)) | 0;
  return h & SMI_MASK;
}

/**
 * One string per distinct element name, attribute name and short value: a PLCopen file repeats the
 * same few hundred of them hundreds of thousands of times, and a tree of shared strings is far
 * smaller (and faster to collect) than one of copies. Open addressing is not needed: a slot holds
 * the last string hashed to it, a miss just slices.
 */
export class StringTable {
  private readonly slots: string[] = new Array<string>(TABLE_MASK + 1).fill('');
  /** Where in the source each slot's string was read (compared source to source: both flat). */
  private readonly from = new Int32Array(TABLE_MASK + 1);
  constructor(private readonly src: string) {}
  /** The text between start and end; `hash` is any hash of it. */
  get(start: number, end: number, hash: number): string {
    const slot = (hash ^ (hash >>> 13)) & TABLE_MASK;
    const cached = this.slots[slot]!;
    const n = end - start;
    if (cached.length === n) {
      const src = this.src;
      const at = this.from[slot]!;
      let k = 0;
      while (k < n && src.charCodeAt(at + k) === src.charCodeAt(start + k)) k++;
      if (k === n) return cached;
    }
    const s = this.src.slice(start, end);
    this.slots[slot] = s;
    this.from[slot] = start;
    return s;
  }
  hashOf(start: number, end: number): number {
    return hashRange(this.src, start, end);
  }
}

/**
 * Names (element and attribute names) as small integer ids: a document stores one number per name
 * and compares names as numbers. The slot cache gives the id of a recently seen name without
 * slicing; a miss falls back to a map, so one string always has one id whatever hash found it.
 */
export class NameTable {
  private readonly slots = new Int32Array(TABLE_MASK + 1).fill(-1);
  private readonly strings: string[] = [];
  /** Where in the source each name was first read. */
  private readonly from: number[] = [];
  private readonly byName = new Map<string, number>();
  constructor(private readonly src: string) {}
  /** The id of the text between start and end; `hash` is any hash of it. */
  get(start: number, end: number, hash: number): number {
    const slot = (hash ^ (hash >>> 13)) & TABLE_MASK;
    const cached = this.slots[slot]!;
    const n = end - start;
    const src = this.src;
    if (cached !== -1) {
      const s = this.strings[cached]!;
      if (s.length === n && src.startsWith(s, start)) return cached;
    }
    const s = src.slice(start, end);
    let id = this.byName.get(s);
    if (id === undefined) {
      id = this.strings.length;
      this.strings.push(s);
      this.from.push(start);
      this.byName.set(s, id);
    }
    this.slots[slot] = id;
    return id;
  }
  hashOf(start: number, end: number): number {
    return hashRange(this.src, start, end);
  }
  name(id: number): string {
    return this.strings[id]!;
  }
  /** The id of a name, or -1 if the document never uses it. */
  lookup(name: string): number {
    return this.byName.get(name) ?? -1;
  }
}
