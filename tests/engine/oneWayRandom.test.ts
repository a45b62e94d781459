// Property: on random drawings of contacts, lines, vertical links and coils, the engine gives every
// coil what IEC's one-way reading of the grid gives it (LD-SEMANTICS section 1), computed here
// straight from the drawing: a bar (points joined by vertical links) is the OR of what is attached
// on its left (the left rail, element outputs, lines ending there); a line carries the bar on its
// left; a contact ANDs its input with its variable; a coil passes its input on. Coils write X, Y,
// Z, W, which no contact reads, so the order inside a network does not matter and both profiles
// must agree with the reference.
import { describe, expect, test } from 'vitest';
import { checkProject } from '../../src/engine/check';
import type { LdElement } from '../../src/model/elements';
import type { Network, Profile } from '../../src/model/project';
import { buildGraph } from '../../src/engine/compile/graph';
import { compileProgram, createPlc } from '../../src/engine/plc';
import { ladder, project, vars } from './ladder';

const INPUTS = ['A', 'B', 'C', 'D'];
const COILS = ['X', 'Y', 'Z', 'W'];

function rng(seed: number) {
  let s = seed >>> 0 || 1;
  return () => ((s = (s * 1103515245 + 12345) >>> 0) & 0x7fffffff) / 0x80000000;
}

/** A random drawing in the row notation of ladder.ts: coils in the last column, `+` for bars. */
function randomDrawing(r: () => number): Network {
  const rows = 2 + Math.floor(r() * 3);
  const cols = 3 + Math.floor(r() * 3);
  const lines: string[] = [];
  for (let row = 0; row < rows; row++) {
    const tokens: string[] = [];
    for (let col = 0; col < cols; col++) {
      if (col > 0 && r() < 0.35) tokens.push('+');
      if (col === cols - 1) {
        tokens.push(r() < 0.6 ? `(${COILS[Math.floor(r() * COILS.length)]})` : r() < 0.5 ? '-' : '.');
        continue;
      }
      const x = r();
      const v = INPUTS[Math.floor(r() * INPUTS.length)];
      tokens.push(x < 0.35 ? '-' : x < 0.6 ? `[${v}]` : x < 0.7 ? `[/${v}]` : '.');
    }
    if (r() < 0.3) tokens.push('+');
    lines.push(tokens.join(' '));
  }
  return ladder(lines, { cols });
}

/** The state of every coil's input under IEC's one-way reading; undefined: fed by nothing. */
function reference(net: Network, inputs: ReadonlyMap<string, boolean>): Map<LdElement, boolean | undefined> {
  const W = net.cols + 1;
  const bar = new Map<number, number>(); // point -> bar id (lowest point of the bar)
  const find = (p: number): number => {
    let q = p;
    while (bar.has(q) && bar.get(q) !== q) q = bar.get(q)!;
    return q;
  };
  for (const v of net.vlinks) {
    const a = find(v.row * W + v.boundary);
    const b = find((v.row + 1) * W + v.boundary);
    if (a !== b) bar.set(Math.max(a, b), Math.min(a, b));
    bar.set(Math.min(a, b), Math.min(a, b));
  }
  const points = (root: number) => {
    const out: number[] = [];
    for (let p = 0; p < net.rows * W; p++) if (find(p) === root) out.push(p);
    return out;
  };
  const at = (p: number) => net.elements.filter((e) => e.row * W + e.col + 1 === p); // elements ending at p
  const memo = new Map<number, boolean | undefined>();
  /** State of the bar of point p: undefined when nothing feeds it. */
  const state = (p: number): boolean | undefined => {
    const root = find(p);
    if (memo.has(root)) return memo.get(root);
    memo.set(root, undefined);
    let fed = false;
    let on = false;
    for (const q of points(root)) {
      if (q % W === 0) {
        fed = true;
        on = true;
      }
      for (const el of at(q)) {
        const input = state(el.row * W + el.col);
        if (input === undefined) continue;
        fed = true;
        if (el.kind === 'link' || el.kind === 'coil') on ||= input;
        else if (el.kind === 'contact') on ||= input && (el.contact === 'NC' ? !inputs.get(el.variable)! : inputs.get(el.variable)!);
      }
    }
    const v = fed ? on : undefined;
    memo.set(root, v);
    return v;
  };
  const out = new Map<LdElement, boolean | undefined>();
  for (const el of net.elements) if (el.kind === 'coil') out.set(el, state(el.row * W + el.col));
  return out;
}

describe('one-way vertical links on random drawings', () => {
  test.each<Profile>(['iec', 'openplc'])('every coil gets what reaches it from its left (%s, 400 drawings)', (profile) => {
    const r = rng(profile === 'iec' ? 61131 : 3);
    let accepted = 0;
    let split = 0;
    for (let k = 0; k < 400; k++) {
      const net = randomDrawing(r);
      const p = project(vars(...[...INPUTS, ...COILS].map((n) => `${n} BOOL`)), [net], profile);
      if (checkProject(p).some((d) => d.severity === 'error')) continue;
      const { program } = compileProgram(p);
      const plc = createPlc(program!, { cycleMs: 10 });
      accepted++;
      // Where two coils of one variable disagree, the last one in the engine's order wins: skip those variables.
      const coils = net.elements.filter((e) => e.kind === 'coil');
      const single = COILS.filter((v) => coils.filter((c) => c.kind === 'coil' && c.variable === v).length === 1);
      for (let scan = 0; scan < 8; scan++) {
        const inputs = new Map(INPUTS.map((n) => [n, r() < 0.5]));
        for (const [n, v] of inputs) plc.write(n, v);
        const before = new Map(COILS.map((n) => [n, plc.read(n)]));
        plc.scan();
        const want = reference(net, inputs);
        for (const [el, v] of want) {
          if (el.kind !== 'coil' || !single.includes(el.variable)) continue;
          const expected = v === undefined ? before.get(el.variable) : v;
          expect(plc.read(el.variable), `drawing ${k} scan ${scan}: ${JSON.stringify(net.elements.map((e) => [e.kind, e.row, e.col, 'variable' in e ? e.variable : '']))} ${JSON.stringify(net.vlinks)}`).toBe(expected);
        }
      }
      if (buildGraph(net).bridges.length) split++;
    }
    expect(accepted).toBeGreaterThan(300);
    // Some of them hold a wire the one-way reading splits (a fan-out into different ORs).
    expect(split).toBeGreaterThan(25);
  });
});
