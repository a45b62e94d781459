// The app shell: top bar with menus, palette and project tree on the left, the open POUs' tabs
// and the canvas in the centre, tabbed side and
// bottom panels (slots in ./panels.ts), status bar.
import { Fragment, useEffect, useMemo } from 'react';
import { selectDirty, useDocument, useDocumentStore } from '../../store/documentStore';
import { selectTheme, useUi, useUiStore } from '../../store/uiStore';
import { CanvasOverlayContext } from '../canvas/overlay';
import type { EditorContext } from '../commands/editorActions';
import { useShortcuts } from '../commands/useShortcuts';
import { LeftPanel } from '../project/LeftPanel';
import { PouView } from '../project/PouView';
import { Timeline } from '../history/Timeline';
import { MenuBar } from './MenuBar';
import { BOTTOM_PANELS, CANVAS_OVERLAY, HOSTS, RIGHT_PANELS, TOP_BAR_ITEMS } from './panels';
import { StatusBar } from './StatusBar';
import { TabbedPanel } from './TabbedPanel';
import './shell.css';

export const THEME_KEY = 'rungsmith.theme';

export function AppShell() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  const theme = useUi(selectTheme);
  const dirty = useDocument(selectDirty);
  const projectName = useDocument((s) => s.project.name);
  useShortcuts(ctx);

  useEffect(() => {
    document.documentElement.dataset.theme = theme;
    try {
      localStorage.setItem(THEME_KEY, theme);
    } catch {
      // Private mode: the theme just is not remembered.
    }
  }, [theme]);

  const shell = (
    <div className="rs-app" data-theme={theme}>
      <header className="rs-topbar">
        <h1 className="rs-brand">Rungsmith</h1>
        <MenuBar ctx={ctx} />
        {TOP_BAR_ITEMS.map(({ id, component: Item }) => (
          <Item key={id} />
        ))}
        <span className="rs-spacer" />
        <span
          className="rs-project-name"
          data-testid="project-name"
          title={dirty ? 'Unsaved changes' : 'Saved'}
        >
          {projectName}
          {dirty ? ' •' : ''}
        </span>
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
      <div className="rs-workspace">
        <aside className="rs-left">
          <LeftPanel />
        </aside>
        <main className="rs-center">
          <PouView />
          <Timeline />
        </main>
        <aside className="rs-right">
          <TabbedPanel panels={RIGHT_PANELS} label="Side panel" className="rs-side-panel" />
        </aside>
      </div>
      <TabbedPanel panels={BOTTOM_PANELS} label="Bottom panel" className="rs-bottom-panel" />
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
