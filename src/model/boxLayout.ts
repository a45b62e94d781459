// Where a box's pins sit on the grid. Functions show EN/ENO on their first row; function blocks
// take power flow through their first BOOL input and give it on their first BOOL output, or
// through EN/ENO when the box has execution control. User blocks come from a BlockLibrary.
import type { BlockSignature, PinSignature } from './blocks';
import { STANDARD_LIBRARY, type BlockLibrary } from './library';
import type { BoxElement } from './elements';

export const BOX_COLS = 2;

export interface PlacedPin extends PinSignature {
  /** Row offset from the box's top row. */
  readonly rowOffset: number;
}

export interface BoxLayout {
  readonly signature: BlockSignature;
  readonly rows: number;
  readonly cols: number;
  /** Input pins at boundary `col` (left edge), rows row + rowOffset. */
  readonly inputs: readonly PlacedPin[];
  /** Output pins at boundary `col + cols` (right edge). */
  readonly outputs: readonly PlacedPin[];
}

/** The input pin list of a signature with `count` extensible inputs. */
export function expandInputs(sig: BlockSignature, count?: number): PinSignature[] {
  if (!sig.extensible) return [...sig.inputs];
  const { prefix, start, min, max } = sig.extensible;
  const n = Math.max(min, Math.min(max, count ?? min));
  const fixed = sig.inputs.filter((pin) => !pin.name.startsWith(prefix) || !/^\d+$/.test(pin.name.slice(prefix.length)));
  const template = sig.inputs[sig.inputs.length - 1]!;
  const repeated = Array.from({ length: n }, (_, i) => ({ ...template, name: `${prefix}${start + i}` }));
  return [...fixed, ...repeated];
}

/** Layouts per signature object (a user block's signature is a new object when its interface changes). */
const cache = new WeakMap<BlockSignature, Map<string, BoxLayout>>();

/** Layout of a signature with `inputCount` extensible inputs; EN/ENO on row 0 for functions and FBs with `executionControl`. */
export function layoutOfSignature(signature: BlockSignature, inputCount?: number, executionControl = false): BoxLayout {
  const enEno = signature.kind === 'function' || executionControl;
  const key = `${inputCount ?? ''}/${enEno ? 'en' : ''}`;
  let byKey = cache.get(signature);
  if (!byKey) {
    byKey = new Map();
    cache.set(signature, byKey);
  }
  const hit = byKey.get(key);
  if (hit) return hit;
  const ins = expandInputs(signature, inputCount);
  const outs = [...signature.outputs];
  const inputs: PlacedPin[] = [];
  const outputs: PlacedPin[] = [];
  if (enEno) {
    inputs.push({ name: 'EN', type: 'BOOL', rowOffset: 0 });
    outputs.push({ name: 'ENO', type: 'BOOL', rowOffset: 0 });
  }
  const base = enEno ? 1 : 0;
  ins.forEach((pin, i) => inputs.push({ ...pin, rowOffset: base + i }));
  outs.forEach((pin, i) => outputs.push({ ...pin, rowOffset: base + i }));
  const rows = Math.max(inputs.length, outputs.length);
  const layout: BoxLayout = { signature, rows, cols: BOX_COLS, inputs, outputs };
  byKey.set(key, layout);
  return layout;
}

/**
 * Layout for a block type; undefined for an unknown block. Without a library only standard
 * blocks are known; pass `blockLibrary(project)` for the project's own FBs and functions.
 */
export function boxLayoutFor(
  blockType: string,
  inputCount?: number,
  library: BlockLibrary = STANDARD_LIBRARY,
  executionControl = false,
): BoxLayout | undefined {
  const signature = library.signature(blockType);
  return signature ? layoutOfSignature(signature, inputCount, executionControl) : undefined;
}

export const boxLayout = (
  box: Pick<BoxElement, 'blockType' | 'inputCount' | 'executionControl'>,
  library: BlockLibrary = STANDARD_LIBRARY,
): BoxLayout | undefined => boxLayoutFor(box.blockType, box.inputCount, library, box.executionControl === true);
