// Where a box's pins sit on the grid. Functions show EN/ENO on their first row; function blocks
// take power flow through their first BOOL input and give it on their first BOOL output.
import { blockSignature, type BlockSignature, type PinSignature } from './blocks';
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

const cache = new Map<string, BoxLayout>();

/** Layout for a block type; undefined for an unknown block. */
export function boxLayoutFor(blockType: string, inputCount?: number): BoxLayout | undefined {
  const key = `${blockType.toUpperCase()}/${inputCount ?? ''}`;
  const hit = cache.get(key);
  if (hit) return hit;
  const signature = blockSignature(blockType);
  if (!signature) return undefined;
  const ins = expandInputs(signature, inputCount);
  const outs = [...signature.outputs];
  const inputs: PlacedPin[] = [];
  const outputs: PlacedPin[] = [];
  if (signature.kind === 'function') {
    inputs.push({ name: 'EN', type: 'BOOL', rowOffset: 0 });
    outputs.push({ name: 'ENO', type: 'BOOL', rowOffset: 0 });
  }
  const base = signature.kind === 'function' ? 1 : 0;
  ins.forEach((pin, i) => inputs.push({ ...pin, rowOffset: base + i }));
  outs.forEach((pin, i) => outputs.push({ ...pin, rowOffset: base + i }));
  const rows = Math.max(inputs.length, outputs.length);
  const layout: BoxLayout = { signature, rows, cols: BOX_COLS, inputs, outputs };
  cache.set(key, layout);
  return layout;
}

export const boxLayout = (box: Pick<BoxElement, 'blockType' | 'inputCount'>): BoxLayout | undefined =>
  boxLayoutFor(box.blockType, box.inputCount);
