// Input names CODESYS's Standard library gives the IEC bistables and counters
// (helpme-codesys.com, Standard library: "SRInst(SET1 := .., RESET := ..)", "CTUInst(CU := ..,
// RESET := .., PV := ..)"): SR (SET1, RESET), RS (SET, RESET1), CTU (CU, RESET, PV),
// CTD (CD, LOAD, PV), CTUD (CU, CD, RESET, LOAD, PV). They are the IEC inputs S1, R, S, R1, R and
// LD of the same blocks (same behaviour; CODESYS's PV and CV are WORD where IEC has INT). A
// CODESYS program wires and calls them by these names; Rungsmith reads them as the IEC pins.
const ALIASES: Readonly<Record<string, Readonly<Record<string, string>>>> = {
  SR: { SET1: 'S1', RESET: 'R' },
  RS: { SET: 'S', RESET1: 'R1' },
  CTU: { RESET: 'R' },
  CTD: { LOAD: 'LD' },
  CTUD: { RESET: 'R', LOAD: 'LD' },
};

/** The IEC input a CODESYS input name stands for on a standard block, or undefined. */
/** Whether a block type has inputs named otherwise in CODESYS (SR, RS, the counters). */
export const hasInputAliases = (blockType: string): boolean => Object.hasOwn(ALIASES, blockType);

/** The CODESYS names of a block type's inputs and their IEC names (undefined: none differ). */
export function inputAliases(blockType: string): Readonly<Record<string, string>> | undefined {
  const key = blockType.trim().toUpperCase();
  return Object.hasOwn(ALIASES, key) ? ALIASES[key] : undefined;
}

export function iecInputName(blockType: string, pin: string): string | undefined {
  return ALIASES[blockType.trim().toUpperCase()]?.[pin.trim().toUpperCase()];
}
