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
    | 'numerical'
    | 'time'
    | 'control'
    | 'string'
    | 'user'
    | 'external';
  readonly description: string;
  /** A block of a library kept with the project (category 'user'): the library's name. */
  readonly library?: string;
}

const p = (name: string, type: PinType, poly = false): PinSignature => (poly ? { name, type, poly } : { name, type });

const fbSig = (
  name: string,
  category: BlockSignature['category'],
  inputs: string,
  outputs: string,
  description: string,
): BlockSignature => {
  const pins = (spec: string) =>
    spec.split(' ').map((item) => {
      const [pin = '', type = ''] = item.split(':');
      return p(pin, type as ElementaryType);
    });
  return { name, kind: 'fb', category, inputs: pins(inputs), outputs: pins(outputs), description };
};

/**
 * SEMA (OpenPLC Editor's Standard_Function_Blocks.xml) and the blocks of its
 * Additional_Function_Blocks.xml, from the standard's annex F (MATIEC AnnexF/*_st.txt), and RTC
 * (MATIEC lib/rtc.txt). TIME_TO_REAL in their bodies follows the profile's unit.
 */
const ADDITIONAL_FB_SIGNATURES: readonly BlockSignature[] = [
  fbSig('SEMA', 'bistable', 'CLAIM:BOOL RELEASE:BOOL', 'BUSY:BOOL', 'Semaphore: BUSY goes ON with CLAIM and stays ON until RELEASE (CLAIM wins).'),
  fbSig(
    'INTEGRAL',
    'control',
    'RUN:BOOL R1:BOOL XIN:REAL X0:REAL CYCLE:TIME',
    'Q:BOOL XOUT:REAL',
    'Integrator: each call with RUN adds XIN * TIME_TO_REAL(CYCLE) to XOUT; R1 sets XOUT to X0; Q = NOT R1.',
  ),
  fbSig(
    'DERIVATIVE',
    'control',
    'RUN:BOOL XIN:REAL CYCLE:TIME',
    'XOUT:REAL',
    'Differentiator over the last four samples of XIN taken every CYCLE; RUN OFF gives 0.',
  ),
  fbSig(
    'PID',
    'control',
    'AUTO:BOOL PV:REAL SP:REAL X0:REAL KP:REAL TR:REAL TD:REAL CYCLE:TIME',
    'XOUT:REAL',
    'PID controller: XOUT = KP * (ERROR + integral/TR + derivative*TD), ERROR = PV - SP; with AUTO OFF (manual), XOUT = KP * X0.',
  ),
  fbSig(
    'RAMP',
    'control',
    'RUN:BOOL X0:REAL X1:REAL TR:TIME CYCLE:TIME',
    'BUSY:BOOL XOUT:REAL',
    'Ramp: with RUN, XOUT goes from X0 to X1 in TR (CYCLE per call); without RUN, XOUT tracks X0.',
  ),
  fbSig(
    'RTC',
    'control',
    'IN:BOOL PDT:DT',
    'Q:BOOL CDT:DT',
    'Real-time clock: CDT is the current date and time; a rising edge of IN loads PDT, and while IN is ON CDT runs on from it. Q copies IN.',
  ),
  fbSig(
    'HYSTERESIS',
    'control',
    'XIN1:REAL XIN2:REAL EPS:REAL',
    'Q:BOOL',
    'Hysteresis: Q goes ON when XIN1 > XIN2 + EPS and OFF when XIN1 < XIN2 - EPS.',
  ),
];

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
  ...ADDITIONAL_FB_SIGNATURES,
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
  // ANY_MAGNITUDE, not ANY_NUM: IN1 may be a TIME when IN2 is a number (MATIEC's MUL/DIV of TIME, as MULTIME/DIVTIME).
  arith2('MUL', 'ANY_MAGNITUDE', 'OUT := IN1 * IN2 * ... (also a TIME times a number, as MULTIME)', true),
  arith2('DIV', 'ANY_MAGNITUDE', 'OUT := IN1 / IN2 (integer division truncates; division by zero turns ENO OFF; a TIME divided by a number, as DIVTIME).', false),
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

const real1 = (name: string, d: string) =>
  fn(name, 'numerical', [p('IN', 'ANY_REAL', true)], p('OUT', 'ANY_REAL', true), d);

/** BCD pairs of OpenPLC Editor's palette (BCD_TO_** and *_TO_BCD filtered by its ANY_TO_BCD rules). */
const BCD_PAIRS = [
  ['BYTE', 'USINT'],
  ['WORD', 'UINT'],
  ['DWORD', 'UDINT'],
  ['LWORD', 'ULINT'],
] as const;

/**
 * The functions of OpenPLC Editor's palette (iec_std.csv) beyond the base set: numerical
 * functions (table 23), EXPT, TRUNC, BCD conversions and the TIME functions (table 30).
 */
export const MORE_FUNCTION_SIGNATURES: readonly BlockSignature[] = [
  real1('SQRT', 'Square root (a negative IN gives NaN).'),
  real1('LN', 'Natural logarithm (IN = 0 gives -Inf, IN < 0 NaN).'),
  real1('LOG', 'Logarithm to base 10 (IN = 0 gives -Inf, IN < 0 NaN).'),
  real1('EXP', 'Natural exponential e^IN (too large gives +Inf).'),
  real1('SIN', 'Sine of IN in radians.'),
  real1('COS', 'Cosine of IN in radians.'),
  real1('TAN', 'Tangent of IN in radians.'),
  real1('ASIN', 'Arc sine in radians (|IN| > 1 gives NaN).'),
  real1('ACOS', 'Arc cosine in radians (|IN| > 1 gives NaN).'),
  real1('ATAN', 'Arc tangent in radians.'),
  fn('EXPT', 'arithmetic', [p('IN1', 'ANY_REAL', true), p('IN2', 'ANY_NUM')], p('OUT', 'ANY_REAL', true), 'OUT := IN1 ** IN2 (C pow: a negative IN1 with a fractional IN2 gives NaN).'),
  fn('TRUNC', 'conversion', [p('IN', 'ANY_REAL', true)], p('OUT', 'ANY_INT'), 'Truncates toward zero to the integer type OUT is written to (DINT when nothing says).'),
  ...BCD_PAIRS.map(([bits, int]) =>
    fn(`BCD_TO_${int}`, 'conversion', [p('IN', bits)], p('OUT', int), `Decodes a BCD ${bits} (a nibble above 9 turns ENO OFF).`),
  ),
  ...BCD_PAIRS.map(([bits, int]) =>
    fn(`${int}_TO_BCD`, 'conversion', [p('IN', int)], p('OUT', bits), `Encodes ${int} as BCD in a ${bits} (digits beyond its width are lost).`),
  ),
  fn('ADD_TIME', 'time', [p('IN1', 'TIME'), p('IN2', 'TIME')], p('OUT', 'TIME'), 'OUT := IN1 + IN2 (TIME).'),
  fn('SUB_TIME', 'time', [p('IN1', 'TIME'), p('IN2', 'TIME')], p('OUT', 'TIME'), 'OUT := IN1 - IN2 (TIME).'),
  fn('MULTIME', 'time', [p('IN1', 'TIME'), p('IN2', 'ANY_NUM')], p('OUT', 'TIME'), 'OUT := IN1 * IN2, a TIME times a number (to whole ms).'),
  fn('ADD_TOD_TIME', 'time', [p('IN1', 'TOD'), p('IN2', 'TIME')], p('OUT', 'TOD'), 'OUT := IN1 + IN2, a time of day moved by a TIME.'),
  fn('ADD_DT_TIME', 'time', [p('IN1', 'DT'), p('IN2', 'TIME')], p('OUT', 'DT'), 'OUT := IN1 + IN2, a date and time moved by a TIME.'),
  fn('SUB_DATE_DATE', 'time', [p('IN1', 'DATE'), p('IN2', 'DATE')], p('OUT', 'TIME'), 'OUT := IN1 - IN2, the TIME between two dates.'),
  fn('SUB_TOD_TIME', 'time', [p('IN1', 'TOD'), p('IN2', 'TIME')], p('OUT', 'TOD'), 'OUT := IN1 - IN2, a time of day moved back by a TIME.'),
  fn('SUB_TOD_TOD', 'time', [p('IN1', 'TOD'), p('IN2', 'TOD')], p('OUT', 'TIME'), 'OUT := IN1 - IN2, the TIME between two times of day.'),
  fn('SUB_DT_TIME', 'time', [p('IN1', 'DT'), p('IN2', 'TIME')], p('OUT', 'DT'), 'OUT := IN1 - IN2, a date and time moved back by a TIME.'),
  fn('SUB_DT_DT', 'time', [p('IN1', 'DT'), p('IN2', 'DT')], p('OUT', 'TIME'), 'OUT := IN1 - IN2, the TIME between two dates and times.'),
  fn('CONCAT_DATE_TOD', 'time', [p('IN1', 'DATE'), p('IN2', 'TOD')], p('OUT', 'DT'), 'OUT := the date IN1 at the time of day IN2.'),
  fn('DIVTIME', 'time', [p('IN1', 'TIME'), p('IN2', 'ANY_NUM')], p('OUT', 'TIME'), 'OUT := IN1 / IN2, a TIME divided by a number (to whole ms; IN2 = 0 turns ENO OFF).'),
];

const str = (name: string, inputs: PinSignature[], out: PinSignature, d: string, extensible?: BlockSignature['extensible']) =>
  fn(name, 'string', inputs, out, d, extensible);

/**
 * The character string functions (IEC 61131-3 table 29), positions counted from 1, with MATIEC's
 * behaviour on lengths and positions out of range (engine/library/strings.ts).
 */
export const STRING_FUNCTION_SIGNATURES: readonly BlockSignature[] = [
  str('LEN', [p('IN', 'ANY_STRING')], p('OUT', 'ANY_INT'), 'Length of IN in characters.'),
  str('LEFT', [p('IN', 'ANY_STRING', true), p('L', 'ANY_INT')], p('OUT', 'ANY_STRING', true), 'The first L characters of IN (L < 0 turns ENO OFF).'),
  str('RIGHT', [p('IN', 'ANY_STRING', true), p('L', 'ANY_INT')], p('OUT', 'ANY_STRING', true), 'The last L characters of IN (L < 0 turns ENO OFF).'),
  str(
    'MID',
    [p('IN', 'ANY_STRING', true), p('L', 'ANY_INT'), p('P', 'ANY_INT')],
    p('OUT', 'ANY_STRING', true),
    'L characters of IN from position P (1 = first; P beyond the end gives an empty string).',
  ),
  str('CONCAT', [p('IN1', 'ANY_STRING', true), p('IN2', 'ANY_STRING', true)], p('OUT', 'ANY_STRING', true), 'IN1, IN2, ... joined (cut at 126 characters).', ext('IN', 1)),
  str(
    'INSERT',
    [p('IN1', 'ANY_STRING', true), p('IN2', 'ANY_STRING', true), p('P', 'ANY_INT')],
    p('OUT', 'ANY_STRING', true),
    'IN2 inserted into IN1 after its first P characters.',
  ),
  str(
    'DELETE',
    [p('IN', 'ANY_STRING', true), p('L', 'ANY_INT'), p('P', 'ANY_INT')],
    p('OUT', 'ANY_STRING', true),
    'IN without the L characters from position P (1 = first).',
  ),
  str(
    'REPLACE',
    [p('IN1', 'ANY_STRING', true), p('IN2', 'ANY_STRING', true), p('L', 'ANY_INT'), p('P', 'ANY_INT')],
    p('OUT', 'ANY_STRING', true),
    'IN1 with the L characters from position P replaced by IN2.',
  ),
  str('FIND', [p('IN1', 'ANY_STRING', true), p('IN2', 'ANY_STRING', true)], p('OUT', 'ANY_INT'), 'Position of the first IN2 in IN1 (1 = first; 0 when there is none).'),
];

const TIMES: readonly ElementaryType[] = ['TIME', 'DATE', 'TOD', 'DT'];

/**
 * Every A_TO_B conversion between the supported elementary types that MATIEC's library has:
 * WSTRING has none (its WSTRING has no C type), and between TIME, DATE, TOD and DT only DT_TO_DATE
 * and DT_TO_TOD ("Not supported" in its iec_std_functions.h).
 */
export const CONVERSION_SIGNATURES: readonly BlockSignature[] = ELEMENTARY_TYPES.filter((t) => t !== 'WSTRING').flatMap((from) =>
  ELEMENTARY_TYPES.filter(
    (to) => to !== from && to !== 'WSTRING' && !(TIMES.includes(from) && TIMES.includes(to) && !(from === 'DT' && to !== 'TIME')),
  ).map((to) => fn(`${from}_TO_${to}`, 'conversion', [p('IN', from)], p('OUT', to), conversionText(from, to))),
);

function conversionText(from: ElementaryType, to: ElementaryType): string {
  if (to === 'STRING') return `Converts ${from} to its text, as MATIEC writes it.`;
  if (from === 'STRING') return `Reads a ${to} from the text, as MATIEC reads it.`;
  return `Converts ${from} to ${to} (out of range turns ENO OFF).`;
}

export const FUNCTION_SIGNATURES: readonly BlockSignature[] = [
  ...FUNCTION_SIGNATURES_BASE,
  ...MORE_FUNCTION_SIGNATURES,
  ...STRING_FUNCTION_SIGNATURES,
  ...CONVERSION_SIGNATURES,
];

const BY_NAME = new Map<string, BlockSignature>([...FB_SIGNATURES, ...FUNCTION_SIGNATURES].map((s) => [s.name, s]));

/** The signature of a standard block by (case-insensitive) name. */
export const blockSignature = (name: string): BlockSignature | undefined => BY_NAME.get(name.toUpperCase());
export const isFbType = (type: string): boolean => blockSignature(type)?.kind === 'fb';
/** The types of an A_TO_B conversion (not TRUNC or the BCD conversions, also in category 'conversion'). */
export const conversionTypes = (name: string): { from: ElementaryType; to: ElementaryType } | undefined => {
  const s = blockSignature(name);
  if (s?.category !== 'conversion') return undefined;
  const from = s.inputs[0]!.type;
  const to = s.outputs[0]!.type;
  if (s.name !== `${from}_TO_${to}`) return undefined;
  return { from: from as ElementaryType, to: to as ElementaryType };
};
