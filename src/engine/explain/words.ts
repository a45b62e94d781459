// How "Why?" names elements and counts things, as a PLC programmer reads them on the canvas.
import type { LdElement } from '../../model/elements';

const CONTACT: Record<string, string> = { NO: '| |', NC: '|/|', P: '|P|', N: '|N|', NOT: '|NOT|' };
const COIL: Record<string, string> = { COIL: '( )', NEG: '(/)', SET: '(S)', RESET: '(R)', M: '(M)', SM: '(SM)', RM: '(RM)', P: '(P)', N: '(N)' };

/** `|/| Stop`, `( ) Motor`, `TON T1`, `ADD`, `>> Fill`. */
export function elementSymbol(el: LdElement): string {
  switch (el.kind) {
    case 'contact':
      return el.contact === 'NOT' ? '|NOT|' : `${CONTACT[el.contact]} ${el.variable.trim()}`;
    case 'coil':
      return `${COIL[el.coil]} ${el.variable.trim()}`;
    case 'box':
      return el.instance ? `${el.blockType} ${el.instance}` : el.blockType;
    case 'jump':
      return `>> ${el.target}`;
    case 'return':
      return '<RETURN>';
    case 'link':
      return 'the line';
    case 'connector':
    case 'continuation':
      return `>${el.name.trim()}>`;
  }
}

export const plural = (n: number, word: string): string => `${n} ${word}${n === 1 ? '' : 's'}`;

/** 850 ms, 1.2 s, 3 s. */
export function seconds(ms: number): string {
  if (Math.abs(ms) < 1000) return `${ms} ms`;
  return `${Number((ms / 1000).toFixed(3))} s`;
}
