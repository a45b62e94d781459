// A short id for "which program is this": the same for two documents that behave the same (titles,
// comments and layout-only fields left out, see programFingerprint), different otherwise. The worker
// reports the id of the program it runs in every frame, and the store compares it with the id of the
// document on screen, so the simulation never shows "Running" for a program that is not the one shown.
import type { Project } from '../model/project';
import { yieldPoint } from '../engine/yieldPoint';
import { programFingerprint } from './layout';

/** Characters hashed between two yield points. */
const HASH_PIECE = 1 << 16;

/** 53-bit hash (cyrb53) of a fingerprint, as base-36 text with the length (collisions need both equal). */
export function fingerprintId(fingerprint: string): string {
  let h1 = 0xdeadbeef;
  let h2 = 0x41c6ce57;
  // A 650-network program's fingerprint is ~0.5 MB: hashed in pieces, with a yield point between
  // them (the worker's scans that fall due run there during an online change).
  for (let start = 0; start < fingerprint.length; start += HASH_PIECE) {
    if (start > 0) yieldPoint();
    const end = Math.min(fingerprint.length, start + HASH_PIECE);
    for (let i = start; i < end; i++) {
      const c = fingerprint.charCodeAt(i);
      h1 = Math.imul(h1 ^ c, 2654435761);
      h2 = Math.imul(h2 ^ c, 1597334677);
    }
  }
  h1 = Math.imul(h1 ^ (h1 >>> 16), 2246822507) ^ Math.imul(h2 ^ (h2 >>> 13), 3266489909);
  h2 = Math.imul(h2 ^ (h2 >>> 16), 2246822507) ^ Math.imul(h1 ^ (h1 >>> 13), 3266489909);
  return `${(4294967296 * (2097151 & h2) + (h1 >>> 0)).toString(36)}-${fingerprint.length.toString(36)}`;
}

const ids = new WeakMap<Project, string>();

/** The program id of a document (cached per document object: documents are immutable). */
export function programId(project: Project): string {
  let id = ids.get(project);
  if (id === undefined) {
    id = fingerprintId(programFingerprint(project));
    ids.set(project, id);
  }
  return id;
}
