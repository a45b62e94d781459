// Profile `openplc`: blocks and outVariables with a PLCopen executionOrderId (BoxElement.executionOrder,
// outputOrders) run as Beremiz's and OpenPLC's generator runs them (PLCGenerator.py ComputeProgram:
// orderedInstances first, in id order, before every coil of the POU body; GenerateBlock traces an
// ordered block's inputs with `order` set: the blocks upstream not called yet are not called, their
// stored outputs are read). Each case runs under both profiles and without the ids; the comment
// gives the ST the generator writes. Profile `iec` ignores the ids (IEC 61131-3 defines none for LD).
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { compileProgram } from '../../src/engine/plc';
import { explain, liveScanView } from '../../src/engine/explain';
import { ScanPlc } from '../../src/engine/runtime/scanner';
import { DEFAULT_TIERING } from '../../src/engine/runtime/tiering';
import { withoutExecutionOrder } from '../../src/model/elements';
import type { Network, Profile, Variable } from '../../src/model/project';
import { io, multiProject, pou } from './userBlocksHelpers';
import { ladder, plcOf, project, trace, vars } from './ladder';

type Steps = readonly Record<string, boolean | number>[];

const strip = (networks: readonly Network[]): Network[] =>
  networks.map((n) => ({ ...n, elements: n.elements.map(withoutExecutionOrder) }));

/** Traces under iec and openplc, with the ids and without them. */
function runs(variables: readonly Variable[], networks: readonly Network[], steps: Steps, names: readonly string[]) {
  const run = (nets: readonly Network[], profile: Profile) => trace(plcOf(project(variables, nets, profile)), steps, names);
  return {
    iec: run(networks, 'iec'),
    iecWithout: run(strip(networks), 'iec'),
    openplc: run(networks, 'openplc'),
    openplcWithout: run(strip(networks), 'openplc'),
  };
}

const dispatchOnly = { ...DEFAULT_TIERING, startAfterEvals: Infinity };
const switchAtOnce = { ...DEFAULT_TIERING, startAfterEvals: 0, minScans: 1, msPerNetwork: 0, batch: 1 };

describe('openplc: instances with an executionOrderId run before every coil of the POU body', () => {
  const V = vars('Run BOOL', 'Lamp BOOL', 'T1 TON');
  // Network 1 reads T1.Q; network 2 holds T1 (id 1), whose output reaches only the rail.
  const networks = [
    ladder(['[T1.Q] (Lamp)']),
    ladder(['[Run] # # -', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#20ms' }, executionOrder: 1 }] }),
  ];

  test('an FB of a later network with an id runs before the coil above it: the lamp follows T1.Q in the same scan', () => {
    // T1(IN := Run, PT := T#20ms);   (* orderedInstances: before every coil *)
    // Lamp := T1.Q;
    const t = runs(V, networks, [{ Run: true }, {}, {}, {}], ['T1.Q', 'Lamp']);
    expect(t.openplc).toEqual([[0, 0], [0, 0], [1, 1], [1, 1]]);
    // Without the id T1 runs after every coil (no coil needs it): the lamp is one scan late.
    expect(t.openplcWithout).toEqual([[0, 0], [0, 0], [1, 0], [1, 1]]);
    // iec: networks in order, the id ignored.
    expect(t.iec).toEqual([[0, 0], [0, 0], [1, 0], [1, 1]]);
    expect(t.iec).toEqual(t.iecWithout);
  });

  test('the early FB runs on the dispatch loops and on straight-line code alike, and shows its powered input', () => {
    const { program } = compileProgram(project(V, networks, 'openplc'));
    expect(program!.networks[0]!.runEarly).toEqual([[1, 0]]);
    expect(program!.networks[1]!.ops.some((op) => op.op === 'fb')).toBe(false);
    for (const tiering of [dispatchOnly, switchAtOnce]) {
      const plc = new ScanPlc(program!, { cycleMs: 10 }, tiering);
      plc.write('Run', true);
      const rows = Array.from({ length: 4 }, () => (plc.scan(), [plc.read('T1.Q'), plc.read('Lamp')].map(Number)));
      expect(rows).toEqual([[0, 0], [0, 0], [1, 1], [1, 1]]);
      // The power display: the contact before T1 (in network 2) is powered.
      const contact = networks[1]!.elements.findIndex((e) => e.kind === 'contact');
      expect(plc.snapshot().networks[1]!.elements[contact]! & 2).toBe(2);
    }
  });

  test('forcing the variable an early FB reads, and stepping over the network that runs it', () => {
    const { program } = compileProgram(project(V, networks, 'openplc'));
    const plc = new ScanPlc(program!, { cycleMs: 10 }, dispatchOnly);
    plc.force('Run', true);
    plc.scans(3);
    expect([plc.read('T1.Q'), plc.read('Lamp')]).toEqual([true, true]);
    plc.unforce('Run');
    plc.write('Run', false);
    // A step runs network 1 with the early T1 before it: T1.Q drops and the lamp with it.
    const r = plc.stepNetwork({ into: true });
    expect(r.scanDone).toBe(false);
    expect([plc.read('T1.Q'), plc.read('Lamp')]).toEqual([false, false]);
  });

  test('Why? on the early FB explains its powered input', () => {
    const p = project(V, networks, 'openplc');
    const { program } = compileProgram(p);
    const plc = new ScanPlc(program!, { cycleMs: 10 }, dispatchOnly);
    plc.write('Run', true);
    plc.scans(3);
    const box = networks[1]!.elements.findIndex((e) => e.kind === 'box');
    const why = explain(program!, p.pous[0]!, liveScanView(plc, program!), { kind: 'element', network: 1, element: box });
    expect(why.lines.join('\n')).toMatch(/T1\.Q is TRUE: .*IN is TRUE/);
  });
});

describe('openplc: an ordered block reads the stored outputs of blocks that have not run yet', () => {
  test('a data line: INT_TO_REAL (id 1) reads C1.CV before C1 (id 2) counts: R follows CV one scan late', () => {
    // _TMP_INT_TO_REAL4_OUT := INT_TO_REAL(EN := TRUE, IN := C1.CV);   (* id 1: C1 not called *)
    // C1(CU := Pulse, PV := 100);                                      (* id 2 *)
    // R := _TMP_INT_TO_REAL4_OUT;                                      (* the outVariable, by position *)
    const V = vars('Pulse BOOL', 'R REAL', 'C1 CTU');
    const net = ladder(['[Pulse] # # . # # .', '. # # - # # .', '. # # . . . .'], {
      boxes: [
        { row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { PV: '100' }, executionOrder: 2 },
        { row: 0, col: 4, type: 'INT_TO_REAL', outputs: { OUT: 'R' }, executionOrder: 1 },
      ],
    });
    // The line at row 1, column 3 joins C1.CV to IN of INT_TO_REAL.
    const steps = [{ Pulse: true }, { Pulse: false }, { Pulse: true }, { Pulse: false }, { Pulse: true }];
    const t = runs(V, [net], steps, ['C1.CV', 'R']);
    expect(t.openplcWithout).toEqual([[1, 1], [1, 1], [2, 2], [2, 2], [3, 3]]);
    expect(t.openplc).toEqual([[1, 0], [1, 1], [2, 1], [2, 2], [3, 2]]);
    expect(t.iec).toEqual(t.openplcWithout);
    expect(t.iec).toEqual(t.iecWithout);
  });

  test('power flow: R1 (id 1) reads the inverting contact\'s stored result, which runs after every coil', () => {
    // R_TRIG1 is R1; the inverting contact is a NOT block no statement needs once R1 has run:
    // R1(CLK := _TMP_NOT2_OUT);          (* id 1: NOT not called, its last result read *)
    // Y := R1.Q;
    // _TMP_NOT2_OUT := NOT(A);           (* blocks no coil needed, after every coil *)
    const V = vars('A BOOL', 'Y BOOL', 'R1 R_TRIG');
    const net = ladder(['[A] [NOT] # # (Y)'], { boxes: [{ row: 0, col: 2, type: 'R_TRIG', instance: 'R1', executionOrder: 1 }] });
    const t = runs(V, [net], [{}, {}, {}], ['Y']);
    expect(t.openplc).toEqual([[0], [1], [0]]);
    expect(t.openplcWithout).toEqual([[1], [0], [0]]);
    expect(t.iec).toEqual([[1], [0], [0]]);
  });

  test('a data line from a function of a generic type: called first, with LD-W23', () => {
    const V = vars('N INT', 'M INT', 'K INT');
    const net = ladder(['. # # . # # .', '. # # - # # .'], {
      boxes: [
        { row: 0, col: 1, type: 'ADD', inputs: { IN1: 'N', IN2: '1' } },
        { row: 0, col: 4, type: 'ADD', inputs: { IN2: '10' }, outputs: { OUT: 'M' }, executionOrder: 1 },
      ],
    });
    const p = project(V, [net], 'openplc');
    expect(checkProject(p).filter((d) => d.rule === 'LD-W23')).toHaveLength(1);
    expect(checkProject(project(V, [net], 'iec')).some((d) => d.rule === 'LD-W23')).toBe(false);
    const plc = plcOf(p);
    plc.write('N', 5);
    plc.scan();
    expect(plc.read('M')).toBe(16);
  });
});

describe('openplc: an outVariable with an executionOrderId', () => {
  test('M := R1.Q (id 1) runs before the coil above it, calling R1 first', () => {
    // M := R1.Q;   (* ordered outVariable: R1(CLK := Run) generated first *)
    // Y := M;
    const V = vars('Run BOOL', 'M BOOL', 'Y BOOL', 'R1 R_TRIG');
    const networks = [
      ladder(['[M] (Y)']),
      ladder(['[Run] # # .'], { boxes: [{ row: 0, col: 1, type: 'R_TRIG', instance: 'R1', outputs: { Q: 'M' }, outputOrders: { Q: 1 } }] }),
    ];
    const t = runs(V, networks, [{ Run: true }, {}, {}], ['M', 'Y']);
    expect(t.openplc).toEqual([[1, 1], [0, 0], [0, 0]]);
    expect(t.openplcWithout).toEqual([[1, 0], [0, 1], [0, 0]]);
    expect(t.iec).toEqual(t.openplcWithout);
    // Forced, M is not written by its early statement (on both kinds of code), and is again once unforced.
    const { program } = compileProgram(project(V, networks, 'openplc'));
    for (const tiering of [dispatchOnly, switchAtOnce]) {
      const plc = new ScanPlc(program!, { cycleMs: 10 }, tiering);
      plc.force('M', false);
      plc.write('Run', true);
      plc.scan();
      expect([plc.read('R1.Q'), plc.read('M'), plc.read('Y')]).toEqual([true, false, false]);
      plc.unforce('M');
      plc.write('Run', false);
      plc.scan();
      plc.write('Run', true);
      plc.scan();
      expect([plc.read('M'), plc.read('Y')]).toEqual([true, true]);
    }
  });

  test('ids order the instances over the whole body, not network by network', () => {
    // M := R1.Q; (id 1, network 2)   Y := M AND ...: T copies M before R2 runs (id 2, network 1)
    // R2(CLK := M);  (* id 2 *)
    // Z := R2.Q;
    const V = vars('Run BOOL', 'M BOOL', 'Z BOOL', 'R1 R_TRIG', 'R2 R_TRIG');
    const networks = [
      ladder(['[M] # # (Z)'], { boxes: [{ row: 0, col: 1, type: 'R_TRIG', instance: 'R2', executionOrder: 2 }] }),
      ladder(['[Run] # # .'], { boxes: [{ row: 0, col: 1, type: 'R_TRIG', instance: 'R1', outputs: { Q: 'M' }, outputOrders: { Q: 1 } }] }),
    ];
    const { program } = compileProgram(project(V, networks, 'openplc'));
    expect(program!.networks[0]!.runEarly).toEqual([[1, 0], [0, 0]]);
    const t = runs(V, networks, [{ Run: true }, {}, {}], ['M', 'Z']);
    expect(t.openplc).toEqual([[1, 1], [0, 0], [0, 0]]);
    expect(t.iec).toEqual([[1, 0], [0, 1], [0, 0]]);
  });
});

describe('openplc: an early block inside a user FB body', () => {
  test('runs at the start of each call of the body, written in place or called', () => {
    // Holder's body: T1(IN := Go, PT := T#20ms) (id 1); Lamp := T1.Q;   Main: H1(Go := Go); Out := H1.Lamp;
    const holder = pou('Holder', 'FUNCTION_BLOCK', [...io('input', 'Go BOOL'), ...io('output', 'Lamp BOOL'), ...vars('T1 TON')], [
      ladder(['[T1.Q] (Lamp)']),
      ladder(['[Go] # # -', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#20ms' }, executionOrder: 1 }] }),
    ]);
    const main = pou('Main', 'PROGRAM', vars('Go BOOL', 'Out BOOL', 'H1 Holder'), [
      ladder(['[Go] # # - (Out)', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'Holder', instance: 'H1', outputs: {} }] }),
    ]);
    for (const profile of ['openplc', 'iec'] as const) {
      const { program, diagnostics } = compileProgram({ ...multiProject([main, holder]), profile });
      if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
      for (const tiering of [dispatchOnly, switchAtOnce]) {
        const plc = new ScanPlc(program, { cycleMs: 10 }, tiering);
        plc.write('Go', true);
        const rows = Array.from({ length: 4 }, () => (plc.scan(), [plc.read('H1.T1.Q'), plc.read('H1.Lamp')].map(Number)));
        expect(rows).toEqual(profile === 'openplc' ? [[0, 0], [0, 0], [1, 1], [1, 1]] : [[0, 0], [0, 0], [1, 0], [1, 1]]);
      }
    }
  });
});
