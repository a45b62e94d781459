// Mounted once by the app shell (panels.ts HOSTS): canvas clicks on inputs, the force menu, and
// online changes while the simulation runs.
import { SimContextMenu } from './SimContextMenu';
import { useCanvasSimInput } from './useCanvasSimInput';
import { useOnlineChange } from './useOnlineChange';

export function SimHostMount() {
  useCanvasSimInput();
  useOnlineChange();
  return <SimContextMenu />;
}
