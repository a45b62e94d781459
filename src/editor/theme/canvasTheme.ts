// The canvas colours, read from the CSS variables of the current theme (theme.css).
export interface CanvasTheme {
  readonly bg: string;
  readonly grid: string;
  readonly rail: string;
  readonly wire: string;
  readonly symbol: string;
  readonly text: string;
  readonly operand: string;
  readonly muted: string;
  readonly selection: string;
  readonly selectionFill: string;
  readonly cursor: string;
  readonly hover: string;
  readonly error: string;
  readonly warning: string;
  readonly energised: string;
  /** A FALSE value while simulating (wires, symbols and value tags; drawn thin and hollow too). */
  readonly falseState: string;
  readonly boxFill: string;
  readonly networkBg: string;
  /** Forced variables (simulation). */
  readonly forced: string;
}

const KEYS: Record<keyof CanvasTheme, string> = {
  bg: '--canvas-bg',
  grid: '--canvas-grid',
  rail: '--canvas-rail',
  wire: '--canvas-wire',
  symbol: '--canvas-symbol',
  text: '--canvas-text',
  operand: '--canvas-operand',
  muted: '--canvas-muted',
  selection: '--canvas-selection',
  selectionFill: '--canvas-selection-fill',
  cursor: '--canvas-cursor',
  hover: '--canvas-hover',
  error: '--canvas-error',
  warning: '--canvas-warning',
  energised: '--canvas-energised',
  falseState: '--canvas-false',
  boxFill: '--canvas-box-fill',
  networkBg: '--canvas-network-bg',
  forced: '--forced',
};

/** Reads the canvas colours from the element's computed style (call after the theme attribute changed). */
export function readCanvasTheme(el: Element = document.documentElement): CanvasTheme {
  const style = getComputedStyle(el);
  const out: Record<string, string> = {};
  for (const [k, v] of Object.entries(KEYS)) out[k] = style.getPropertyValue(v).trim() || '#888888';
  return out as unknown as CanvasTheme;
}
