// The string table of the XML parser (see parse.ts).

const TABLE_MASK = 4095;
/** Hashes are kept to small integers: larger ones would be boxed when passed to the table. */
export const SMI_MASK = 0x3fffffff;

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
    let h = end - start;
    for (let k = start; k < end; k++) h = (Math.imul(h, 31) + this.src.charCodeAt(k)) | 0;
    return h & SMI_MASK;
  }
}
