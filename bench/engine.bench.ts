// npm run bench:engine — compile time, scan speed and memory of the LD engine on generated programs
// of 1,000 and 10,000 networks (mixed contacts, branches, coils; one TON and one CTU every 10
// networks), against hand-written straight-line JavaScript for the same logic in the same process;
// then 100 and 1,000 calls of a user FB against the same logic drawn inline (userBlocksBench.ts),
// and 1,000 calls of it from one ST body against the same calls from LD networks (stCallsBench.ts).
//
// Fairness: the baseline is generated from the same rung descriptions as plain JS over plain
// variables (0/1 numbers, bitwise logic), in functions of 100 rungs, calling the same TON/CTU
// classes the engine uses. Both run the same scans and their outputs are compared at the end.
import { setFlagsFromString } from 'node:v8';
import { runInNewContext } from 'node:vm';
import type { LdElement, VLink } from '../src/model/elements';
import { newNetwork, newPou, newProject, variable } from '../src/model/factory';
import type { ElementId } from '../src/model/ids';
import type { Network, Project, Variable } from '../src/model/project';
import { compileProgram, createPlc } from '../src/engine/plc';
import { createFb } from '../src/engine/library/fbs';
import { compareMotorPrograms, fbProject, inlineProject } from './userBlocksBench';
import { measureStCalls } from './stCallsBench';

type Rung =
  | { kind: 'branch'; a: string; b: string; c: string; d: string; out: string }
  | { kind: 'parallel'; a: string; b: string; c: string; out: string; latch: string; edge: number }
  | { kind: 'ton'; in: string; inst: string; out: string }
  | { kind: 'ctu'; in: string; reset: string; inst: string; out: string };

/** Deterministic pseudo-random numbers (mulberry32). */
function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function rungs(count: number): { rungs: Rung[]; bools: string[]; tons: string[]; ctus: string[] } {
  const rand = rng(count);
  const bools = ['Tick', ...Array.from({ length: 32 }, (_, i) => `I${i}`)];
  const readable = [...bools];
  const pick = () => readable[Math.floor(rand() * readable.length)]!;
  const out: Rung[] = [];
  const tons: string[] = [];
  const ctus: string[] = [];
  let edges = 0;
  for (let k = 0; k < count; k++) {
    const o = `O${k}`;
    bools.push(o);
    if (k % 10 === 3) {
      tons.push(`T${k}`);
      out.push({ kind: 'ton', in: pick(), inst: `T${k}`, out: o });
    } else if (k % 10 === 7) {
      ctus.push(`C${k}`);
      out.push({ kind: 'ctu', in: pick(), reset: pick(), inst: `C${k}`, out: o });
    } else if (k % 2 === 0) {
      out.push({ kind: 'branch', a: pick(), b: pick(), c: pick(), d: pick(), out: o });
    } else {
      bools.push(`L${k}`);
      out.push({ kind: 'parallel', a: pick(), b: pick(), c: pick(), out: o, latch: `L${k}`, edge: edges++ });
    }
    readable.push(o);
  }
  return { rungs: out, bools, tons, ctus };
}

let ids = 0;
const id = () => `b${++ids}` as ElementId;
const contact = (row: number, col: number, v: string, type: 'NO' | 'NC' | 'P' = 'NO'): LdElement => ({
  id: id(),
  kind: 'contact',
  contact: type,
  variable: v,
  row,
  col,
});
const coil = (row: number, col: number, v: string, type: 'COIL' | 'SET' = 'COIL'): LdElement => ({
  id: id(),
  kind: 'coil',
  coil: type,
  variable: v,
  row,
  col,
});
const link = (row: number, col: number): LdElement => ({ id: id(), kind: 'link', row, col });

function toNetwork(r: Rung): Network {
  let elements: LdElement[];
  let vlinks: VLink[] = [];
  let rows = 2;
  switch (r.kind) {
    case 'branch': // (a OR d) AND NOT b AND c -> out
      elements = [
        contact(0, 0, r.a),
        contact(0, 1, r.b, 'NC'),
        contact(0, 2, r.c),
        link(0, 3),
        coil(0, 4, r.out),
        contact(1, 0, r.d),
      ];
      vlinks = [{ row: 0, boundary: 1 }];
      break;
    case 'parallel': // rising edge of a, AND NOT b AND c -> out, and set latch
      elements = [
        contact(0, 0, r.a, 'P'),
        contact(0, 1, r.b, 'NC'),
        contact(0, 2, r.c),
        link(0, 3),
        coil(0, 4, r.out),
        coil(1, 4, r.latch, 'SET'),
      ];
      vlinks = [{ row: 0, boundary: 4 }];
      break;
    case 'ton':
      elements = [
        contact(0, 0, r.in),
        link(0, 1),
        {
          id: id(),
          kind: 'box',
          blockType: 'TON',
          instance: r.inst,
          row: 0,
          col: 2,
          inputs: { PT: 'T#100ms' },
          outputs: {},
        },
        coil(0, 4, r.out),
      ];
      break;
    case 'ctu':
      rows = 3;
      elements = [
        contact(0, 0, r.in),
        link(0, 1),
        {
          id: id(),
          kind: 'box',
          blockType: 'CTU',
          instance: r.inst,
          row: 0,
          col: 2,
          inputs: { R: r.reset, PV: '10' },
          outputs: {},
        },
        coil(0, 4, r.out),
      ];
      break;
  }
  return newNetwork({ rows, cols: 5, elements, vlinks });
}

function toProject(count: number): Project {
  const { rungs: rs, bools, tons, ctus } = rungs(count);
  const variables: Variable[] = [
    ...bools.map((b) => variable(b, 'BOOL')),
    ...tons.map((t) => variable(t, 'TON')),
    ...ctus.map((c) => variable(c, 'CTU')),
  ];
  const tick = newNetwork({ rows: 1, cols: 2, elements: [contact(0, 0, 'Tick', 'NC'), coil(0, 1, 'Tick')] });
  return newProject('bench', {
    pous: [newPou('Main', { variables, networks: [tick, ...rs.map(toNetwork)] })],
  });
}

/** Hand-written-style JS for the same rungs: plain variables, bitwise logic, the same FB classes. */
function baseline(count: number): { scan: (now: number) => void; outputs: () => number[] } {
  const { rungs: rs, bools, tons, ctus } = rungs(count);
  // `var`, not `let`: closure variables declared with let pay a hole check on every access.
  const lines: string[] = [
    `var ${bools.map((b) => `${b} = 0`).join(', ')};`,
    `var E = new Uint8Array(${count});`,
  ];
  for (const t of [...tons, ...ctus]) lines.push(`var ${t} = mk('${t.startsWith('T') ? 'TON' : 'CTU'}');`);
  const chunks: string[] = [];
  for (let start = 0; start < rs.length; start += 100) {
    const body: string[] = [];
    if (start === 0) body.push('Tick = Tick ^ 1;');
    for (const r of rs.slice(start, start + 100)) {
      switch (r.kind) {
        case 'branch':
          body.push(`${r.out} = (${r.a} | ${r.d}) & (${r.b} ^ 1) & ${r.c};`);
          break;
        case 'parallel':
          body.push(
            `{ const e = ${r.a} & (E[${r.edge}] ^ 1); E[${r.edge}] = ${r.a}; const q = e & (${r.b} ^ 1) & ${r.c}; ${r.out} = q; if (q) ${r.latch} = 1; }`,
          );
          break;
        case 'ton':
          body.push(
            `${r.inst}.IN = ${r.in} === 1; ${r.inst}.PT = 100; ${r.inst}.execute(now); ${r.out} = ${r.inst}.Q ? 1 : 0;`,
          );
          break;
        case 'ctu':
          body.push(
            `${r.inst}.CU = ${r.in} === 1; ${r.inst}.R = ${r.reset} === 1; ${r.inst}.PV = 10; ${r.inst}.execute(now); ${r.out} = ${r.inst}.Q ? 1 : 0;`,
          );
          break;
      }
    }
    chunks.push(`function chunk${chunks.length}(now) {\n${body.join('\n')}\n}`);
  }
  lines.push(...chunks);
  lines.push(
    `return { scan(now) { ${chunks.map((_, i) => `chunk${i}(now);`).join(' ')} }, outputs() { return [${rs.map((r) => r.out).join(', ')}]; } };`,
  );
  const make = new Function('mk', lines.join('\n')) as (mk: (t: string) => unknown) => {
    scan: (now: number) => void;
    outputs: () => number[];
  };
  return make((t) => createFb(t, 'iec'));
}

setFlagsFromString('--expose_gc');
// V8 runs with its default settings (as in a browser's Web Worker); node's flags are printed so a
// run with tuned flags is not mistaken for a normal one.
const loaders = new Set(['--require', '-r', '--import', '--loader', '--experimental-loader']);
const v8Flags = process.execArgv.filter(
  (a, i) => !loaders.has(a) && !loaders.has(process.execArgv[i - 1] ?? ''),
);
console.log(`node ${process.version}, V8 flags: ${v8Flags.join(' ') || 'default'}`);

const gc = runInNewContext('gc') as () => void;

function measure(count: number, scans: number, warmMs: number): { ratio: number; nsEngine: number } {
  const t0 = performance.now();
  const { program, diagnostics } = compileProgram(toProject(count));
  if (!program) throw new Error(`bench program does not compile: ${diagnostics[0]?.message}`);
  // A generous time budget: the first scans of a big program include V8's compilation.
  const plc = createPlc(program, { cycleMs: 10, maxScanMs: 60_000 });
  const compileMs = performance.now() - t0;
  const base = baseline(count);

  // Warm up both, then time alternately (five rounds each, best kept) so neither gets a quieter machine.
  // V8 optimises both sides' code concurrently; the baseline's 10,000 rungs (100 functions) need
  // some 10 s on a busy machine before they all run optimised. Warm up for at least `warmMs`,
  // then until both sides' scan times are steady (5 rounds within 5%), at most 3 x warmMs. Every
  // round's time is kept to tell when each side reached its steady speed.
  let baseScans = 0;
  const perRound = Math.max(10, Math.round(100_000 / count));
  const started = performance.now();
  const history: { at: number; e: number; b: number }[] = [];
  let prev = [Infinity, Infinity];
  let steady = 0;
  while (performance.now() - started < 3 * warmMs) {
    let t = performance.now();
    plc.scans(perRound);
    const e = performance.now() - t;
    t = performance.now();
    for (let s = 0; s < perRound; s++) base.scan(baseScans++ * 10);
    const b = performance.now() - t;
    history.push({ at: t - started, e: e / perRound, b: b / perRound });
    steady = Math.abs(e - prev[0]!) < 0.05 * e && Math.abs(b - prev[1]!) < 0.05 * b ? steady + 1 : 0;
    prev = [e, b];
    if (steady >= 5 && performance.now() - started >= warmMs) break;
  }
  const warmS = (performance.now() - started) / 1000;
  let bestEngine = Infinity;
  let bestBase = Infinity;
  for (let round = 0; round < 5; round++) {
    let t = performance.now();
    plc.scans(scans);
    bestEngine = Math.min(bestEngine, performance.now() - t);
    t = performance.now();
    for (let s = 0; s < scans; s++) base.scan((baseScans + s) * 10);
    baseScans += scans;
    bestBase = Math.min(bestBase, performance.now() - t);
  }
  const networks = count + 1;
  const nsEngine = (bestEngine * 1e6) / (scans * networks);
  const nsBase = (bestBase * 1e6) / (scans * networks);

  // Same logic, same results: both ran the same number of scans from the same start.
  if (plc.fault) throw new Error(`the PLC faulted: ${plc.fault.message}`);
  const baseOut = base.outputs();
  let mismatches = 0;
  for (let k = 0; k < count; k++) if ((plc.read(`O${k}`) ? 1 : 0) !== baseOut[k]) mismatches++;

  // Memory: heap after many scans, with a full GC before and after.
  gc();
  const before = process.memoryUsage().heapUsed;
  const memScans = count >= 10_000 ? 2_000 : 20_000;
  plc.scans(memScans);
  gc();
  const growth = (process.memoryUsage().heapUsed - before) / memScans;

  // Time to steady speed: when the median scan time over the next half second of warm-up first
  // comes within 20% of the lowest such median (single rounds are too noisy on a shared machine).
  const steadyAt = (side: 'e' | 'b'): number => {
    const medians = history.map((h, k) => {
      const window = history
        .slice(k)
        .filter((w) => w.at < h.at + 500)
        .map((w) => w[side]);
      return window.sort((x, y) => x - y)[Math.floor(window.length / 2)]!;
    });
    const last = history.findIndex((h) => h.at > history[history.length - 1]!.at - 500);
    const floor = Math.min(...medians.slice(0, Math.max(1, last)));
    return history[medians.findIndex((m) => m <= 1.2 * floor)]!.at / 1000;
  };
  const toSteadyEngine = steadyAt('e');
  const toSteadyBase = steadyAt('b');

  const ratio = nsEngine / nsBase;
  console.log(
    `${count.toLocaleString('en-US')} networks: compile ${compileMs.toFixed(0)} ms; warm-up ${warmS.toFixed(1)} s (${steady >= 5 ? 'steady' : 'not steady: V8 still optimising'}); ` +
      `time to steady speed: engine ${toSteadyEngine.toFixed(1)} s, baseline ${toSteadyBase.toFixed(1)} s; ` +
      `engine ${nsEngine.toFixed(1)} ns/network/scan; baseline JS ${nsBase.toFixed(1)} ns/network/scan; ratio ${ratio.toFixed(2)}; ` +
      `heap growth ${growth.toFixed(2)} bytes/scan over ${memScans.toLocaleString('en-US')} scans; ` +
      `outputs ${mismatches === 0 ? 'agree' : `DIFFER in ${mismatches} networks`}`,
  );
  if (mismatches) process.exitCode = 1;
  return { ratio, nsEngine };
}

/**
 * User FBs: N calls of a 3-network Motor FB (seal-in, TON, permissive) against the same logic drawn
 * inline (3 networks per motor), both compiled by the engine; outputs compared at the end.
 */
function measureCalls(count: number, warmMs: number): { ratio: number; usFb: number } {
  const { usA: usInline, usB: usFb, mismatches } = compareMotorPrograms(inlineProject(count), fbProject(count), count, warmMs);
  const ratio = usFb / usInline;
  console.log(
    `${count.toLocaleString('en-US')} calls of a 3-network FB: ${usFb.toFixed(1)} µs/scan; ` +
      `same logic inline (${(3 * count).toLocaleString('en-US')} networks): ${usInline.toFixed(1)} µs/scan; ` +
      `ratio ${ratio.toFixed(2)}; outputs ${mismatches === 0 ? 'agree' : `DIFFER for ${mismatches} motors`}`,
  );
  if (mismatches) process.exitCode = 1;
  return { ratio, usFb };
}

const small = measure(1_000, 2_000, 6_000);
const large = measure(10_000, 200, 15_000);
const calls100 = measureCalls(100, 3_000);
const calls1000 = measureCalls(1_000, 6_000);
const st1000 = measureStCalls(1_000, 8_000);
console.log(
  `bench:engine worst-ratio=${Math.max(small.ratio, large.ratio).toFixed(2)} ns-per-network-10k=${Math.round(large.nsEngine)} ` +
    `fb-calls-ratio-100=${calls100.ratio.toFixed(2)} fb-calls-ratio-1000=${calls1000.ratio.toFixed(2)} fb-1000-calls-us-per-scan=${calls1000.usFb.toFixed(1)} ` +
    `st-1000-calls-us-per-scan=${st1000.usSt.toFixed(1)} ld-1000-calls-us-per-scan=${st1000.usLd.toFixed(1)} st-vs-ld-ratio=${st1000.ratio.toFixed(2)}`,
);
