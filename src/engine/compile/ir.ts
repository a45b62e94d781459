// The checked, ordered form of a network that code generation turns into JavaScript.
import type { CoilType, ContactType } from '../../model/elements';
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { StOp } from '../st/lowered';
import type { SfcOp } from '../sfc/ir';
import type { Access, Store } from './symbols';

/** Where a value comes from: a power-flow net (BOOL), a data slot fed by a box output, or an operand. */
export type Source =
  | { readonly from: 'power'; readonly net: number }
  | { readonly from: 'data'; readonly store: Store; readonly slot: number; readonly type: ElementaryType }
  | { readonly from: 'access'; readonly access: Access };

export interface ArgIR {
  readonly pin: string;
  /** Type the block expects at this pin (after resolving generic pins). */
  readonly type: ElementaryType;
  readonly src: Source;
}

export interface OutIR {
  readonly pin: string;
  readonly type: ElementaryType;
  /** BOOL output wired as power flow. */
  readonly net?: number;
  /** Non-BOOL output wired to other blocks: the persistent slot that carries it. */
  readonly data?: { readonly store: Store; readonly slot: number };
  /** Output assigned to a variable written beside the pin. */
  readonly dst?: Access;
}

export type Op =
  | {
      readonly op: 'contact';
      readonly node: number;
      readonly contact: ContactType;
      readonly src?: Access;
      readonly inNet: number;
      readonly outNet: number;
      /** The contact's own result when other outputs join its right side (for the power display). */
      readonly ownNet?: number;
      readonly edge?: number;
    }
  | {
      readonly op: 'coil';
      readonly node: number;
      readonly coil: CoilType;
      readonly dst: Access;
      readonly inNet: number;
      readonly outNet: number;
      readonly edge?: number;
    }
  /**
   * openplc profile: carries a value that is not re-read into an OR join of a later reading (a
   * block output computed once, or a coil's left side passed on by the coil), `out |= in`.
   */
  | { readonly op: 'pass'; readonly node: number; readonly inNet: number; readonly outNet: number }
  | { readonly op: 'jump'; readonly node: number; readonly inNet: number; readonly target: number }
  | { readonly op: 'return'; readonly node: number; readonly inNet: number }
  | {
      readonly op: 'function';
      readonly node: number;
      readonly name: string;
      /** Index in the program's function table. */
      readonly fn: number;
      /** EN: a net, an operand, or undefined (not connected: always runs). */
      readonly en?: Source;
      readonly args: readonly ArgIR[];
      readonly out: OutIR;
      readonly eno: OutIR;
      /**
       * openplc (MATIEC as Beremiz generates it): with EN not connected the output variable is
       * written even on an error (no `IF ENO` around it), with the error value MATIEC returns (the
       * type's initial value); with EN connected and OFF, outputs wired to other blocks carry that
       * initial value (the function returned it). Absent: iec, an error or EN OFF assigns nothing.
       */
      readonly matiecOutputs?: true;
    }
  | {
      readonly op: 'fb';
      readonly node: number;
      readonly fb: number;
      /** EN of a box with execution control: OFF = not executed, outputs kept, ENO OFF. */
      readonly en?: Source;
      readonly args: readonly ArgIR[];
      readonly outs: readonly OutIR[];
      readonly eno?: OutIR;
      /** The instance's kept EN (enMemoryOf in box.ts): set by a call with EN, read by one without. */
      readonly enMemory?: Access;
    }
  | CallOp
  | StOp
  | SfcOp;

/**
 * A call of a user FUNCTION_BLOCK instance or FUNCTION: inputs assigned to the callee's variables,
 * temporaries (and a function's own variables) set to their initial values, the body networks
 * [first, end) run, then the outputs read (an FB's always, a function's only when it ran).
 */
export interface CallOp {
  readonly op: 'call';
  readonly node: number;
  readonly kind: 'fb' | 'function';
  readonly pou: string;
  readonly en?: Source;
  readonly inits: readonly { readonly dst: Access; readonly value: Value }[];
  readonly assigns: readonly { readonly dst: Access; readonly src: Source }[];
  readonly first: number;
  readonly end: number;
  readonly outs: readonly { readonly out: OutIR; readonly src: Access }[];
  readonly eno?: OutIR;
  /** An FB instance's kept EN (enMemoryOf in box.ts): set by a call with EN, read by one without. */
  readonly enMemory?: Access;
}

export interface NetworkIR {
  readonly index: number;
  readonly label?: string;
  readonly ops: readonly Op[];
  /** Number of power-flow nets (locals in the generated code). */
  readonly netCount: number;
  /** Nets that hold a left-rail point (always ON). */
  readonly railNets: readonly number[];
  /** Net of every element terminal for the power snapshot: element index -> [input net, output net] (-1 = none). */
  readonly elementNets: readonly (readonly [number, number])[];
  readonly vlinkNets: readonly number[];
  /** Constants used by the generated code (literals that are not plain numbers/booleans). */
  readonly constants: readonly Value[];
  /**
   * openplc profile (LD-SEMANTICS.md section 6): this network's blocks no coil needed, run after
   * every coil of the POU body, by the body's last network (`runLate`). Their nets are this
   * network's (its power words are read, updated and written back there).
   */
  readonly late?: readonly Op[];
  /** openplc profile: networks (program indexes) whose `late` operations run at the end of this one. */
  readonly runLate?: readonly number[];
  /**
   * openplc profile: the statements of this network's instances with a PLCopen executionOrderId
   * (boxes, variables written beside block outputs), one segment per instance in id order, run
   * before every coil of the POU body by the body's first network (`runEarly`); `earlyOrder` gives
   * each segment's id. Their nets are this network's, like the late operations'.
   */
  readonly early?: readonly (readonly Op[])[];
  readonly earlyOrder?: readonly number[];
  /**
   * openplc profile, a network whose statements interleave with its neighbours' (Network.turns):
   * the early segments after the `earlyOrder.length` ordered ones are its coils' and output
   * variables' statements, one each, with their turns here; the group's first network runs them
   * (with its neighbours') in turn order, after the ordered ones when it is the body's first network.
   */
  readonly earlyTurns?: readonly number[];
  /** openplc profile: early segments [network (program index), segment] run at the start of this network, in order. */
  readonly runEarly?: readonly (readonly [number, number])[];
}
