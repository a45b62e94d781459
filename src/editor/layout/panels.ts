// Slots of the app shell. Other parts of the editor add themselves by adding an entry here:
// a tab in the right side panel or the bottom panel, an item in the top bar, or a host component
// mounted once (dialogs, background work such as autosave).
import { CommandHost } from '../commands/CommandHost';
import type { ComponentType } from 'react';
import { FilesHost, FileNotice } from '../files/FilesHost';
import { HardwarePanel } from '../hardware/HardwarePanel';
import { HardwareSimLink } from '../hardware/HardwareSimLink';
import { PlcopenHost } from '../plcopen/PlcopenHost';
import { LibraryHost } from '../library/LibraryManager';
import { InspectorPanel } from '../inspector/InspectorPanel';
import { ProblemsPanel } from '../problems/ProblemsPanel';
import { VariablesPanel } from '../variables/VariablesPanel';
import type { NetworkOverlayHook } from '../canvas/overlay';
import { useSimNetworkOverlay } from '../sim/canvasOverlay';
import { InputsPanel } from '../sim/InputsPanel';
import { SimHostMount } from '../sim/SimHostMount';
import { SimToolbar } from '../sim/SimToolbar';
import { SteppingBadge } from '../hardware/HardwareStepping';
import { SimNotices } from '../sim/SimNotices';
import { SimulationPanel } from '../sim/SimulationPanel';
import { TrendPanel } from '../sim/TrendPanel';
import { WatchPanel } from '../sim/WatchPanel';
import { WhyPanel } from '../history/WhyPanel';
import { TestsPanel } from '../scenarios/TestsPanel';
import { NetworkUnitsHost } from '../outline/NetworkUnitsHost';
import { OutlinePanel } from '../outline/OutlinePanel';
import { FindHost } from '../find/FindHost';
import { XrefPanel } from '../find/XrefPanel';
import { PrintHost } from '../print/PrintHost';
import { PlantPanel } from '../plant/PlantPanel';
import { PlantHost } from '../plant/PlantHost';

export interface PanelSlot {
  readonly id: string;
  readonly title: string;
  readonly component: ComponentType;
}

export interface BarSlot {
  readonly id: string;
  readonly component: ComponentType;
}

/** The variable table: a tab of the side panel, or of the full-width bottom panel in the wide view. */
export const VARIABLES_PANEL: PanelSlot = { id: 'variables', title: 'Variables', component: VariablesPanel };

/** Tabs of the right side panel; the first is open at start. */
export const RIGHT_PANELS: readonly PanelSlot[] = [
  { id: 'inspector', title: 'Inspector', component: InspectorPanel },
  VARIABLES_PANEL,
  { id: 'hardware', title: 'Hardware', component: HardwarePanel },
  { id: 'inputs', title: 'Inputs', component: InputsPanel },
  { id: 'outline', title: 'Outline', component: OutlinePanel },
  { id: 'plant', title: 'Plant', component: PlantPanel },
];

/** Tabs of the bottom panel; the first is open at start. */
export const BOTTOM_PANELS: readonly PanelSlot[] = [
  { id: 'problems', title: 'Problems', component: ProblemsPanel },
  { id: 'watch', title: 'Watch', component: WatchPanel },
  { id: 'trend', title: 'Trend', component: TrendPanel },
  { id: 'breakpoints', title: 'Breakpoints & forces', component: SimulationPanel },
  { id: 'why', title: 'Why?', component: WhyPanel },
  { id: 'tests', title: 'Tests', component: TestsPanel },
  { id: 'xref', title: 'Cross-reference', component: XrefPanel },
];

/** Items in the top bar, after the menus (e.g. simulation controls). */
export const TOP_BAR_ITEMS: readonly BarSlot[] = [{ id: 'simulation', component: SimToolbar }];

/**
 * The notices, in the notice area under the tool bar (NoticeArea.tsx): in the layout flow, so a
 * notice never covers a control.
 */
export const NOTICES: readonly BarSlot[] = [
  { id: 'simulation', component: SimNotices },
  { id: 'files', component: FileNotice },
  // The page driving hardware: stepping, or running with the outputs not driven (and why).
  { id: 'hardware', component: SteppingBadge },
];

/** Mounted once inside the stores' providers. */
export const HOSTS: readonly BarSlot[] = [
  { id: 'files', component: FilesHost },
  { id: 'plcopen', component: PlcopenHost },
  { id: 'libraries', component: LibraryHost },
  { id: 'simulation', component: SimHostMount },
  { id: 'hardware-sim-link', component: HardwareSimLink },
  { id: 'network-units', component: NetworkUnitsHost },
  { id: 'find', component: FindHost },
  { id: 'print', component: PrintHost },
  { id: 'commands', component: CommandHost },
  { id: 'plant', component: PlantHost },
];

/** Power flow and live values on the canvas (see src/editor/canvas/overlay.ts); undefined: none. */
export const CANVAS_OVERLAY: NetworkOverlayHook | undefined = useSimNetworkOverlay;
