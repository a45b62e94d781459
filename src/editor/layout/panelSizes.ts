// Sizes of the shell's resizable panels: the limits a drag or an arrow key keeps to, and the copy
// kept in localStorage so the layout comes back after a reload. The sizes live in the UI store
// (`panels`); the shell reads them as CSS variables (shell.css).
import { DEFAULT_PANELS, type PanelLayout } from '../../store/uiStore';

export const PANELS_KEY = 'rungsmith.panels';

export type PanelSide = 'left' | 'right' | 'bottom';

/** Smallest and largest size of each panel (CSS px); the window may cap the largest further. */
export const PANEL_LIMITS: Readonly<Record<PanelSide, { readonly min: number; readonly max: number }>> = {
  left: { min: 160, max: 560 },
  right: { min: 240, max: 960 },
  bottom: { min: 80, max: 900 },
};

/** The canvas keeps at least this much room whatever the panels do. */
const CENTRE_MIN = { width: 320, height: 160 };

const COLLAPSED_KEY: Readonly<Record<PanelSide, 'leftCollapsed' | 'rightCollapsed' | 'bottomCollapsed'>> = {
  left: 'leftCollapsed',
  right: 'rightCollapsed',
  bottom: 'bottomCollapsed',
};

export const collapsedKey = (side: PanelSide) => COLLAPSED_KEY[side];

/** The largest size `side` may take in a window of this size, given the other panels. */
export function maxSize(side: PanelSide, p: PanelLayout, win: { width: number; height: number }): number {
  const room =
    side === 'bottom'
      ? win.height - CENTRE_MIN.height - 100
      : win.width -
        CENTRE_MIN.width -
        (side === 'left' ? (p.rightCollapsed ? 0 : p.right) : p.leftCollapsed ? 0 : p.left);
  return Math.max(PANEL_LIMITS[side].min, Math.min(PANEL_LIMITS[side].max, room));
}

export function clampSize(side: PanelSide, size: number, p: PanelLayout, win: { width: number; height: number }) {
  return Math.round(Math.min(maxSize(side, p, win), Math.max(PANEL_LIMITS[side].min, size)));
}

const isBool = (v: unknown): v is boolean => typeof v === 'boolean';
const isSize = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v) && v > 0;

/** The layout saved by `savePanels`, each field checked; defaults for anything missing or broken. */
export function parsePanels(text: string | null): PanelLayout {
  if (!text) return DEFAULT_PANELS;
  let raw: Record<string, unknown>;
  try {
    const parsed: unknown = JSON.parse(text);
    if (!parsed || typeof parsed !== 'object') return DEFAULT_PANELS;
    raw = parsed as Record<string, unknown>;
  } catch {
    return DEFAULT_PANELS;
  }
  const size = (side: PanelSide) => {
    const v = raw[side];
    return isSize(v)
      ? Math.min(PANEL_LIMITS[side].max, Math.max(PANEL_LIMITS[side].min, Math.round(v)))
      : DEFAULT_PANELS[side];
  };
  const flag = (k: 'leftCollapsed' | 'rightCollapsed' | 'bottomCollapsed') => {
    const v = raw[k];
    return isBool(v) ? v : DEFAULT_PANELS[k];
  };
  return {
    left: size('left'),
    right: size('right'),
    bottom: size('bottom'),
    leftCollapsed: flag('leftCollapsed'),
    rightCollapsed: flag('rightCollapsed'),
    bottomCollapsed: flag('bottomCollapsed'),
    variablesDock: raw.variablesDock === 'bottom' ? 'bottom' : 'side',
  };
}

export function loadPanels(): PanelLayout {
  try {
    return parsePanels(localStorage.getItem(PANELS_KEY));
  } catch {
    return DEFAULT_PANELS;
  }
}

export function savePanels(p: PanelLayout): void {
  try {
    localStorage.setItem(PANELS_KEY, JSON.stringify(p));
  } catch {
    // Private mode or full storage: the layout is just not remembered.
  }
}
