// A PLC's memory copied whole and put back (PlcProbe.save/restore), for replaying recorded scans on
// a second PLC of the same compiled program (the scan history, src/sim/replay.ts). FB instances go
// through their own saveState/loadState with absolute times (time base 0): the replaying PLC runs
// at the recorded PLC times, so timers' start times carry over as they are.
import type { PlcImage } from '../api';
import type { FbInstance, FbState } from '../library/fbBase';
import type { Memory } from './memory';

export interface MemoryImage {
  readonly b: Uint8Array;
  readonly n: Float64Array;
  readonly g: Memory['g'];
  /** Per FB instance: a copy of its fields (plain instances) or its saveState. */
  readonly fbs: readonly FbState[];
  readonly edges: Uint8Array;
}

/**
 * The fields of an FB instance that hold its state: its plain values (pins, internal state). Other
 * fields are its configuration (counter limits, conversions), the same in every PLC of the program;
 * an instance holding inner FBs (PID) has none here and goes through saveState/loadState instead.
 * Copying fields is far cheaper than saveState, which builds its record key by key.
 */
const stateFields = new WeakMap<FbInstance, readonly string[] | null>();

function fieldsOf(fb: FbInstance): readonly string[] | null {
  let fields = stateFields.get(fb);
  if (fields === undefined) {
    const entries = Object.entries(fb);
    const nested = entries.some(([, v]) => typeof v === 'object' && v !== null && typeof (v as Partial<FbInstance>).saveState === 'function');
    fields = nested ? null : entries.filter(([, v]) => typeof v !== 'object' && typeof v !== 'function').map(([k]) => k);
    stateFields.set(fb, fields);
  }
  return fields;
}

export function saveMemory(mem: Memory): MemoryImage {
  const fbs = mem.fbs.map((fb) => (fieldsOf(fb) ? ({ ...fb } as unknown as FbState) : fb.saveState(0)));
  return { b: mem.b.slice(), n: mem.n.slice(), g: mem.g.slice(), fbs, edges: mem.edges.slice() };
}

export function restoreMemory(mem: Memory, image: MemoryImage): void {
  mem.b.set(image.b);
  mem.n.set(image.n);
  for (let i = 0; i < image.g.length; i++) mem.g[i] = image.g[i]!;
  mem.fbs.forEach((fb, i) => {
    const fields = fieldsOf(fb);
    const saved = image.fbs[i]!;
    if (fields) {
      const target = fb as unknown as Record<string, unknown>;
      for (const k of fields) target[k] = saved[k];
    } else {
      fb.reset();
      fb.loadState(saved, 0);
    }
  });
  mem.edges.set(image.edges);
}

/** Estimated bytes of a memory image (an FB instance taken as 160) and of `extra` further 8-byte slots (for history budgets). */
export function imageBytes(image: MemoryImage, extra: number): number {
  return 64 + image.b.length + image.n.length * 8 + image.g.length * 16 + image.fbs.length * 160 + image.edges.length + extra * 8;
}

/** What a PLC keeps beside its memory (scanner.ts fills it). */
export interface MachineImage<V, F> extends PlcImage {
  readonly mem: MemoryImage;
  readonly power: Int32Array;
  readonly ranIn: Int32Array;
  readonly inputs: readonly V[];
  readonly outputs: readonly V[];
  readonly forces: readonly F[];
  /** What the observed ST/IL bodies did (ScanCycle traces): a replay puts back the live ones. */
  readonly traces?: ReadonlyMap<number, unknown>;
}
