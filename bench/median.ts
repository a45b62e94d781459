// Median wall time of a function over several runs, for the Node-side figures of the benchmarks.

/** Median time of `fn` over `runs` runs, in ms. */
export function median(runs: number, fn: () => void): number {
  const t: number[] = [];
  for (let i = 0; i < runs; i++) {
    const t0 = performance.now();
    fn();
    t.push(performance.now() - t0);
  }
  return t.sort((a, b) => a - b)[Math.floor(runs / 2)]!;
}
