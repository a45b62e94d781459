// An online change's compile runs on the thread that scans, and the scans that fall due meanwhile
// run at its yield points (engine/yieldPoint.ts, sim/session.ts). Besides lowering a network at a
// time, the work over the whole program gives way too: the document's fingerprint (a yield point
// every 64 networks), the symbol table (every 64 declarations) and the call graph (every 64
// networks). Without them a 1,000-network program ran 10-25 ms in one stretch in the browser's
// worker, and a scan at 10 ms came a cycle late. Each gives way without changing its result.
import { describe, expect, test } from 'vitest';
import { withYieldPoints } from '../../src/engine/yieldPoint';
import { buildSymbols } from '../../src/engine/compile/pouSymbols';
import { usesOf } from '../../src/engine/compile/callGraph';
import { Reporter } from '../../src/engine/compile/report';
import type { Diagnostic } from '../../src/engine/api';
import { compileProgram } from '../../src/engine/plc';
import { blockLibrary } from '../../src/model/library';
import { variable } from '../../src/model/factory';
import { programFingerprint } from '../../src/sim/layout';
import { sealInProject } from '../e2e/sealInProject';

const NETWORKS = 1000;
const project = (() => {
  const p = sealInProject(NETWORKS);
  // 200 globals besides the program's 4,000 variables.
  return { ...p, globals: Array.from({ length: 200 }, (_, i) => variable(`G${i}`, 'INT')) };
})();
const main = project.pous[0]!;

function counted<T>(work: () => T): { result: T; yields: number } {
  let yields = 0;
  const result = withYieldPoints(() => yields++, work);
  return { result, yields };
}

describe('the compile of a large program gives way to due scans', () => {
  test('the fingerprint: a yield point every 64 networks, the same text', () => {
    const { result, yields } = counted(() => programFingerprint(project));
    expect(yields).toBe(Math.floor(NETWORKS / 64));
    expect(result).toBe(programFingerprint(project));
  });

  test('the symbol table: a yield point every 64 declarations, every variable and global declared', () => {
    const table = () => {
      const out: Diagnostic[] = [];
      const r = new Reporter(out, main.name, -1);
      return { table: buildSymbols(project, main, r, r, blockLibrary(project)), out };
    };
    const { result, yields } = counted(table);
    expect(main.variables.length).toBe(4 * NETWORKS);
    expect(yields).toBe(Math.floor((main.variables.length + project.globals!.length) / 64));
    expect(result.out).toEqual(table().out);
    for (const name of ['Start0', `Motor${NETWORKS - 1}`, 'G0', 'G199']) expect(result.table.lookup(name)?.name.toUpperCase()).toBe(name.toUpperCase());
  });

  test('the call graph: a yield point every 64 networks, the same uses', () => {
    const { result, yields } = counted(() => usesOf(project, main));
    expect(yields).toBe(Math.floor(NETWORKS / 64));
    expect(result).toEqual(usesOf(project, main));
  });

  test('the whole compile: the same program with yield points as without, and they come often', () => {
    const { result, yields } = counted(() => compileProgram(project));
    const plain = compileProgram(project);
    expect(result.diagnostics).toEqual(plain.diagnostics);
    expect(result.program).toBeDefined();
    // Two per network (started, lowered) at least, plus the pieces above.
    expect(yields).toBeGreaterThan(2 * NETWORKS + 3 * Math.floor(NETWORKS / 64));
  });
});
