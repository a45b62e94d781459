// Mounted once by the app shell (panels.ts HOSTS): canvas clicks on inputs, the force menu, and
// online changes while the simulation runs, the shown POU's body monitored and followed when stepping,
// the watch list kept with the project.
import { SimContextMenu } from './SimContextMenu';
import { useSimStore } from './simContext';
import { useCanvasSimInput } from './useCanvasSimInput';
import { useFollowExecution } from './useFollowExecution';
import { useOnlineChange } from './useOnlineChange';
import { useWatchList } from './useWatchList';
import { useDocumentStore } from '../../store/documentStore';

export function SimHostMount() {
  useCanvasSimInput();
  useOnlineChange();
  useFollowExecution(useSimStore());
  useWatchList(useDocumentStore(), useSimStore());
  return <SimContextMenu />;
}
