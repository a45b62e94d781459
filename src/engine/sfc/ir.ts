// The checked form of a chart that code generation turns into one cycle of MATIEC's SFC code.
import type { StOp } from '../st/lowered';
import type { Access } from '../compile/symbols';

/** A range of the program's networks (a body lowered from LD). */
export interface RangeIR {
  readonly first: number;
  readonly end: number;
}

export interface StepIR {
  readonly name: string;
  /** Step.X, Step.T (watchable as `Instance.Step.X`), and X of the previous cycle. */
  readonly x: Access;
  readonly t: Access;
  readonly prev: Access;
}

export interface ActionIR {
  readonly name: string;
  /** MATIEC's action record: Q (`state`), set, reset, stored and the SD/DS/SL countdowns. */
  readonly state: Access;
  readonly set: Access;
  readonly reset: Access;
  readonly stored: Access;
  readonly setTime: Access;
  readonly resetTime: Access;
  /** A BOOL variable used as an action (N, S, R... write it directly). */
  readonly variable?: Access;
  /** An LD body (a range of networks) or ST statements (an `st` operation run in place). */
  readonly body?: { readonly range: RangeIR } | { readonly st: StOp };
}

export interface TransitionIR {
  readonly from: readonly number[];
  readonly to: readonly number[];
  readonly priority: boolean;
  /** The transition's value in this cycle (MATIEC's __transition_list[k]). */
  readonly flag: Access;
  /** ST: statements assigning `flag`; LD: a body writing `result`. */
  readonly condition: { readonly st: StOp } | { readonly range: RangeIR; readonly result: Access };
}

export interface AssociationIR {
  readonly step: number;
  readonly action: number;
  readonly qualifier: string;
  /** Duration of L, D, SD, DS, SL in ms. */
  readonly time: number;
}

export interface ChartIR {
  readonly pou: string;
  readonly lasttick: Access;
  readonly steps: readonly StepIR[];
  readonly actions: readonly ActionIR[];
  /** In text order. */
  readonly transitions: readonly TransitionIR[];
  /** Transitions in the order they are tested: by PRIORITY first (MATIEC's list), text order otherwise. */
  readonly testOrder: readonly number[];
  /** Per step in text order, its associations in order. */
  readonly associations: readonly AssociationIR[];
  /** Actions that are BOOL variables, in the order they were first associated. */
  readonly variables: readonly number[];
  /** Actions with a body, in text order. */
  readonly bodies: readonly number[];
}

/** Every range a chart runs, its LD pieces and the calls of its ST (for size estimates). */
export function chartRanges(c: ChartIR): RangeIR[] {
  const out: RangeIR[] = [];
  for (const t of c.transitions) out.push(...('range' in t.condition ? [t.condition.range] : t.condition.st.calls));
  for (const a of c.actions) if (a.body) out.push(...('range' in a.body ? [a.body.range] : a.body.st.calls));
  return out;
}

/** A chart's cycle, alone in the network that stands for its POU's body (see sfc/body.ts). */
export interface SfcOp {
  readonly op: 'sfc';
  readonly node: number;
  readonly chart: ChartIR;
}
