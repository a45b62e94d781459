// Elements placed on a network grid. Every element occupies one cell except boxes (see boxLayout).
import type { ElementId } from './ids';

export const CONTACT_TYPES = ['NO', 'NC', 'P', 'N', 'NOT'] as const;
/** NO `| |`, NC `|/|`, P `|P|`, N `|N|`, NOT `|NOT|` (inverting contact, no variable). */
export type ContactType = (typeof CONTACT_TYPES)[number];

export const COIL_TYPES = ['COIL', 'NEG', 'SET', 'RESET', 'M', 'SM', 'RM', 'P', 'N'] as const;
/** COIL `( )`, NEG `(/)`, SET `(S)`, RESET `(R)`, M/SM/RM retentive, P `(P)`, N `(N)`. */
export type CoilType = (typeof COIL_TYPES)[number];

interface Placed {
  readonly id: ElementId;
  readonly row: number;
  readonly col: number;
  /**
   * The element's own comment (CODESYS "operand comment"), besides the network comment: shown
   * under it on the canvas and in print, exported to PLCopen as a comment object beside it.
   */
  readonly comment?: string;
}

/** A horizontal link: copies the state on its left to its right. */
export interface LinkElement extends Placed {
  readonly kind: 'link';
}

export interface ContactElement extends Placed {
  readonly kind: 'contact';
  readonly contact: ContactType;
  /** Variable name, `Instance.Pin`, or a bit of a word `Word.3`; empty for NOT. */
  readonly variable: string;
}

export interface CoilElement extends Placed {
  readonly kind: 'coil';
  readonly coil: CoilType;
  readonly variable: string;
}

/** `-->>LABEL`: when powered, execution continues at the network labelled LABEL. */
export interface JumpElement extends Placed {
  readonly kind: 'jump';
  readonly target: string;
}

/** `<RETURN>`: when powered, the POU ends for this scan. */
export interface ReturnElement extends Placed {
  readonly kind: 'return';
}

/**
 * A function or function block box. Top-left cell at (row, col); size from boxLayout().
 * Pins not wired on the grid take an operand: a variable name, `Instance.Pin`, or a literal
 * (`T#5s`, `10`, `TRUE`, `INT#-3`, `2.5`). Outputs not wired may be assigned to a variable.
 */
export interface BoxElement extends Placed {
  readonly kind: 'box';
  /** Block name: standard (TON, CTU, ADD, INT_TO_REAL, ...) or a FUNCTION_BLOCK/FUNCTION POU of the project. */
  readonly blockType: string;
  /** FB instance name (declared in the variable table with type = blockType); absent for functions. */
  readonly instance?: string;
  /**
   * A function block box with EN/ENO pins (PLCopen `executionControl`): with EN FALSE the FB is
   * not executed and keeps its outputs. Functions always have EN/ENO.
   */
  readonly executionControl?: boolean;
  /**
   * The PLCopen file left EN unconnected (Rungsmith draws the box powered from the left rail). While
   * EN is fed by the rail alone, the openplc profile runs the box as Beremiz generates a call
   * without EN: a function's output variable is written even on an error, and an FB instance's
   * call reads the EN the instance kept (LD-SEMANTICS.md); an export leaves EN unconnected again.
   */
  readonly enOpen?: boolean;
  /** Number of extensible inputs (ADD, AND, MUX, ...); defaults to the signature's minimum. */
  readonly inputCount?: number;
  readonly inputs: Readonly<Record<string, string>>;
  readonly outputs: Readonly<Record<string, string>>;
  /**
   * PLCopen `executionOrderId` of the block (kept from an imported file, written back on export;
   * absent or 0: none). Under the openplc profile a box with one runs before every coil of its POU
   * body, in id order (LD-SEMANTICS.md section 6); the iec profile ignores it.
   */
  readonly executionOrder?: number;
  /** `executionOrderId` of the variable written beside each output pin (a PLCopen outVariable), by pin. */
  readonly outputOrders?: Readonly<Record<string, number>>;
}

/**
 * The PLCopen executionOrderId of a box (0: none), or with `pin`, of the variable written beside
 * that output pin (pin names compared without case).
 */
export function executionOrderOf(el: LdElement, pin?: string): number {
  if (el.kind !== 'box') return 0;
  if (pin === undefined) return el.executionOrder ?? 0;
  const key = Object.keys(el.outputOrders ?? {}).find((k) => k.toUpperCase() === pin.toUpperCase());
  return key === undefined ? 0 : (el.outputOrders![key] ?? 0);
}

/** The element without its PLCopen execution order (a pasted copy must not jump the queue). */
export function withoutExecutionOrder<T extends LdElement>(el: T): T {
  if (el.kind !== 'box' || (el.executionOrder === undefined && el.outputOrders === undefined)) return el;
  const { executionOrder: _e, outputOrders: _o, ...rest } = el;
  return rest as T;
}

/**
 * `>NAME>` connector (IEC 61131-3 connection, PLCopen `connector`): ends the line on its left.
 * Its state or value is carried on by every continuation of the same NAME in the network, as if
 * the two were joined by a wire. Lets any graph be drawn without crossings.
 */
export interface ConnectorElement extends Placed {
  readonly kind: 'connector';
  readonly name: string;
}

/** `>NAME>` continuation (PLCopen `continuation`): starts a line on its right with connector NAME's state or value. */
export interface ContinuationElement extends Placed {
  readonly kind: 'continuation';
  readonly name: string;
}

export type LdElement =
  | LinkElement
  | ContactElement
  | CoilElement
  | JumpElement
  | ReturnElement
  | BoxElement
  | ConnectorElement
  | ContinuationElement;
export type ElementKind = LdElement['kind'];

/** A vertical link joining point (row, boundary) to point (row + 1, boundary). */
export interface VLink {
  readonly row: number;
  readonly boundary: number;
}
