// Profile `openplc`: an LD POU runs as Beremiz and OpenPLC run it (LD-SEMANTICS.md section 6,
// issue 12). Their generator (PLCGenerator.py) writes one ST statement per coil, by position, each
// re-reading the coil's whole path; blocks run once, at the first coil that needs them, and blocks
// no coil needs after every coil of the POU; jumps and RETURNs are never generated. Each case runs
// under both profiles; the comment gives the ST Beremiz generates for it.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { explain, liveScanView } from '../../src/engine/explain';
import type { Network, Profile, Variable } from '../../src/model/project';
import { buildGraph, upstream } from '../../src/engine/compile/graph';
import { exportBehaviour } from '../../src/plcopen/exportBehaviour';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { EXAMPLES } from '../../src/model/examples';
import { ScanPlc } from '../../src/engine/runtime/scanner';
import { DEFAULT_TIERING } from '../../src/engine/runtime/tiering';
import { io, multiProject, pou } from './userBlocksHelpers';
import { ladder, plcOf, project, trace, vars } from './ladder';

type Steps = readonly Record<string, boolean | number>[];

/** The trace of the same program under each profile. */
function both(variables: readonly Variable[], networks: readonly Network[], steps: Steps, names: readonly string[], cycleMs = 10) {
  const run = (profile: Profile) => trace(plcOf(project(variables, networks, profile), cycleMs), steps, names);
  return { iec: run('iec'), openplc: run('openplc') };
}

const V = vars('A BOOL', 'B BOOL', 'X BOOL', 'Y BOOL', 'Run BOOL', 'Mid BOOL', 'Lamp BOOL', 'T1 TON');

describe('openplc: every coil re-reads its path at its own turn', () => {
  test('a contact shared by two coils is read again after the upper coil reset its variable', () => {
    // IF B THEN B := FALSE; (*reset*) END_IF;
    // Y := B;
    const t = both(V, [ladder(['[B] + (R:B)', '. + (Y)'])], [{ B: true }], ['B', 'Y']);
    expect(t.iec).toEqual([[0, 1]]); // one reading of B feeds both coils
    expect(t.openplc).toEqual([[0, 0]]); // Y's statement reads B after the reset
  });

  test('a set coil drawn above a reset coil: the reset coil sees the variable the set coil wrote', () => {
    // IF NOT(X) THEN X := TRUE; (*set*) END_IF;
    // IF NOT(X) THEN Y := FALSE; (*reset*) END_IF;
    const t = both(V, [ladder(['[/X] + (S:X)', '. + (R:Y)'])], [{ Y: true }, {}], ['X', 'Y']);
    expect(t.iec).toEqual([[1, 0], [1, 0]]);
    expect(t.openplc).toEqual([[1, 1], [1, 1]]);
  });

  test('a coil after a coil passes on its left side, re-read: coils in series', () => {
    // IF X THEN X := FALSE; (*reset*) END_IF;
    // Y := X;
    const t = both(V, [ladder(['[X] (R:X) (Y)'])], [{ X: true }], ['X', 'Y']);
    expect(t.iec).toEqual([[0, 1]]);
    expect(t.openplc).toEqual([[0, 0]]);
  });

  test('an edge contact on the paths of two coils has two edge memories, one per reading', () => {
    // R_TRIG1(CLK := A);
    // IF R_TRIG1.Q THEN A := FALSE; (*reset*) END_IF;
    // R_TRIG2(CLK := A);
    // Y := R_TRIG2.Q;
    const t = both(V, [ladder(['[P:A] + (R:A)', '. + (Y)'])], [{ A: true }, { A: true }, { A: true }], ['A', 'Y']);
    // iec: one memory, read once per scan: the edge resets A and energises Y in the same scan.
    expect(t.iec).toEqual([[0, 1], [1, 0], [1, 0]]);
    // openplc: the second R_TRIG saw A already reset in scan 1, and sees its own rising edge in scan 2.
    expect(t.openplc).toEqual([[0, 0], [1, 1], [1, 0]]);
    const { program } = compileProgram(project(V, [ladder(['[P:A] + (R:A)', '. + (Y)'])], 'openplc'));
    expect(program!.edgeCount).toBe(2);
  });
});

describe('openplc: blocks run once, when a coil first needs them', () => {
  const timer = { row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#20ms' } };

  test('an FB whose output reaches only the right rail runs after every coil of the POU (the lamp is one scan late)', () => {
    // Lamp := T1.Q;
    // T1(IN := Run, PT := T#20ms);   (* no coil needs T1: generated after every coil *)
    const networks = [ladder(['[Run] # # -', '. # # .'], { boxes: [timer] }), ladder(['[T1.Q] (Lamp)'])];
    const t = both(V, networks, [{ Run: true }, {}, {}, {}], ['T1.Q', 'Lamp']);
    expect(t.iec).toEqual([[0, 0], [0, 0], [1, 1], [1, 1]]);
    expect(t.openplc).toEqual([[0, 0], [0, 0], [1, 0], [1, 1]]);
  });

  test('an FB runs at the turn of the first coil that needs it, not at its own position', () => {
    // Mid := T1.Q;                    (* Mid is drawn above Lamp *)
    // T1(IN := Run, PT := T#20ms);    (* Lamp needs T1 through the connector C *)
    // Lamp := T1.Q;
    const net = ladder(['[Run] # # >C>| .', '. # # . .', '[T1.Q] - - - (Mid)', '|>C> - - - (Lamp)'], { boxes: [timer] });
    const t = both(V, [net], [{ Run: true }, {}, {}, {}], ['Mid', 'Lamp']);
    expect(t.iec).toEqual([[0, 0], [0, 0], [1, 1], [1, 1]]);
    expect(t.openplc).toEqual([[0, 0], [0, 0], [0, 1], [1, 1]]);
  });

  test('a block read by two coils runs once: the second coil reads its stored output', () => {
    // X := T1.Q;  (* T1 called here, once *)   Y := T1.Q;
    const net = ladder(['[Run] # # - + (X)', '. # # . + .', '. . . . + (Y)'], { boxes: [timer] });
    const { program } = compileProgram(project(V, [net], 'openplc'));
    expect(program!.networks[0]!.ops.filter((op) => op.op === 'fb')).toHaveLength(1);
    const t = both(V, [net], [{ Run: true }, {}, {}], ['X', 'Y']);
    expect(t.openplc).toEqual(t.iec);
    expect(t.openplc).toEqual([[0, 0], [0, 0], [1, 1]]);
  });

  test('a function with no input connected is not called under openplc (LD-W22)', () => {
    // ("MOVE" function cancelled in "Main" POU: No input connected): X keeps its value.
    const net = ladder(['. # # .'], { boxes: [{ row: 0, col: 1, type: 'MOVE', outputs: { OUT: 'I' } }] });
    const p = (profile: Profile) => project(vars('I INT := 5'), [net], profile);
    expect(checkProject(p('openplc')).some((d) => d.rule === 'LD-W22' && d.network === 0)).toBe(true);
    expect(checkProject(p('iec')).some((d) => d.rule === 'LD-W22')).toBe(false);
    const run = (profile: Profile) => {
      const plc = plcOf(p(profile));
      plc.scan();
      return plc.read('I');
    };
    expect(run('iec')).toBe(0); // the open input takes INT's initial value
    expect(run('openplc')).toBe(5); // not called: I keeps its value
  });
});

describe('openplc: a statement calls first, then reads its contacts (PLCGenerator GeneratePaths)', () => {
  const W = vars('A BOOL', 'B BOOL', 'C BOOL', 'D BOOL', 'Set BOOL', 'Rst BOOL', 'Y BOOL', 'W BOOL', 'Z BOOL', 'L SR');

  test('a contact beside a block in the same statement reads the output the block has just written', () => {
    // L(S1 := A);
    // Y := L.Q1 OR B AND L.Q1;   (* the contact L.Q1 is read after the call *)
    const net = ladder(['[L.Q1] - - - + (Y)', '[A] # # [B] + .', '. # # . .'], { boxes: [{ row: 1, col: 1, type: 'SR', instance: 'L' }] });
    const t = both(W, [net], [{ A: true }, {}], ['L.Q1', 'Y']);
    expect(t.openplc).toEqual([[1, 1], [1, 1]]);
    expect(t.iec).toEqual([[1, 0], [1, 1]]); // iec: the upper contact runs before the block
  });

  test("an edge contact's trigger reads its variable before the blocks of its own path are called", () => {
    // R_TRIG1(CLK := L.Q1);      (* ExtractModifier writes the trigger before GeneratePaths goes upstream *)
    // L(S1 := A);
    // Y := R_TRIG1.Q AND L.Q1;
    const net = ladder(['[A] # # [P:L.Q1] (Y)', '. # # . .'], { boxes: [{ row: 0, col: 1, type: 'SR', instance: 'L' }] });
    const t = both(W, [net], [{ A: true }, {}, {}], ['L.Q1', 'Y']);
    expect(t.openplc).toEqual([[1, 0], [1, 1], [1, 0]]); // the rising edge of L.Q1 is seen one scan later
    expect(t.iec).toEqual([[1, 1], [1, 0], [1, 0]]);
  });
});

describe('openplc: a part of the path that splits and joins again is written once per branch', () => {
  test('an edge contact before the split gets a trigger per branch, each reading its variable at its own place', () => {
    // R_TRIG1(CLK := L.Q1);             (* branch C *)
    // L(S1 := Set, R := Rst);           (* the block on the middle branch *)
    // R_TRIG2(CLK := L.Q1);             (* branch D: the part before the split written again *)
    // Y := C AND R_TRIG1.Q OR L.Q1 OR D AND R_TRIG2.Q;
    const V2 = vars('C BOOL', 'D BOOL', 'Set BOOL', 'Rst BOOL', 'Y BOOL', 'L SR');
    const rows = ['[P:L.Q1] + [C] - - + (Y)', '. + . # # + .', '. + . # # + .', '. + [D] - - + .'];
    const net = ladder(rows, { boxes: [{ row: 1, col: 2, type: 'SR', instance: 'L', inputs: { S1: 'Set', R: 'Rst' } }] });
    const steps: Steps = [{ Set: true, D: true }, { Set: false, Rst: true }];
    const t = both(V2, [net], steps, ['L.Q1', 'Y']);
    // Scan 2: L resets; R_TRIG1 saw L.Q1 rise (before the call), R_TRIG2 sees it fall: Y := C = FALSE.
    expect(t.openplc).toEqual([[1, 1], [0, 0]]);
    // iec: one edge memory read once: the edge holds for D too.
    expect(t.iec).toEqual([[1, 1], [0, 1]]);
    expect(compileProgram(project(V2, [net], 'openplc')).program!.edgeCount).toBe(2);
    expect(compileProgram(project(V2, [net], 'iec')).program!.edgeCount).toBe(1);
  });
});

describe('openplc: a variable beside a block output is written at its own turn', () => {
  test('a coil drawn above the output variable reads the value from before the call', () => {
    // _TMP_MOVE2_OUT := MOVE(EN := TRUE, IN := A, ENO => _TMP_MOVE2_ENO);   (* W needs the block (connector C) *)
    // W := _TMP_MOVE2_ENO AND Z;     (* Z is not written yet *)
    // IF _TMP_MOVE2_ENO THEN Z := _TMP_MOVE2_OUT; END_IF;   (* the outVariable's own statement, at its position *)
    const V3 = vars('A BOOL', 'W BOOL', 'Z BOOL');
    const net = ladder(['|>C> [Z] (W)', '- # # >C>|', '. # # .'], {
      boxes: [{ row: 1, col: 1, type: 'MOVE', inputs: { IN: 'A' }, outputs: { OUT: 'Z' } }],
    });
    const t = both(V3, [net], [{ A: true }, {}, { A: false }, {}], ['Z', 'W']);
    expect(t.openplc).toEqual([[1, 0], [1, 1], [0, 1], [0, 0]]);
    expect(t.iec).toEqual([[1, 1], [1, 1], [0, 0], [0, 0]]);
  });

  test("with the block's EN wired, the output variable is written only while ENO is on", () => {
    // Z := B;                                                        (* network 1 *)
    // _TMP_MOVE1_OUT := MOVE(EN := E, IN := A, ENO => _TMP_MOVE1_ENO);  (* network 2 *)
    // IF _TMP_MOVE1_ENO THEN Z := _TMP_MOVE1_OUT; END_IF;            (* GetUsedEno *)
    const V3 = vars('A BOOL', 'B BOOL', 'E BOOL', 'Z BOOL');
    const move = ladder(['[E] # # .', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'MOVE', inputs: { IN: 'A' }, outputs: { OUT: 'Z' } }] });
    const t = both(V3, [ladder(['[B] (Z)']), move], [{ E: true, A: true }, { E: false }], ['Z']);
    expect(t.openplc).toEqual([[1], [0]]); // not Z := the value MOVE kept from scan 1
    expect(t.iec).toEqual(t.openplc);
  });
});

describe('openplc: jumps and RETURNs are never generated', () => {
  test('a powered jump does nothing, with a located warning (LD-W20)', () => {
    const networks = [ladder(['[A] >>SKIP']), ladder(['[B] (X)']), ladder(['[B] (Y)'], { label: 'SKIP' })];
    const t = both(V, networks, [{ A: true, B: true }], ['X', 'Y']);
    expect(t.iec).toEqual([[0, 1]]);
    expect(t.openplc).toEqual([[1, 1]]);
    const warnings = checkProject(project(V, networks, 'openplc')).filter((d) => d.rule === 'LD-W20');
    expect(warnings).toHaveLength(1);
    expect(warnings[0]!.network).toBe(0);
    expect(warnings[0]!.message).toMatch(/Beremiz and OpenPLC drop this jump.*under the openplc profile it does nothing/);
    expect(checkProject(project(V, networks, 'iec')).some((d) => d.rule === 'LD-W20')).toBe(false);
  });

  test('a powered RETURN does nothing, with a located warning (LD-W21)', () => {
    const networks = [ladder(['[A] <RET>']), ladder(['[B] (X)'])];
    const t = both(V, networks, [{ A: true, B: true }], ['X']);
    expect(t.iec).toEqual([[0]]);
    expect(t.openplc).toEqual([[1]]);
    expect(checkProject(project(V, networks, 'openplc')).filter((d) => d.rule === 'LD-W21').map((d) => d.network)).toEqual([0]);
  });
});

describe('openplc: power display and Why?', () => {
  test("each element shows its latest reading, and Why? on a coil explains the coil's own reading", () => {
    const p = project(V, [ladder(['[B] + (R:B)', '. + (Y)'])], 'openplc');
    const { program } = compileProgram(p);
    const plc = createPlc(program!, { cycleMs: 10 });
    plc.write('B', true);
    plc.scan();
    const pou = p.pous[0]!;
    const index = (kind: string, variable: string) =>
      pou.networks[0]!.elements.findIndex((e) => e.kind === kind && 'variable' in e && e.variable === variable);
    const power = plc.snapshot().networks[0]!.elements;
    // Contact B: its latest reading (for Y) found B FALSE; the reset coil was energised by the first one.
    expect(power[index('contact', 'B')]! & 2).toBe(0);
    expect(power[index('coil', 'B')]! & 1).toBe(1);
    expect(power[index('coil', 'Y')]! & 1).toBe(0);
    const why = (element: number) => explain(program!, pou, liveScanView(plc, program!), { kind: 'element', network: 0, element });
    expect(why(index('coil', 'B')).lines[0]).toMatch(/energised through \| \| B/);
    expect(why(index('coil', 'Y')).lines.join('\n')).toMatch(/gets no power/);
    expect(why(index('contact', 'B')).lines.join('\n')).toMatch(/read 2 times in each scan.*this is its last reading/);
  });
});

describe('openplc: a PLCopen file imported and run under the openplc profile', () => {
  test('the fixture runs as Beremiz generates it: Y re-reads B, the lamp follows T1.Q one scan late', () => {
    const r = importPlcopen(readFileSync(join(__dirname, '../fixtures/plcopen/openplc-order.xml'), 'utf8'));
    if (!r.ok) throw new Error(JSON.stringify(r.errors));
    const run = (profile: Profile) => {
      const { program, diagnostics } = compileProgram({ ...r.project, profile }, { pou: 'Main' });
      if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
      return trace(createPlc(program, { cycleMs: 10 }), [{ B: true, Run: true }, {}, {}, {}], ['B', 'Y', 'T1.Q', 'Lamp']);
    };
    expect(run('iec')).toEqual([[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 1, 1], [0, 0, 1, 1]]);
    expect(run('openplc')).toEqual([[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]);
  });
});

describe('openplc: the export review of a project the simulator already runs that way', () => {
  test('LD-X05 stays, and says the simulation under openplc already shows the re-read', () => {
    const networks = [ladder(['[B] + (R:B)', '. + (Y)'])];
    const x05 = (profile: Profile) => exportBehaviour(project(V, networks, profile)).filter((w) => w.rule === 'LD-X05');
    expect(x05('iec')).toHaveLength(1);
    expect(x05('iec')[0]!.message).toContain("the simulator's iec profile reads it once");
    expect(x05('iec')[0]!.message).not.toContain('runs under the openplc profile');
    expect(x05('openplc')).toHaveLength(1);
    expect(x05('openplc')[0]!.message).toMatch(/runs under the openplc profile, so the simulator already reads it again/);
  });
});

// A reference of the generator's ST (PLCGenerator.py) for networks of contacts, inverting contacts,
// SR boxes and coils, written as the generator writes it: a list of statements built once, run in
// order every scan. Each coil and each variable beside a block output, by position, gets a
// statement; GeneratePaths walks its path from the coil back to the rail (a join's branches top
// first, a branch that splits and joins again once per branch), writing before the statement an
// R_TRIG/F_TRIG call for each edge contact it meets (before going further upstream) and a call for
// each block not called yet (its inputs traced the same way first); the statement's expression reads
// the plain contacts when it runs. Blocks no statement needs are called after every coil of the POU.
type Expr = () => boolean;
function generatorProgram(networks: readonly Network[], state: Map<string, boolean>): () => void {
  const program: (() => void)[] = [];
  const read = (name: string) => state.get(name.toUpperCase()) ?? false;
  const trigger = (falling: boolean) => {
    let mem = false;
    let q = false;
    return { call: (clk: boolean) => ((q = (falling ? !clk : clk) && !mem), (mem = falling ? !clk : clk)), q: () => q };
  };
  const lateBlocks: (() => void)[] = [];
  networks.forEach((network) => {
    const g = buildGraph(network);
    const outputs = new Map<number, Expr>(); // ComputedBlocks: a block's output, read when an expression runs
    const byPosition = (a: { node: number }, b: { node: number }) => {
      const x = g.nodes[a.node]!.el;
      const y = g.nodes[b.node]!.el;
      return x.row - y.row || x.col - y.col;
    };
    const fed = (net: number) => upstream(g, net).fed;
    const paths = (net: number): Expr => {
      const n = g.nets[net]!;
      if (n.leftRail) return () => true;
      const terms = [...n.sources].sort(byPosition).map(source);
      // A one-way bridge (a fan-out into two different ORs) is one more term of the OR.
      for (const b of n.feeds) terms.push(paths(g.bridges[b]!.from));
      return () => terms.map((t) => t()).some(Boolean);
    };
    const source = (s: { node: number }): Expr => {
      const node = g.nodes[s.node]!;
      const el = node.el;
      if (el.kind === 'box' || (el.kind === 'contact' && el.contact === 'NOT')) return block(s.node);
      if (el.kind === 'coil') return paths(node.inputs[0]!.net);
      if (el.kind !== 'contact') return () => false;
      let own: Expr = () => read(el.variable);
      if (el.contact === 'NC') own = () => !read(el.variable);
      if (el.contact === 'P' || el.contact === 'N') {
        const t = trigger(el.contact === 'N');
        program.push(() => t.call(read(el.variable))); // R_TRIGn(CLK := v);
        own = t.q;
      }
      const up = paths(node.inputs[0]!.net);
      return () => own() && up();
    };
    const block = (ni: number): Expr => {
      const known = outputs.get(ni);
      if (known) return known;
      const node = g.nodes[ni]!;
      const el = node.el;
      if (el.kind === 'contact') {
        // NOT: cancelled (FALSE) when its input is not connected.
        let out = false;
        outputs.set(ni, () => out);
        const input = node.inputs[0]!.net;
        if (fed(input)) {
          const e = paths(input);
          program.push(() => (out = !e()));
        }
        return () => out;
      }
      if (el.kind !== 'box') return () => false;
      // SR: Q1 := S1 OR (NOT R AND Q1); an input with no wire takes the variable beside it, else keeps its value.
      const q = `${el.instance}.Q1`;
      outputs.set(ni, () => read(q));
      const pins = ['S1', 'R'].map((pin) => {
        const t = node.inputs.find((i) => i.pin === pin)!;
        if (fed(t.net)) return paths(t.net);
        const operand = el.inputs[pin];
        return operand ? () => read(operand) : undefined;
      });
      const held = { s1: false, r: false };
      program.push(() => {
        held.s1 = pins[0] ? pins[0]() : held.s1;
        held.r = pins[1] ? pins[1]() : held.r;
        state.set(q.toUpperCase(), held.s1 || (!held.r && read(q)));
      });
      return () => read(q);
    };
    const turns: { row: number; col: number; run: () => void }[] = [];
    g.nodes.forEach((node, i) => {
      const el = node.el;
      if (el.kind === 'box' && el.outputs.Q1)
        turns.push({ row: el.row, col: el.col + 2, run: () => {
          const q = block(i);
          program.push(() => state.set(el.outputs.Q1!.toUpperCase(), q())); // X := L.Q1;
        } });
      if (el.kind !== 'coil') return;
      turns.push({ row: el.row, col: el.col, run: () => {
        const input = node.inputs[0]!.net;
        if (!fed(input)) return;
        const p = paths(input);
        const name = el.variable.toUpperCase();
        let mem = false;
        const edge = (clk: boolean) => {
          const q = clk && !mem;
          mem = clk;
          return q;
        };
        program.push(() => {
          const v = p();
          if (el.coil === 'COIL') state.set(name, v);
          else if (el.coil === 'NEG') state.set(name, !v);
          else if (el.coil === 'SET') { if (v) state.set(name, true); }
          else if (el.coil === 'RESET') { if (v) state.set(name, false); }
          else if (el.coil === 'P') state.set(name, edge(v));
          else if (el.coil === 'N') state.set(name, edge(!v));
        });
      } });
    });
    turns.sort((a, b) => a.row - b.row || a.col - b.col).forEach((t) => t.run());
    lateBlocks.push(() =>
      g.nodes
        .map((n, i) => ({ el: n.el, i }))
        .filter(({ el }) => el.kind === 'box' || (el.kind === 'contact' && el.contact === 'NOT'))
        .sort((a, b) => a.el.row - b.el.row || a.el.col - b.el.col)
        .forEach(({ i }) => block(i)),
    );
  });
  for (const late of lateBlocks) late();
  return () => program.forEach((statement) => statement());
}

describe('openplc: random networks of contacts, SR blocks and coils run as the generator writes them', () => {
  const rng = (seed: number) => {
    let s = seed >>> 0;
    return () => ((s = (s * 1664525 + 1013904223) >>> 0) / 2 ** 32);
  };
  const INPUTS = ['A', 'B', 'C'];
  const WRITTEN = ['X', 'Y', 'Z'];
  const LATCHES = ['L0', 'L1', 'L2'];
  const COILS = ['(X)', '(Y)', '(Z)', '(/X)', '(S:Y)', '(R:Y)', '(S:Z)', '(R:X)', '(P:Z)', '(N:X)'];
  const randomNetwork = (r: () => number, l: () => number, index: number): Network => {
    const pick = <T,>(xs: readonly T[], from = r) => xs[Math.floor(from() * xs.length)]!;
    const lines: string[] = [];
    const rows = 1 + Math.floor(r() * 3);
    const cols = 1 + Math.floor(r() * 3);
    for (let row = 0; row < rows; row++) {
      const tokens = ['+'];
      for (let col = 0; col < cols; col++) {
        const v = pick([...INPUTS, ...WRITTEN]);
        tokens.push(r() < 0.1 ? '-' : pick([`[${v}]`, `[${v}]`, `[/${v}]`, `[P:${v}]`, `[N:${v}]`, '[NOT]']));
        if (col < cols - 1 && r() < 0.3) tokens.push('+');
      }
      if (r() < 0.7) tokens.push('+');
      tokens.push(pick(COILS));
      lines.push(tokens.join(' '));
    }
    if (l() >= 0.7) return ladder(lines);
    // An SR latch below (its own random stream): S1 from a contact, Q1 on to a contact and a coil
    // (and maybe a variable), its output line joined to the rows above where they meet; R from a
    // contact or a variable. Its contacts often read the latch itself.
    const latch = LATCHES[index]!;
    const cell = () => {
      const v = l() < 0.3 ? `${latch}.Q1` : pick([...INPUTS, ...WRITTEN], l);
      return pick([`[${v}]`, `[${v}]`, `[/${v}]`, `[P:${v}]`, `[N:${v}]`, '[NOT]'], l);
    };
    const row = lines.length;
    const tokens = ['+', l() < 0.85 ? cell() : '-', '#', '#'];
    if (l() < 0.5) tokens.push('+');
    if (l() < 0.6) tokens.push(l() < 0.5 ? pick([`[P:${latch}.Q1]`, `[/${latch}.Q1]`], l) : cell());
    if (l() < 0.4) tokens.push('+');
    if (l() < 0.85) tokens.push(pick(COILS, l));
    const wired = l() < 0.5;
    lines.push(tokens.join(' '), `+ ${wired ? cell() : '.'} # #`);
    const inputs: Record<string, string> = wired ? {} : { R: pick([...INPUTS, ...WRITTEN], l) };
    const outputs: Record<string, string> = l() < 0.4 ? { Q1: pick(WRITTEN, l) } : {};
    return ladder(lines, { boxes: [{ row, col: 1, type: 'SR', instance: latch, inputs, outputs }] });
  };

  test('every variable after every scan equals the reference, over 150 random programs', () => {
    let compared = 0;
    let differFromIec = 0;
    let withLatch = 0;
    for (let seed = 1; seed <= 150; seed++) {
      const r = rng(seed);
      const l = rng(seed + 1000);
      const networks = Array.from({ length: 1 + Math.floor(r() * 3) }, (_, i) => randomNetwork(r, l, i));
      const variables = vars(...[...INPUTS, ...WRITTEN].map((n) => `${n} BOOL`), ...LATCHES.map((n) => `${n} SR`));
      const { program } = compileProgram(project(variables, networks, 'openplc'));
      if (!program) continue; // a random shape the rules refuse
      if (networks.some((n) => n.elements.some((e) => e.kind === 'box'))) withLatch++;
      const iec = compileProgram(project(variables, networks, 'iec')).program!;
      const plc = createPlc(program, { cycleMs: 10 });
      const other = createPlc(iec, { cycleMs: 10 });
      const state = new Map<string, boolean>();
      const scan = generatorProgram(networks, state);
      const names = [...INPUTS, ...WRITTEN, ...LATCHES.map((latch) => `${latch}.Q1`)];
      for (let k = 0; k < 10; k++) {
        for (const n of INPUTS) {
          const v = r() < 0.5;
          plc.write(n, v);
          other.write(n, v);
          state.set(n, v);
        }
        plc.scan();
        other.scan();
        scan();
        expect(names.map((n) => plc.read(n)), `seed ${seed} scan ${k}`).toEqual(names.map((n) => state.get(n.toUpperCase()) ?? false));
        if (names.some((n) => other.read(n) !== plc.read(n))) differFromIec++;
        compared++;
      }
    }
    expect(compared).toBeGreaterThan(500);
    expect(withLatch).toBeGreaterThan(100);
    // The programs are varied enough that the two profiles often differ.
    expect(differFromIec).toBeGreaterThan(20);
  });
});

describe('openplc: dispatch loops and straight-line functions agree, late blocks included', () => {
  const dispatchOnly = { ...DEFAULT_TIERING, startAfterEvals: Infinity };
  const switchAtOnce = { ...DEFAULT_TIERING, startAfterEvals: 0, minScans: 1, msPerNetwork: 0, batch: 1 };
  // A user FB whose TON reaches only the rail (a late block of its body) and whose coil reads it.
  const blinker = pou('Blinker', 'FUNCTION_BLOCK', [...io('input', 'Go BOOL'), ...io('output', 'Lamp BOOL'), ...vars('T1 TON')], [
    ladder(['[Go] # # -', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'TON', instance: 'T1', inputs: { PT: 'T#30ms' } }] }),
    ladder(['[T1.Q] (Lamp)']),
  ]);
  const main = pou('Main', 'PROGRAM', vars('Go BOOL %IX0.0', 'Lamp BOOL %QX0.0', 'B1 Blinker'), [
    ladder(['[Go] # # (Lamp)', '. # # .'], { boxes: [{ row: 0, col: 1, type: 'Blinker', instance: 'B1' }] }),
  ]);
  // Networks drawn side by side (Network.turns): their statements run as units of the group's first network.
  const sideBySide = importPlcopen(readFileSync(join(__dirname, '../fixtures/reference/c03-networks-side-by-side.xml'), 'utf8'));
  if (!sideBySide.ok) throw new Error('c03 does not import');
  const programs = [
    ...EXAMPLES.map((e) => [e.id, e.build()] as const),
    ['user FB with a late TON', multiProject([main, blinker])] as const,
    ['networks side by side, interleaved (c03)', sideBySide.project] as const,
  ];
  test.each(programs)('%s, scan by scan (values, outputs, power)', (_id, p) => {
    const { program, diagnostics } = compileProgram({ ...p, profile: 'openplc' });
    if (!program) throw new Error(diagnostics.map((d) => d.message).join('\n'));
    const inputs = program.symbols.vars.filter((v) => v.location?.area === 'I' && v.type === 'BOOL');
    const plcs = [new ScanPlc(program, { cycleMs: 10 }, dispatchOnly), new ScanPlc(program, { cycleMs: 10 }, switchAtOnce)];
    const r = ((s: number) => () => ((s = (s * 1103515245 + 12345) % 2147483648) & 0x10000) !== 0)(11);
    const state = (plc: ScanPlc) => ({ values: plc.values(), outputs: plc.outputs(), power: plc.snapshot().networks });
    for (let scan = 1; scan <= 120; scan++) {
      const values = Object.fromEntries(inputs.map((v) => [v.locationText!, scan % 17 < 12 ? true : r()]));
      for (const plc of plcs) {
        plc.setInputs(values);
        plc.scan();
      }
      expect(state(plcs[1])).toEqual(state(plcs[0]));
    }
    // Stepping network by network shows the same networks and ends with the same values.
    const steps = plcs.map((plc) => Array.from({ length: 2 * program.networks.length + 3 }, () => plc.stepNetwork()));
    expect(steps[1]).toEqual(steps[0]);
    expect(state(plcs[1])).toEqual(state(plcs[0]));
  });

  test('in the user FB, the lamp follows its TON one scan late under openplc', () => {
    const run = (profile: Profile) => {
      const { program } = compileProgram({ ...multiProject([main, blinker]), profile });
      const plc = createPlc(program!, { cycleMs: 10 });
      return trace(plc, [{ Go: true }, {}, {}, {}, {}], ['B1.T1.Q', 'Lamp']);
    };
    expect(run('iec')).toEqual([[0, 0], [0, 0], [0, 0], [1, 1], [1, 1]]);
    expect(run('openplc')).toEqual([[0, 0], [0, 0], [0, 0], [1, 0], [1, 1]]);
  });
});
