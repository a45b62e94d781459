// Yield points: long engine work (compiling and preparing a program, network by network) calls
// yieldPoint() between networks. The simulator sets a hook while it compiles an online change on
// the thread that also scans: the hook runs the scans that fell due, so a compile never delays a
// scan (src/sim/session.ts). Outside withYieldPoints a yield point does nothing.

let hook: (() => void) | undefined;

/** Runs `work` with `onYield` called at every yield point inside it (nested: the inner hook, then the outer one). */
export function withYieldPoints<T>(onYield: () => void, work: () => T): T {
  const outer = hook;
  hook = outer
    ? () => {
        onYield();
        outer();
      }
    : onYield;
  try {
    return work();
  } finally {
    hook = outer;
  }
}

/** Between two pieces of long work (a network lowered, a network's code generated). */
export function yieldPoint(): void {
  hook?.();
}
