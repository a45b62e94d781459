// The left column: the palette and the project tree, as tabs.
import { useMemo } from 'react';
import { useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import type { EditorContext } from '../commands/editorActions';
import type { PanelSlot } from '../layout/panels';
import { TabbedPanel } from '../layout/TabbedPanel';
import { Palette } from '../palette/Palette';
import { ProjectTree } from './ProjectTree';

function PalettePanel() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  return <Palette ctx={ctx} />;
}

const LEFT_PANELS: readonly PanelSlot[] = [
  { id: 'palette', title: 'Palette', component: PalettePanel },
  { id: 'project', title: 'Project', component: ProjectTree },
];

export function LeftPanel() {
  return <TabbedPanel panels={LEFT_PANELS} label="Palette and project" className="rs-left-panel" />;
}
