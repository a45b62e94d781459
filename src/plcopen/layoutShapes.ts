// Shapes of laid-out nodes (cells and pins) and the nets between them, shared by the two layout passes.
import { boxLayoutFor, type BoxLayout } from '../model/boxLayout';
import type { BlockLibrary } from '../model/library';
import type { LdElement, VLink } from '../model/elements';
import type { ElementId } from '../model/ids';
import type { GNode } from './ldNodes';

/** Point and cell keys: row * KEY + column (networks have at most 1,000 columns). */
export const KEY = 4096;

export interface PinSpec {
  readonly pin: string;
  readonly off: number;
}

export interface Shape {
  readonly w: number;
  readonly h: number;
  readonly inputs: readonly PinSpec[];
  readonly outputs: readonly PinSpec[];
}

const CELL_SHAPE: Shape = { w: 1, h: 1, inputs: [{ pin: 'in', off: 0 }], outputs: [{ pin: 'out', off: 0 }] };
const END_SHAPE: Shape = { w: 1, h: 1, inputs: [{ pin: 'in', off: 0 }], outputs: [] };
const UNKNOWN_SHAPE: Shape = { w: 1, h: 1, inputs: [], outputs: [] };
/** Shapes per box layout (layouts are cached per signature, so one object per block type and pin count). */
const boxShapes = new WeakMap<BoxLayout, Shape>();

export function shapeOf(n: GNode, library: BlockLibrary): Shape {
  switch (n.kind) {
    case 'contact':
    case 'coil':
      return CELL_SHAPE;
    case 'jump':
    case 'return':
    case 'connector':
      return END_SHAPE;
    case 'continuation':
      // Its left side is never wired: the row pass keeps other wires off it, as for an open input.
      return CELL_SHAPE;
    case 'box': {
      const l = boxLayoutFor(n.blockType ?? '', n.inputCount, library, n.executionControl === true);
      if (!l) return UNKNOWN_SHAPE;
      let shape = boxShapes.get(l);
      if (!shape) {
        shape = {
          w: l.cols,
          h: l.rows,
          inputs: l.inputs.map((p) => ({ pin: p.name, off: p.rowOffset })),
          outputs: l.outputs.map((p) => ({ pin: p.name, off: p.rowOffset })),
        };
        boxShapes.set(l, shape);
      }
      return shape;
    }
  }
}

export interface Net {
  readonly id: number;
  readonly producers: { node: number; pin: string }[];
  readonly consumers: { node: number; pin: string }[];
  rail: boolean;
  rightRail: boolean;
  /** Boundary of the vertical bar. */
  b: number;
  min: number;
  max: number;
}

export interface LaidOut {
  readonly rows: number;
  readonly cols: number;
  readonly elements: LdElement[];
  readonly vlinks: VLink[];
  /** Element id per node index (for verification and preserved data). */
  readonly elementOf: Map<number, ElementId>;
  /** Nodes that could not be placed without touching another net (their wiring may differ). */
  readonly forced: number[];
}
