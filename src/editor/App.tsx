// The editor application: one document store and one UI store, provided to the shell.
// `window.rungsmith` exposes both stores as a scripting aid (docs/editor.md "Scripting aid"); tests read the
// document through it but drive the editor like a user.
import { useEffect, useState } from 'react';
import type { Project } from '../model/project';
import { createDocumentStore, DocumentStoreProvider, type DocumentStore } from '../store/documentStore';
import { createUiStore, UiStoreProvider, type Theme, type UiStore } from '../store/uiStore';
import { AppShell, THEME_KEY } from './layout/AppShell';
import './theme/theme.css';

declare global {
  interface Window {
    rungsmith?: { documentStore?: DocumentStore; uiStore?: UiStore; [key: string]: unknown };
  }
}

function initialTheme(): Theme {
  try {
    const saved = localStorage.getItem(THEME_KEY);
    if (saved === 'light' || saved === 'dark') return saved;
  } catch {
    // Storage unavailable: fall back to the system preference.
  }
  return window.matchMedia?.('(prefers-color-scheme: dark)').matches ? 'dark' : 'light';
}

export function App({ project }: { readonly project?: Project }) {
  const [documentStore] = useState(() => createDocumentStore(project));
  const [uiStore] = useState(() => createUiStore({ theme: initialTheme() }));
  useEffect(() => {
    window.rungsmith = { ...(window.rungsmith ?? {}), documentStore, uiStore };
  }, [documentStore, uiStore]);
  return (
    <DocumentStoreProvider store={documentStore}>
      <UiStoreProvider store={uiStore}>
        <AppShell />
      </UiStoreProvider>
    </DocumentStoreProvider>
  );
}
