// What the generated code of a whole program shares, beside each network's own text (codegen.ts):
// the values a generated function declares once (ProgramConstants: functions, K constants, FB
// instances), the openplc profile's units run elsewhere in a POU body (bodyUnits), and which bodies
// are straight enough to be written in place of their calls (isStraight, INLINE_OPS).
import type { Value } from '../../model/iecTypes';
import type { ResolvedFunction } from '../library/fnTypes';
import type { NetworkIR, Op } from './ir';
import { chartRanges } from '../sfc/ir';

/**
 * openplc profile: operations of a network that run elsewhere in its POU body, each group a dispatch
 * entry of its own, a *unit*, numbered after the networks and the end marker (unit j has the plan
 * index `networks.length + 1 + j`). A network's late blocks (its `late` operations) are one unit,
 * run by the body's last network in the order of its `runLate` list; each early segment (`early`:
 * an instance with an executionOrderId) is one unit, run by the body's first network before its
 * own code in the order of its `runEarly` list. A runner runs its units with one call
 * `X.late(first, end, now, scan)`. Written into the runner's code instead, 1,000 late TONs made
 * one switch case of 400 KB that V8 never optimised (bench/openplcOrder.bench.ts: 9x the iec scan).
 */
export interface BodyUnits {
  /** Each unit: the network whose nets it uses, its operations, and whether it is early. */
  readonly units: readonly { readonly owner: number; readonly ops: readonly Op[]; readonly early: boolean }[];
  /** Plan indexes [first, end) of the units each runner runs: late (by last network), early (by first network). */
  readonly late: ReadonlyMap<number, readonly [number, number]>;
  readonly early: ReadonlyMap<number, readonly [number, number]>;
}

const unitCache = new WeakMap<readonly NetworkIR[], BodyUnits>();

export function bodyUnits(networks: readonly NetworkIR[]): BodyUnits {
  let found = unitCache.get(networks);
  if (!found) {
    const units: { owner: number; ops: readonly Op[]; early: boolean }[] = [];
    const late = new Map<number, readonly [number, number]>();
    const early = new Map<number, readonly [number, number]>();
    const at = () => networks.length + 1 + units.length;
    networks.forEach((ir, i) => {
      if (ir.runEarly?.length) {
        const first = at();
        for (const [k, seg] of ir.runEarly) units.push({ owner: k, ops: networks[k]!.early![seg]!, early: true });
        early.set(i, [first, at()]);
      }
      if (ir.runLate?.length) {
        const first = at();
        for (const k of ir.runLate) units.push({ owner: k, ops: networks[k]!.late ?? [], early: false });
        late.set(i, [first, at()]);
      }
    });
    found = { units, late, early };
    unitCache.set(networks, found);
  }
  return found;
}

/** Values shared by the networks of a generated function: functions (`Cfn3`), K constants (`k0`), FB instances (`F7`). */
export class ProgramConstants {
  readonly constants: Value[] = [];
  readonly functionsUsed = new Set<number>();
  readonly fbsUsed = new Set<number>();
  private readonly byKey = new Map<string, number>();
  private readonly straightBodies = new Map<number, number>();
  constructor(
    readonly functions: readonly ResolvedFunction[],
    readonly fbTypes: readonly string[],
    /**
     * The program's networks and their power words: with `inlineCalls`, a call of a body without
     * jumps or RETURN has the body's code written in place (no nested dispatch, as fast as the
     * same logic drawn inline); otherwise calls run their body through `X.call` (stepping).
     */
    readonly program?: { readonly networks: readonly NetworkIR[]; readonly words: ArrayLike<number> },
    readonly inlineCalls = true,
  ) {}
  /** openplc profile: the plan indexes [first, end) of the late or early units network `i` runs (see bodyUnits). */
  units(i: number, kind: 'late' | 'early'): readonly [number, number] {
    const u = bodyUnits(this.program!.networks)[kind].get(i);
    if (u === undefined) throw new Error(`network ${i + 1} runs no ${kind} units`);
    return u;
  }
  /** True when the body [first, end) is written in place of its calls. */
  inlines(first: number, end: number): boolean {
    return this.inlinedOps(first, end) !== undefined;
  }
  /** Operations the body [first, end) adds where it is written in place (undefined: it is called). */
  inlinedOps(first: number, end: number): number | undefined {
    if (!this.inlineCalls || !this.program) return undefined;
    let hit = this.straightBodies.get(first);
    if (hit === undefined) {
      hit = straightOps(this.program.networks, first, end) ?? -1;
      this.straightBodies.set(first, hit);
    }
    return hit < 0 ? undefined : hit;
  }
  /** Name of a K constant (bigints, non-finite numbers, -0). */
  constant(v: Value): string {
    const key = `${typeof v}:${Object.is(v, -0) ? '-0' : String(v)}`;
    let i = this.byKey.get(key);
    if (i === undefined) {
      i = this.constants.length;
      this.constants.push(v);
      this.byKey.set(key, i);
    }
    return `k${i}`;
  }
  /** Declarations the dispatch functions start with. */
  head(): string[] {
    return [
      ...[...this.functionsUsed].map((f) => `const Cfn${f} = fns[${f}];`),
      ...this.constants.map((_, i) => `const k${i} = K[${i}];`),
      ...[...this.fbsUsed].map((f) => `const F${f} = fb[${f}]; // ${this.fbTypes[f]}`),
    ];
  }
}

/** Most operations (nested bodies written in place included) of a body written in place of its calls. */
export const INLINE_OPS = 200;

/**
 * A body without jumps or RETURN runs its networks once each, in order: its calls can hold its
 * code, when it is small enough (every call of it repeats the code, and a function V8 optimises
 * has a size limit).
 */
export function isStraight(networks: readonly NetworkIR[], first: number, end: number): boolean {
  return straightOps(networks, first, end) !== undefined;
}

/** The operations of a straight body with the nested bodies written in it; undefined when it is not straight. */
function straightOps(networks: readonly NetworkIR[], first: number, end: number): number | undefined {
  let ops = 0;
  const visit = (a: number, b: number): boolean => {
    for (let i = a; i < b; i++)
      // The late blocks a body's last network runs are not written in it (one `X.late` call, see bodyUnits).
      for (const op of networks[i]!.ops) {
        if (op.op === 'jump' || op.op === 'return') return false;
        if (++ops > INLINE_OPS) return false;
        if (op.op === 'st') {
          ops += op.weight;
          if (ops > INLINE_OPS) return false;
          for (const c of op.calls) if (isStraight(networks, c.first, c.end) && !visit(c.first, c.end)) return false;
        }
        if (op.op === 'call' && isStraight(networks, op.first, op.end) && !visit(op.first, op.end)) return false;
        if (op.op === 'sfc')
          for (const r of chartRanges(op.chart)) if (isStraight(networks, r.first, r.end) && !visit(r.first, r.end)) return false;
      }
    return true;
  };
  return visit(first, end) ? ops : undefined;
}
