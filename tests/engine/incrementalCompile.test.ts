// A compile of an edited project reuses what the networks the edit did not touch gave the compile
// before (their graphs and structural findings, compile/graph.ts and structure.ts, kept per network
// object): the program must behave exactly as a compile of the same project from scratch, scan by
// scan, display included, and an online change must keep the same state.
import { describe, expect, test } from 'vitest';
import type { Plc } from '../../src/engine/api';
import { buildGraph } from '../../src/engine/compile/graph';
import { compileProgram, createPlc } from '../../src/engine/plc';
import type { BoxElement, LdElement } from '../../src/model/elements';
import { newId } from '../../src/model/ids';
import type { Network, Pou, Project } from '../../src/model/project';
import { bottleFillerProject } from '../../bench/bottleFiller';
import { ladder } from './ladder';

/** A compile of `p` from scratch: every object new, nothing remembered from an earlier compile can match. */
const fresh = (p: Project): Project => structuredClone(p);

function compiled(p: Project) {
  const { program, diagnostics } = compileProgram(p);
  return { program, diagnostics };
}

function plcOf(p: Project): Plc {
  const { program, diagnostics } = compiled(p);
  if (!program) throw new Error(`does not compile: ${JSON.stringify(diagnostics)}`);
  return createPlc(program, { cycleMs: 10 });
}

/** The inputs of the bottle filler (every BOOL global at an %I address), switched in a fixed pattern. */
function inputsOf(p: Project): string[] {
  return p.globals.filter((v) => v.type === 'BOOL' && (v.location ?? '').startsWith('%I')).map((v) => v.name);
}

/** What a scan shows: every variable's value and the power of every network. */
function observe(plc: Plc) {
  return { values: plc.values(), power: plc.snapshot() };
}

/** Runs both PLCs `scans` scans with the same inputs and expects the same variables and power after each. */
function expectSameScans(a: Plc, b: Plc, inputs: readonly string[], scans: number, seed = 1): void {
  let x = seed;
  for (let k = 0; k < scans; k++) {
    for (const name of inputs) {
      x = (x * 1103515245 + 12345) % 2147483648;
      const on = (x >> 16) % 5 < 2;
      a.write(name, on);
      b.write(name, on);
    }
    a.scan();
    b.scan();
    expect(observe(a), `scan ${k + 1}`).toEqual(observe(b));
  }
}

const mainOf = (p: Project): Pou => p.pous.find((x) => x.name === 'Main')!;

function withNetworks(p: Project, pou: string, change: (nets: readonly Network[]) => Network[]): Project {
  return { ...p, pous: p.pous.map((x) => (x.name === pou ? { ...x, networks: change(x.networks) } : x)) };
}

/** The element of the first network of `pou` matching `pick`, replaced by `change` of it (a new object, as the editor makes). */
function editElement(p: Project, pou: string, pick: (e: LdElement) => boolean, change: (e: LdElement) => LdElement): Project {
  let done = false;
  return withNetworks(p, pou, (nets) =>
    nets.map((n) => {
      if (done || !n.elements.some(pick)) return n;
      done = true;
      return { ...n, elements: n.elements.map((e) => (pick(e) ? change(e) : e)) };
    }),
  );
}

const base = bottleFillerProject(3);

const edits: [string, (p: Project) => Project][] = [
  [
    'an operand retyped (the first contact reads another input)',
    (p) => {
      const inputs = inputsOf(p);
      return editElement(
        p,
        'Main',
        (e) => e.kind === 'contact' && inputs.includes(e.variable),
        (e) => ({ ...e, variable: inputs.find((n) => n !== (e as { variable: string }).variable)! }) as LdElement,
      );
    },
  ],
  ['a network added (a copy of the fifth network, new ids)', (p) => withNetworks(p, 'Main', (nets) => [...nets.slice(0, 5), renumbered(nets[4]!), ...nets.slice(5)])],
  ['a network deleted (the fourth)', (p) => withNetworks(p, 'Main', (nets) => nets.filter((_, i) => i !== 3))],
  [
    'an FB instance edited (the fill timer preset)',
    (p) =>
      editElement(
        p,
        'Main',
        (e) => e.kind === 'box' && e.blockType === 'TON',
        (e) => ({ ...(e as BoxElement), inputs: { ...(e as BoxElement).inputs, PT: 'T#70ms' } }),
      ),
  ],
  [
    "the FB's body edited (Conveyor's motor runs without its fault contact)",
    (p) =>
      withNetworks(p, 'Conveyor', (nets) =>
        nets.map((n, i) =>
          i === 1 ? { ...n, elements: [...n.elements.filter((e) => !(e.kind === 'contact' && e.variable === 'Fault')), linkAt(n, 0, 1)] } : n,
        ),
      ),
  ],
];

/** A copy of a network with new element ids (a pasted network). */
function renumbered(n: Network): Network {
  const { label: _label, ...rest } = n;
  return { ...rest, id: newId<'NetworkId'>('n'), elements: n.elements.map((e) => ({ ...e, id: newId<'ElementId'>('e') }) as LdElement) };
}

/** A horizontal line at (row, col) of a network, where an element was taken away. */
function linkAt(n: Network, row: number, col: number): LdElement {
  return { id: newId<'ElementId'>(`${n.id}-link`), kind: 'link', row, col };
}

describe('a compile of an edited project behaves as a compile from scratch', () => {
  test('the bottle filler compiles without errors (the base of the edits)', () => {
    const { program, diagnostics } = compiled(base);
    expect(diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
    expect(program).toBeDefined();
  });

  for (const [what, edit] of edits) {
    test(`${what}, compiled as the simulator runs it (its two tasks' configuration): the same findings and scans as from scratch`, () => {
      const asRun = { configuration: true } as const;
      compileProgram(base, asRun);
      const edited = edit(base);
      const incremental = compileProgram(edited, asRun);
      const scratch = compileProgram(fresh(edited), asRun);
      expect(incremental.diagnostics).toEqual(scratch.diagnostics);
      expect(incremental.program).toBeDefined();
      const a = createPlc(incremental.program!, { cycleMs: 10 });
      const b = createPlc(scratch.program!, { cycleMs: 10 });
      expectSameScans(a, b, inputsOf(base), 120);
    });

    test(`${what}: the same findings, and the same variables and power in every scan`, () => {
      // The running program's compile first (what the next compile can reuse), then the edit.
      compiled(base);
      const edited = edit(base);
      expect(edited).not.toEqual(base);
      const incremental = compiled(edited);
      const scratch = compiled(fresh(edited));
      expect(incremental.diagnostics).toEqual(scratch.diagnostics);
      expect(incremental.program?.networks.length).toBe(scratch.program?.networks.length);
      const a = createPlc(incremental.program!, { cycleMs: 10 });
      const b = createPlc(scratch.program!, { cycleMs: 10 });
      expectSameScans(a, b, inputsOf(base), 120);
    });

    test(`${what}: an online change keeps the same state and goes on the same way`, () => {
      const running = plcOf(base);
      const inputs = inputsOf(base);
      // The station runs a while (bottles counted, timers running, conveyors on), then the edit goes in.
      let x = 7;
      for (let k = 0; k < 60; k++) {
        for (const name of inputs) {
          x = (x * 1103515245 + 12345) % 2147483648;
          running.write(name, (x >> 16) % 3 === 0);
        }
        running.scan();
      }
      const edited = edit(base);
      const a = plcOf(edited);
      const b = plcOf(fresh(edited));
      const state = running.exportState();
      const ta = a.importState(state);
      const tb = b.importState(state);
      expect(ta).toEqual(tb);
      expect(observe(a).values).toEqual(observe(b).values);
      expectSameScans(a, b, inputs, 80, 3);
    });
  }

  test("a changed FB interface is seen by the unchanged networks calling it (Conveyor's new input makes its boxes one row taller than their networks)", () => {
    compiled(base);
    const edited: Project = {
      ...base,
      pous: base.pous.map((x) =>
        x.name === 'Conveyor' ? { ...x, variables: [{ ...x.variables[0]!, id: 'spare-input', name: 'Spare' }, ...x.variables] } : x,
      ),
    };
    const incremental = compiled(edited);
    expect(incremental.diagnostics).toEqual(compiled(fresh(edited)).diagnostics);
    expect(incremental.program).toBeUndefined();
    expect(incremental.diagnostics.filter((d) => d.rule === 'LD-E30').map((d) => d.message)).toContain('the Conveyor block "InfeedConv" lies outside the 2x10 grid');
  });

  test('a network whose element list was changed in place after a compile gets a new graph (never the one compiled before)', () => {
    const net = ladder(['[A] (Q)']);
    const first = buildGraph(net);
    expect(buildGraph(net)).toBe(first);
    const contact = net.elements.find((e) => e.kind === 'contact')!;
    const index = net.elements.indexOf(contact);
    (net.elements as LdElement[])[index] = { ...contact, variable: 'B' } as LdElement;
    const replaced = buildGraph(net);
    expect(replaced).not.toBe(first);
    expect(replaced.nodes.map((n) => (n.el.kind === 'contact' ? n.el.variable : '')).filter(Boolean)).toEqual(['B']);
    (net.elements as LdElement[]).push({ ...contact, id: 'outside', row: 5 } as LdElement);
    expect(buildGraph(net).misplaced.length).toBe(replaced.misplaced.length + 1);
  });

  test('a project compiled twice gives the same program as the first time (the reused parts are not changed by use)', () => {
    const p = bottleFillerProject(2);
    const once = compiled(p);
    const twice = compiled(p);
    expect(twice.diagnostics).toEqual(once.diagnostics);
    expectSameScans(createPlc(once.program!, { cycleMs: 10 }), createPlc(twice.program!, { cycleMs: 10 }), inputsOf(p), 60);
    expect(mainOf(p).networks.length).toBe(26);
  });
});
