// What the LD writer passes between a network (exportBody.ts) and its boxes (exportBlock.ts): the
// local id allocator, an element placed with its absolute pin positions (Placed), and the function
// writing a pin's connections (Connect).
import type { Point } from './geometry';
import type { Source } from './gridGraph';

export interface IdAllocator {
  next(): number;
}

export interface Placed {
  readonly id: number;
  /** Absolute pin positions by pin name (inputs; both pins of a 1-cell element). */
  readonly pins: Map<string, Point>;
  /** A box's output pins (an in-out pin has one of each name on either side). */
  readonly outs?: Map<string, Point>;
  /** Pin name written in formalParameter when this element is a connection's source (blocks only). */
  readonly formal?: (pin: string) => string;
}

export type Connect = (
  consumer: Point,
  origin: Point,
  srcs: readonly Source[] | undefined,
  barX: number | undefined,
) => void;
