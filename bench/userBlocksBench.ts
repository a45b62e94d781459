// Programs for bench:engine's user-FB case: N calls of a 3-network Motor FB against the same logic
// written inline (3 networks per motor), with the same variables and results.
import { compileProgram, createPlc } from '../src/engine/plc';
import type { LdElement } from '../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../src/model/factory';
import type { ElementId } from '../src/model/ids';
import type { Network, Project, Variable } from '../src/model/project';

let ids = 0;
const id = (): ElementId => `b${++ids}` as ElementId;
const contact = (row: number, col: number, v: string, nc = false): LdElement => ({ id: id(), kind: 'contact', row, col, contact: nc ? 'NC' : 'NO', variable: v });
const coil = (row: number, col: number, v: string): LdElement => ({ id: id(), kind: 'coil', row, col, coil: 'COIL', variable: v });
const link = (row: number, col: number): LdElement => ({ id: id(), kind: 'link', row, col });

/** The Motor logic over variable names: seal-in, an on-delay, a permissive. */
function motorNetworks(n: { start: string; stop: string; run: string; timer: string; ready: string; fault: string; out: string }): Network[] {
  return [
    // Run := (Start OR Run) AND NOT Stop
    newNetwork({
      rows: 2,
      cols: 4,
      elements: [contact(0, 0, n.start), contact(0, 1, n.stop, true), link(0, 2), coil(0, 3, n.run), contact(1, 0, n.run)],
      vlinks: [{ row: 0, boundary: 0 }, { row: 0, boundary: 1 }],
    }),
    // Ready := TON(IN := Run, PT := T#50ms).Q
    newNetwork({
      rows: 2,
      cols: 4,
      elements: [
        contact(0, 0, n.run),
        { id: id(), kind: 'box', row: 0, col: 1, blockType: 'TON', instance: n.timer, inputs: { PT: 'T#50ms' }, outputs: {} },
        coil(0, 3, n.ready),
      ],
      vlinks: [],
    }),
    // Out := Ready AND NOT Fault
    newNetwork({ rows: 1, cols: 3, elements: [contact(0, 0, n.ready), contact(0, 1, n.fault, true), coil(0, 2, n.out)], vlinks: [] }),
  ];
}

const v = (name: string, type: string, varClass: Variable['varClass'] = 'local') => variable(name, type, { varClass });

/** Inputs every motor reads: Start cycles with the scan count (the bench drives Tick). */
export function inlineProject(count: number): Project {
  const variables: Variable[] = [v('Tick', 'BOOL'), v('Stop', 'BOOL'), v('Fault', 'BOOL')];
  const networks: Network[] = [];
  for (let k = 0; k < count; k++) {
    variables.push(v(`Run${k}`, 'BOOL'), v(`T${k}`, 'TON'), v(`Ready${k}`, 'BOOL'), v(`Out${k}`, 'BOOL'));
    networks.push(...motorNetworks({ start: 'Tick', stop: 'Stop', run: `Run${k}`, timer: `T${k}`, ready: `Ready${k}`, fault: 'Fault', out: `Out${k}` }));
  }
  return newProject('Inline', { pous: [newPou('Main', { variables, networks })] });
}

export function fbProject(count: number): Project {
  const motor = newPou('Motor', {
    kind: 'FUNCTION_BLOCK',
    variables: [
      v('Start', 'BOOL', 'input'),
      v('Stop', 'BOOL', 'input'),
      v('Fault', 'BOOL', 'input'),
      v('Out', 'BOOL', 'output'),
      v('Run', 'BOOL'),
      v('Ready', 'BOOL'),
      v('T', 'TON'),
    ],
    networks: motorNetworks({ start: 'Start', stop: 'Stop', run: 'Run', timer: 'T', ready: 'Ready', fault: 'Fault', out: 'Out' }),
  });
  const variables: Variable[] = [v('Tick', 'BOOL'), v('Stop', 'BOOL'), v('Fault', 'BOOL')];
  const networks: Network[] = [];
  for (let k = 0; k < count; k++) {
    variables.push(v(`M${k}`, 'Motor'), v(`Out${k}`, 'BOOL'));
    networks.push(
      newNetwork({
        rows: 3,
        cols: 3,
        elements: [
          contact(0, 0, 'Tick'),
          { id: id(), kind: 'box', row: 0, col: 1, blockType: 'Motor', instance: `M${k}`, inputs: { Stop: 'Stop', Fault: 'Fault' }, outputs: { Out: `Out${k}` } },
        ],
        vlinks: [],
      }),
    );
  }
  return newProject('Calls', { pous: [newPou('Main', { variables, networks }), motor] });
}

/**
 * µs per scan of two motor programs (best of five rounds after `warmMs` of alternating warm-up,
 * Tick toggled every 8 scans) and how many of the `count` motors' outputs differ at the end.
 */
export function compareMotorPrograms(
  a: Project,
  b: Project,
  count: number,
  warmMs: number,
): { usA: number; usB: number; mismatches: number } {
  const make = (p: Project) => {
    const { program, diagnostics } = compileProgram(p);
    if (!program) throw new Error(`bench program does not compile: ${diagnostics[0]?.message}`);
    return createPlc(program, { cycleMs: 10, maxScanMs: 60_000 });
  };
  const plcA = make(a);
  const plcB = make(b);
  let k = 0;
  const run = (plc: ReturnType<typeof make>, scans: number, from: number): number => {
    const t = performance.now();
    for (let s = 0; s < scans; s++) {
      plc.write('Tick', ((from + s) >> 3) % 2 === 0);
      plc.scan();
    }
    return (performance.now() - t) / scans;
  };
  const scans = Math.max(200, Math.round(400_000 / count));
  const started = performance.now();
  while (performance.now() - started < warmMs) {
    run(plcA, scans, k);
    run(plcB, scans, k);
    k += scans;
  }
  let bestA = Infinity;
  let bestB = Infinity;
  for (let round = 0; round < 5; round++) {
    bestA = Math.min(bestA, run(plcA, scans, k));
    bestB = Math.min(bestB, run(plcB, scans, k));
    k += scans;
  }
  let mismatches = 0;
  for (let m = 0; m < count; m++) if (plcA.read(`Out${m}`) !== plcB.read(`Out${m}`)) mismatches++;
  return { usA: bestA * 1000, usB: bestB * 1000, mismatches };
}
