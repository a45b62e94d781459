// Everything the palette can place, with its keyboard shortcut (the same shortcut the command
// registry binds). Blocks (every standard FB and library function) come from src/model/blocks.ts,
// the project's own FBs and functions from its block library (src/model/library.ts).
import { boxLayoutFor } from '../../model/boxLayout';
import { FB_SIGNATURES, FUNCTION_SIGNATURES, type BlockSignature } from '../../model/blocks';
import { declaredPinType, STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import type { CoilType, ContactType } from '../../model/elements';
import type { Pou } from '../../model/project';
import type { ElementTemplate } from '../../store/networkEdits';

export interface PaletteItem {
  /** Stable id, also the command id suffix: 'contact-NO' -> command 'place.contact-NO'. */
  readonly id: string;
  readonly label: string;
  /** The IEC symbol as text, shown on the palette button. */
  readonly symbol: string;
  readonly group: 'Contacts' | 'Coils' | 'Wires' | 'Control';
  readonly template: ElementTemplate;
  /** Key spec for the command registry (see commands/keys.ts), e.g. 'shift+c'. */
  readonly keys?: string;
  readonly description: string;
}

const contact = (
  c: ContactType,
  label: string,
  symbol: string,
  keys: string | undefined,
  description: string,
): PaletteItem => ({
  id: `contact-${c}`,
  label,
  symbol,
  group: 'Contacts',
  template: { kind: 'contact', contact: c, variable: '' },
  ...(keys ? { keys } : {}),
  description,
});

const coil = (
  c: CoilType,
  label: string,
  symbol: string,
  keys: string | undefined,
  description: string,
): PaletteItem => ({
  id: `coil-${c}`,
  label,
  symbol,
  group: 'Coils',
  template: { kind: 'coil', coil: c, variable: '' },
  ...(keys ? { keys } : {}),
  description,
});

export const PALETTE_ITEMS: readonly PaletteItem[] = [
  contact('NO', 'Normally open contact', '-| |-', 'c', 'Passes power when the variable is TRUE.'),
  contact('NC', 'Normally closed contact', '-|/|-', 'shift+c', 'Passes power when the variable is FALSE.'),
  contact(
    'P',
    'Positive transition contact',
    '-|P|-',
    'p',
    'Passes power for one evaluation when the variable rises.',
  ),
  contact(
    'N',
    'Negative transition contact',
    '-|N|-',
    'shift+p',
    'Passes power for one evaluation when the variable falls.',
  ),
  contact('NOT', 'Inverting contact', '-|NOT|-', 'i', 'Inverts the power flow (no variable).'),
  coil('COIL', 'Coil', '-( )-', 'o', 'Writes the power flow to the variable.'),
  coil('NEG', 'Negated coil', '-(/)-', 'shift+o', 'Writes the inverted power flow to the variable.'),
  coil('SET', 'Set coil', '-(S)-', 's', 'Sets the variable TRUE while powered (latch).'),
  coil('RESET', 'Reset coil', '-(R)-', 'r', 'Resets the variable FALSE while powered (unlatch).'),
  coil('M', 'Retentive coil', '-(M)-', 'm', 'A coil whose variable is kept over a warm restart.'),
  coil('SM', 'Retentive set coil', '-(SM)-', 'shift+s', 'A set coil whose variable is retentive.'),
  coil('RM', 'Retentive reset coil', '-(RM)-', 'shift+r', 'A reset coil whose variable is retentive.'),
  coil('P', 'Positive transition coil', '-(P)-', 'u', 'TRUE for one evaluation when the power flow rises.'),
  coil(
    'N',
    'Negative transition coil',
    '-(N)-',
    'shift+u',
    'TRUE for one evaluation when the power flow falls.',
  ),
  {
    id: 'link',
    label: 'Horizontal link',
    symbol: '———',
    group: 'Wires',
    template: { kind: 'link' },
    keys: 'h',
    description: 'A wire: copies the state on its left to its right.',
  },
  {
    id: 'connector',
    label: 'Connector',
    symbol: '—>C>',
    group: 'Wires',
    template: { kind: 'connector', name: '' },
    keys: 'x',
    description:
      'Ends a line here and carries its state to every continuation of the same name in the network (no crossing wires). New ones are named C1, C2…',
  },
  {
    id: 'continuation',
    label: 'Continuation',
    symbol: '>C>—',
    group: 'Wires',
    template: { kind: 'continuation', name: '' },
    keys: 'shift+x',
    description:
      'Starts a line here with the state of the connector of the same name in this network.',
  },
  {
    id: 'jump',
    label: 'Jump',
    symbol: '->>L',
    group: 'Control',
    template: { kind: 'jump', target: '' },
    keys: 'j',
    description: 'When powered, execution continues at the network with this label.',
  },
  {
    id: 'return',
    label: 'Return',
    symbol: '<RET>',
    group: 'Control',
    template: { kind: 'return' },
    keys: 'shift+j',
    description: 'When powered, the POU ends for this scan.',
  },
];

/** The template of a box for a block: inputs/outputs empty, FB instance to be named. */
export function boxTemplate(sig: BlockSignature, library: BlockLibrary = STANDARD_LIBRARY): ElementTemplate {
  const layout = boxLayoutFor(sig.name, undefined, library);
  return {
    kind: 'box',
    blockType: sig.name,
    ...(sig.kind === 'fb' ? { instance: '' } : {}),
    ...(sig.extensible && layout ? { inputCount: sig.extensible.min } : {}),
    inputs: {},
    outputs: {},
  };
}

export const ALL_BLOCKS: readonly BlockSignature[] = [...FB_SIGNATURES, ...FUNCTION_SIGNATURES];

const CATEGORY_ORDER: readonly BlockSignature['category'][] = [
  'user',
  'timer',
  'counter',
  'edge',
  'bistable',
  'control',
  'move',
  'arithmetic',
  'numerical',
  'comparison',
  'bitwise',
  'selection',
  'conversion',
  'string',
  'time',
  // Vendor library blocks the simulator does not run (library.externalBlocks): last.
  'external',
];

/** Place of a block's category in the list; a category not listed goes last. */
const categoryRank = (s: BlockSignature) => {
  const i = CATEGORY_ORDER.indexOf(s.category);
  return i < 0 ? CATEGORY_ORDER.length : i;
};

/** "Start : BOOL, Stop : BOOL → Run : BOOL": a block's pins for tooltips and the block picker. */
export function pinSummary(sig: BlockSignature): string {
  const pins = (list: BlockSignature['inputs']) =>
    list.map((p) => `${p.name} : ${declaredPinType(p)}`).join(', ');
  return `${pins(sig.inputs) || '(no inputs)'} → ${pins(sig.outputs) || '(no outputs)'}`;
}

/**
 * Blocks whose name, category or description matches the query: the project's own blocks, the
 * blocks of its libraries (`library` set), then FBs and common blocks. Inside a POU (`editing`), the POU itself is left out (no recursion), and a
 * FUNCTION is offered no function blocks (it cannot hold their instances).
 */
export function searchBlocks(
  query: string,
  library: BlockLibrary = STANDARD_LIBRARY,
  editing?: Pick<Pou, 'name' | 'kind'>,
): BlockSignature[] {
  const q = query.trim().toUpperCase();
  const rank = (s: BlockSignature) => {
    if (!q) return 0;
    const name = s.name.toUpperCase();
    if (name === q) return 0;
    if (name.startsWith(q)) return 1;
    if (name.includes(q)) return 2;
    if (s.category.toUpperCase().includes(q) || s.description.toUpperCase().includes(q)) return 3;
    return -1;
  };
  const skip = editing?.name.toUpperCase();
  const users = library.userBlocks.filter((s) => s.name.toUpperCase() !== skip);
  // The blocks of the libraries kept with the project (the palette lists them under each library's name).
  const libraries = library.libraryBlocks;
  const inFunction = editing?.kind === 'FUNCTION';
  return [...users, ...libraries, ...ALL_BLOCKS]
    .filter((s) => !inFunction || s.kind !== 'fb')
    .map((s) => ({ s, r: rank(s) }))
    .filter((x) => x.r >= 0)
    .sort((a, b) => a.r - b.r || categoryRank(a.s) - categoryRank(b.s))
    .map((x) => x.s);
}
