// Wires the ladder grid cannot route without crossing are drawn through IEC connector/continuation
// pairs (>NAME>): the graph the engine compiles is the file's, nothing is reported as redrawn, and the
// program runs as the file says. Fixtures: an LD crossing (first_steps' CounterLD shape), an FBD body
// whose wires cross (converted to LD), and a file with its own connector pairs.
import { describe, expect, it } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { Project } from '../../src/model/project';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { trace as ladderTrace } from '../engine/ladder';
import { trace } from './behaviour';
import { canonical, fixture, imported, run } from './fixtures';
import { graphOf } from './ldXml';

const pairs = (project: Project) =>
  project.pous[0]!.networks.flatMap((n) => n.elements).flatMap((e) =>
    e.kind === 'connector' || e.kind === 'continuation' ? [`${e.kind} ${e.name}`] : [],
  );

/** Export and import again: the same graph and the same 100-scan trace (pairs drawn again where needed). */
function roundTrip(project: Project): void {
  const again = importPlcopen(exportPlcopen(project));
  if (!again.ok) throw new Error(JSON.stringify(again.errors));
  expect(graphOf(again.project)).toEqual(graphOf(project));
  expect(pairs(again.project).length).toBeGreaterThan(0);
  expect(trace(again.project, 'Main', 100)).toEqual(trace(project, 'Main', 100));
}

const COUNTER = [
  'box:ADD:.EN <- rail',
  'box:SEL:.G <- contact:NO:Reset.OUT',
  'box:SEL:.IN0 <- box:ADD:.OUT',
  'contact:NO:Reset.IN <- rail',
];
/** Cnt := SEL(Reset, Cnt + 1, 0), scan by scan. */
const COUNTS = {
  steps: [{ Reset: false }, { Reset: false }, { Reset: false }, { Reset: true }, { Reset: false }],
  cnt: [[1], [2], [3], [0], [1]],
};

describe('connector pairs where the grid cannot route a wire', () => {
  it('LD: the Reset contact below ADD feeds SEL.G through a connector pair; exact, clean, runs', () => {
    const { project, report } = imported('conn-crossing.xml');
    expect(report.warnings).toEqual([]);
    expect(graphOf(project)).toEqual(COUNTER);
    const drawn = pairs(project);
    expect(drawn.filter((p) => p.startsWith('connector')).length).toBeGreaterThan(0);
    for (const p of drawn) expect(drawn).toContain(p.replace(/^\w+/, (k) => (k === 'connector' ? 'continuation' : 'connector')));
    expect(checkProject(project)).toEqual([]);
    expect(ladderTrace(run(project, 'Main'), COUNTS.steps, ['Cnt'])).toEqual(COUNTS.cnt);
    roundTrip(project);
  });

  it('FBD: crossing wires between a CTU and a SEL, a negated input: converted to LD exactly, runs', () => {
    const { project, report } = imported('conn-fbd-crossing.xml');
    expect(report.warnings.map((w) => w.message)).toEqual([
      'POU "Main" was converted from FBD to LD (2 networks, every wire kept)',
    ]);
    expect(project.pous[0]!.language).toBe('LD');
    expect(graphOf(project)).toEqual([
      'box:AND:.EN <- rail',
      'box:AND:.IN2 <- contact:NC:Stop.OUT',
      'box:GE:.IN1 <- box:CTU:C1.CV',
      'box:SEL:.G <- box:GE:.OUT',
      'box:SEL:.IN0 <- box:CTU:C1.Q',
      'box:TON:T1.IN <- box:AND:.OUT',
      'contact:NC:Stop.IN <- rail',
    ]);
    expect(pairs(project).length).toBeGreaterThan(0);
    expect(checkProject(project)).toEqual([]);
    // Out = C1.CV >= 2 ? Stop : C1.Q (C1 counts Pulse up to PV 3); Run = Start AND NOT Stop.
    const steps: Record<string, boolean>[] = [
      { Pulse: true, Start: true },
      { Pulse: false },
      { Pulse: true },
      { Pulse: false, Stop: true },
      { Pulse: true, Stop: false },
      { Clear: true },
    ];
    expect(ladderTrace(run(project, 'Main'), steps, ['Out', 'Run'])).toEqual([
      [0, 1],
      [0, 1],
      [0, 1],
      [1, 0],
      [0, 1],
      [0, 1],
    ]);
    const plc = run(project, 'Main');
    expect(ladderTrace(plc, [{ Start: true }, {}, {}, {}, {}, {}], ['Done']).at(-1)).toEqual([1]);
    roundTrip(project);
  });

  it("the file's own connector pairs: wires where they route, the file's names where a pair is drawn", () => {
    const { project, report } = imported('conn-explicit.xml');
    expect(report.warnings).toEqual([]);
    expect(graphOf(project)).toEqual([...COUNTER, 'coil:COIL:Lamp.IN <- contact:NO:Reset.OUT'].sort());
    const names = pairs(project).map((p) => p.split(' ')[1]!);
    expect(names.some((n) => n === 'RST' || n === 'LAMP')).toBe(true);
    expect(checkProject(project)).toEqual([]);
    expect(ladderTrace(run(project, 'Main'), COUNTS.steps, ['Cnt', 'Lamp'])).toEqual(
      COUNTS.cnt.map(([c], k) => [c!, COUNTS.steps[k]!.Reset ? 1 : 0]),
    );
    roundTrip(project);
  });

  it.each(['conn-crossing.xml', 'conn-fbd-crossing.xml', 'conn-explicit.xml'])(
    '%s: the same drawing in every batch size, with or without shared layouts',
    (name) => {
      const text = fixture(name);
      const base = importPlcopen(text);
      const plain = importPlcopen(text, { batchObjects: 1, shareLayouts: false });
      if (!base.ok || !plain.ok) throw new Error('import');
      expect(canonical(plain.project)).toBe(canonical(base.project));
    },
  );
});
