// Blocks of CODESYS's Util library (Util.library, "Signals" and "Analog Monitors") that a CODESYS
// V3 export calls without declaring them (the library is part of the CODESYS installation, not of
// the file). The ones a simulator can run exactly are given here as FUNCTION_BLOCK POUs written in
// ST, from the behaviour CODESYS documents (helpme-codesys.com, Util library, 3.5.17/3.5.18):
//
// - BLINK (ENABLE: BOOL; TIMELOW, TIMEHIGH: TIME -> OUT: BOOL): "If ENABLE is set to TRUE, BLINK
//   begins to set the output for the time period TIMEHIGH to TRUE, and then afterwards to set it
//   for the time period TIMELOW to FALSE. When ENABLE is reset to FALSE, output OUT is not
//   changed, i.e. no further pulse is generated." The next rising ENABLE starts again with a
//   TIMEHIGH phase. Times are measured on the scan clock (a phase ends at the first scan at which
//   it has lasted its time; the next phase starts at that scan).
// - LIMITALARM (IN, HIGH, LOW: INT -> O, U, IL: BOOL): O is TRUE when IN exceeds HIGH, U when IN
//   is below LOW, IL when IN lies between LOW and HIGH (limits included).
//
// The import adds such a block to the project as a library POU (read-only, not exported: CODESYS
// brings its own) when the file calls it, does not declare it, and wires only its pins.
// HYSTERESIS (IN, HIGH, LOW -> OUT), PID, INTEGRAL and DERIVATIVE of Util share their names with
// the annex F blocks of OpenPLC's library (controlFbs.ts), which always win: they and the other
// Util blocks (GEN, RAMP_INT, CHARCURVE, PD, STATISTICS_*, ...) import as external blocks, named
// as Util's in the import report.
import type { PouId } from './ids';
import type { Pou, Variable } from './project';

/** `extensions.library` of a library POU: where it comes from; the editor shows it read-only. */
export interface LibraryInfo {
  readonly vendor: string;
  readonly library: string;
}

export const CODESYS_UTIL: LibraryInfo = { vendor: 'CODESYS', library: 'Util' };

const v = (name: string, type: string, varClass: Variable['varClass'], comment = ''): Variable => ({
  name,
  type,
  varClass,
  retain: false,
  comment,
});

const fb = (name: string, comment: string, variables: Variable[], source: string): Pou => ({
  id: `library:codesys-util:${name}` as PouId,
  name,
  kind: 'FUNCTION_BLOCK',
  language: 'ST',
  comment,
  variables,
  networks: [],
  source,
  extensions: { library: CODESYS_UTIL },
});

const BLINK = fb(
  'BLINK',
  'CODESYS Util: pulsating signal. With ENABLE, OUT is TRUE for TIMEHIGH, then FALSE for TIMELOW, and so on; when ENABLE goes FALSE, OUT keeps its value (use OUT AND ENABLE for a FALSE output).',
  [
    v('ENABLE', 'BOOL', 'input'),
    v('TIMELOW', 'TIME', 'input', 'how long OUT is FALSE'),
    v('TIMEHIGH', 'TIME', 'input', 'how long OUT is TRUE'),
    v('OUT', 'BOOL', 'output'),
    v('CLOCK', 'TON', 'local', 'times the current phase'),
    v('RUNNING', 'BOOL', 'local', 'ENABLE was TRUE at the last call'),
  ],
  [
    'IF ENABLE THEN',
    '  IF NOT RUNNING THEN',
    '    RUNNING := TRUE;',
    '    OUT := TRUE;',
    '    CLOCK(IN := FALSE);',
    '  END_IF;',
    '  IF OUT THEN',
    '    CLOCK(IN := TRUE, PT := TIMEHIGH);',
    '  ELSE',
    '    CLOCK(IN := TRUE, PT := TIMELOW);',
    '  END_IF;',
    '  IF CLOCK.Q THEN',
    '    OUT := NOT OUT;',
    '    CLOCK(IN := FALSE);',
    '    IF OUT THEN',
    '      CLOCK(IN := TRUE, PT := TIMEHIGH);',
    '    ELSE',
    '      CLOCK(IN := TRUE, PT := TIMELOW);',
    '    END_IF;',
    '  END_IF;',
    'ELSE',
    '  RUNNING := FALSE;',
    'END_IF;',
    '',
  ].join('\n'),
);

const LIMITALARM = fb(
  'LIMITALARM',
  'CODESYS Util: O is TRUE when IN exceeds HIGH, U when IN is below LOW, IL when IN lies between LOW and HIGH (limits included).',
  [
    v('IN', 'INT', 'input'),
    v('HIGH', 'INT', 'input'),
    v('LOW', 'INT', 'input'),
    v('O', 'BOOL', 'output', 'IN > HIGH'),
    v('U', 'BOOL', 'output', 'IN < LOW'),
    v('IL', 'BOOL', 'output', 'LOW <= IN <= HIGH'),
  ],
  ['O := IN > HIGH;', 'U := IN < LOW;', 'IL := NOT O AND NOT U;', ''].join('\n'),
);

/** The Util blocks Rungsmith runs, by upper-case name. */
const RUNNABLE = new Map<string, Pou>([BLINK, LIMITALARM].map((p) => [p.name, p]));

/** Util blocks Rungsmith does not run (they import as external blocks, named as Util's). */
const OTHERS = [
  'BIT_AS_BYTE', 'BIT_AS_DWORD', 'BIT_AS_WORD', 'BYTE_AS_BIT', 'DWORD_AS_BIT', 'WORD_AS_BIT', 'UNPACK',
  'EXTRACT', 'GETBIT', 'PACK', 'PUTBIT', 'SETBIT', 'SWITCHBIT',
  'BCD_TO_BYTE', 'BCD_TO_DWORD', 'BCD_TO_INT', 'BCD_TO_WORD', 'BYTE_TO_BCD', 'DWORD_TO_BCD', 'INT_TO_BCD', 'WORD_TO_BCD',
  'PD', 'PID', 'PID_FIXCYCLE', 'CHARCURVE', 'RAMP_INT', 'RAMP_REAL', 'GEN', 'FREQ_MEASURE', 'HYSTERESIS',
  'DERIVATIVE', 'INTEGRAL', 'LIN_TRAFO', 'STATISTICS_INT', 'STATISTICS_REAL', 'VARIANCE',
  'BYTE_TO_GRAY', 'DWORD_TO_GRAY', 'GRAY_TO_BYTE', 'GRAY_TO_DWORD', 'GRAY_TO_WORD', 'WORD_TO_GRAY',
  'BYTE_TO_HEXINASCII', 'HEXINASCII_TO_BYTE', 'WORD_AS_STRING', 'BASE64',
];
const KNOWN = new Set([...RUNNABLE.keys(), ...OTHERS]);

/** The runnable Util block of that name (case-insensitive), as a library POU. */
export const codesysUtilBlock = (name: string): Pou | undefined => RUNNABLE.get(name.trim().toUpperCase());

/** True when the name is a block of CODESYS's Util library (run or not). */
export const isCodesysUtilName = (name: string): boolean => KNOWN.has(name.trim().toUpperCase());

/** The library a POU comes from (a library POU the import added), or undefined for the project's own. */
export function libraryInfo(pou: Pou | undefined): LibraryInfo | undefined {
  const info = pou?.extensions?.['library'];
  return typeof info === 'object' && info !== null && 'library' in info ? (info as LibraryInfo) : undefined;
}

/**
 * True when a call of `pou` that wires `pins` fits it: every wired pin (EN/ENO aside) is one of
 * its inputs or outputs. A file's own block of the same name with other pins is not Util's.
 */
export function fitsPins(pou: Pou, pins: Iterable<string>): boolean {
  const known = new Set(pou.variables.filter((x) => x.varClass !== 'local').map((x) => x.name.toUpperCase()));
  for (const p of pins) {
    const u = p.trim().toUpperCase();
    if (u !== 'EN' && u !== 'ENO' && !known.has(u)) return false;
  }
  return true;
}

/** The language a POU's body is written in, as its author calls it: CFC for a CODESYS CFC body kept as FBD. */
export function bodyLanguage(pou: Pou): string {
  return pou.language === 'FBD' && pou.source?.trimStart().startsWith('<CFC') ? 'CFC' : pou.language;
}
