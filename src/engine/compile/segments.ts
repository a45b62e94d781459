// Straight-line functions for runs of networks (segments): every operand a literal, FB instances
// and functions closure constants. Once V8 has optimised them they run about twice as fast as the
// dispatch loops (dispatch.ts), but V8 needs a few hundred calls and, on a busy machine, some
// 100 ms of background compilation per segment first. The runtime therefore starts every program
// on the dispatch loops and moves segments over a few at a time (runtime/tiering.ts).
import type { ResolvedFunction } from '../library/fnTypes';
import { generateNetwork } from './codegen';
import type { CodeMode } from './emitter';
import { ProgramConstants } from './programConstants';
import type { NetworkIR } from './ir';
import type { Value } from '../../model/iecTypes';

/** A segment: `(now, scan) => next network` (-1 after RETURN), S[0] = last network run. */
export type SegmentFn = (now: number, scan: number) => number;

/** Most operations and networks in one segment (V8 optimises functions only up to a size). */
export const SEGMENT_OPS = 400;
export const SEGMENT_NETWORKS = 64;

/**
 * Segment starts: runs of consecutive networks that end before every jump target (so jumps land
 * on a segment start) and after SEGMENT_NETWORKS networks or about SEGMENT_OPS operations.
 * Returns the first network of each segment, then the network count.
 */
export function planSegments(networks: readonly NetworkIR[], bodyStarts: readonly number[] = []): number[] {
  // Jump targets and the first network of every body (programs, calls) start a segment.
  const targets = new Set([
    ...networks.flatMap((ir) => ir.ops.flatMap((op) => (op.op === 'jump' ? [op.target] : []))),
    ...bodyStarts,
  ]);
  // A call's body may be written in place: its operations count where the call is.
  const weights = new Map<number, number>();
  const weight = (i: number): number => {
    let w = weights.get(i);
    if (w === undefined) {
      w = 1;
      // openplc: the late blocks a body's last network runs are one call there (codegen.ts bodyUnits).
      for (const op of networks[i]!.ops) {
        w++;
        if (op.op === 'call') for (let k = op.first; k < op.end; k++) w += weight(k);
        if (op.op === 'st') {
          w += op.weight;
          for (const c of op.calls) for (let k = c.first; k < c.end; k++) w += weight(k);
        }
      }
      weights.set(i, w);
    }
    return w;
  };
  const starts: number[] = [];
  let start = -1;
  let ops = 0;
  networks.forEach((_, i) => {
    const size = weight(i);
    if (start < 0 || targets.has(i) || ops + size > SEGMENT_OPS || i - start >= SEGMENT_NETWORKS) {
      start = i;
      ops = 0;
      starts.push(i);
    }
    ops += size;
  });
  starts.push(networks.length);
  return starts;
}

/** Body of `new Function(...DISPATCH_PARAMS, body)` returning the segment function for networks [first, end). */
export function generateSegment(
  networks: readonly NetworkIR[],
  first: number,
  end: number,
  functions: readonly ResolvedFunction[],
  fbTypes: readonly string[],
  words: ArrayLike<number>,
  mode: Extract<CodeMode, { kind: 'inline' }>,
): { body: string; constants: readonly Value[] } {
  const pc = new ProgramConstants(functions, fbTypes, { networks, words });
  const lines: string[] = [];
  const arrays: string[] = [];
  for (let i = first; i < end; i++) {
    const code = generateNetwork(networks[i]!, pc, words[i]!, mode);
    code.arrays.forEach((n, j) => arrays.push(`const A${i}_${j} = new Array(${n}).fill(0);`));
    lines.push(`{ // network ${i + 1}`, code.text.replace(/\$A(\d+)/g, `A${i}_$1`), '}');
  }
  const body = [
    '"use strict";',
    ...pc.head(),
    ...arrays,
    `return function networks_${first + 1}_to_${end}(now, scan) {`,
    'let t = 0, r, eno = 0, go = 0, next = 0;',
    ...lines,
    `S[0] = ${end - 1};`,
    `return ${end};`,
    '};',
  ].join('\n');
  return { body, constants: pc.constants };
}
