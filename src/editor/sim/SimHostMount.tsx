// Mounted once by the app shell (panels.ts HOSTS): canvas clicks on inputs, the force menu, and
// online changes while the simulation runs, the shown POU's body monitored and followed when stepping.
import { SimContextMenu } from './SimContextMenu';
import { useSimStore } from './simContext';
import { useCanvasSimInput } from './useCanvasSimInput';
import { useFollowExecution } from './useFollowExecution';
import { useOnlineChange } from './useOnlineChange';

export function SimHostMount() {
  useCanvasSimInput();
  useOnlineChange();
  useFollowExecution(useSimStore());
  return <SimContextMenu />;
}
