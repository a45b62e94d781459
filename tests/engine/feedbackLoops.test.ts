// Explicit feedback loops (IEC 61131-3 4.1.3, figure 23a) drawn on the grid with a connector pair:
// a loop through a block runs, one element reading the block's stored output (its value from its
// previous call), with a located warning LD-W30 in both profiles; a loop of contacts and coils
// alone has nothing to read and stays LD-R01. The PLCopen side (MATIEC's traces) is covered by
// tests/fixtures/reference/c04-*.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { Profile } from '../../src/model/project';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { ladder, plcOf, project, trace, vars } from './ladder';

const VARS = vars('Go BOOL', 'A BOOL', 'Q BOOL', 'R BOOL', 'N INT', 'T1 TON', 'RS0 RS');

/** TON T1 whose Q, passed on by the coil Q, comes back through >C> to the inverting contact before it. */
const blinker = () =>
  ladder(['|>C> [NOT] # # (Q) >C>|', '. . # # . .'], { boxes: [{ row: 0, col: 2, type: 'TON', instance: 'T1', inputs: { PT: 'T#30ms' } }] });

/** RS0 reset by AND(RS0.Q1, A): the AND's output drives Q and comes back to R1 through >C>. */
const resetLoop = () =>
  ladder(['[Go] - # # - + . # # . .', '. |>C> # # . + - # # + (Q)', '[A] - - - - - # # + >C>|'], {
    boxes: [
      { row: 0, col: 2, type: 'RS', instance: 'RS0' },
      { row: 0, col: 6, type: 'AND' },
    ],
  });

const steps = (n: number, inputs: Record<string, boolean> = {}) => Array.from({ length: n }, () => inputs);

describe('explicit feedback loops through a block', () => {
  for (const profile of ['iec', 'openplc'] as Profile[]) {
    test(`${profile}: the blinker checks with one located warning naming the block and the reader`, () => {
      const net = blinker();
      const ds = checkProject(project(VARS, [net], profile));
      expect(ds.filter((d) => d.severity === 'error')).toEqual([]);
      const w = ds.filter((d) => d.rule === 'LD-W30');
      expect(w).toHaveLength(1);
      expect(w[0]!.severity).toBe('warning');
      expect(w[0]!.network).toBe(0);
      expect(w[0]!.message).toMatch(/feeds back into/);
      expect(w[0]!.message).toMatch(/previous call|instance keeps/);
      expect(w[0]!.elementId).toBeDefined();
      const at = net.elements.find((e) => e.id === w[0]!.elementId)!;
      expect(at.kind === 'box' || (at.kind === 'contact' && at.contact === 'NOT')).toBe(true);
    });
  }

  test('openplc: the blinker runs as MATIEC runs it (NOT reads T1.Q of the previous call; Q on for one scan every 50 ms)', () => {
    const plc = plcOf(project(VARS, [blinker()], 'openplc'), 10);
    expect(trace(plc, steps(11), ['Q', 'T1.Q', 'T1.ET'])).toEqual([
      [0, 0, 0],
      [0, 0, 10],
      [0, 0, 20],
      [1, 1, 30],
      [0, 0, 0],
      [0, 0, 0],
      [0, 0, 10],
      [0, 0, 20],
      [1, 1, 30],
      [0, 0, 0],
      [0, 0, 0],
    ]);
  });

  test('iec: the loop is cut on the wire into the block (T1 reads the inverting contact of the previous scan); it still blinks', () => {
    const plc = plcOf(project(VARS, [blinker()], 'iec'), 10);
    const rows = trace(plc, steps(16), ['Q', 'T1.Q']);
    // Q is T1.Q of this scan (the coil runs after T1), and it pulses periodically.
    expect(rows.every(([q, t]) => q === t)).toBe(true);
    const on = rows.flatMap(([q], k) => (q ? [k] : []));
    expect(on.length).toBeGreaterThanOrEqual(2);
    expect(new Set(on.slice(1).map((k, i) => k - on[i]!)).size).toBe(1);
  });

  for (const profile of ['iec', 'openplc'] as Profile[]) {
    test(`${profile}: RS0 reset by AND(RS0.Q1, A) through a connector: the AND's output of the previous call resets it`, () => {
      const ds = checkProject(project(VARS, [resetLoop()], profile));
      expect(ds.filter((d) => d.severity === 'error')).toEqual([]);
      expect(ds.filter((d) => d.rule === 'LD-W30').map((d) => d.message)).toEqual([expect.stringMatching(/^the AND block at R1C7 feeds back into the RS block "RS0"/)]);
      const plc = plcOf(project(VARS, [resetLoop()], profile), 10);
      // Go and A held: set, then AND = Q1 AND A resets at the next scan, then sets again: it toggles.
      // RS0 reads the AND of the previous call: after A falls it still resets once.
      expect(trace(plc, steps(5, { Go: true, A: true }), ['Q', 'RS0.Q1'])).toEqual([
        [1, 1],
        [0, 0],
        [1, 1],
        [0, 0],
        [1, 1],
      ]);
      expect(trace(plc, steps(2, { Go: true, A: false }), ['Q', 'RS0.Q1'])).toEqual([
        [0, 0],
        [0, 1],
      ]);
    });
  }

  for (const profile of ['iec', 'openplc'] as Profile[]) {
    test(`${profile}: a block reading its own output (ADD accumulating into N, XOR toggling Q) reads its previous result`, () => {
      const acc = ladder(['. . # # .', '|>C> - # # >C>|'], {
        boxes: [{ row: 0, col: 2, type: 'ADD', inputs: { IN2: '5' }, outputs: { OUT: 'N' } }],
      });
      const toggle = ladder(['. . # # . .', '[Go] - # # + (Q)', '|>D> - # # + >D>|'], { boxes: [{ row: 0, col: 2, type: 'XOR' }] });
      const p = project(VARS, [acc, toggle], profile);
      const ds = checkProject(p);
      expect(ds.filter((d) => d.severity === 'error')).toEqual([]);
      expect(ds.filter((d) => d.rule === 'LD-W30').map((d) => [d.network, d.message.replace(/ \(.*/, '')])).toEqual([
        [0, 'the ADD block at R1C3 feeds back into its own input'],
        [1, 'the XOR block at R1C3 feeds back into its own input'],
      ]);
      const plc = plcOf(p, 10);
      expect(trace(plc, [{ Go: true }, { Go: true }, { Go: true }, { Go: false }, { Go: true }], ['N', 'Q'])).toEqual([
        [5, 1],
        [10, 0],
        [15, 1],
        [20, 1],
        [25, 0],
      ]);
    });
  }

  test('a loop of contacts and coils alone has no stored value to read: LD-R01, in both profiles', () => {
    for (const profile of ['iec', 'openplc'] as Profile[]) {
      const net = ladder(['|>C> [A] (Q) >C>|']);
      const ds = checkProject(project(VARS, [net], profile));
      const errors = ds.filter((d) => d.severity === 'error');
      expect(errors.map((d) => d.rule)).toEqual(['LD-R01']);
      // Located on the first element of the loop: the contact A.
      expect(errors[0]).toMatchObject({ network: 0, cell: { row: 0, col: 1 }, elementId: net.elements[1]!.id });
      expect(ds.some((d) => d.rule === 'LD-W30')).toBe(false);
    }
  });
});

describe('where each profile cuts a loop with a contact on it (tests/fixtures/reference/c04-contact-in-loop.xml)', () => {
  // RS R1 (S from Go) -> TON T1 (IN from R1.Q1) -> contact Go on T1.Q -> R1.R1, and the contact drives coil Q.
  const xml = readFileSync(fileURLToPath(new URL('../fixtures/reference/c04-contact-in-loop.xml', import.meta.url)), 'utf8');
  const imported = importPlcopen(xml);
  if (!imported.ok) throw new Error('the fixture does not import');
  const withProfile = (profile: Profile) => ({ ...imported.project, profile });
  const warnings = (profile: Profile) =>
    checkProject(withProfile(profile))
      .filter((d) => d.rule === 'LD-W30')
      .map((d) => d.message.replace(/ \(.*/, ''));

  test('iec cuts the wire into a block (T1 reads R1.Q1 of the previous call), so the contact passes the new T1.Q on to Q', () => {
    expect(warnings('iec')).toEqual(['the RS block "R1" feeds back into the TON block "T1"']);
    const plc = plcOf(withProfile('iec'), 10);
    const rows = trace(plc, steps(8, { Go: true }), ['Q', 'T1.Q']);
    expect(rows.every(([q, t]) => q === t)).toBe(true);
    expect(rows.some(([q]) => q === 1)).toBe(true);
  });

  test('openplc cuts where Beremiz does: R1 reads T1.Q of the previous call (the contact is traced again for Q)', () => {
    expect(warnings('openplc')).toEqual(['the TON block "T1" feeds back into the RS block "R1"']);
  });
});
