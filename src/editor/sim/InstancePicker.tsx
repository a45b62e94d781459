// Pick the instance to monitor (as CODESYS does): shown beside the POU tabs while a program is
// loaded and the shown POU is an FB (its instances, nested ones by path: `Line.Motor1`) or, in a
// configuration, a program run by several program instances.
import type { SimState } from '../../store/simState';
import { useSim, useSimStore } from './simContext';

const selectScope = (s: SimState) => s.canvasScope;
const selectShown = (s: SimState) => s.shownPou;
const selectLoaded = (s: SimState) => s.layout !== undefined;

export function InstancePicker() {
  const sim = useSimStore();
  const scope = useSim(selectScope);
  const shown = useSim(selectShown);
  const loaded = useSim(selectLoaded);
  if (!loaded || !shown || shown.kind === 'FUNCTION') return null;
  if (!scope) {
    return (
      <span className="rs-sim-instance rs-sim-unit" data-testid="instance-picker-none">
        {shown.kind === 'FUNCTION_BLOCK' ? `No instance of ${shown.name} is in the running program` : `${shown.name} is not run by the tasks`}
      </span>
    );
  }
  if (scope.choices.length === 0) return null;
  const current = scope.view.instance ?? '';
  return (
    <label className="rs-sim-instance" title={`The instance of ${shown.name} whose values and power flow the canvas shows`}>
      <span className="rs-sim-unit">Instance</span>
      <select value={current} aria-label={`Instance of ${shown.name} to monitor`} data-testid="instance-picker"
        onChange={(e) => sim.getState().pickInstance(shown.name, e.target.value)}>
        {scope.choices.map((path) => (
          <option key={path} value={path}>{path}</option>
        ))}
      </select>
    </label>
  );
}
