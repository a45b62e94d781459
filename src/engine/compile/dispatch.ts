// Shapes and dispatch loops: networks whose generated text is identical (same structure, other
// operands) share one `switch` case; the cases are gathered into a few dispatch functions
// `(first, end, now, scan) => next network`, each a loop that runs networks until one of
// another function's shapes, a jump, RETURN or `end`.
//
// Why: one function per run of networks made a 10,000-network program ~160 functions, each
// called once per scan; V8 optimises a function only after many calls and queues few at a time,
// so such a program ran unoptimised for tens of seconds. A loop is optimised (on-stack) within
// its first scans, and its size depends on the variety of networks, not on their number.
import type { Value } from '../../model/iecTypes';
import type { ResolvedFunction } from '../library/fnTypes';
import {
  CALL_TEXT,
  generateNetwork,
  generateUnit,
  LATE_TEXT,
  NETS_PER_WORD,
  STEP_CALL_TEXT,
  STEP_LATE_TEXT,
} from './codegen';
import { bodyUnits, ProgramConstants } from './programConstants';
import { slotKey } from './emitter';
import type { NetworkIR } from './ir';
import { yieldPoint } from '../yieldPoint';

/** What each generated dispatch factory receives, in this order. */
export const DISPATCH_PARAMS = [
  'b',
  'n',
  'g',
  'fb',
  'fns',
  'e',
  'W',
  'K',
  'ctx',
  'R',
  'S',
  'P',
  'V',
  'base',
  'shape',
  'X',
] as const;

/**
 * Most characters of case text in one dispatch function: V8 does not optimise functions beyond a
 * bytecode size (TurboFan's limit is 60 KB), and a loop must stay below it; but each change of
 * dispatch function between networks costs a return to the scanner (measured, 3,000 networks of
 * 126 shapes: 16-19 ns per network in one function of 49,000 characters, 26-60 in two).
 */
export const GROUP_CHARS = 32_000;

/**
 * Runs networks from `first`, in order, until `end`, a network of another dispatch function, a jump
 * or RETURN; returns the next network to run (-1 after RETURN) and sets S[0] to the last one run.
 */
export type DispatchFn = (first: number, end: number, now: number, scan: number) => number;

export interface DispatchPlan {
  /** Body of `new Function(...DISPATCH_PARAMS, body)` per dispatch function. */
  readonly bodies: readonly string[];
  /** Shape of each network, then -1 (the end), then of each unit (openplc, codegen.ts bodyUnits). */
  readonly shape: Int32Array;
  /** Dispatch function holding each network's (and unit's) shape. */
  readonly groupOf: Int32Array;
  /** Offset of each network's (and unit's) parameters in P and V. */
  readonly base: Int32Array;
  readonly P: Int32Array;
  readonly V: Float64Array;
  /** Positions in P of every write to a variable slot (`b:3`), to redirect while it is forced. */
  readonly writes: ReadonlyMap<string, readonly number[]>;
  /**
   * Networks writing each variable slot (units not included: they always run on the dispatch
   * loops, whose writes `writes` redirects).
   */
  readonly writers: ReadonlyMap<string, ReadonlySet<number>>;
  readonly constants: readonly Value[];
  readonly shapeCount: number;
  /** First power word of each network in W, and how many words W needs. */
  readonly words: Int32Array;
  readonly wordCount: number;
  /**
   * Body of `new Function(...DISPATCH_PARAMS, stepBody)` returning one generator function per
   * shape, `(i, now, scan) => next network`, whose calls of bodies are `yield* X.stepCall(...)`:
   * the slow path used only to step into calls (runtime/scanCycle.ts).
   */
  readonly stepBody: string;
}

/** `inlineCalls` false: every call runs its body through `X.call` (the plan for stepping into calls). */
/** First power word of each network in W. */
export function powerWords(networks: readonly NetworkIR[]): Int32Array {
  const words = new Int32Array(networks.length);
  let at = 0;
  networks.forEach((ir, i) => {
    words[i] = at;
    at += Math.ceil(ir.netCount / NETS_PER_WORD);
  });
  return words;
}

export function planDispatch(
  networks: readonly NetworkIR[],
  functions: readonly ResolvedFunction[],
  fbTypes: readonly string[],
  inlineCalls = true,
): DispatchPlan {
  const count = networks.length;
  const words = powerWords(networks);
  const wordCount = count ? words[count - 1]! + Math.ceil(networks[count - 1]!.netCount / NETS_PER_WORD) : 0;
  const pc = new ProgramConstants(functions, fbTypes, { networks, words }, inlineCalls);
  const { units } = bodyUnits(networks);
  const codes = [
    ...networks.map((ir, i) => {
      const code = generateNetwork(ir, pc, words[i]!);
      yieldPoint();
      return code;
    }),
    // The end marker's entry (no code), then the units of openplc bodies (early and late).
    { text: '', ints: [], reals: [], writes: [], arrays: [] },
    ...units.map((u) => generateUnit(networks[u.owner]!, u.ops, u.early, pc, words[u.owner]!)),
  ];

  // Shapes in order of first appearance; the argument-array sizes are part of a shape.
  const shapeIds = new Map<string, number>();
  const shapes: { text: string; arrays: readonly number[]; params: number }[] = [];
  const shape = new Int32Array(codes.length);
  const base = new Int32Array(codes.length);
  let params = 0;
  codes.forEach((c, i) => {
    if (i === count) return void (shape[i] = -1);
    const key = `${c.arrays.join(',')}\n${c.text}`;
    let s = shapeIds.get(key);
    if (s === undefined) {
      s = shapes.length;
      shapeIds.set(key, s);
      shapes.push({ text: c.text, arrays: c.arrays, params: c.ints.length });
    }
    shape[i] = s;
    base[i] = params;
    params += c.ints.length;
  });

  const P = new Int32Array(Math.max(1, params));
  const V = new Float64Array(Math.max(1, params));
  const writes = new Map<string, number[]>();
  const writers = new Map<string, Set<number>>();
  codes.forEach((c, i) => {
    const at = base[i]!;
    P.set(c.ints, at);
    V.set(c.reals, at);
    for (const w of c.writes) {
      const key = slotKey(w.store, w.slot);
      if (!writes.has(key)) writes.set(key, []);
      writes.get(key)!.push(at + w.at);
      if (i > count) continue;
      if (!writers.has(key)) writers.set(key, new Set());
      writers.get(key)!.add(i);
    }
  });

  // Consecutive shapes fill a dispatch function up to GROUP_CHARS.
  const groupOfShape: number[] = [];
  const groupCases: string[][] = [];
  const groupArrays: string[][] = [];
  let size = Infinity;
  shapes.forEach((sh, s) => {
    if (size + sh.text.length > GROUP_CHARS) {
      groupCases.push([]);
      groupArrays.push([]);
      size = 0;
    }
    size += sh.text.length;
    const g = groupCases.length - 1;
    groupOfShape.push(g);
    sh.arrays.forEach((n, j) => groupArrays[g]!.push(`const A${s}_${j} = new Array(${n}).fill(0);`));
    const text = sh.text.replace(/\$A(\d+)/g, `A${s}_$1`).split('\n');
    // Parameters of consecutive networks are consecutive: p moves on by the shape's count.
    groupCases[g]!.push(
      `case ${s}: {`,
      ...text.map((l) => `  ${l}`),
      `  p += ${sh.params};`,
      '  break;',
      '}',
    );
  });
  const head = pc.head();
  const bodies = groupCases.map((cases, g) =>
    [
      '"use strict";',
      ...head,
      ...groupArrays[g]!,
      `return function networks_shapes_${g}(i, end, now, scan) {`,
      '  let t = 0, r, eno = 0, go = 0, next = 0, p = base[i];',
      '  loop: for (; i < end; i++) {',
      '    switch (shape[i]) {',
      ...cases.map((l) => `      ${l}`),
      '      default:',
      '        break loop;',
      '    }',
      '  }',
      '  S[0] = i - 1;',
      '  return i;',
      '};',
    ].join('\n'),
  );
  const stepBody = [
    '"use strict";',
    ...head,
    ...shapes.flatMap((sh, s) => sh.arrays.map((n, j) => `const A${s}_${j} = new Array(${n}).fill(0);`)),
    `const gens = new Array(${shapes.length});`,
    ...shapes.map(
      (sh, s) =>
        `gens[${s}] = function* step_shape_${s}(i, now, scan) {\n  let t = 0, r, eno = 0, go = 0, next = 0, p = base[i];\n  ${sh.text
          .replace(/\$A(\d+)/g, `A${s}_$1`)
          .split(CALL_TEXT)
          .join(STEP_CALL_TEXT)
          .split(LATE_TEXT)
          .join(STEP_LATE_TEXT)
          .split('\n')
          .join('\n  ')}\n  return i + 1;\n};`,
    ),
    'return gens;',
  ].join('\n');
  const groupOf = new Int32Array(codes.length);
  for (let i = 0; i < codes.length; i++) if (i !== count) groupOf[i] = groupOfShape[shape[i]!]!;
  return {
    bodies,
    shape,
    groupOf,
    base,
    P,
    V,
    writes,
    writers,
    constants: pc.constants,
    shapeCount: shapes.length,
    words,
    wordCount,
    stepBody,
  };
}
