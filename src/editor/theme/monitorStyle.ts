// How monitored values look, in one place for the canvas and the panels: TRUE and FALSE differ in
// colour AND in shape (thick wire and filled symbol vs thin wire and hollow symbol, a filled
// "TRUE" tag vs an outlined "FALSE" tag), so they read without colour too; numbers are neutral.
// A forced value carries one badge everywhere: the canvas draws it, the watch table shows it
// (ForcedBadge.tsx), both from FORCED_BADGE.

/** Wire widths while simulating: energised (TRUE) and not (FALSE); the editor's wire is WIRE_EDIT. */
export const WIRE_TRUE = 3.5;
export const WIRE_FALSE = 1.25;
export const WIRE_EDIT = 1.5;
/** FALSE wires are dashed, so they differ from TRUE ones without colour. */
export const WIRE_FALSE_DASH: readonly number[] = [4, 3];
/** Opacity of the energised colour filling a contact or coil whose variable is TRUE. */
export const SYMBOL_TRUE_FILL_ALPHA = 0.3;

/** The badge of a forced value: a filled square with a white letter, in the theme's --forced colour. */
export const FORCED_BADGE = {
  letter: 'F',
  /** Square side in CSS pixels (content pixels on the canvas). */
  size: 14,
  font: 'bold 11px system-ui, sans-serif',
  /** CSS variable of its colour (the canvas reads it as CanvasTheme.forced). */
  colourVar: '--forced',
  /** The letter's colour. */
  letterColour: '#ffffff',
  title: 'Forced: the program cannot change this value',
} as const;

export type BoolState = 'TRUE' | 'FALSE';

/** TRUE or FALSE when a live text shows a BOOL value (a forced mark may follow), else undefined. */
export function boolState(text: string | undefined): BoolState | undefined {
  if (!text) return undefined;
  if (/^TRUE\b/.test(text)) return 'TRUE';
  if (/^FALSE\b/.test(text)) return 'FALSE';
  return undefined;
}
