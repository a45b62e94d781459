// Signatures of the standard function blocks and functions (IEC 61131-3 tables 22-36, 71-75).
// Pure data shared by the editor (to draw boxes and pins), the engine (to type-check and run them)
// and PLCopen import/export. Behaviour lives in src/engine.
import { ELEMENTARY_TYPES, type ElementaryType, type PinType } from './iecTypes';

export interface PinSignature {
  readonly name: string;
  readonly type: PinType;
  /** Pins marked poly share one concrete type within a call (the generic "T" of the standard). */
  readonly poly?: boolean;
}

export interface BlockSignature {
  readonly name: string;
  readonly kind: 'fb' | 'function';
  readonly inputs: readonly PinSignature[];
  readonly outputs: readonly PinSignature[];
  /** Extensible inputs: the last input pin repeats as PREFIX<start>..PREFIX<start+n-1>. */
  readonly extensible?: { readonly prefix: string; readonly start: number; readonly min: number; readonly max: number };
  /** 'user': a POU of the project; 'external': a block the simulator does not run (externalBlocks.ts). */
  readonly category:
    | 'timer'
    | 'counter'
    | 'edge'
    | 'bistable'
    | 'move'
    | 'arithmetic'
    | 'comparison'
    | 'bitwise'
    | 'selection'
    | 'conversion'
    | 'user'
    | 'external';
  readonly description: string;
}

const p = (name: string, type: PinType, poly = false): PinSignature => (poly ? { name, type, poly } : { name, type });

const timer = (name: string, description: string): BlockSignature => ({
  name,
  kind: 'fb',
  category: 'timer',
  inputs: [p('IN', 'BOOL'), p('PT', 'TIME')],
  outputs: [p('Q', 'BOOL'), p('ET', 'TIME')],
  description,
});

/** The PV/CV types of the counters: INT for CTU/CTD/CTUD, the others as MATIEC's typed CTU_DINT ... CTUD_ULINT. */
export const COUNTER_TYPES = ['INT', 'DINT', 'LINT', 'UDINT', 'ULINT'] as const;
export type CounterType = (typeof COUNTER_TYPES)[number];

/** CTU, CTD and CTUD whose PV and CV have type `t` (suffix "" for INT, "_DINT" ...). */
const counters = (suffix: string, t: CounterType): BlockSignature[] => {
  const typed = suffix ? ` PV and CV are ${t}.` : '';
  return [
    {
      name: `CTU${suffix}`,
      kind: 'fb',
      category: 'counter',
      inputs: [p('CU', 'BOOL'), p('R', 'BOOL'), p('PV', t)],
      outputs: [p('Q', 'BOOL'), p('CV', t)],
      description: `Up counter: CV counts rising edges of CU; Q = CV >= PV; R resets CV to 0.${typed}`,
    },
    {
      name: `CTD${suffix}`,
      kind: 'fb',
      category: 'counter',
      inputs: [p('CD', 'BOOL'), p('LD', 'BOOL'), p('PV', t)],
      outputs: [p('Q', 'BOOL'), p('CV', t)],
      description: `Down counter: CV counts down on rising edges of CD; Q = CV <= 0; LD loads PV.${typed}`,
    },
    {
      name: `CTUD${suffix}`,
      kind: 'fb',
      category: 'counter',
      inputs: [p('CU', 'BOOL'), p('CD', 'BOOL'), p('R', 'BOOL'), p('LD', 'BOOL'), p('PV', t)],
      outputs: [p('QU', 'BOOL'), p('QD', 'BOOL'), p('CV', t)],
      description: `Up-down counter: QU = CV >= PV, QD = CV <= 0; R resets, LD loads PV.${typed}`,
    },
  ];
};

export const FB_SIGNATURES: readonly BlockSignature[] = [
  timer('TON', 'On-delay timer: Q goes ON when IN has been ON for PT.'),
  timer('TOF', 'Off-delay timer: Q stays ON for PT after IN goes OFF.'),
  timer('TP', 'Pulse timer: Q is ON for PT from a rising edge of IN (not retriggerable).'),
  ...counters('', 'INT'),
  {
    name: 'R_TRIG',
    kind: 'fb',
    category: 'edge',
    inputs: [p('CLK', 'BOOL')],
    outputs: [p('Q', 'BOOL')],
    description: 'Rising edge detector: Q is ON for one evaluation when CLK goes ON.',
  },
  {
    name: 'F_TRIG',
    kind: 'fb',
    category: 'edge',
    inputs: [p('CLK', 'BOOL')],
    outputs: [p('Q', 'BOOL')],
    description: 'Falling edge detector: Q is ON for one evaluation when CLK goes OFF.',
  },
  {
    name: 'SR',
    kind: 'fb',
    category: 'bistable',
    inputs: [p('S1', 'BOOL'), p('R', 'BOOL')],
    outputs: [p('Q1', 'BOOL')],
    description: 'Set-dominant bistable: Q1 := S1 OR (NOT R AND Q1).',
  },
  {
    name: 'RS',
    kind: 'fb',
    category: 'bistable',
    inputs: [p('S', 'BOOL'), p('R1', 'BOOL')],
    outputs: [p('Q1', 'BOOL')],
    description: 'Reset-dominant bistable: Q1 := NOT R1 AND (S OR Q1).',
  },
  // MATIEC's typed counters (lib/counter.txt): same bodies, PV and CV of the type in the name.
  ...COUNTER_TYPES.filter((t) => t !== 'INT').flatMap((t) => counters(`_${t}`, t)),
];

const ext = (prefix: string, start: number) => ({ prefix, start, min: 2, max: 16 });
const fn = (
  name: string,
  category: BlockSignature['category'],
  inputs: PinSignature[],
  out: PinSignature,
  description: string,
  extensible?: BlockSignature['extensible'],
): BlockSignature => ({ name, kind: 'function', category, inputs, outputs: [out], description, ...(extensible ? { extensible } : {}) });

const arith2 = (name: string, t: PinType, d: string, extend: boolean) =>
  fn(name, 'arithmetic', [p('IN1', t, true), p('IN2', t, true)], p('OUT', t, true), d, extend ? ext('IN', 1) : undefined);
const cmp = (name: string, d: string, extend: boolean) =>
  fn(name, 'comparison', [p('IN1', 'ANY_ELEMENTARY', true), p('IN2', 'ANY_ELEMENTARY', true)], p('OUT', 'BOOL'), d, extend ? ext('IN', 1) : undefined);
const bit2 = (name: string, d: string) =>
  fn(name, 'bitwise', [p('IN1', 'ANY_BIT', true), p('IN2', 'ANY_BIT', true)], p('OUT', 'ANY_BIT', true), d, ext('IN', 1));
const shift = (name: string, d: string) =>
  fn(name, 'bitwise', [p('IN', 'ANY_BIT', true), p('N', 'ANY_INT')], p('OUT', 'ANY_BIT', true), d);

export const FUNCTION_SIGNATURES_BASE: readonly BlockSignature[] = [
  fn('MOVE', 'move', [p('IN', 'ANY', true)], p('OUT', 'ANY', true), 'Copies IN to OUT.'),
  arith2('ADD', 'ANY_MAGNITUDE', 'OUT := IN1 + IN2 + ...', true),
  arith2('SUB', 'ANY_MAGNITUDE', 'OUT := IN1 - IN2', false),
  arith2('MUL', 'ANY_NUM', 'OUT := IN1 * IN2 * ...', true),
  arith2('DIV', 'ANY_NUM', 'OUT := IN1 / IN2 (integer division truncates; division by zero turns ENO OFF).', false),
  arith2('MOD', 'ANY_INT', 'OUT := IN1 MOD IN2 (IN2 = 0 gives 0 and turns ENO OFF).', false),
  fn('ABS', 'arithmetic', [p('IN', 'ANY_NUM', true)], p('OUT', 'ANY_NUM', true), 'Absolute value.'),
  fn('NEG', 'arithmetic', [p('IN', 'ANY_NUM', true)], p('OUT', 'ANY_NUM', true), 'Negation (signed types).'),
  cmp('GT', 'OUT := IN1 > IN2 > ...', true),
  cmp('GE', 'OUT := IN1 >= IN2 >= ...', true),
  cmp('EQ', 'OUT := IN1 = IN2 = ...', true),
  cmp('NE', 'OUT := IN1 <> IN2', false),
  cmp('LE', 'OUT := IN1 <= IN2 <= ...', true),
  cmp('LT', 'OUT := IN1 < IN2 < ...', true),
  bit2('AND', 'Bitwise AND.'),
  bit2('OR', 'Bitwise OR.'),
  bit2('XOR', 'Bitwise XOR.'),
  fn('NOT', 'bitwise', [p('IN', 'ANY_BIT', true)], p('OUT', 'ANY_BIT', true), 'Bitwise complement.'),
  shift('SHL', 'Shift left by N bits, filling with 0.'),
  shift('SHR', 'Shift right by N bits, filling with 0.'),
  shift('ROL', 'Rotate left by N bits.'),
  shift('ROR', 'Rotate right by N bits.'),
  fn('SEL', 'selection', [p('G', 'BOOL'), p('IN0', 'ANY', true), p('IN1', 'ANY', true)], p('OUT', 'ANY', true), 'OUT := IN0 if G is FALSE, IN1 if G is TRUE.'),
  fn('MUX', 'selection', [p('K', 'ANY_INT'), p('IN0', 'ANY', true), p('IN1', 'ANY', true)], p('OUT', 'ANY', true), 'OUT := IN<K> (K out of range turns ENO OFF).', ext('IN', 0)),
  fn('MAX', 'selection', [p('IN1', 'ANY_ELEMENTARY', true), p('IN2', 'ANY_ELEMENTARY', true)], p('OUT', 'ANY_ELEMENTARY', true), 'Maximum.', ext('IN', 1)),
  fn('MIN', 'selection', [p('IN1', 'ANY_ELEMENTARY', true), p('IN2', 'ANY_ELEMENTARY', true)], p('OUT', 'ANY_ELEMENTARY', true), 'Minimum.', ext('IN', 1)),
  fn('LIMIT', 'selection', [p('MN', 'ANY_ELEMENTARY', true), p('IN', 'ANY_ELEMENTARY', true), p('MX', 'ANY_ELEMENTARY', true)], p('OUT', 'ANY_ELEMENTARY', true), 'OUT := MIN(MAX(IN, MN), MX).'),
];

/** Every A_TO_B conversion between the supported elementary types. */
export const CONVERSION_SIGNATURES: readonly BlockSignature[] = ELEMENTARY_TYPES.flatMap((from) =>
  ELEMENTARY_TYPES.filter((to) => to !== from).map((to) =>
    fn(`${from}_TO_${to}`, 'conversion', [p('IN', from)], p('OUT', to), `Converts ${from} to ${to} (out of range turns ENO OFF).`),
  ),
);

export const FUNCTION_SIGNATURES: readonly BlockSignature[] = [...FUNCTION_SIGNATURES_BASE, ...CONVERSION_SIGNATURES];

const BY_NAME = new Map<string, BlockSignature>([...FB_SIGNATURES, ...FUNCTION_SIGNATURES].map((s) => [s.name, s]));

/** The signature of a standard block by (case-insensitive) name. */
export const blockSignature = (name: string): BlockSignature | undefined => BY_NAME.get(name.toUpperCase());
export const isFbType = (type: string): boolean => blockSignature(type)?.kind === 'fb';
export const conversionTypes = (name: string): { from: ElementaryType; to: ElementaryType } | undefined => {
  const s = blockSignature(name);
  if (s?.category !== 'conversion') return undefined;
  return { from: s.inputs[0]!.type as ElementaryType, to: s.outputs[0]!.type as ElementaryType };
};
