// Buttons in the top bar that show or hide each panel (pressed = shown), with their keys.
import type { EditorContext } from '../commands/editorActions';
import { keyLabel } from '../commands/keys';
import { useUi } from '../../store/uiStore';
import { SHELL_COMMANDS } from './shellCommands';
import { collapsedKey, type PanelSide } from './panelSizes';

const TOGGLES: readonly { side: PanelSide; command: string; icon: string; name: string }[] = [
  { side: 'left', command: 'view.toggleLeft', icon: '◧', name: 'palette and project tree' },
  { side: 'bottom', command: 'view.toggleBottom', icon: '⬓', name: 'bottom panel' },
  { side: 'right', command: 'view.toggleRight', icon: '◨', name: 'side panel' },
];

export function PanelToggles({ ctx }: { readonly ctx: EditorContext }) {
  const panels = useUi((s) => s.panels);
  return (
    <span className="rs-panel-toggles" role="group" aria-label="Panels">
      {TOGGLES.map(({ side, command, icon, name }) => {
        const c = SHELL_COMMANDS.find((x) => x.id === command)!;
        const shown = !panels[collapsedKey(side)];
        return (
          <button
            key={side}
            type="button"
            className="rs-icon-button rs-panel-toggle"
            aria-pressed={shown}
            aria-label={`Show the ${name}`}
            aria-controls={`rs-${side}-panel`}
            title={`${shown ? 'Hide' : 'Show'} the ${name} (${keyLabel(c.keys![0]!)})`}
            data-testid={`toggle-${side}`}
            onClick={() => c.run(ctx)}
          >
            {icon}
          </button>
        );
      })}
    </span>
  );
}
