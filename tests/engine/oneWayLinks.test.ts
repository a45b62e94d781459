// LD-SEMANTICS section 1: a vertical link's state is the OR of what is attached on its left, copied
// to what is attached on its right, never back to its left. A line that fans out and then runs
// into two different ORs (X := A; Y := A OR B, or X := T1.Q OR B; Y := T1.Q OR C) is legal IEC,
// and MATIEC runs it so; the grid draws it, and it runs with each coil getting only what reaches
// it from its left.
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { buildGraph } from '../../src/engine/compile/graph';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { explain, liveScanView } from '../../src/engine/explain';
import type { Profile } from '../../src/model/project';
import { ladder, plcOf, project, trace, vars } from './ladder';

const V = vars('A BOOL', 'B BOOL', 'C BOOL', 'X BOOL', 'Y BOOL', 'T1 TON');

// A's line fans out on boundary 1: row 1 runs on into the bar where B joins Y's line; row 0 runs to X.
//   |--[A]--+------( X )
//   |       +--+---( Y )
//   |--+[B]----+
const FAN_THEN_OR = ['[A] + - (X)', '. + - + (Y)', '- [B] + .'];

// T1.Q fans out on bar 4 (rows 1 to 3) into two ORs: X := T1.Q OR B (bar 5, rows 0-1) and
// Y := T1.Q OR C (bar 5, rows 3-4).
//   |--------[B]--+--( X )
//   |--[A]-[T1]-Q-+--+
//   |             |
//   |             +--+--( Y )
//   |--------[C]-----+
const Q_INTO_TWO_ORS = () =>
  ladder(['- - - - [B] + (X)', '[A] # # - + - + .', '. # # . + . .', '. . . . + - + (Y)', '- - - - [C] + .'], {
    boxes: [{ row: 1, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#20ms' } }],
  });

describe('one-way vertical links', () => {
  test.each<Profile>(['iec', 'openplc'])('a fan-out into an OR: X gets A only, Y gets A OR B (%s)', (profile) => {
    const p = project(V, [ladder(FAN_THEN_OR)], profile);
    expect(checkProject(p).filter((d) => d.severity === 'error')).toEqual([]);
    const plc = plcOf(p);
    const steps = [
      { A: false, B: false },
      { A: false, B: true },
      { A: true, B: false },
      { A: true, B: true },
    ];
    expect(trace(plc, steps, ['X', 'Y'])).toEqual([
      [0, 0],
      [0, 1],
      [1, 1],
      [1, 1],
    ]);
  });

  test('the graph splits the wire in two nets joined one way, and lights each part with its own state', () => {
    const net = ladder(FAN_THEN_OR);
    const g = buildGraph(net);
    expect(g.bridges).toHaveLength(1);
    const x = g.nodes.find((n) => n.el.kind === 'coil' && n.el.variable === 'X')!;
    const y = g.nodes.find((n) => n.el.kind === 'coil' && n.el.variable === 'Y')!;
    expect(x.inputs[0]!.net).not.toBe(y.inputs[0]!.net);
    expect(g.bridges[0]).toMatchObject({ from: x.inputs[0]!.net, to: y.inputs[0]!.net });

    const p = project(V, [net]);
    const { program } = compileProgram(p);
    const plc = createPlc(program!, { cycleMs: 10 });
    plc.write('B', true);
    plc.scan();
    const power = plc.snapshot().networks[0]!;
    // Row 1's line (from A's bar) is dark; the bar where B joins and Y's coil are lit.
    const link = net.elements.findIndex((e) => e.kind === 'link' && e.row === 1 && e.col === 1);
    expect(power.elements[link]! & 1).toBe(0);
    const vlinkB = net.vlinks.findIndex((v) => v.boundary === 2);
    const vlinkA = net.vlinks.findIndex((v) => v.boundary === 1);
    expect([power.vlinks[vlinkA], power.vlinks[vlinkB]]).toEqual([0, 1]);
    expect(plc.read('X')).toBe(false);
    expect(plc.read('Y')).toBe(true);
    // Why? on Y names B's path; on X, A's contact blocks.
    const pou = p.pous[0]!;
    const why = (variable: string) =>
      explain(program!, pou, liveScanView(plc, program!), {
        kind: 'element',
        network: 0,
        element: net.elements.findIndex((e) => e.kind === 'coil' && e.variable === variable),
      }).lines.join('\n');
    expect(why('Y')).toMatch(/Y is energised through \| \| B/);
    // X has one path only (A's): B's line does not reach it.
    expect(why('X')).toMatch(/X gets no power: 1 path from the left rail could energise it/);
    expect(why('X')).toMatch(/A is open: A is FALSE/);
  });

  test.each<Profile>(['iec', 'openplc'])('one block output into two ORs: X := T1.Q OR B, Y := T1.Q OR C (%s)', (profile) => {
    const p = project(V, [Q_INTO_TWO_ORS()], profile);
    expect(checkProject(p).filter((d) => d.severity === 'error').map((d) => d.message)).toEqual([]);
    const plc = plcOf(p);
    let differ = 0;
    let seed = 7;
    const bit = () => ((seed = (seed * 1103515245 + 12345) & 0x7fffffff) >> 16) % 2 === 1;
    for (let scan = 0; scan < 60; scan++) {
      const [a, b, c] = [scan % 10 < 6, bit(), bit()];
      plc.write('A', a);
      plc.write('B', b);
      plc.write('C', c);
      plc.scan();
      const q = plc.read('T1.Q') === true;
      expect([plc.read('X'), plc.read('Y')], `scan ${scan + 1}`).toEqual([q || b, q || c]);
      if (plc.read('X') !== plc.read('Y')) differ++;
    }
    expect(differ).toBeGreaterThan(5);
  });

  test.each<Profile>(['iec', 'openplc'])('a line from an open contact to an OR bar is drawn dark while the OR is lit (a link shows its left side; %s)', (profile) => {
    const net = ladder(['[A] - + (X)', '[B] - + .']);
    const p = project(V, [net], profile);
    const { program } = compileProgram(p);
    const plc = createPlc(program!, { cycleMs: 10 });
    const linkOn = (row: number) => {
      const k = net.elements.findIndex((e) => e.kind === 'link' && e.row === row);
      return plc.snapshot().networks[0]!.elements[k]! & 1;
    };
    plc.write('A', true);
    plc.scan();
    expect([linkOn(0), linkOn(1), plc.snapshot().networks[0]!.vlinks[0]]).toEqual([1, 0, 1]);
    plc.write('A', false);
    plc.write('B', true);
    plc.scan();
    expect([linkOn(0), linkOn(1), plc.snapshot().networks[0]!.vlinks[0]]).toEqual([0, 1, 1]);
  });

  test('a line fed only from its right is still refused (LD-R01): a U-turn carries nothing', () => {
    const p = project(V, [ladder(['[A] [B] + . .', '. + - + . .', '. + - - - (X)'])]);
    const d = checkProject(p).find((x) => x.rule === 'LD-R01');
    expect(d?.message).toMatch(/coil "?X"? is fed from its right/i);
  });
});
