// Beremiz's generator (PLCGenerator.py, ComputeProgram) writes the statements of an LD body's
// coils and output variables in the order of SortInstances over the whole body; the import follows
// it (layoutRows.ts places parallel coils that way; importBody.ts records Network.turns).

/**
 * Beremiz's SortInstances (PLCGenerator.py, with the oracle's port fix): two instances whose tops
 * are less than 10 apart by x, others by y. Positions are read as integers (Python's int()).
 */
export function sortInstances(a: { x: number; y: number }, b: { x: number; y: number }): number {
  const ay = Math.trunc(a.y);
  const by = Math.trunc(b.y);
  return Math.abs(ay - by) < 10 ? Math.trunc(a.x) - Math.trunc(b.x) : ay - by;
}
