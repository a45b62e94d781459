// A PLC's memory copied whole and put back (PlcProbe.save/restore), for replaying recorded scans on
// a second PLC of the same compiled program (the scan history, src/sim/replay.ts). FB instances go
// through their own saveState/loadState with absolute times (time base 0): the replaying PLC runs
// at the recorded PLC times, so timers' start times carry over as they are.
import type { PlcImage } from '../api';
import type { FbState } from '../library/fbBase';
import type { Memory } from './memory';

export interface MemoryImage {
  readonly b: Uint8Array;
  readonly n: Float64Array;
  readonly g: Memory['g'];
  readonly fbs: readonly FbState[];
  readonly edges: Uint8Array;
}

export function saveMemory(mem: Memory): MemoryImage {
  return { b: mem.b.slice(), n: mem.n.slice(), g: mem.g.slice(), fbs: mem.fbs.map((fb) => fb.saveState(0)), edges: mem.edges.slice() };
}

export function restoreMemory(mem: Memory, image: MemoryImage): void {
  mem.b.set(image.b);
  mem.n.set(image.n);
  for (let i = 0; i < image.g.length; i++) mem.g[i] = image.g[i]!;
  mem.fbs.forEach((fb, i) => {
    fb.reset();
    fb.loadState(image.fbs[i]!, 0);
  });
  mem.edges.set(image.edges);
}

/** Estimated bytes of a memory image and of `extra` further 8-byte slots (for history budgets). */
export function imageBytes(image: MemoryImage, extra: number): number {
  let fbFields = 0;
  for (const f of image.fbs) for (const _ in f) fbFields++;
  return 64 + image.b.length + image.n.length * 8 + image.g.length * 16 + fbFields * 24 + image.edges.length + extra * 8;
}

/** What a PLC keeps beside its memory (scanner.ts fills it). */
export interface MachineImage<V, F> extends PlcImage {
  readonly mem: MemoryImage;
  readonly power: Int32Array;
  readonly ranIn: Int32Array;
  readonly inputs: readonly V[];
  readonly outputs: readonly V[];
  readonly forces: readonly F[];
}
