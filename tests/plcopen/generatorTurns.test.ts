// Profile openplc: Beremiz's order of statements over a whole LD body (issue 23, classes 1-3;
// LD-SEMANTICS.md section 6). PLCGenerator.py's ComputeProgram writes one statement per coil and
// per output variable of the body, sorted by SortInstances (by y; by x when the tops are less than
// 10 apart), across networks. The import lays parallel coils out in that order and records it as
// Network.turns where network by network, row by row would differ (networks drawn side by side);
// the engine runs consecutive networks with turns together, in turn order.
import { describe, expect, test } from 'vitest';
import type { CoilElement } from '../../src/model/elements';
import { loadProject, saveProject } from '../../src/model/load';
import type { Network, Profile, Project } from '../../src/model/project';
import { exportBehaviour } from '../../src/plcopen/exportBehaviour';
import { exportPlcopen } from '../../src/plcopen/exportPlcopen';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { sortInstances } from '../../src/plcopen/generatorOrder';
import { ladder, plcOf, project, trace, vars } from '../engine/ladder';
import { ldXml, type LdNetwork, type LdVar } from './ldXml';

const VARS: LdVar[] = [
  { name: 'X', type: 'BOOL' },
  { name: 'M', type: 'BOOL' },
  { name: 'Q', type: 'BOOL' },
];

/** X sets M (y 10) and resets it (y 110); the other network copies M to Q at `q` (left at x 500 when side by side). */
function body(q: { x: number; y: number }): LdNetwork[] {
  return [
    {
      objects: [
        { id: 1, kind: 'contact', v: 'X', in: ['rail'] },
        { id: 2, kind: 'coil', v: 'M', storage: 'set', in: ['1'] },
        { id: 3, kind: 'coil', v: 'M', storage: 'reset', in: ['1'] },
      ],
      toRail: [2, 3],
      pos: { 1: { x: 40, y: 10 }, 2: { x: 200, y: 10 }, 3: { x: 200, y: 110 } },
    },
    {
      objects: [
        { id: 4, kind: 'contact', v: 'M', in: ['rail'] },
        { id: 5, kind: 'coil', v: 'Q', in: ['4'] },
      ],
      toRail: [5],
      pos: { 4: { x: q.x + 40, y: q.y }, 5: { x: q.x + 200, y: q.y } },
    },
  ];
}

function imported(xml: string): { project: Project; notes: string[] } {
  const r = importPlcopen(xml);
  if (!r.ok) throw new Error(JSON.stringify(r.errors));
  return { project: r.project, notes: r.report.notes.map((n) => n.message) };
}

const networksOf = (p: Project): readonly Network[] => p.pous.find((x) => x.name === 'Main')!.networks;
const coil = (n: Network, variable: string, kind: CoilElement['coil']) =>
  n.elements.find((e): e is CoilElement => e.kind === 'coil' && e.variable === variable && e.coil === kind)!;

function run(p: Project, profile: Profile) {
  return trace(plcOf({ ...p, profile }), [{ X: true }, { X: false }], ['M', 'Q']);
}

describe('networks drawn side by side (class 3)', () => {
  test('the import records the interleaved order, and openplc runs the copy between the set and the reset', () => {
    const { project: p, notes } = imported(ldXml(VARS, body({ x: 500, y: 60 })));
    expect(p.profile).toBe('openplc');
    const [n1, n2] = networksOf(p);
    expect(n1!.turns).toEqual({ [coil(n1!, 'M', 'SET').id]: 0, [coil(n1!, 'M', 'RESET').id]: 2 });
    expect(n2!.turns).toEqual({ [coil(n2!, 'Q', 'COIL').id]: 1 });
    expect(notes.some((m) => /networks 1 to 2 are drawn so that Beremiz and OpenPLC run their coils/.test(m))).toBe(true);
    // IF X THEN M := TRUE; END_IF;  Q := M;  IF X THEN M := FALSE; END_IF;
    expect(run(p, 'openplc')).toEqual([
      [0, 1],
      [0, 0],
    ]);
    // iec: network by network (the turns are the generator's, not the standard's).
    expect(run(p, 'iec')).toEqual([
      [0, 0],
      [0, 0],
    ]);
  });

  test('networks drawn one under the other keep network order and get no turns', () => {
    const { project: p, notes } = imported(ldXml(VARS, body({ x: 0, y: 300 })));
    expect(networksOf(p).every((n) => n.turns === undefined)).toBe(true);
    expect(notes.some((m) => /interleaved/.test(m))).toBe(false);
    expect(run(p, 'openplc')).toEqual([
      [0, 0],
      [0, 0],
    ]);
  });

  test('tops less than 10 apart are ordered by x, across networks', () => {
    // The copy's coil at y 5, x 700 and the set at y 10, x 200: by x, the set first (then the copy, then the reset).
    const near = imported(ldXml(VARS, body({ x: 500, y: 5 })));
    expect(networksOf(near.project).every((n) => n.turns !== undefined)).toBe(true);
    expect(run(near.project, 'openplc')[0]).toEqual([0, 1]);
    // At y 0 the tops are 10 apart: by y, the copy first (network order: no turns needed).
    const above = imported(ldXml(VARS, body({ x: 500, y: 0 })));
    expect(networksOf(above.project).every((n) => n.turns === undefined)).toBe(true);
    expect(run(above.project, 'openplc')[0]).toEqual([0, 0]);
  });

  test('the export cannot draw the interleaved order: the review says so (LD-X08), and the exported file runs network by network', () => {
    const { project: p } = imported(ldXml(VARS, body({ x: 500, y: 60 })));
    const x08 = exportBehaviour(p).filter((w) => w.rule === 'LD-X08');
    expect(x08.map((w) => w.network)).toEqual([0]);
    expect(x08[0]!.message).toMatch(/networks 1 to 2 run their coils and output variables interleaved/);
    expect(exportBehaviour({ ...p, profile: 'iec' }).some((w) => w.rule === 'LD-X08')).toBe(false);
    const again = imported(exportPlcopen(p)).project;
    expect(networksOf(again).every((n) => n.turns === undefined)).toBe(true);
    expect(run(again, 'openplc')).toEqual([
      [0, 0],
      [0, 0],
    ]);
  });

  test('turns survive saving and loading the project', () => {
    const { project: p } = imported(ldXml(VARS, body({ x: 500, y: 60 })));
    const back = loadProject(saveProject(p));
    expect(back.ok).toBe(true);
    if (back.ok) expect(networksOf(back.project).map((n) => n.turns)).toEqual(networksOf(p).map((n) => n.turns));
  });
});

describe('Network.turns in the engine', () => {
  const V = vars('X BOOL', 'M BOOL', 'Y BOOL');
  const net = () => ladder(['[X] + (S:M)', '. + (R:M)', '[M] - (Y)']);
  const ids = (n: Network) => n.elements.filter((e) => e.kind === 'coil').map((e) => e.id);

  test('a network with turns runs its coils in that order under openplc, by row under iec', () => {
    const n = net();
    const [set, reset, y] = ids(n);
    const turned: Network = { ...n, turns: { [reset!]: 0, [set!]: 1, [y!]: 2 } };
    const step = [{ X: true }];
    expect(trace(plcOf(project(V, [n], 'openplc')), step, ['M', 'Y'])).toEqual([[0, 0]]);
    expect(trace(plcOf(project(V, [turned], 'openplc')), step, ['M', 'Y'])).toEqual([[1, 1]]);
    expect(trace(plcOf(project(V, [turned], 'iec')), step, ['M', 'Y'])).toEqual([[0, 0]]);
  });

  test('a coil without a turn (drawn after the import) runs right after the coil before it in its network', () => {
    const n = net();
    const [set, reset] = ids(n);
    // Y has no turn: it follows the reset (row 1), which runs first.
    const turned: Network = { ...n, turns: { [reset!]: 0, [set!]: 1 } };
    expect(trace(plcOf(project(V, [turned], 'openplc')), [{ X: true }], ['M', 'Y'])).toEqual([[1, 0]]);
  });

  test('two networks with turns interleave; a network without turns between them separates them', () => {
    const a = ladder(['[X] + (S:M)', '. + (R:M)']);
    const b = ladder(['[M] (Y)']);
    const [set, reset] = ids(a);
    const [y] = ids(b);
    const ta: Network = { ...a, turns: { [set!]: 0, [reset!]: 2 } };
    const tb: Network = { ...b, turns: { [y!]: 1 } };
    expect(trace(plcOf(project(V, [ta, tb], 'openplc')), [{ X: true }], ['Y'])).toEqual([[1]]);
    const between = ladder(['[X] (Q)']);
    const V2 = vars('X BOOL', 'M BOOL', 'Y BOOL', 'Q BOOL');
    expect(trace(plcOf(project(V2, [ta, between, tb], 'openplc')), [{ X: true }], ['Y'])).toEqual([[0]]);
  });
});

describe('parallel coils in drawn order (class 2)', () => {
  test('the import places parallel coils top to bottom as drawn, whatever the file order', () => {
    // A -> M -> (R:M) drawn at y 160 but first in the file, (Q) at y 120: Beremiz writes Q first.
    const nets: LdNetwork[] = [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'X', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'M', in: ['1'] },
          { id: 3, kind: 'coil', v: 'M', storage: 'reset', in: ['2'] },
          { id: 4, kind: 'coil', v: 'Q', in: ['2'] },
        ],
        toRail: [3, 4],
        pos: { 1: { x: 40, y: 110 }, 2: { x: 100, y: 110 }, 3: { x: 200, y: 160 }, 4: { x: 200, y: 110 } },
      },
    ];
    const { project: p } = imported(ldXml(VARS, nets));
    const [n] = networksOf(p);
    expect(coil(n!, 'Q', 'COIL').row).toBeLessThan(coil(n!, 'M', 'RESET').row);
    expect(n!.turns).toBeUndefined();
    expect(trace(plcOf({ ...p, profile: 'openplc' }, 10), [{ X: true, M: true }], ['M', 'Q'])).toEqual([[0, 1]]);
  });

  test('coils whose tops are less than 10 apart are ordered by x (SortInstances)', () => {
    expect(sortInstances({ x: 300, y: 130 }, { x: 320, y: 125 })).toBeLessThan(0);
    expect(sortInstances({ x: 300, y: 135 }, { x: 320, y: 125 })).toBeGreaterThan(0);
    expect(sortInstances({ x: 300.7, y: 10.9 }, { x: 300.2, y: 10.1 })).toBe(0); // Python's int()
  });
});

describe('a generic function\'s BOOL output into another block (class 1)', () => {
  test('OR reads what AND wrote in the same scan (_TMP_AND_OUT), under both profiles', () => {
    const nets: LdNetwork[] = [
      {
        objects: [
          { id: 1, kind: 'contact', v: 'A', in: ['rail'] },
          { id: 2, kind: 'contact', v: 'B', in: ['rail'] },
          { id: 3, kind: 'contact', v: 'C', in: ['rail'] },
          { id: 4, kind: 'block', type: 'AND', inputs: { IN1: ['1'], IN2: ['2'] }, outputs: ['OUT'] },
          { id: 5, kind: 'block', type: 'OR', inputs: { IN1: ['4.OUT'], IN2: ['3'] }, outputs: ['OUT'] },
          { id: 6, kind: 'block', type: 'XOR', inputs: { IN1: ['4.OUT'], IN2: ['5.OUT'] }, outputs: ['OUT'] },
          { id: 7, kind: 'coil', v: 'Q', in: ['5.OUT'] },
          { id: 8, kind: 'coil', v: 'R', in: ['6.OUT'] },
        ],
        toRail: [7, 8],
      },
    ];
    const abc: LdVar[] = ['A', 'B', 'C', 'Q', 'R'].map((name) => ({ name, type: 'BOOL' }));
    const { project: p } = imported(ldXml(abc, nets));
    const steps = [0, 1, 2, 3, 4, 5, 6, 7].map((k) => ({ A: !!(k & 1), B: !!(k & 2), C: !!(k & 4) }));
    const expected = steps.map(({ A, B, C }) => [+((A && B) || C), +((A && B) !== ((A && B) || C))]);
    expect(trace(plcOf({ ...p, profile: 'openplc' }), steps, ['Q', 'R'])).toEqual(expected);
    expect(trace(plcOf({ ...p, profile: 'iec' }), steps, ['Q', 'R'])).toEqual(expected);
  });
});
