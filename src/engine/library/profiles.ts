// Semantics profiles (LD-SEMANTICS.md section 10): where the standard's text and MATIEC (the compiler
// under Beremiz and OpenPLC Runtime) give different results for the same program.
//
// Found by reading MATIEC's lib/counter.txt, lib/C/iec_std_lib.h and lib/C/iec_std_functions.h:
//
// | id                   | iec (standard text)                         | openplc (MATIEC)                                   |
// | counter-up-limit     | CTU/CTUD count up while CV < 32767 (INT max)| count up only while CV < PV                        |
// | counter-down-limit   | CTD/CTUD count down while CV > -32768       | count down only while CV > 0                       |
// | time-conversion-unit | TIME_TO_<int/bits/real> gives ms, and       | gives seconds (timespec tv_sec; REAL with fraction)|
// |                      | <int/bits/real>_TO_TIME reads ms            | and reads seconds                                  |
// |                      | (so do INTEGRAL, DERIVATIVE, PID's CYCLE)   | (their bodies call TIME_TO_REAL(CYCLE))            |
// | mod-by-zero          | MOD(x, 0) = 0 with ENO OFF                  | MOD(x, 0) = 0 with ENO ON (TEST_EN, no condition)  |
// | conversion-range     | out-of-range conversion or TRUNC: ENO OFF   | C cast: ENO stays ON                               |
// |                      | (the value is the same wrapped result)      |                                                    |
// | limit-crossed        | LIMIT = MIN(MAX(IN, MN), MX): MX if MN > MX | IN > MN ? (IN < MX ? IN : MX) : MN: MN if MN >= IN |
// | mux-negative         | MUX with K < 0: ENO OFF, output not assigned| ENO ON, OUT = 0 (MATIEC tests only K >= n)         |
// | string-find          | FIND: first occurrence, 0 when none         | __pfind: resumes past a partial match, so it misses|
// |                      |                                             | an occurrence starting inside one (FIND('aab','ab')|
// |                      |                                             | = 0)                                               |
// | time-to-string       | TIME_TO_STRING(T#1s500ms) = 'T#1s500ms'     | 'T#0d0h0m1s500ms' (__time_to_string)               |
// | string-to-number     | STRING_TO_<num/TIME> reads an IEC literal,  | __pstring_to_sint/atof: skips what it cannot read, |
// |                      | other text is an error (ENO OFF, 0)         | ENO ON; TIME in seconds                            |
//
// Same in both (checked): string comparisons (MATIEC's __str_cmp since 2020: 'abc' < 'abcd', ''
// equals only ''; OpenPLC v3's runtime still bundles the library from before, where a prefix and ''
// compared equal and FIND gave LEN(IN1) + 1 when nothing was found); timers, edge detection, bistables; DIV by zero (ENO OFF, result 0);
// REAL_TO_<int> rounds to nearest with ties to even (MATIEC __real_round); negative REAL to an
// unsigned type gives 0; <num>_TO_BOOL is TRUE for any non-zero value; integer arithmetic wraps.
// Not emulated (undefined behaviour in MATIEC's C, differs between x86 and ARM targets): shifts by
// N >= the type's width (here: 0 for SHL/SHR), DINT/LINT minimum DIV -1 (a crash there, wraps here).
import type { CounterType } from '../../model/blocks';
import type { Profile } from '../../model/project';
import { defaultValue, isBigIntType, typeRange } from '../values/types';

export interface ProfileDifference {
  readonly id: string;
  readonly summary: string;
  readonly iec: string;
  readonly openplc: string;
}

export const PROFILE_DIFFERENCES: readonly ProfileDifference[] = [
  {
    id: 'counter-up-limit',
    summary: 'Where CTU and CTUD stop counting up',
    iec: 'Count up while CV < 32767 (the INT maximum; the maximum of DINT, LINT, UDINT or ULINT for CTU_DINT ...); CV can pass PV.',
    openplc: 'Count up only while CV < PV; CV stops at PV.',
  },
  {
    id: 'counter-down-limit',
    summary: 'Where CTD and CTUD stop counting down',
    iec: "Count down while CV > -32768 (the INT minimum; the minimum of the typed counters' type, 0 if unsigned); CV can go below 0.",
    openplc: 'Count down only while CV > 0; CV stops at 0.',
  },
  {
    id: 'time-conversion-unit',
    summary: 'Unit of TIME_TO_* and *_TO_TIME conversions',
    iec: 'Milliseconds: TIME_TO_DINT(T#1s500ms) = 1500, DINT_TO_TIME(250) = T#250ms. INTEGRAL, DERIVATIVE and PID read CYCLE as TIME_TO_REAL does: in ms, so PID\'s TR and TD are in ms.',
    openplc:
      'Seconds: TIME_TO_DINT(T#1s500ms) = 1, DINT_TO_TIME(250) = T#4m10s, TIME_TO_REAL(T#1s500ms) = 1.5. INTEGRAL, DERIVATIVE and PID read CYCLE in seconds (PID\'s TR and TD in seconds).',
  },
  {
    id: 'mod-by-zero',
    summary: 'MOD with IN2 = 0',
    iec: 'OUT = 0 and ENO goes OFF (an error): a variable written beside OUT keeps its value.',
    openplc: 'OUT = 0 and ENO stays ON.',
  },
  {
    id: 'conversion-range',
    summary: 'Conversions whose value does not fit the target type',
    iec: 'ENO goes OFF; OUT is the wrapped value (INT_TO_SINT(300) = 44, REAL_TO_UINT(-1.0) = 0). TRUNC alike.',
    openplc: 'ENO stays ON; OUT is the same wrapped value (a C cast).',
  },
  {
    id: 'mux-negative',
    summary: 'MUX with a negative selector K',
    iec: 'An error: ENO goes OFF and the output variable keeps its value.',
    openplc: 'ENO stays ON and OUT is 0 (the type\'s initial value): MATIEC checks only K >= the input count.',
  },
  {
    id: 'string-find',
    summary: 'FIND when IN2 starts inside a partial match',
    iec: "The position of the first occurrence, 0 when there is none: FIND('aab', 'ab') = 2.",
    openplc: "MATIEC's scan resumes after a partial match, so it misses an occurrence that starts inside one: FIND('aab', 'ab') = 0. Both give 0 when IN2 is empty, longer than IN1 or absent.",
  },
  {
    id: 'time-to-string',
    summary: 'Text of TIME_TO_STRING',
    iec: "An IEC literal: TIME_TO_STRING(T#1s500ms) = 'T#1s500ms'.",
    openplc: "MATIEC's format, days first: 'T#0d0h0m1s500ms' ('T#0d' for zero).",
  },
  {
    id: 'string-to-number',
    summary: 'STRING_TO_<number or TIME> on text',
    iec: "Reads a literal of the type ('42', '16#FF', '1.5', 'T#2s' or a number of ms); other text is an error (ENO OFF, OUT 0).",
    openplc: "MATIEC's readers: digits are read from the end and other characters skipped ('1 000' = 1000, '12abc34' = 12); REAL with atof; TIME in seconds; ENO stays ON.",
  },
  {
    id: 'limit-crossed',
    summary: 'LIMIT when MN is greater than MX',
    iec: 'OUT = MIN(MAX(IN, MN), MX), which is MX.',
    openplc: 'OUT = MN unless IN > MN (then MX, as IN > MX too).',
  },
];

/** A counter's PV/CV: bigint for LINT/ULINT, a number otherwise. */
export type CounterValue = number | bigint;

export interface CounterLimits {
  /** CV may count up while CV < upTo(PV). */
  upTo(pv: CounterValue): CounterValue;
  /** CV may count down while CV > downTo. */
  readonly downTo: CounterValue;
}

/**
 * Counting limits of a counter whose CV has type `type` (INT for CTU/CTD/CTUD, DINT for CTU_DINT ...).
 * iec: the range of CV's type (so CV never wraps); openplc: MATIEC's PV and 0 for every type (its
 * typed counters CTU_DINT ... CTUD_ULINT have the same body as CTU/CTD/CTUD).
 * Values are bigint for LINT/ULINT, numbers otherwise, as CV is.
 */
export function counterLimits(profile: Profile, type: CounterType = 'INT'): CounterLimits {
  const big = isBigIntType(type);
  if (profile === 'openplc') return { upTo: (pv) => pv, downTo: defaultValue(type) as CounterValue };
  const { min, max } = typeRange(type);
  const top = big ? max : Number(max);
  return { upTo: () => top, downTo: big ? min : Number(min) };
}

/** Milliseconds per unit of a number converted to or from TIME. */
export const timeConversionUnitMs = (profile: Profile): number => (profile === 'openplc' ? 1000 : 1);
