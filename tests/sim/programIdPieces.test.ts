// The program id of a large document is hashed in pieces with yield points between them (so the
// worker's due scans run during an online change): the id must not depend on how it is cut, and
// two documents that differ anywhere, even in the last piece, must get different ids.
import { describe, expect, test } from 'vitest';
import { withYieldPoints } from '../../src/engine/yieldPoint';
import { fingerprintId } from '../../src/sim/programId';

/** cyrb53 over the whole text at once (the id before it was hashed in pieces). */
function wholeId(text: string): string {
  let h1 = 0xdeadbeef;
  let h2 = 0x41c6ce57;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    h1 = Math.imul(h1 ^ c, 2654435761);
    h2 = Math.imul(h2 ^ c, 1597334677);
  }
  h1 = Math.imul(h1 ^ (h1 >>> 16), 2246822507) ^ Math.imul(h2 ^ (h2 >>> 13), 3266489909);
  h2 = Math.imul(h2 ^ (h2 >>> 16), 2246822507) ^ Math.imul(h1 ^ (h1 >>> 13), 3266489909);
  return `${(4294967296 * (2097151 & h2) + (h1 >>> 0)).toString(36)}-${text.length.toString(36)}`;
}

const big = Array.from({ length: 30_000 }, (_, i) => `{"kind":"contact","variable":"X${i}"}`).join(',');

describe('program id in pieces', () => {
  test('the same id as hashing the whole text, short or over several pieces', () => {
    expect(big.length).toBeGreaterThan(4 * 65536);
    for (const text of ['', 'a', 'Main', big, big.slice(0, 65536), big.slice(0, 65537)]) expect(fingerprintId(text)).toBe(wholeId(text));
  });

  test('a change in the last piece changes the id', () => {
    const changed = `${big.slice(0, -3)}Y"}`;
    expect(changed.length).toBe(big.length);
    expect(fingerprintId(changed)).not.toBe(fingerprintId(big));
  });

  test('the due scans get their turn between pieces, and the id is the same with them', () => {
    let yields = 0;
    const id = withYieldPoints(() => yields++, () => fingerprintId(big));
    expect(yields).toBe(Math.ceil(big.length / 65536) - 1);
    expect(id).toBe(wholeId(big));
  });
});
