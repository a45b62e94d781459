// The app shell: a menu bar, a tool bar under it, palette and project tree on the left, the open
// POUs' tabs and the canvas in the centre, tabbed side and bottom panels (slots in ./panels.ts),
// status bar. Notices go in the notice area under the tool bar (NoticeArea), never over a control. The left, side and bottom panels are resizable (ResizeHandle) and collapsible; their
// sizes are remembered (panelSizes.ts). Each bar is one line: nothing wraps or moves when the
// simulation starts.
import { SymbolCommentsToggle } from '../canvas/SymbolCommentsToggle';
import { Fragment, useEffect, useLayoutEffect, useMemo, type CSSProperties } from 'react';
import { selectDirty, useDocument, useDocumentStore } from '../../store/documentStore';
import { selectPanels, selectTheme, useUi, useUiStore, type PanelLayout } from '../../store/uiStore';
import { CanvasOverlayContext } from '../canvas/overlay';
import type { EditorContext } from '../commands/editorActions';
import { useShortcuts } from '../commands/useShortcuts';
import { LeftPanel } from '../project/LeftPanel';
import { PouView } from '../project/PouView';
import { Timeline } from '../history/Timeline';
import { MenuBar } from './MenuBar';
import { NoticeArea } from './NoticeArea';
import { loadPanels, savePanels, type PanelSide } from './panelSizes';
import { BOTTOM_PANELS, CANVAS_OVERLAY, HOSTS, RIGHT_PANELS, TOP_BAR_ITEMS, VARIABLES_PANEL } from './panels';
import { PanelToggles } from './PanelToggles';
import { ResizeHandle } from './ResizeHandle';
import { useShellKeys } from './useShellKeys';
import { StatusBar } from './StatusBar';
import { TabbedPanel } from './TabbedPanel';
import './shell.css';

export const THEME_KEY = 'rungsmith.theme';

/** The panel sizes as CSS variables of the shell's grid (shell.css); a collapsed panel takes 0. */
function panelVars(p: PanelLayout): CSSProperties {
  return {
    '--rs-left-w': p.leftCollapsed ? '0px' : `${p.left}px`,
    '--rs-right-w': p.rightCollapsed ? '0px' : `${p.right}px`,
    '--rs-bottom-h': p.bottomCollapsed ? '0px' : `${p.bottom}px`,
  } as CSSProperties;
}

export function AppShell() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  const theme = useUi(selectTheme);
  const dirty = useDocument(selectDirty);
  const projectName = useDocument((s) => s.project.name);
  const panels = useUi(selectPanels);
  useShortcuts(ctx);
  useShellKeys(ctx);

  // The remembered layout, before the first paint; then every change is remembered.
  useLayoutEffect(() => {
    ui.getState().setPanels(loadPanels());
    return ui.subscribe((s, prev) => {
      if (s.panels !== prev.panels) savePanels(s.panels);
    });
  }, [ui]);
  const { right, bottom } = useMemo(
    () =>
      panels.variablesDock === 'bottom'
        ? {
            right: RIGHT_PANELS.filter((p) => p.id !== VARIABLES_PANEL.id),
            bottom: [BOTTOM_PANELS[0]!, VARIABLES_PANEL, ...BOTTOM_PANELS.slice(1)],
          }
        : { right: RIGHT_PANELS, bottom: BOTTOM_PANELS },
    [panels.variablesDock],
  );
  /** A tab chosen in a collapsed panel (e.g. a problem revealing its variable) opens the panel. */
  const expand = (side: PanelSide) => () => {
    const key = side === 'right' ? 'rightCollapsed' : 'bottomCollapsed';
    if (ui.getState().panels[key]) ui.getState().setPanels({ [key]: false });
  };

  useEffect(() => {
    document.documentElement.dataset.theme = theme;
    try {
      localStorage.setItem(THEME_KEY, theme);
    } catch {
      // Private mode: the theme just is not remembered.
    }
  }, [theme]);

  const shell = (
    <div className="rs-app" data-theme={theme} style={panelVars(panels)}>
      <header className="rs-topbar">
        <h1 className="rs-brand">Rungsmith</h1>
        <MenuBar ctx={ctx} />
        <span className="rs-spacer" />
        <PanelToggles ctx={ctx} />
        <span
          className="rs-project-name"
          data-testid="project-name"
          title={dirty ? 'Unsaved changes' : 'Saved'}
        >
          {projectName}
          {dirty ? ' •' : ''}
        </span>
        <SymbolCommentsToggle />
        <button
          type="button"
          className="rs-icon-button"
          aria-label={theme === 'dark' ? 'Switch to light theme' : 'Switch to dark theme'}
          data-testid="theme-toggle"
          title="Light / dark theme"
          onClick={() => ui.getState().setTheme(theme === 'dark' ? 'light' : 'dark')}
        >
          {theme === 'dark' ? '☀' : '☾'}
        </button>
      </header>
      <div className="rs-toolbar" data-testid="toolbar">
        {TOP_BAR_ITEMS.map(({ id, component: Item }) => (
          <Item key={id} />
        ))}
      </div>
      <NoticeArea />
      <div className="rs-workspace">
        <aside id="rs-left-panel" className="rs-left" hidden={panels.leftCollapsed}>
          <LeftPanel />
        </aside>
        <ResizeHandle side="left" controls="rs-left-panel" />
        <main className="rs-center">
          <PouView />
          <Timeline />
        </main>
        <ResizeHandle side="right" controls="rs-right-panel" />
        <aside id="rs-right-panel" className="rs-right" hidden={panels.rightCollapsed}>
          <TabbedPanel panels={right} label="Side panel" className="rs-side-panel" onActivate={expand('right')} />
        </aside>
      </div>
      <ResizeHandle side="bottom" controls="rs-bottom-panel" />
      <div id="rs-bottom-panel" className="rs-bottom" hidden={panels.bottomCollapsed}>
        <TabbedPanel panels={bottom} label="Bottom panel" className="rs-bottom-panel" onActivate={expand('bottom')} />
      </div>
      <StatusBar />
      {HOSTS.map(({ id, component: Host }) => (
        <Fragment key={id}>
          <Host />
        </Fragment>
      ))}
    </div>
  );
  return CANVAS_OVERLAY ? (
    <CanvasOverlayContext.Provider value={CANVAS_OVERLAY}>{shell}</CanvasOverlayContext.Provider>
  ) : (
    shell
  );
}
