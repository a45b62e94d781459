// The nodes of an LD body as the importer reads them (ldGraph.ts builds them, ldBlocks.ts fills in
// boxes, ldNormalize.ts and the layout place them): a node (GNode) with the sources of its input
// pins (GSource), and a finding reported about the file (Finding).
import type { CoilType, ContactType } from '../model/elements';
import type { RawObject } from './ldObjects';

export type GSource =
  { readonly kind: 'rail' } | { readonly kind: 'node'; readonly node: number; readonly pin: string };

export interface GNode {
  readonly index: number;
  readonly obj: RawObject;
  /** 'connector' and 'continuation' are drawn by the layout only (layoutCut.ts), never read from a file. */
  readonly kind: 'contact' | 'coil' | 'box' | 'jump' | 'return' | 'connector' | 'continuation';
  /** Name of a drawn connector or continuation. */
  name?: string;
  /** Input pins the file wires through one of its own connector/continuation pairs: the pair's name. */
  via?: Record<string, string>;
  contact?: ContactType;
  coil?: CoilType;
  variable?: string;
  target?: string;
  blockType?: string;
  instance?: string;
  inputCount?: number;
  /** An FB box with EN/ENO (PLCopen executionControl). */
  executionControl?: boolean;
  /**
   * EN is not in the file and was wired to the left rail (a function always runs then). The layout
   * may leave it open instead when the rail cannot reach it: an open EN runs the block too.
   */
  implicitEn?: boolean;
  /** Wired input pins (model pin names: "in" for 1-cell elements) and their sources. */
  readonly inputs: Map<string, GSource[]>;
  readonly operandsIn: Record<string, string>;
  readonly operandsOut: Record<string, string>;
  /** Position hints from the file (0,0 in files without geometry). */
  readonly x: number;
  readonly y: number;
  readonly order: number;
  /** A block's PLCopen executionOrderId (> 0 only; kept on the box, see BoxElement.executionOrder). */
  executionOrder?: number;
  /** executionOrderId (> 0) of the outVariable written beside each output pin, by model pin name. */
  outputOrders?: Record<string, number>;
  /** The outVariable (without executionOrderId) written beside each output pin, by model pin name: where the file draws it. */
  outputAt?: Record<string, RawObject>;
  feedsRightRail: boolean;
  /** Raw `<data>` elements of the object's addData kept for the round trip. */
  data?: string[];
}

export interface Finding {
  readonly message: string;
  readonly obj?: RawObject;
}
