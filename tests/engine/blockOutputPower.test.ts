// The power display of a line from a block output (issue 22, section 2 item 9). A horizontal link
// shows its left side (LD-SEMANTICS section 1): the line from TON0.Q to TOF0.IN shows TON0.Q, not
// the block's first BOOL output (its ENO, lit whenever the block runs). Under the openplc profile
// the display took the block's ENO for every line leaving it, so OpenPLC's Blink example showed
// the Q line lit every scan while Q was FALSE.
import { describe, expect, test } from 'vitest';
import type { LdElement } from '../../src/model/elements';
import type { Network, Profile } from '../../src/model/project';
import { ladder, plcOf, project, vars } from './ladder';

const V = vars('Lamp BOOL', 'A BOOL', 'TON0 TON', 'TOF0 TOF');

/** Boxes of a network drawn with EN/ENO pins (PLCopen executionControl), optionally with an execution order. */
function withEn(net: Network, orders: Record<string, number> = {}): Network {
  const elements = net.elements.map((e): LdElement => {
    if (e.kind !== 'box') return e;
    const order = orders[e.instance ?? ''];
    return { ...e, executionControl: true, ...(order ? { executionOrder: order } : {}) };
  });
  return { ...net, elements };
}

// OpenPLC's Blink, drawn with EN/ENO: TON0's ENO feeds TOF0's EN, TON0.Q feeds TOF0.IN, TOF0.Q the lamp.
//   |--------EN[TON0]ENO----EN[TOF0]ENO
//   |--[/Lamp]-IN   Q-------IN      Q---( Lamp )
const BLINK = () =>
  withEn(
    ladder(['- - # # - - # # .', '[/Lamp] - # # - - # # (Lamp)', '. . # # . . # # .'], {
      boxes: [
        { row: 0, col: 2, type: 'TON', instance: 'TON0', inputs: { PT: 'T#50ms' } },
        { row: 0, col: 6, type: 'TOF', instance: 'TOF0', inputs: { PT: 'T#50ms' } },
      ],
    }),
  );

// TON0.Q through a contact into TOF0.IN.
//   |--------EN[TON0]ENO-----EN[TOF0]ENO
//   |--[/Lamp]-IN   Q--[A]--IN      Q---( Lamp )
const THROUGH_CONTACT = () =>
  withEn(
    ladder(['- - # # - - - # # .', '[/Lamp] - # # - [A] - # # (Lamp)', '. . # # . . . # # .'], {
      boxes: [
        { row: 0, col: 2, type: 'TON', instance: 'TON0', inputs: { PT: 'T#50ms' } },
        { row: 0, col: 7, type: 'TOF', instance: 'TOF0', inputs: { PT: 'T#50ms' } },
      ],
    }),
  );

// Without EN/ENO: Q is the block's first BOOL output (the display was right there before too).
const NO_EN = () =>
  ladder(['[/Lamp] - # # - - # # (Lamp)', '. . # # . . # # .'], {
    boxes: [
      { row: 0, col: 2, type: 'TON', instance: 'TON0', inputs: { PT: 'T#50ms' } },
      { row: 0, col: 6, type: 'TOF', instance: 'TOF0', inputs: { PT: 'T#50ms' } },
    ],
  });

interface Shape {
  readonly name: string;
  readonly net: () => Network;
  readonly orders?: Record<string, number>;
  /** Links (row, col) that show TON0.Q, and those that show TON0.Q AND A. */
  readonly qLinks: readonly (readonly [number, number])[];
  readonly andLinks?: readonly (readonly [number, number])[];
  /** Links that show ENO (always lit while the POU runs). */
  readonly enoLinks?: readonly (readonly [number, number])[];
}

const SHAPES: Shape[] = [
  { name: 'Q into IN (Blink)', net: BLINK, qLinks: [[1, 4], [1, 5]], enoLinks: [[0, 4], [0, 5]] },
  { name: 'Q into IN, TOF0 with an execution order (as the Blink file)', net: () => withEn(BLINK(), { TOF0: 1 }), qLinks: [[1, 4], [1, 5]], enoLinks: [[0, 4], [0, 5]] },
  { name: 'Q through a contact into IN', net: THROUGH_CONTACT, qLinks: [[1, 4]], andLinks: [[1, 6]], enoLinks: [[0, 4], [0, 5], [0, 6]] },
  { name: 'Q into IN without EN/ENO', net: NO_EN, qLinks: [[0, 4], [0, 5]] },
];

describe('a line from a block output shows that output', () => {
  const profiles: Profile[] = ['iec', 'openplc'];
  test.each(SHAPES.flatMap((s) => profiles.map((p) => [s.name, p, s] as const)))('%s (%s)', (_name, profile, shape) => {
    const net = shape.net();
    const plc = plcOf(project(V, [net], profile), 10);
    const at = (row: number, col: number) => {
      const k = net.elements.findIndex((e) => e.kind === 'link' && e.row === row && e.col === col);
      if (k < 0) throw new Error(`no link at row ${row}, column ${col}`);
      return k;
    };
    const lit = (row: number, col: number) => (plc.snapshot().networks[0]!.elements[at(row, col)]! & 1) === 1;
    const seen = { qOn: 0, qOff: 0 };
    for (let scan = 1; scan <= 60; scan++) {
      plc.write('A', scan % 7 < 4);
      plc.scan();
      const q = plc.read('TON0.Q') === true;
      const a = plc.read('A') === true;
      seen[q ? 'qOn' : 'qOff']++;
      for (const [r, c] of shape.qLinks) expect({ scan, row: r, col: c, lit: lit(r, c) }).toEqual({ scan, row: r, col: c, lit: q });
      for (const [r, c] of shape.andLinks ?? []) expect({ scan, row: r, col: c, lit: lit(r, c) }).toEqual({ scan, row: r, col: c, lit: q && a });
      for (const [r, c] of shape.enoLinks ?? []) expect({ scan, row: r, col: c, lit: lit(r, c) }).toEqual({ scan, row: r, col: c, lit: true });
    }
    // The timers blink: both states of Q were shown.
    expect(seen.qOn).toBeGreaterThanOrEqual(3);
    expect(seen.qOff).toBeGreaterThanOrEqual(10);
  });
});

describe('a line from a block output into an OR shows the output, not the OR', () => {
  // X := TON0.Q OR A; the line from Q to the bar shows Q while A lights the bar and X.
  //   |--[Run]--[TON0]Q---+--( X )
  //   |                   |
  //   |--[A]--------------+
  const net = () =>
    ladder(['[Run] # # - + (X)', '. # # . + .', '[A] - - - + .'], {
      boxes: [{ row: 0, col: 1, type: 'TON', instance: 'TON0', inputs: { PT: 'T#30ms' } }],
    });
  test.each<Profile>(['iec', 'openplc'])('%s', (profile) => {
    const n = net();
    const plc = plcOf(project(vars('Run BOOL', 'A BOOL', 'X BOOL', 'TON0 TON'), [n], profile), 10);
    const k = (row: number, col: number) => n.elements.findIndex((e) => e.kind === 'link' && e.row === row && e.col === col);
    const box = n.elements.findIndex((e) => e.kind === 'box');
    const byte = (i: number) => plc.snapshot().networks[0]!.elements[i]!;
    const seen = new Set<string>();
    for (let scan = 1; scan <= 80; scan++) {
      plc.write('Run', scan % 20 < 12);
      plc.write('A', scan % 7 < 3);
      plc.scan();
      const q = plc.read('TON0.Q') === true;
      const a = plc.read('A') === true;
      seen.add(`${q}${a}`);
      expect({ scan, q, a, x: plc.read('X') }).toEqual({ scan, q, a, x: q || a });
      expect({ scan, line: byte(k(0, 3)) & 1, boxOut: (byte(box) >> 1) & 1 }).toEqual({ scan, line: Number(q), boxOut: Number(q) });
      expect({ scan, line: byte(k(2, 3)) & 1 }).toEqual({ scan, line: Number(a) });
      expect({ scan, bar: plc.snapshot().networks[0]!.vlinks[0] }).toEqual({ scan, bar: Number(q || a) });
    }
    // Q off while A lights the OR, and the other way round, were both seen.
    expect(seen.has('falsetrue')).toBe(true);
    expect(seen.has('truefalse')).toBe(true);
  });
});
