// Online change keeps instance state (issue 10): exportState/importState carry FB instances (by
// name and type) and edge memories (by element id, symbol and operand) to a new program; what is
// new starts fresh, as IEC says a new element does.
import { describe, expect, test } from 'vitest';
import type { Plc, StateTransfer } from '../../src/engine/api';
import { compileProgram, createPlc, planStateTransfer } from '../../src/engine/plc';
import type { Network, Project } from '../../src/model/project';
import { ladder, plcOf, project, vars } from './ladder';

/** The new program takes over the old PLC's instance state, as the simulator does at a scan boundary. */
function change(old: Plc, next: Project, opts: { cycleMs?: number; clock?: { now(): number } } = {}) {
  const { program } = compileProgram(next);
  if (!program) throw new Error('the edited program does not compile');
  const plc = createPlc(program, { cycleMs: opts.cycleMs ?? 10, ...(opts.clock ? { clock: opts.clock } : {}) });
  const transfer = plc.importState(old.exportState());
  return { plc, transfer };
}

const labels = (t: StateTransfer) => ({
  kept: t.kept.map((i) => i.label),
  reset: t.reset.map((r) => `${r.item.label} (${r.detail})`),
  removed: t.removed.map((i) => i.label),
});

/** A network somewhere else in the program: Other drives Lamp. */
const elsewhere = (): Network => ladder(['[Other] (Lamp)']);

const counterNetwork = (): Network =>
  ladder(['[Pulse] # # (Full)', '. # # .', '. # # .'], {
    boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { R: 'Clear', PV: '100' }, outputs: { CV: 'Count' } }],
  });
const counterVars = () => vars('Pulse BOOL', 'Clear BOOL', 'C1 CTU', 'Count INT', 'Full BOOL', 'Other BOOL', 'Lamp BOOL');

describe('FB instances keep their state when the program changes elsewhere', () => {
  test('a CTU keeps its CV (5 stays 5) and counts on from there', () => {
    const counting = counterNetwork();
    const old = plcOf(project(counterVars(), [counting]));
    for (let i = 0; i < 5; i++) {
      old.write('Pulse', true);
      old.scan();
      old.write('Pulse', false);
      old.scan();
    }
    expect(old.read('C1.CV')).toBe(5);
    const { plc, transfer } = change(old, project(counterVars(), [counting, elsewhere()]));
    expect(plc.read('C1.CV')).toBe(5);
    expect(labels(transfer).kept).toEqual(['C1']);
    plc.scan();
    expect(plc.read('Count')).toBe(5);
    plc.write('Pulse', true);
    plc.scan();
    expect(plc.read('C1.CV')).toBe(6);
  });

  test("a CTU whose count input is held ON through the change does not count it again (its CU edge memory is kept)", () => {
    const counting = counterNetwork();
    const old = plcOf(project(counterVars(), [counting]));
    old.write('Pulse', true);
    old.scans(3);
    expect(old.read('C1.CV')).toBe(1);
    const { plc } = change(old, project(counterVars(), [elsewhere(), counting]));
    plc.write('Pulse', true);
    plc.scans(3);
    expect(plc.read('C1.CV')).toBe(1);
  });

  test("a TON keeps timing: ET continues from where it was, not from 0, and Q comes at PT", () => {
    const timing = ladder(['[Go] # # - (Q)', '. # # . .'], {
      boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#100ms' } }],
    });
    const tVars = () => vars('Go BOOL := TRUE', 'T1 TON', 'Q BOOL', 'Other BOOL', 'Lamp BOOL');
    const old = plcOf(project(tVars(), [timing]));
    old.scans(5); // started at 0 ms; the 5th scan (40 ms) shows ET 40
    expect(old.read('T1.ET')).toBe(40);
    const { plc } = change(old, project(tVars(), [timing, elsewhere()]));
    expect(plc.read('T1.ET')).toBe(40);
    plc.scan(); // what would have been the old PLC's 6th scan, at 50 ms
    expect(plc.read('T1.ET')).toBe(50);
    plc.scans(4);
    expect([plc.read('T1.ET'), plc.read('Q')]).toEqual([90, false]);
    plc.scan();
    expect([plc.read('T1.ET'), plc.read('Q')]).toEqual([100, true]);
  });

  test('a TON keeps timing on a real clock too, although the new PLC starts its clock later', () => {
    let t = 5_000;
    const clock = { now: () => t };
    const timing = ladder(['[Go] # # - (Q)', '. # # . .'], {
      boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#1s' } }],
    });
    const tVars = () => vars('Go BOOL := TRUE', 'T1 TON', 'Q BOOL', 'Other BOOL', 'Lamp BOOL');
    const old = createPlc(compileProgram(project(tVars(), [timing])).program!, { cycleMs: 10, clock });
    old.scan();
    t += 600;
    old.scan();
    expect(old.read('T1.ET')).toBe(600);
    const { plc } = change(old, project(tVars(), [timing, elsewhere()]), { clock }); // its clock starts at 5,600
    t += 300;
    plc.scan();
    expect([plc.read('T1.ET'), plc.read('Q')]).toEqual([900, false]);
    t += 100;
    plc.scan();
    expect([plc.read('T1.ET'), plc.read('Q')]).toEqual([1000, true]);
  });

  test('R_TRIG and F_TRIG instances keep their memory: a steady input gives no pulse after the change', () => {
    const trig = ladder(['[A] # # (RQ)', '. # # .', '[A] # # (FQ)', '. # # .'], {
      boxes: [
        { row: 0, col: 1, type: 'R_TRIG', instance: 'RT' },
        { row: 2, col: 1, type: 'F_TRIG', instance: 'FT' },
      ],
    });
    const tVars = () => vars('A BOOL := TRUE', 'RT R_TRIG', 'FT F_TRIG', 'RQ BOOL', 'FQ BOOL', 'Other BOOL', 'Lamp BOOL');
    const old = plcOf(project(tVars(), [trig]));
    old.scan();
    expect(old.read('RQ')).toBe(true);
    old.scan();
    const { plc, transfer } = change(old, project(tVars(), [elsewhere(), trig]));
    expect(labels(transfer).kept).toEqual(['RT', 'FT']);
    plc.scan();
    expect([plc.read('RQ'), plc.read('FQ')]).toEqual([false, false]);
  });
});

describe('edge elements keep their memory by element id', () => {
  const eVars = () => vars('A BOOL := TRUE', 'X BOOL', 'Y BOOL', 'Other BOOL', 'Lamp BOOL');

  test('a |P| contact on a steady TRUE input does not fire after an edit elsewhere, even when its network moved', () => {
    const edge = ladder(['[P:A] (X)']);
    const old = plcOf(project(eVars(), [edge]));
    old.scan();
    expect(old.read('X')).toBe(true); // the first evaluation of a |P| with A TRUE fires (R_TRIG, M starts FALSE)
    old.scan();
    expect(old.read('X')).toBe(false);
    const { plc, transfer } = change(old, project(eVars(), [elsewhere(), edge]));
    expect(labels(transfer)).toEqual({ kept: ['|P| A in network 2'], reset: [], removed: [] });
    plc.scans(3);
    expect(plc.read('X')).toBe(false);
    plc.write('A', false);
    plc.scan();
    plc.write('A', true);
    plc.scan();
    expect(plc.read('X')).toBe(true); // a real rising edge still fires
  });

  test('a NEW |P| element placed on a steady TRUE input is a fresh element: it fires once at its first evaluation', () => {
    const edge = ladder(['[P:A] (X)']);
    const old = plcOf(project(eVars(), [edge]));
    old.scans(3);
    const added = ladder(['[P:A] (Y)']);
    const { plc, transfer } = change(old, project(eVars(), [edge, added]));
    expect(labels(transfer).reset).toEqual(['|P| A in network 2 (new)']);
    plc.scan();
    expect([plc.read('X'), plc.read('Y')]).toEqual([false, true]);
    plc.scan();
    expect(plc.read('Y')).toBe(false);
  });

  test('|N| contacts and (P)/(N) coils keep their memories', () => {
    const net = ladder(['[N:A] (X)', '[A] (P:Y)']);
    const coilN = ladder(['[A] (N:Other)']);
    const old = plcOf(project(eVars(), [net, coilN]));
    old.scans(2);
    const { plc, transfer } = change(old, project(eVars(), [coilN, elsewhere(), net]));
    expect(transfer.kept.map((i) => i.type).sort()).toEqual(['(N)', '(P)', '|N|']);
    plc.scan();
    expect([plc.read('X'), plc.read('Y'), plc.read('Other')]).toEqual([false, false, false]);
  });

  test('an edge element that now reads another variable starts fresh, and the plan says why', () => {
    const before = ladder(['[P:A] (X)']);
    const old = plcOf(project(eVars(), [before]));
    old.scans(2);
    const el = before.elements[0]!;
    const after: Network = { ...before, elements: before.elements.map((e) => (e === el ? { ...el, variable: 'Other' } : e)) };
    const { transfer } = change(old, project(eVars(), [after]));
    expect(labels(transfer).reset).toEqual(['|P| Other in network 1 (now Other, was A)']);
  });
});

describe('what is reset, and why', () => {
  const timer = (type: string, name = 'T1') =>
    ladder(['[Go] # # - (Q)', '. # # . .'], {
      boxes: [{ row: 0, col: 1, type, instance: name, inputs: { PT: 'T#1s' } }],
    });

  test('an instance whose FB type changed (TON -> TOF) is reset and listed with the change', () => {
    const old = plcOf(project(vars('Go BOOL := TRUE', 'T1 TON', 'Q BOOL'), [timer('TON')]));
    old.scans(20);
    expect(old.read('T1.ET')).toBe(190);
    const { plc, transfer } = change(old, project(vars('Go BOOL := TRUE', 'T1 TOF', 'Q BOOL'), [timer('TOF')]));
    expect(labels(transfer)).toEqual({ kept: [], reset: ['T1 (TON → TOF)'], removed: [] });
    expect(transfer.reset[0]!.reason).toBe('type-changed');
    expect(plc.read('T1.ET')).toBe(0);
  });

  test('an instance deleted and re-added under the same name with another type is reset; a new one is "new"; a deleted one is "removed"', () => {
    const old = plcOf(
      project(vars('Go BOOL := TRUE', 'C1 CTU', 'T1 TON', 'Q BOOL'), [
        timer('TON'),
        ladder(['[Go] # # .', '. # # .', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'CTU', instance: 'C1', inputs: { R: 'FALSE', PV: '5' } }] }),
      ]),
    );
    old.scans(3);
    const { transfer } = change(
      old,
      project(vars('Go BOOL := TRUE', 'C1 TP', 'T3 TON', 'Q BOOL'), [timer('TP', 'C1'), timer('TON', 'T3')]),
    );
    expect(labels(transfer)).toEqual({ kept: [], reset: ['C1 (CTU → TP)', 'T3 (new)'], removed: ['T1'] });
    expect(transfer.reset.map((r) => r.reason)).toEqual(['type-changed', 'new']);
  });

  test('planStateTransfer gives the same plan before anything is applied', () => {
    const net = counterNetwork();
    const old = plcOf(project(counterVars(), [net]));
    const next = plcOf(project(vars('Pulse BOOL', 'Clear BOOL', 'C1 CTU', 'Count INT', 'Full BOOL', 'T3 TON'), [net]));
    const plan = planStateTransfer(old.stateItems(), next.stateItems());
    expect(labels(plan).reset).toEqual(['T3 (new)']);
    expect(labels(next.importState(old.exportState()))).toEqual(labels(plan));
  });
});

test('exported state is exact: a copy of the program continues scan for scan like the original, through JSON', () => {
  const block = (type: string, name: string, out: string, inputs: Record<string, string>) =>
    ladder(['[A] # # - (' + out + ')', ...Array<string>(5).fill('. # # . .')], { boxes: [{ row: 0, col: 1, type, instance: name, inputs }] });
  const p = project(vars('A BOOL', 'B BOOL', 'Q1 BOOL', 'Q2 BOOL', 'Q3 BOOL', 'Q4 BOOL', 'X BOOL', 'Y BOOL', 'Tp TP', 'Tf TOF', 'Cud CTUD', 'Sr SR'), [
    block('TP', 'Tp', 'Q1', { PT: 'T#70ms' }),
    block('TOF', 'Tf', 'Q2', { PT: 'T#50ms' }),
    block('CTUD', 'Cud', 'Q3', { CD: 'B', R: 'FALSE', LD: 'FALSE', PV: '3' }),
    block('SR', 'Sr', 'Q4', { R: 'B' }),
    ladder(['[P:A] (X)']),
    ladder(['[N:B] (P:Y)']),
  ]);
  const { program, diagnostics } = compileProgram(p);
  expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
  const a = createPlc(program!, { cycleMs: 10 });
  const inputs = (k: number) => ({ A: k % 7 < 3, B: k % 5 === 0 });
  const step = (plc: Plc, k: number) => {
    plc.write('A', inputs(k).A);
    plc.write('B', inputs(k).B);
    plc.scan();
  };
  for (let k = 0; k < 19; k++) step(a, k);
  expect([a.read('Tp.ET'), a.read('Tf.ET')]).toEqual([40, 10]); // both timers are timing when the state is taken
  const b = createPlc(compileProgram(p).program!, { cycleMs: 10 });
  b.importState(JSON.parse(JSON.stringify(a.exportState())));
  for (const name of ['A', 'B', 'Q1', 'Q2', 'Q3', 'Q4', 'X', 'Y']) b.write(name, a.read(name));
  for (let k = 19; k < 60; k++) {
    step(a, k);
    step(b, k);
    const names = a.variableNames();
    expect(names.map((n) => b.read(n)), `scan ${k + 1}`).toEqual(names.map((n) => a.read(n)));
  }
});
